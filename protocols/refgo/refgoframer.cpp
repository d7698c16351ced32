#include "refgoframer.h"
#include <QCoreApplication>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::refgo)
};
} // namespace

namespace db::refgo {

std::vector<Result<Answer>> Framer::feed(const QByteArray &bytes)
{
    std::vector<Result<Answer>> out;
    const char *const end = bytes.constEnd();
    for (const char *p = bytes.constBegin(); p != end; ++p) {
        const char c = *p;
        const bool atLineStart = m_line.isEmpty();
        if (c == '\r' || c == '\n') {
            if (!atLineStart)
                endLine();
            continue;
        }
        if (atLineStart && c == '>') {
            // The prompt: the answer is complete (spec 3.1). Before an echo it answers nothing.
            if (m_haveEcho && !m_discarding)
                out.push_back(std::move(m_answer));
            reset();
            continue;
        }
        if (m_discarding)
            continue;
        if (atLineStart && !m_haveEcho && (c == ' ' || c == '\t'))
            continue;
        // The rest of the line up to its terminator, appended at once.
        const char *lineEnd = p + 1;
        while (lineEnd != end && *lineEnd != '\r' && *lineEnd != '\n')
            ++lineEnd;
        const qsizetype room = kMaxAnswerBytes - m_size;
        if (lineEnd - p > room) {
            out.push_back(Error(Error::Kind::Malformed,
                                Tr::tr("answer too long without prompt (more than %1 "
                                       "bytes)")
                                    .arg(kMaxAnswerBytes)));
            reset();
            m_discarding = true;
            p += qMax<qsizetype>(room, 0); // the byte past the limit; later ones are discarded
            continue;
        }
        m_line.append(p, lineEnd - p);
        m_size += lineEnd - p;
        p = lineEnd - 1;
    }
    return out;
}

void Framer::reset()
{
    m_line.resize(0); // keeps the capacity for the next answer
    m_answer = {};
    m_haveEcho = false;
    m_discarding = false;
    m_size = 0;
}

void Framer::endLine()
{
    if (m_discarding) {
        m_line.resize(0);
        return;
    }
    const QString line = QString::fromLatin1(m_line);
    m_line.resize(0); // keeps the capacity for the next line
    m_size += 2; // terminators count towards the limit too
    if (!m_haveEcho) {
        m_answer.echo = line;
        m_haveEcho = true;
    } else {
        m_answer.lines.append(line);
    }
}

} // namespace db::refgo
