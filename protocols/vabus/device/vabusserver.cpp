#include "vabusserver.h"

#include "transport/device/streamserver.h"
#include "vabus/vabuslogging.h"

#include <QCoreApplication>
#include <QPointer>
#include <QTcpSocket>
#include <QTimer>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::vabus)
};
} // namespace

namespace db::vabus {

class Server::Private
{
public:
    Private(Server *server, DeviceHandler *deviceHandler)
        : q(server)
        , handler(deviceHandler)
        , tcp(Tr::tr("VABus server"), lcVabus(), server)
    { }

    Server *q;
    DeviceHandler *handler;
    StreamServer tcp;
    QPointer<QTcpSocket> client; // the one PLC connection
    QByteArray buffer; // its bytes not handled yet
    FailureMode failure;
    int answered = 0;

    void accept(QTcpSocket *socket);
    void forget();
    void read(QTcpSocket *socket);
    void respond(const QByteArray &frame);
    void send(const QByteArray &bytes);
};

Server::Server(DeviceHandler *handler, QObject *parent)
    : QObject(parent)
    , d(new Private(this, handler))
{
    connect(&d->tcp, &StreamServer::clientConnected, this, [this](QTcpSocket *s) { d->accept(s); });
    connect(&d->tcp, &StreamServer::readable, this, [this](QTcpSocket *s) { d->read(s); });
    connect(&d->tcp, &StreamServer::clientGone, this, [this](QTcpSocket *s) {
        if (s == d->client)
            d->forget();
    });
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
    d->tcp.close();
    d->forget();
}

bool Server::hasClient() const
{
    return !d->client.isNull();
}

void Server::setFailure(const FailureMode &mode)
{
    d->failure = mode;
    d->answered = 0;
}

std::optional<Server::Failure> Server::failureFromName(const QString &name)
{
    static const QList<std::pair<QString, Failure>> names = {
        { QStringLiteral("none"), Failure::None },
        { QStringLiteral("silent"), Failure::Silent },
        { QStringLiteral("garbage"), Failure::Garbage },
        { QStringLiteral("slow"), Failure::Slow },
        { QStringLiteral("drop-after"), Failure::DropAfter },
        { QStringLiteral("split"), Failure::SplitBytes },
    };
    for (const auto &[text, failure] : names) {
        if (text == name)
            return failure;
    }
    return std::nullopt;
}

void Server::Private::accept(QTcpSocket *socket)
{
    if (client) {
        const QString line = Tr::tr("refusing the connection from %1:%2: the PLC port takes one "
                                    "connection and %3:%4 holds it")
                                 .arg(socket->peerAddress().toString())
                                 .arg(socket->peerPort())
                                 .arg(client->peerAddress().toString())
                                 .arg(client->peerPort());
        qCWarning(lcVabus).noquote() << line;
        Q_EMIT q->logLine(line);
        tcp.abortClient(socket);
        return;
    }
    client = socket;
    buffer.clear();
    answered = 0;
}

void Server::Private::forget()
{
    client.clear();
    buffer.clear();
}

// Handles the complete telegrams of the PLC connection while it reads its answers; a paused
// client's telegrams wait in the buffer (at most one read slice) and in the kernel.
void Server::Private::read(QTcpSocket *socket)
{
    if (socket != client || !tcp.mayRead(socket))
        return;
    buffer += socket->read(ClientThrottle::kReadSliceBytes);
    while (client == socket && tcp.mayRead(socket) && buffer.size() >= 2) {
        const int nob = quint8(buffer.at(1));
        if (nob < kAddressBytes || nob > kMaxNob) {
            // Structurally broken: no answer (7.2); start afresh with the next bytes.
            qCDebug(lcVabus) << "VABus server: dropping" << buffer.size() << "bytes, NoB" << nob;
            buffer.clear();
            Q_EMIT q->exchanged();
            return;
        }
        if (buffer.size() < nob + 2)
            return;
        const QByteArray frame = buffer.left(nob + 2);
        buffer.remove(0, nob + 2);
        Q_EMIT q->exchanged();
        respond(frame);
    }
}

void Server::Private::respond(const QByteArray &frame)
{
    qCDebug(lcVabusRaw) << "server <-" << frame.toHex(' ');
    const quint8 header = quint8(frame.at(0));
    Telegram request;
    request.write = header & kRwBit;
    request.sys = quint8(frame.at(2));
    request.dataSet = quint8(frame.at(3));
    request.parameter = quint16(quint8(frame.at(4)) | (quint8(frame.at(5)) << 8));
    request.data = frame.mid(kMinTelegramBytes);
    std::optional<Telegram> answer;
    // A select without data is an empty string (NoB = 4 + length): the handler judges it, as
    // it judges any data length.
    if ((header & ~(kRwBit | kErrorBit)) || (header & kErrorBit)
        || (!request.write && !request.data.isEmpty()))
        answer = Telegram::errorAnswer(request, SyntaxError);
    else
        answer = handler->handle(request);
    Q_EMIT q->requestHandled(request, answer);
    if (!answer)
        return;
    const auto bytes = encode(*answer);
    if (!bytes) {
        qCWarning(lcVabus).noquote()
            << "VABus server: cannot encode answer:" << bytes.error().message();
        return;
    }
    send(bytes.value());
}

void Server::Private::send(const QByteArray &bytes)
{
    if (!client)
        return; // a slot of requestHandled closed the connection
    switch (failure.failure) {
    case Failure::None:
        tcp.write(client, bytes);
        break;
    case Failure::Silent:
        return;
    case Failure::Garbage:
        tcp.write(client, QByteArrayLiteral("\xff\xfe garbage, not VABus\r\n"));
        break;
    case Failure::Slow: {
        QPointer<QTcpSocket> socket = client;
        QTimer::singleShot(failure.slowMs, q, [this, socket, bytes] {
            if (socket)
                tcp.write(socket, bytes);
        });
        break;
    }
    case Failure::DropAfter:
        if (answered >= failure.dropAfter) {
            client->abort();
            return;
        }
        tcp.write(client, bytes);
        break;
    case Failure::SplitBytes:
        for (const char c : bytes) {
            tcp.write(client, QByteArray(1, c));
            client->flush(); // one segment per byte (LowDelayOption: no Nagle)
        }
        break;
    }
    ++answered;
}

} // namespace db::vabus
