#include "errorcontrolslave.h"

namespace db::canopen {

namespace {
constexpr quint16 kGuardTime = 0x100C;
constexpr quint16 kLifeTimeFactor = 0x100D;
constexpr quint16 kConsumerHeartbeat = 0x1016;
constexpr quint8 kToggleBit = 0x80;
constexpr int kMaxConsumerEntries = 127;
} // namespace

ErrorControlSlave::ErrorControlSlave(ObjectAccess *access, QObject *parent)
    : QObject(parent)
    , m_access(access)
{
    m_lifeTimer.setSingleShot(true);
    m_lifeTimer.setTimerType(Qt::PreciseTimer);
    connect(&m_lifeTimer, &QTimer::timeout, this, [this] {
        Q_EMIT lost(QStringLiteral("life guarding: no guard request for %1 ms").arg(lifeTimeMs()));
    });
}

ErrorControlSlave::~ErrorControlSlave() = default;

quint32 ErrorControlSlave::u32(ObjectAddress address) const
{
    if (!m_access->dictionary().contains(address))
        return 0;
    const auto value = m_access->read(address);
    return value ? quint32(value.value().toULongLong()) : 0;
}

int ErrorControlSlave::lifeTimeMs() const
{
    return int(u32({ kGuardTime, 0 }) & 0xFFFF) * int(u32({ kLifeTimeFactor, 0 }) & 0xFF);
}

void ErrorControlSlave::configure()
{
    if (lifeTimeMs() == 0)
        m_lifeTimer.stop();
    else if (m_lifeTimer.isActive())
        m_lifeTimer.start(lifeTimeMs());
    std::map<NodeId, std::unique_ptr<QTimer>> consumers;
    const int entries = std::min(int(u32({ kConsumerHeartbeat, 0 })), kMaxConsumerEntries);
    for (int sub = 1; sub <= entries; ++sub) {
        const quint32 entry = u32({ kConsumerHeartbeat, quint8(sub) });
        const auto producer = NodeId((entry >> 16) & 0xFF);
        const int ms = int(entry & 0xFFFF);
        if (producer < kMinNodeId || producer > kMaxNodeId || ms == 0)
            continue;
        auto timer = std::make_unique<QTimer>();
        timer->setSingleShot(true);
        timer->setTimerType(Qt::PreciseTimer);
        timer->setInterval(ms);
        connect(timer.get(), &QTimer::timeout, this, [this, producer, ms] {
            Q_EMIT lost(
                QStringLiteral("heartbeat of node %1 not heard for %2 ms").arg(producer).arg(ms));
        });
        consumers[producer] = std::move(timer);
    }
    m_consumers = std::move(consumers); // a changed entry waits for the next heartbeat
}

void ErrorControlSlave::reset()
{
    m_toggle = false;
    m_lifeTimer.stop();
    configure(); // the objects may have been reset too; every watch starts idle again
}

bool ErrorControlSlave::receive(const QCanBusFrame &frame, NmtState state)
{
    if (frame.hasExtendedFrameFormat())
        return false;
    const quint32 id = frame.frameId();
    if (id == cob::heartbeat(m_node) && frame.frameType() == QCanBusFrame::RemoteRequestFrame) {
        const quint8 byte = quint8(state) | (m_toggle ? kToggleBit : 0);
        m_toggle = !m_toggle;
        Q_EMIT transmit(QCanBusFrame(id, QByteArray(1, char(byte))));
        if (const int ms = lifeTimeMs(); ms > 0)
            m_lifeTimer.start(ms);
        return true;
    }
    if (frame.frameType() == QCanBusFrame::DataFrame && id > cob::Heartbeat
        && id <= cob::heartbeat(kMaxNodeId) && frame.payload().size() == 1) {
        const auto it = m_consumers.find(NodeId(id - cob::Heartbeat));
        if (it != m_consumers.end() && quint8(frame.payload().at(0)) != 0)
            it->second->start(); // a boot-up (00h) starts no supervision
    }
    return false;
}

} // namespace db::canopen
