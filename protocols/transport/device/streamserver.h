#pragma once

// The TCP side that the simulators' RefGo, SLCAN and VABus servers share: listens on loopback,
// accepts clients with TCP_NODELAY, throttles each one (ClientThrottle: a client that does not read
// its answers is paused, and dropped once it stays paused), and tells the protocol when a client
// may be read and when it is gone. The protocol keeps its own per-client state keyed by the
// socket, reads at most ClientThrottle::kReadSliceBytes per readable() and answers with write().

#include "core/result.h"
#include "transport/clientthrottle.h"

#include <QHash>
#include <QHostAddress>
#include <QList>
#include <QObject>
#include <QTcpServer>

class QLoggingCategory;
class QTcpSocket;

namespace db {

class StreamServer : public QObject
{
    Q_OBJECT
public:
    // name: the server in messages ("RefGo server"); log: the protocol's logging category.
    // The client sockets are children of the StreamServer.
    StreamServer(const QString &name, const QLoggingCategory &log, QObject *parent = nullptr);
    ~StreamServer() override;

    // Listens on address:port (port 0 = chosen by the OS). Loopback only by default.
    Result<void> listen(quint16 port = 0, const QHostAddress &address = QHostAddress::LocalHost);
    quint16 port() const { return m_server.serverPort(); }
    bool isListening() const { return m_server.isListening(); }
    // Stops listening and drops every client.
    void close();
    // Aborts every client connection (RST, no goodbye) and keeps listening: a cut cable as the
    // clients see it. Returns how many were dropped. clientGone() is not emitted for them.
    int dropClients();
    // Aborts one client (RST) and forgets it, e.g. one the protocol refuses; clientGone() is
    // not emitted for it.
    void abortClient(QTcpSocket *client);
    int clientCount() const { return int(m_clients.size()); }
    QList<QTcpSocket *> clients() const { return m_clients.keys(); }
    // Applies to clients that connect afterwards.
    void setClientLimits(const ClientThrottle::Limits &limits) { m_limits = limits; }
    // The longest output queue any client had so far, in bytes.
    qint64 peakQueuedBytes() const { return m_peakQueued; }

    // False while the client is paused (its output queue is full) or after it has gone.
    bool mayRead(QTcpSocket *client) const;
    // Writes to a client and notes its output queue (which may pause it).
    void write(QTcpSocket *client, const QByteArray &bytes);

Q_SIGNALS:
    void clientConnected(QTcpSocket *client);
    // The client sent bytes, or was resumed with bytes still unread.
    void readable(QTcpSocket *client);
    // The client disconnected or was dropped for not reading: forget its state.
    void clientGone(QTcpSocket *client);

private:
    void accept();
    void drop(QTcpSocket *client, qint64 queued, int pausedMs);

    QString m_name;
    const QLoggingCategory &m_log;
    QTcpServer m_server;
    QHash<QTcpSocket *, ClientThrottle *> m_clients; // throttles are children of their sockets
    ClientThrottle::Limits m_limits;
    qint64 m_peakQueued = 0;
};

} // namespace db
