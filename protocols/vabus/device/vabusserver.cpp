#include "vabusserver.h"

#include "vabus/vabuslogging.h"

#include <QPointer>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTimer>

namespace db::vabus {

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
    QPointer<QTcpSocket> client;
    QByteArray buffer;
    FailureMode failure;
    int answered = 0;

    void accept();
    void read();
    void respond(const QByteArray &frame);
    void send(const QByteArray &bytes);
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
            QStringLiteral("VABus server already listens on port %1").arg(d->server.serverPort()));
    if (!d->server.listen(address, port))
        return Error(Error::Kind::Io,
                     QStringLiteral("VABus server cannot listen on %1:%2: %3")
                         .arg(address.toString())
                         .arg(port)
                         .arg(d->server.errorString()));
    qCInfo(lcVabus).noquote() << "VABus server listening on" << address.toString()
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
    if (d->client) {
        d->client->disconnect(this);
        d->client->abort();
        d->client->deleteLater();
    }
    d->buffer.clear();
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

void Server::Private::accept()
{
    while (QTcpSocket *socket = server.nextPendingConnection()) {
        if (client) {
            const QString line =
                QStringLiteral("refusing the connection from %1:%2: the PLC port takes one "
                               "connection and %3:%4 holds it")
                    .arg(socket->peerAddress().toString())
                    .arg(socket->peerPort())
                    .arg(client->peerAddress().toString())
                    .arg(client->peerPort());
            qCWarning(lcVabus).noquote() << line;
            Q_EMIT q->logLine(line);
            socket->abort();
            socket->deleteLater();
            continue;
        }
        socket->setParent(q);
        socket->setSocketOption(QAbstractSocket::LowDelayOption, 1);
        client = socket;
        buffer.clear();
        answered = 0;
        qCDebug(lcVabus) << "VABus client connected from" << socket->peerPort();
        QObject::connect(socket, &QTcpSocket::readyRead, q, [this] { read(); });
        QObject::connect(socket, &QTcpSocket::disconnected, q, [this, socket] {
            if (client == socket)
                client.clear();
            socket->deleteLater();
        });
    }
}

void Server::Private::read()
{
    if (!client)
        return;
    buffer += client->readAll();
    while (buffer.size() >= 2) {
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
        return;
    switch (failure.failure) {
    case Failure::None:
        client->write(bytes);
        break;
    case Failure::Silent:
        return;
    case Failure::Garbage:
        client->write(QByteArrayLiteral("\xff\xfe garbage, not VABus\r\n"));
        break;
    case Failure::Slow: {
        QPointer<QTcpSocket> socket = client;
        QTimer::singleShot(failure.slowMs, q, [socket, bytes] {
            if (socket)
                socket->write(bytes);
        });
        break;
    }
    case Failure::DropAfter:
        if (answered >= failure.dropAfter) {
            client->abort();
            return;
        }
        client->write(bytes);
        break;
    case Failure::SplitBytes:
        for (const char c : bytes) {
            client->write(&c, 1);
            client->flush(); // one segment per byte (LowDelayOption: no Nagle)
        }
        break;
    }
    ++answered;
}

} // namespace db::vabus
