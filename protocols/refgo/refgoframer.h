#pragma once

// Splits the drive's byte stream into RefGo answers (movingcap.md 3.1). Pure: bytes in,
// answers out; knows no socket and no request.

#include "core/result.h"

#include <QByteArray>
#include <QString>
#include <QStringList>

#include <vector>

namespace db::refgo {

// One answer: the echoed request line, zero or more result lines, ended by the prompt '>'.
struct Answer
{
    QString echo;
    QStringList lines;

    friend bool operator==(const Answer &, const Answer &) = default;
};

// Framing rules (spec 3.1 and its [R] notes):
// - A line ends at CR LF, LF CR, a lone CR or a lone LF; any run of CR/LF ends one line, so
//   empty lines vanish and a split between CR and LF does not matter.
// - A '>' at the start of a line after the echo ends the answer; nothing follows it.
// - CR, LF, spaces and tabs before the next echo are skipped. A '>' before any echo (a prompt
//   with no answer, e.g. a greeting) is skipped too.
// - An answer that grows past kMaxAnswerBytes without its prompt yields a Malformed error; the
//   framer then discards bytes up to the next prompt and starts afresh.
class Framer
{
public:
    static constexpr qsizetype kMaxAnswerBytes = 64 * 1024;

    // Bytes may be split anywhere. Returns the answers (or errors) they complete, in order.
    std::vector<Result<Answer>> feed(const QByteArray &bytes);
    // Forgets a partial answer (after a disconnect).
    void reset();
    // True when no partial answer is buffered.
    bool isIdle() const { return !m_haveEcho && m_line.isEmpty() && !m_discarding; }
    // Bytes of the partial answer held (at most kMaxAnswerBytes).
    qsizetype bufferedBytes() const { return m_size; }

private:
    void endLine();

    QByteArray m_line; // current line, without its terminator
    Answer m_answer; // lines of the current answer so far
    bool m_haveEcho = false;
    bool m_discarding = false; // after an oversize answer: skip up to the next prompt
    qsizetype m_size = 0; // bytes of the current answer so far
};

} // namespace db::refgo
