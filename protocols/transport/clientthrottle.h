#pragma once

#include <QObject>
#include <QTimer>

class QTcpSocket;

namespace db {

// Server side of one client connection of a request/answer protocol: keeps a client that sends
// requests without reading the answers from growing the server's memory or starving the other
// clients.
//
// Contract with the server:
// - The socket's read buffer is capped at kReadSliceBytes, so a flood waits in the kernel (TCP
//   flow control) and each readyRead() brings at most one slice: other clients get their turn
//   between slices.
// - The server handles a request only while mayRead() is true and calls queued() after writing
//   answers. Once the socket's output queue (bytesToWrite) exceeds maxQueuedBytes the client is
//   paused; resumed() fires when the queue has drained to half of that, and the server then
//   handles the requests it held back. A client paused for stallTimeoutMs gets stalled(): the
//   server drops it.
class ClientThrottle : public QObject
{
    Q_OBJECT
public:
    struct Limits
    {
        qint64 maxQueuedBytes = 64 * 1024;
        int stallTimeoutMs = 5000;
    };
    static constexpr qint64 kReadSliceBytes = 4096;

    // Becomes a child of the socket.
    ClientThrottle(QTcpSocket *socket, const Limits &limits);

    // Disconnects a stalled client at once (its socket is deleted later) and says why, for the
    // server's warning: "dropping client 127.0.0.1:40000: it has not read ...". The socket's
    // signals to receiver are disconnected first.
    static QString drop(QTcpSocket *socket, QObject *receiver, qint64 queuedBytes, int pausedMs);

    bool mayRead() const { return !m_paused; }
    // After the server queued output: pauses the client when its queue is over the limit.
    // Returns the bytes now queued.
    qint64 queued();

Q_SIGNALS:
    void resumed();
    void stalled(qint64 queuedBytes, int pausedMs);

private:
    void onBytesWritten();

    QTcpSocket *m_socket;
    Limits m_limits;
    bool m_paused = false;
    QTimer m_stall;
};

} // namespace db
