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
    for (const char c : bytes) {
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
        m_line.append(c);
        if (++m_size > kMaxAnswerBytes) {
            out.push_back(Error(Error::Kind::Malformed,
                                Tr::tr("answer too long without prompt (more than %1 "
                                       "bytes)")
                                    .arg(kMaxAnswerBytes)));
            reset();
            m_discarding = true;
        }
    }
    return out;
}

void Framer::reset()
{
    m_line.clear();
    m_answer = {};
    m_haveEcho = false;
    m_discarding = false;
    m_size = 0;
}

void Framer::endLine()
{
    if (m_discarding) {
        m_line.clear();
        return;
    }
    const QString line = QString::fromLatin1(m_line);
    m_line.clear();
    m_size += 2; // terminators count towards the limit too
    if (!m_haveEcho) {
        m_answer.echo = line;
        m_haveEcho = true;
    } else {
        m_answer.lines.append(line);
    }
}

} // namespace db::refgo
