#pragma once

#include "transport/bytestream.h"

#include <QByteArrayList>

namespace db::test {

// A ByteStream for level-2 tests: records what the engine writes and lets the test feed
// received bytes (split anywhere), refuse the open, or drop the link.
class ScriptedStream : public ByteStream
{
    Q_OBJECT
public:
    using ByteStream::ByteStream;

    QString peerName() const override { return QStringLiteral("scripted:0"); }

    // Everything written since the last takeWritten(), concatenated.
    QByteArray takeWritten();
    const QByteArrayList &writes() const { return m_writes; }

    // Next open() fails with this error instead of opening.
    void refuseNextOpen(const Error &error) { m_refusal = error; }
    // Delivers bytes as if received (only while open).
    void feed(const QByteArray &bytes) { deliver(bytes); }
    // The peer goes away.
    void drop(const Error &error) { setClosed(error); }

Q_SIGNALS:
    void written(const QByteArray &bytes);

protected:
    void doOpen() override;
    void doClose() override { setClosed(); }
    void doWrite(const QByteArray &bytes) override;

private:
    QByteArrayList m_writes;
    qsizetype m_taken = 0;
    Error m_refusal;
};

} // namespace db::test
