#include "refgoserver.h"

#include "refgo/refgologging.h"

#include <QCoreApplication>
#include <QHash>
#include <QTcpServer>
#include <QTcpSocket>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::refgo)
};
} // namespace

namespace db::refgo {

namespace {
// A request line is a few dozen bytes; a client sending more without CR is not speaking RefGo.
constexpr qsizetype kMaxRequestBytes = 4096;
} // namespace

class Server::Private
{
public:
    Private(Server *server, DeviceHandler *deviceHandler)
        : q(server)
        , handler(deviceHandler)
    { }

    struct Client
    {
        QByteArray buffer; // received bytes not handled yet
        ClientThrottle *throttle = nullptr; // child of the socket
    };

    Server *q;
    DeviceHandler *handler;
    QTcpServer server;
    QHash<QTcpSocket *, Client> clients;
    ClientThrottle::Limits limits;
    qint64 peakQueued = 0;

    void accept();
    void read(QTcpSocket *socket);
    void drop(QTcpSocket *socket, qint64 queued, int pausedMs);
    QByteArray answer(const QString &line);
};

Server::Server(DeviceHandler *handler, QObject *parent)
    : QObject(parent)
    , d(new Private(this, handler))
{
    connect(&d->server, &QTcpServer::newConnection, this, [this] { d->accept(); });
}

Server::~Server()
{
    close();
    delete d;
}

Result<void> Server::listen(quint16 port, const QHostAddress &address)
{
    if (d->server.isListening())
        return Error(Error::Kind::Busy,
                     Tr::tr("RefGo server already listens on port %1").arg(d->server.serverPort()));
    if (!d->server.listen(address, port))
        return Error(Error::Kind::Io,
                     Tr::tr("RefGo server cannot listen on %1:%2: %3")
                         .arg(address.toString())
                         .arg(port)
                         .arg(d->server.errorString()));
    qCInfo(lcRefgo).noquote() << "RefGo server listening on" << address.toString()
                              << d->server.serverPort();
    return {};
}

quint16 Server::port() const
{
    return d->server.serverPort();
}

void Server::close()
{
    d->server.close();
    dropClients();
}

int Server::dropClients()
{
    const auto sockets = d->clients.keys();
    d->clients.clear();
    for (QTcpSocket *socket : sockets) {
        socket->disconnect(this);
        socket->abort();
        socket->deleteLater();
    }
    return int(sockets.size());
}

int Server::clientCount() const
{
    return int(d->clients.size());
}

void Server::setClientLimits(const ClientThrottle::Limits &limits)
{
    d->limits = limits;
}

qint64 Server::peakQueuedBytes() const
{
    return d->peakQueued;
}

void Server::Private::accept()
{
    while (QTcpSocket *socket = server.nextPendingConnection()) {
        socket->setParent(q);
        socket->setSocketOption(QAbstractSocket::LowDelayOption, 1);
        auto *throttle = new ClientThrottle(socket, limits);
        clients.insert(socket, Client { {}, throttle });
        qCDebug(lcRefgo) << "RefGo client connected from" << socket->peerPort();
        QObject::connect(socket, &QTcpSocket::readyRead, q, [this, socket] { read(socket); });
        QObject::connect(throttle, &ClientThrottle::resumed, q, [this, socket] { read(socket); });
        QObject::connect(throttle, &ClientThrottle::stalled, q,
                         [this, socket](qint64 queued, int ms) { drop(socket, queued, ms); });
        QObject::connect(socket, &QTcpSocket::disconnected, q, [this, socket] {
            clients.remove(socket);
            socket->deleteLater();
        });
    }
}

// Handles the client's complete requests while its answers are read; a paused client's
// requests wait in its buffer (at most one read slice plus one line) and in the kernel.
void Server::Private::read(QTcpSocket *socket)
{
    auto it = clients.find(socket);
    if (it == clients.end())
        return;
    Client &client = it.value();
    if (!client.throttle->mayRead())
        return;
    client.buffer += socket->read(ClientThrottle::kReadSliceBytes);
    client.buffer.replace('\n',
                          QByteArray()); // requests end with CR only (spec 3.1); LF is ignored
    qsizetype start = 0;
    qsizetype cr;
    while (client.throttle->mayRead() && (cr = client.buffer.indexOf('\r', start)) >= 0) {
        const QString line = QString::fromLatin1(client.buffer.mid(start, cr - start));
        start = cr + 1;
        if (line.isEmpty())
            continue; // an empty line gets no answer
        const QByteArray bytes = answer(line);
        qCDebug(lcRefgoRaw) << "server ->" << bytes;
        socket->write(bytes);
        peakQueued = qMax(peakQueued, client.throttle->queued());
    }
    client.buffer.remove(0, start);
    if (client.buffer.size() > kMaxRequestBytes && client.buffer.indexOf('\r') < 0) {
        qCWarning(lcRefgo) << "RefGo server: dropping" << client.buffer.size()
                           << "bytes without CR from a client";
        client.buffer.clear();
    }
}

void Server::Private::drop(QTcpSocket *socket, qint64 queued, int pausedMs)
{
    if (!clients.remove(socket))
        return;
    qCWarning(lcRefgo).noquote() << "RefGo server:"
                                 << ClientThrottle::drop(socket, q, queued, pausedMs);
}

// "<request>\r\n" + "<line>\r\n"... + ">" (spec 3.1, 3.8); a refused request gets one
// "ERROR <reason>" line (not authentic, spec 3.7).
QByteArray Server::Private::answer(const QString &line)
{
    const auto request = parseRequest(line);
    const QStringList result = request
        ? handler->handle(request.value())
        : QStringList { QStringLiteral("ERROR ") + request.error().message() };
    QByteArray bytes = line.toLatin1() + "\r\n";
    for (const QString &resultLine : result)
        bytes += resultLine.toLatin1() + "\r\n";
    bytes += '>';
    Q_EMIT q->requestHandled(line, result);
    return bytes;
}

} // namespace db::refgo
