#include "slcanserver.h"

#include "transport/slcancodec.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QHash>
#include <QLoggingCategory>
#include <QTcpServer>
#include <QTcpSocket>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::transport)
};
} // namespace

namespace db {

Q_LOGGING_CATEGORY(lcSlcanServer, "drivebench.transport.slcanserver")
Q_LOGGING_CATEGORY(lcSlcanServerRaw, "drivebench.transport.slcanserver.raw", QtWarningMsg)

namespace {
// Timestamps count milliseconds modulo one minute (0000-EA5F, spec 4.2).
constexpr qint64 kTimestampModulo = 60000;
const QByteArray kVersionReply = "V1013";
const QByteArray kSerialReply = "N0001";
const QByteArray kStatusReply = "F00";
} // namespace

struct SlcanServer::Private
{
    struct Client
    {
        slcan::Decoder decoder;
        bool channelOpen = false;
        bool timestamps = false;
        int bitrate = 0; // from its Sn command; 0 = never set
        ClientThrottle *throttle = nullptr; // child of the socket
    };

    SlcanServer *q = nullptr;
    QTcpServer server;
    QHash<QTcpSocket *, Client> clients;
    TransmitAck ack = TransmitAck::Lawicel;
    bool requireOpen = false;
    int busBitrate = 0; // 0: any
    QElapsedTimer clock;
    ClientThrottle::Limits limits;
    qint64 peakQueued = 0;
    qint64 dropped = 0;

    void accept();
    void read(QTcpSocket *socket);
    void drop(QTcpSocket *socket, qint64 queued, int pausedMs);
    QByteArray answer(Client &client, const slcan::Message &m);
    // A client set to another bit rate than the bus's hears nothing and is heard by nobody, as
    // on a real bus (where its frames would be errors); one that never said is taken as right.
    bool receives(const Client &client) const
    {
        return (!requireOpen || client.channelOpen)
            && (busBitrate == 0 || client.bitrate == 0 || client.bitrate == busBitrate);
    }
};

SlcanServer::SlcanServer(QObject *parent)
    : QObject(parent)
    , d(std::make_unique<Private>())
{
    d->q = this;
    d->clock.start();
    connect(&d->server, &QTcpServer::newConnection, this, [this] { d->accept(); });
}

SlcanServer::~SlcanServer()
{
    close();
}

Result<void> SlcanServer::listen(quint16 port, const QHostAddress &address)
{
    if (d->server.isListening())
        return Error(Error::Kind::Busy,
                     Tr::tr("slcan server already listens on port %1").arg(d->server.serverPort()));
    if (!d->server.listen(address, port))
        return Error(Error::Kind::Io,
                     Tr::tr("slcan server cannot listen on %1:%2: %3")
                         .arg(address.toString())
                         .arg(port)
                         .arg(d->server.errorString()));
    qCInfo(lcSlcanServer).noquote()
        << "slcan server listening on" << address.toString() << d->server.serverPort();
    return {};
}

quint16 SlcanServer::port() const
{
    return d->server.serverPort();
}

bool SlcanServer::isListening() const
{
    return d->server.isListening();
}

void SlcanServer::close()
{
    d->server.close();
    dropClients();
}

int SlcanServer::dropClients()
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

int SlcanServer::clientCount() const
{
    return int(d->clients.size());
}

void SlcanServer::setClientLimits(const ClientThrottle::Limits &limits)
{
    d->limits = limits;
}

qint64 SlcanServer::peakQueuedBytes() const
{
    return d->peakQueued;
}

qint64 SlcanServer::droppedFrames() const
{
    return d->dropped;
}

void SlcanServer::setTransmitAck(TransmitAck ack)
{
    d->ack = ack;
}

SlcanServer::TransmitAck SlcanServer::transmitAck() const
{
    return d->ack;
}

void SlcanServer::setRequireOpen(bool require)
{
    d->requireOpen = require;
}

void SlcanServer::setBusBitrate(int bitsPerSecond)
{
    d->busBitrate = qMax(0, bitsPerSecond);
}

int SlcanServer::busBitrate() const
{
    return d->busBitrate;
}

int SlcanServer::send(const QCanBusFrame &frame)
{
    const QByteArray plain = slcan::encodeFrame(frame);
    if (plain.isEmpty())
        return 0;
    const auto stamp = quint16(d->clock.elapsed() % kTimestampModulo);
    int count = 0;
    for (auto it = d->clients.begin(); it != d->clients.end(); ++it) {
        if (!d->receives(it.value()))
            continue;
        if (!it->throttle->mayRead()) {
            ++d->dropped; // a client that does not read must not grow the server
            continue;
        }
        const QByteArray line = it->timestamps ? slcan::encodeFrame(frame, stamp) : plain;
        qCDebug(lcSlcanServerRaw) << "server ->" << line;
        it.key()->write(line);
        d->peakQueued = qMax(d->peakQueued, it->throttle->queued());
        ++count;
    }
    return count;
}

void SlcanServer::sendRaw(const QByteArray &bytes)
{
    for (auto it = d->clients.cbegin(); it != d->clients.cend(); ++it)
        it.key()->write(bytes);
}

void SlcanServer::Private::accept()
{
    while (QTcpSocket *socket = server.nextPendingConnection()) {
        socket->setParent(q);
        socket->setSocketOption(QAbstractSocket::LowDelayOption, 1);
        Client client;
        client.throttle = new ClientThrottle(socket, limits);
        clients.insert(socket, client);
        qCDebug(lcSlcanServer) << "slcan client connected from port" << socket->peerPort();
        QObject::connect(socket, &QTcpSocket::readyRead, q, [this, socket] { read(socket); });
        QObject::connect(client.throttle, &ClientThrottle::resumed, q,
                         [this, socket] { read(socket); });
        QObject::connect(client.throttle, &ClientThrottle::stalled, q,
                         [this, socket](qint64 queued, int ms) { drop(socket, queued, ms); });
        QObject::connect(socket, &QTcpSocket::disconnected, q, [this, socket] {
            if (clients.remove(socket))
                Q_EMIT q->clientDisconnected();
            socket->deleteLater();
        });
        Q_EMIT q->clientConnected();
    }
}

void SlcanServer::Private::read(QTcpSocket *socket)
{
    auto it = clients.find(socket);
    if (it == clients.end() || !it->throttle->mayRead())
        return; // a paused client's requests wait in its socket and the kernel
    const QByteArray bytes = socket->read(ClientThrottle::kReadSliceBytes);
    qCDebug(lcSlcanServerRaw) << "server <-" << bytes;
    // Answers first, frames to the device afterwards: a device that answers synchronously must
    // not overtake the transmit ack of the request it answers.
    QByteArray reply;
    QList<QCanBusFrame> frames;
    for (const slcan::Message &m : it->decoder.feed(bytes)) {
        if (m.kind == slcan::Message::Kind::Frame && receives(it.value()))
            frames.append(m.frame);
        reply += answer(it.value(), m);
    }
    if (!reply.isEmpty()) {
        socket->write(reply);
        peakQueued = qMax(peakQueued, it->throttle->queued());
    }
    for (const QCanBusFrame &frame : std::as_const(frames)) {
        Q_EMIT q->frameReceived(frame);
        if (!clients.contains(socket))
            break; // the device closed the server from the slot
    }
}

void SlcanServer::Private::drop(QTcpSocket *socket, qint64 queued, int pausedMs)
{
    if (!clients.remove(socket))
        return;
    qCWarning(lcSlcanServer).noquote()
        << "slcan server:" << ClientThrottle::drop(socket, q, queued, pausedMs);
    Q_EMIT q->clientDisconnected();
}

// Spec 4.2, simulator recommendations.
QByteArray SlcanServer::Private::answer(Client &client, const slcan::Message &m)
{
    const QByteArray ok(1, slcan::kCr);
    const QByteArray bell(1, slcan::kBell);
    switch (m.kind) {
    case slcan::Message::Kind::Frame:
        if (!receives(client))
            break;
        switch (ack) {
        case TransmitAck::Lawicel:
            return QByteArray(1, m.frame.hasExtendedFrameFormat() ? 'Z' : 'z') + slcan::kCr;
        case TransmitAck::Cr:
            return ok;
        case TransmitAck::None:
            return {};
        }
        return {};
    case slcan::Message::Kind::Command:
        if (!m.argument.isEmpty() && (m.command == 'V' || m.command == 'N' || m.command == 'F'))
            break; // replies, not requests
        switch (m.command) {
        case 'O':
            client.channelOpen = true;
            return ok;
        case 'C':
            client.channelOpen = false;
            return ok;
        case 'Z':
            client.timestamps = m.argument == "1";
            return ok;
        case 'V':
            return kVersionReply + ok;
        case 'N':
            return kSerialReply + ok;
        case 'F':
            return kStatusReply + ok;
        case 'S':
            client.bitrate = slcan::bitrateForCode(m.argument.toInt()).value_or(0);
            return ok;
        default: // L, s: accepted, nothing to do on TCP
            return ok;
        }
    case slcan::Message::Kind::Ack:
        return {}; // an empty line: nothing to answer
    case slcan::Message::Kind::Bell:
    case slcan::Message::Kind::TransmitAck:
    case slcan::Message::Kind::Unknown:
        break;
    }
    qCDebug(lcSlcanServer) << "slcan server refuses" << m.line;
    Q_EMIT q->refused(m.line);
    return bell;
}

} // namespace db
