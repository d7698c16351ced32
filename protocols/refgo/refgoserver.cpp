#include "refgoserver.h"

#include "refgologging.h"

#include <QHash>
#include <QTcpServer>
#include <QTcpSocket>

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

    Server *q;
    DeviceHandler *handler;
    QTcpServer server;
    QHash<QTcpSocket *, QByteArray> buffers; // bytes after the last CR, per client

    void accept();
    void read(QTcpSocket *socket);
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
        return Error(
            Error::Kind::Busy,
            QStringLiteral("RefGo server already listens on port %1").arg(d->server.serverPort()));
    if (!d->server.listen(address, port))
        return Error(Error::Kind::Io,
                     QStringLiteral("RefGo server cannot listen on %1:%2: %3")
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
    const auto sockets = d->buffers.keys();
    d->buffers.clear();
    for (QTcpSocket *socket : sockets) {
        socket->disconnect(this);
        socket->abort();
        socket->deleteLater();
    }
}

int Server::clientCount() const
{
    return int(d->buffers.size());
}

void Server::Private::accept()
{
    while (QTcpSocket *socket = server.nextPendingConnection()) {
        socket->setParent(q);
        socket->setSocketOption(QAbstractSocket::LowDelayOption, 1);
        buffers.insert(socket, {});
        qCDebug(lcRefgo) << "RefGo client connected from" << socket->peerPort();
        QObject::connect(socket, &QTcpSocket::readyRead, q, [this, socket] { read(socket); });
        QObject::connect(socket, &QTcpSocket::disconnected, q, [this, socket] {
            buffers.remove(socket);
            socket->deleteLater();
        });
    }
}

void Server::Private::read(QTcpSocket *socket)
{
    auto it = buffers.find(socket);
    if (it == buffers.end())
        return;
    QByteArray &buffer = it.value();
    buffer += socket->readAll();
    buffer.replace('\n', QByteArray()); // requests end with CR only (spec 3.1); LF is ignored
    qsizetype cr;
    while ((cr = buffer.indexOf('\r')) >= 0) {
        const QString line = QString::fromLatin1(buffer.left(cr));
        buffer.remove(0, cr + 1);
        if (line.isEmpty())
            continue; // an empty line gets no answer
        const QByteArray bytes = answer(line);
        qCDebug(lcRefgoRaw) << "server ->" << bytes;
        socket->write(bytes);
    }
    if (buffer.size() > kMaxRequestBytes) {
        qCWarning(lcRefgo) << "RefGo server: dropping" << buffer.size()
                           << "bytes without CR from a client";
        buffer.clear();
    }
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
