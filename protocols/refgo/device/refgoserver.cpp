#include "refgoserver.h"

#include "refgo/refgologging.h"
#include "transport/device/streamserver.h"

#include <QCoreApplication>
#include <QHash>
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
        , tcp(Tr::tr("RefGo server"), lcRefgo(), server)
    { }

    Server *q;
    DeviceHandler *handler;
    StreamServer tcp;
    QHash<QTcpSocket *, QByteArray> buffers; // received bytes not handled yet, per client
    bool silent = false;

    void read(QTcpSocket *socket);
    QByteArray answer(const QString &line);
};

Server::Server(DeviceHandler *handler, QObject *parent)
    : QObject(parent)
    , d(new Private(this, handler))
{
    connect(&d->tcp, &StreamServer::readable, this, [this](QTcpSocket *s) { d->read(s); });
    connect(&d->tcp, &StreamServer::clientGone, this,
            [this](QTcpSocket *s) { d->buffers.remove(s); });
}

Server::~Server()
{
    close();
    delete d;
}

Result<void> Server::listen(quint16 port, const QHostAddress &address)
{
    return d->tcp.listen(port, address);
}

quint16 Server::port() const
{
    return d->tcp.port();
}

void Server::close()
{
    d->buffers.clear();
    d->tcp.close();
}

int Server::dropClients()
{
    d->buffers.clear();
    return d->tcp.dropClients();
}

void Server::setSilent(bool on)
{
    d->silent = on;
    d->buffers.clear();
}

int Server::clientCount() const
{
    return d->tcp.clientCount();
}

void Server::setClientLimits(const ClientThrottle::Limits &limits)
{
    d->tcp.setClientLimits(limits);
}

qint64 Server::peakQueuedBytes() const
{
    return d->tcp.peakQueuedBytes();
}

// Handles the client's complete requests while its answers are read; a paused client's
// requests wait in its buffer (at most one read slice plus one line) and in the kernel.
void Server::Private::read(QTcpSocket *socket)
{
    if (!tcp.mayRead(socket))
        return;
    QByteArray buffer = buffers.take(socket) + socket->read(ClientThrottle::kReadSliceBytes);
    if (silent)
        return;
    buffer.replace('\n', QByteArray()); // requests end with CR only (spec 3.1); LF is ignored
    qsizetype start = 0;
    qsizetype cr;
    while (tcp.mayRead(socket) && (cr = buffer.indexOf('\r', start)) >= 0) {
        const QString line = QString::fromLatin1(buffer.mid(start, cr - start));
        start = cr + 1;
        if (line.isEmpty())
            continue; // an empty line gets no answer
        const QByteArray bytes = answer(line);
        qCDebug(lcRefgoRaw) << "server ->" << bytes;
        tcp.write(socket, bytes);
    }
    if (!tcp.clients().contains(socket))
        return; // gone while answering (a slot of requestHandled closed the server)
    buffer.remove(0, start);
    if (buffer.size() > kMaxRequestBytes && buffer.indexOf('\r') < 0) {
        qCWarning(lcRefgo) << "RefGo server: dropping" << buffer.size()
                           << "bytes without CR from a client";
        buffer.clear();
    }
    buffers.insert(socket, buffer);
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
