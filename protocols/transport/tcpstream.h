#pragma once

#include "bytestream.h"

#include <QTcpSocket>
#include <QTimer>

namespace db {

// TCP client stream: non-blocking, TCP_NODELAY (request/response protocols must not wait for
// Nagle or delayed ACKs), a connect timeout, and errors that name host and port. At most
// kReadBufferBytes are taken from the socket per event-loop pass: a peer that floods waits in
// TCP flow control instead of in this process's memory.
class TcpStream : public ByteStream
{
    Q_OBJECT
public:
    static constexpr int kDefaultConnectTimeoutMs = 3000;
    static constexpr qint64 kReadBufferBytes = 64 * 1024;

    TcpStream(const QString &host, quint16 port, QObject *parent = nullptr);

    void setConnectTimeoutMs(int ms) override { m_connectTimeoutMs = ms; }
    QString peerName() const override;
    QString host() const { return m_host; }
    quint16 port() const { return m_port; }

protected:
    void doOpen() override;
    void doClose() override;
    void doWrite(const QByteArray &bytes) override;

private:
    void onConnected();
    void onSocketError(QAbstractSocket::SocketError error);
    void onDisconnected();
    Error describe(QAbstractSocket::SocketError error) const;

    QString m_host;
    quint16 m_port;
    int m_connectTimeoutMs = kDefaultConnectTimeoutMs;
    QTcpSocket m_socket;
    QTimer m_connectTimer;
};

} // namespace db
