#include "streamserver.h"

#include <QCoreApplication>
#include <QLoggingCategory>
#include <QTcpSocket>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::transport)
};
} // namespace

namespace db {

StreamServer::StreamServer(const QString &name, const QLoggingCategory &log, QObject *parent)
    : QObject(parent)
    , m_name(name)
    , m_log(log)
{
    connect(&m_server, &QTcpServer::newConnection, this, &StreamServer::accept);
}

StreamServer::~StreamServer()
{
    close();
}

Result<void> StreamServer::listen(quint16 port, const QHostAddress &address)
{
    if (m_server.isListening())
        return Error(
            Error::Kind::Busy,
            Tr::tr("%1 already listens on port %2").arg(m_name).arg(m_server.serverPort()));
    if (!m_server.listen(address, port))
        return Error(Error::Kind::Io,
                     Tr::tr("%1 cannot listen on %2:%3: %4")
                         .arg(m_name, address.toString())
                         .arg(port)
                         .arg(m_server.errorString()));
    qCInfo(m_log).noquote() << m_name << "listening on" << address.toString()
                            << m_server.serverPort();
    return {};
}

void StreamServer::close()
{
    m_server.close();
    dropClients();
}

int StreamServer::dropClients()
{
    const auto sockets = m_clients.keys();
    m_clients.clear();
    for (QTcpSocket *socket : sockets) {
        socket->disconnect(this);
        socket->abort();
        socket->deleteLater();
    }
    return int(sockets.size());
}

void StreamServer::abortClient(QTcpSocket *client)
{
    if (!m_clients.remove(client))
        return;
    client->disconnect(this);
    client->abort();
    client->deleteLater();
}

bool StreamServer::mayRead(QTcpSocket *client) const
{
    ClientThrottle *throttle = m_clients.value(client);
    return throttle && throttle->mayRead();
}

void StreamServer::write(QTcpSocket *client, const QByteArray &bytes)
{
    ClientThrottle *throttle = m_clients.value(client);
    if (!throttle)
        return;
    client->write(bytes);
    m_peakQueued = qMax(m_peakQueued, throttle->queued());
}

void StreamServer::accept()
{
    while (QTcpSocket *socket = m_server.nextPendingConnection()) {
        socket->setParent(this);
        socket->setSocketOption(QAbstractSocket::LowDelayOption, 1);
        auto *throttle = new ClientThrottle(socket, m_limits);
        m_clients.insert(socket, throttle);
        qCDebug(m_log).noquote() << m_name << "client connected from port" << socket->peerPort();
        connect(socket, &QTcpSocket::readyRead, this, [this, socket] { Q_EMIT readable(socket); });
        connect(throttle, &ClientThrottle::resumed, this,
                [this, socket] { Q_EMIT readable(socket); });
        connect(throttle, &ClientThrottle::stalled, this,
                [this, socket](qint64 queued, int ms) { drop(socket, queued, ms); });
        connect(socket, &QTcpSocket::disconnected, this, [this, socket] {
            if (m_clients.remove(socket))
                Q_EMIT clientGone(socket);
            socket->deleteLater();
        });
        Q_EMIT clientConnected(socket);
    }
}

void StreamServer::drop(QTcpSocket *client, qint64 queued, int pausedMs)
{
    if (!m_clients.remove(client))
        return;
    qCWarning(m_log).noquote() << m_name + u':'
                               << ClientThrottle::drop(client, this, queued, pausedMs);
    Q_EMIT clientGone(client);
}

} // namespace db
