#include "slcanserver.h"

#include "streamserver.h"
#include "transport/slcancodec.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QHash>
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
    };

    Private()
        : tcp(Tr::tr("slcan server"), lcSlcanServer())
    { }

    SlcanServer *q = nullptr;
    StreamServer tcp;
    QHash<QTcpSocket *, Client> clients;
    TransmitAck ack = TransmitAck::Lawicel;
    bool requireOpen = false;
    QElapsedTimer clock;
    qint64 dropped = 0;

    void read(QTcpSocket *socket);
    QByteArray answer(Client &client, const slcan::Message &m);
    bool receives(const Client &client) const { return !requireOpen || client.channelOpen; }
};

SlcanServer::SlcanServer(QObject *parent)
    : QObject(parent)
    , d(std::make_unique<Private>())
{
    d->q = this;
    d->tcp.setParent(this); // the client sockets are found among the server's children
    d->clock.start();
    connect(&d->tcp, &StreamServer::clientConnected, this, [this](QTcpSocket *socket) {
        d->clients.insert(socket, {});
        Q_EMIT clientConnected();
    });
    connect(&d->tcp, &StreamServer::readable, this, [this](QTcpSocket *s) { d->read(s); });
    connect(&d->tcp, &StreamServer::clientGone, this, [this](QTcpSocket *socket) {
        if (d->clients.remove(socket))
            Q_EMIT clientDisconnected();
    });
}

SlcanServer::~SlcanServer()
{
    close();
}

Result<void> SlcanServer::listen(quint16 port, const QHostAddress &address)
{
    return d->tcp.listen(port, address);
}

quint16 SlcanServer::port() const
{
    return d->tcp.port();
}

bool SlcanServer::isListening() const
{
    return d->tcp.isListening();
}

void SlcanServer::close()
{
    d->clients.clear();
    d->tcp.close();
}

int SlcanServer::dropClients()
{
    d->clients.clear();
    return d->tcp.dropClients();
}

int SlcanServer::clientCount() const
{
    return d->tcp.clientCount();
}

void SlcanServer::setClientLimits(const ClientThrottle::Limits &limits)
{
    d->tcp.setClientLimits(limits);
}

qint64 SlcanServer::peakQueuedBytes() const
{
    return d->tcp.peakQueuedBytes();
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
        if (!d->tcp.mayRead(it.key())) {
            ++d->dropped; // a client that does not read must not grow the server
            continue;
        }
        const QByteArray line = it->timestamps ? slcan::encodeFrame(frame, stamp) : plain;
        qCDebug(lcSlcanServerRaw) << "server ->" << line;
        d->tcp.write(it.key(), line);
        ++count;
    }
    return count;
}

void SlcanServer::sendRaw(const QByteArray &bytes)
{
    for (auto it = d->clients.cbegin(); it != d->clients.cend(); ++it)
        it.key()->write(bytes);
}

void SlcanServer::Private::read(QTcpSocket *socket)
{
    auto it = clients.find(socket);
    if (it == clients.end() || !tcp.mayRead(socket))
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
    if (!reply.isEmpty())
        tcp.write(socket, reply);
    for (const QCanBusFrame &frame : std::as_const(frames)) {
        Q_EMIT q->frameReceived(frame);
        if (!clients.contains(socket))
            break; // the device closed the server from the slot
    }
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
        default: // L, S, s: accepted, nothing to do on TCP
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
