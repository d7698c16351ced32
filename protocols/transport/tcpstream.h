#pragma once

#include "bytestream.h"

#include <QTcpSocket>
#include <QTimer>

#include <memory>

namespace db {

// TCP client stream: non-blocking, TCP_NODELAY (request/response protocols must not wait for
// Nagle or delayed ACKs), a connect timeout, and errors that name host and port. At most
// kReadBufferBytes are taken from the socket per event-loop pass: a peer that floods waits in
// TCP flow control instead of in this process's memory.
// write() hands the bytes to the kernel at once (an unbuffered socket): a request is on the wire
// when write() returns, without waiting for the next event-loop pass; only what the kernel does
// not take is queued and sent from the loop. A failure found while writing is reported from the
// event loop (closed() never comes from inside write()).
class TcpStream : public ByteStream
{
    Q_OBJECT
public:
    static constexpr int kDefaultConnectTimeoutMs = 3000;
    static constexpr qint64 kReadBufferBytes = 64 * 1024;

    TcpStream(const QString &host, quint16 port, QObject *parent = nullptr);
    // Closes without a closed() signal: the socket's own destructor would report its close into
    // this object after the timer member is gone.
    ~TcpStream() override;

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
    std::unique_ptr<char[]> m_readChunk; // kReadBufferBytes, reused for every read
    QByteArray m_received; // what a read delivers; its storage is reused
    bool m_writing = false; // inside m_socket.write(): socket errors wait for the event loop
};

} // namespace db
