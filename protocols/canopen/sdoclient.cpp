#include "sdoclient.h"

#include "canopenlogging.h"
#include "sdoabort.h"
#include "sdoblocktransfer.h"
#include "sdocodec.h"
#include "transport/canbus.h"
#include "transport/responsetimer.h"

#include <QCanBusFrame>
#include <QTimer>

#include <QCoreApplication>
#include <deque>
#include <optional>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::canopen)
};
} // namespace

namespace db::canopen {

struct SdoClient::Job
{
    std::unique_ptr<SdoTransfer> transfer;
    Completion done;
    int timeoutMs = kDefaultTimeoutMs;
    bool upload = false;
};

struct SdoClient::Channel
{
    NodeId node = 0;
    std::deque<Job> queue;
    std::optional<Job> active;
    // Response timeout of the active transfer (re-armed for every frame without registering a
    // dispatcher timer each time).
    std::unique_ptr<ResponseTimer> timer;
    QTimer quiet; // kLateGraceMs after a timeout: late answers are dropped, nothing is sent
    // Timeouts since the node last answered: only the first of a silent episode is logged at
    // info level, so that a node that stops answering does not flood the user's log.
    int timeoutsInRow = 0;
};

SdoClient::SdoClient(CanBus *bus, QObject *parent)
    : QObject(parent)
    , m_bus(bus)
{
    connect(m_bus, &CanBus::frameReceived, this, &SdoClient::onFrame);
    connect(m_bus, &CanBus::closed, this, [this](const Error &error) {
        cancelAll(error.isError() ? error
                                  : Error(Error::Kind::Disconnected,
                                          Tr::tr("CAN bus %1 closed").arg(m_bus->name())));
    });
}

SdoClient::~SdoClient()
{
    cancelAll(Error(Error::Kind::Cancelled, Tr::tr("SDO client deleted")));
}

void SdoClient::setBlockSize(int segments)
{
    m_blockSize = qBound(1, segments, sdo::kMaxBlockSize);
}

Reply *SdoClient::upload(NodeId node, ObjectAddress address, Mode mode, int expectedSize)
{
    auto *reply = new Reply(address);
    upload(node, address, Completion(reply), mode, expectedSize);
    return reply;
}

Reply *SdoClient::download(NodeId node, ObjectAddress address, const QByteArray &data, Mode mode)
{
    auto *reply = new Reply(address);
    download(node, address, data, Completion(reply), mode);
    return reply;
}

void SdoClient::upload(NodeId node, ObjectAddress address, Completion done, Mode mode,
                       int expectedSize)
{
    const bool block = mode == Mode::Block
        || (mode == Mode::Auto && m_blockEnabled
            && (expectedSize < 0 || expectedSize > m_blockThreshold));
    std::unique_ptr<SdoTransfer> transfer;
    if (block)
        transfer = std::make_unique<SdoBlockUpload>(address, m_blockSize);
    else
        transfer = std::make_unique<SdoUpload>(address);
    enqueue(node, std::move(transfer), std::move(done), true);
}

void SdoClient::download(NodeId node, ObjectAddress address, const QByteArray &data,
                         Completion done, Mode mode)
{
    if (mode == Mode::Expedited && (data.isEmpty() || data.size() > sdocodec::kExpeditedMax)) {
        done.completeLater(
            Error(Error::Kind::InvalidArgument,
                  Tr::tr("expedited SDO download carries 1 to 4 bytes, not %1").arg(data.size())));
        return;
    }
    const bool block = mode == Mode::Block
        || (mode == Mode::Auto && m_blockEnabled && data.size() > m_blockThreshold);
    std::unique_ptr<SdoTransfer> transfer;
    if (block)
        transfer = std::make_unique<SdoBlockDownload>(address, data);
    else
        transfer = std::make_unique<SdoDownload>(address, data, mode == Mode::Segmented);
    enqueue(node, std::move(transfer), std::move(done), false);
}

void SdoClient::enqueue(NodeId node, std::unique_ptr<SdoTransfer> transfer, Completion done,
                        bool upload)
{
    if (node < kMinNodeId || node > kMaxNodeId) {
        done.completeLater(
            Error(Error::Kind::InvalidArgument, Tr::tr("node id %1 is outside 1..127").arg(node)));
        return;
    }
    if (!m_bus->isOpen()) {
        done.completeLater(
            Error(Error::Kind::Disconnected, Tr::tr("CAN bus %1 is not open").arg(m_bus->name())));
        return;
    }
    Channel &ch = channel(node);
    ch.queue.push_back(Job { std::move(transfer), std::move(done), m_timeoutMs, upload });
    if (!ch.active && !ch.quiet.isActive()) {
        const bool outer = !std::exchange(m_submitting, true);
        startNext(ch);
        if (outer)
            m_submitting = false;
    }
}

SdoClient::Channel &SdoClient::channel(NodeId node)
{
    auto &slot = m_channels[node];
    if (!slot) {
        slot = std::make_unique<Channel>();
        Channel *ch = slot.get();
        ch->node = node;
        ch->timer = std::make_unique<ResponseTimer>([this, ch] { onTimeout(*ch); });
        ch->quiet.setSingleShot(true);
        ch->quiet.setInterval(kLateGraceMs);
        connect(&ch->quiet, &QTimer::timeout, this, [this, ch] { startNext(*ch); });
    }
    return *slot;
}

int SdoClient::pending(NodeId node) const
{
    const auto it = m_channels.find(node);
    if (it == m_channels.end())
        return 0;
    return int(it->second->queue.size()) + (it->second->active ? 1 : 0);
}

void SdoClient::startNext(Channel &ch)
{
    while (!ch.active && !ch.queue.empty()) {
        Job job = std::move(ch.queue.front());
        ch.queue.pop_front();
        if (!job.done.wanted())
            continue; // the requester gave up before it started
        ch.active = std::move(job);
        apply(ch, ch.active->transfer->start());
    }
}

void SdoClient::onFrame(const QCanBusFrame &frame)
{
    if (frame.frameType() != QCanBusFrame::DataFrame || frame.hasExtendedFrameFormat())
        return;
    const quint32 id = frame.frameId();
    if (id <= cob::SdoTx || id > cob::SdoTx + kMaxNodeId)
        return;
    const NodeId node = NodeId(id - cob::SdoTx);
    const QByteArray payload = frame.payload();
    qCDebug(lcSdoRaw).noquote() << "rx" << node << sdocodec::hex(payload);
    const auto it = m_channels.find(node);
    if (it == m_channels.end() || !it->second->active) {
        drop(node, payload, QStringLiteral("no request pending"));
        return;
    }
    Channel &ch = *it->second;
    const SdoStep step = ch.active->transfer->onFrame(payload);
    if (step.outcome == SdoStep::Outcome::Ignore) {
        drop(node, payload,
             QStringLiteral("not an answer to %1").arg(ch.active->transfer->describe()));
        return;
    }
    if (ch.timeoutsInRow > 1)
        qCInfo(lcSdo).noquote() << "node" << node << "answers again after" << ch.timeoutsInRow
                                << "timeouts";
    ch.timeoutsInRow = 0;
    apply(ch, step);
}

void SdoClient::apply(Channel &ch, const SdoStep &step)
{
    if (!sendAll(ch, step.frames))
        return;
    switch (step.outcome) {
    case SdoStep::Outcome::Continue:
        ch.timer->start(ch.active->timeoutMs);
        return;
    case SdoStep::Outcome::Done:
        finishActive(ch, {}, step.data);
        break;
    case SdoStep::Outcome::Failed:
        if (step.error.deviceCode() != 0 && step.error.kind() == Error::Kind::DeviceError)
            Q_EMIT logLine(QStringLiteral("node %1: SDO abort 0x%2 in %3: %4")
                               .arg(ch.node)
                               .arg(step.error.deviceCode(), 8, 16, QLatin1Char('0'))
                               .arg(ch.active->transfer->describe(), step.error.message()));
        finishActive(ch, step.error);
        break;
    case SdoStep::Outcome::Ignore:
        return;
    }
    startNext(ch);
}

bool SdoClient::sendAll(Channel &ch, const QByteArrayList &frames)
{
    const quint32 id = cob::sdoRequest(ch.node);
    for (const QByteArray &payload : frames) {
        qCDebug(lcSdoRaw).noquote() << "tx" << ch.node << sdocodec::hex(payload);
        if (!m_bus->send(QCanBusFrame(id, payload))) {
            finishActive(ch,
                         Error(Error::Kind::Disconnected,
                               Tr::tr("CAN bus %1 is not open").arg(m_bus->name())));
            return false;
        }
    }
    return true;
}

void SdoClient::finishActive(Channel &ch, const Error &error, const QByteArray &data, bool later)
{
    ch.timer->stop();
    if (!ch.active)
        return;
    Job job = std::move(*ch.active);
    ch.active.reset();
    later = later || m_submitting;
    if (error.isError())
        job.done.complete(error, later);
    else
        job.done.complete(job.upload ? QVariant(data) : QVariant(), later);
}

void SdoClient::onTimeout(Channel &ch)
{
    if (!ch.active)
        return;
    const SdoTransfer &t = *ch.active->transfer;
    const QString what = Tr::tr("node %1 did not answer %2 within %3 ms")
                             .arg(ch.node)
                             .arg(t.describe())
                             .arg(ch.active->timeoutMs);
    if (ch.timeoutsInRow++ == 0)
        qCInfo(lcSdo).noquote() << what;
    else
        qCDebug(lcSdo).noquote() << what;
    Q_EMIT logLine(what);
    // Tell the server to give up too (CiA 301 7.2.4.3.17); the bus may already be gone.
    m_bus->send(
        QCanBusFrame(cob::sdoRequest(ch.node), sdocodec::abort(t.address(), abort::Timeout)));
    // Quiet first: a request made by the failed request's handler waits for the grace time.
    ch.quiet.start();
    finishActive(ch, Error(Error::Kind::Timeout, what));
}

void SdoClient::drop(NodeId node, const QByteArray &payload, const QString &why)
{
    ++m_dropped;
    qCInfo(lcSdo).noquote() << "dropped SDO frame from node" << node << sdocodec::hex(payload)
                            << "-" << why;
}

void SdoClient::cancelAll(const Error &error)
{
    for (auto &[node, ch] : m_channels)
        cancelChannel(*ch, error);
}

void SdoClient::cancelNode(NodeId node, const Error &error)
{
    if (const auto it = m_channels.find(node); it != m_channels.end())
        cancelChannel(*it->second, error);
}

void SdoClient::cancelChannel(Channel &ch, const Error &error)
{
    ch.quiet.stop();
    auto queue = std::exchange(ch.queue, {});
    finishActive(ch, error, {}, true);
    for (Job &job : queue)
        job.done.completeLater(error);
}

} // namespace db::canopen
