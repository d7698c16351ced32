#include "scriptedstream.h"

#include <QTimer>

namespace db::test {

QByteArray ScriptedStream::takeWritten()
{
    QByteArray all;
    for (qsizetype i = m_taken; i < m_writes.size(); ++i)
        all += m_writes.at(i);
    m_taken = m_writes.size();
    return all;
}

void ScriptedStream::doOpen()
{
    // Asynchronous like a real socket.
    QTimer::singleShot(0, this, [this] {
        if (m_refusal.isError())
            setClosed(std::exchange(m_refusal, Error()));
        else
            setOpened();
    });
}

void ScriptedStream::doWrite(const QByteArray &bytes)
{
    m_writes.append(bytes);
    Q_EMIT written(bytes);
}

} // namespace db::test
