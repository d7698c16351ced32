#pragma once

#include "bytestream.h"

#include <QSocketNotifier>
#include <QTcpSocket>
#include <QTimer>

#include <memory>

namespace db {

// TCP client stream: non-blocking, TCP_NODELAY (request/response protocols must not wait for
// Nagle or delayed ACKs), a connect timeout, and errors that name host and port. At most
// kReadBufferBytes are taken from the socket per event-loop pass: a peer that floods waits in
// TCP flow control instead of in this process's memory.
// QTcpSocket makes the connection (name lookup, connect, its errors); once it stands, the
// stream keeps a descriptor of its own and reads and writes it directly, woken by socket
// notifiers: a round trip then costs the kernel's read and write and no socket layer above.
// write() hands the bytes to the kernel at once: a request is on the wire when write() returns;
// only what the kernel does not take is queued and sent from the loop. A failure found while
// writing is reported from the event loop (closed() never comes from inside write()).
class TcpStream : public ByteStream
{
    Q_OBJECT
public:
    static constexpr int kDefaultConnectTimeoutMs = 3000;
    static constexpr qint64 kReadBufferBytes = 64 * 1024;

    TcpStream(const QString &host, quint16 port, QObject *parent = nullptr);
    // Closes without a closed() signal.
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
    void onReadable();
    void onWritable();
    // Closes the descriptor of an established connection; nothing is reported.
    void release();
    // The connection failed with errno `code` while reading or writing.
    void fail(int code);
    Error describe(QAbstractSocket::SocketError error) const;
    Error describeErrno(int code) const;

    QString m_host;
    quint16 m_port;
    int m_connectTimeoutMs = kDefaultConnectTimeoutMs;
    QTcpSocket m_socket; // only while connecting
    QTimer m_connectTimer;
    int m_fd = -1; // the established connection
    std::unique_ptr<QSocketNotifier> m_readable;
    std::unique_ptr<QSocketNotifier> m_writable; // enabled while bytes wait in m_unsent
    QByteArray m_unsent; // what the kernel did not take yet
    int m_writeError = 0; // errno of a failed write, reported from the loop by m_writable
    bool m_handingOver = false; // m_socket lets go of the connection: its signals mean nothing
    std::unique_ptr<char[]> m_readChunk; // kReadBufferBytes, reused for every read
    QByteArray m_received; // what a read delivers; its storage is reused
    bool m_delivering = false; // inside deliver(m_received)
};

} // namespace db
