#include "nodemonitor.h"

#include "canopenlogging.h"
#include "nmtmaster.h"
#include "transport/canbus.h"

#include <QCanBusFrame>
#include <QElapsedTimer>
#include <QTimer>

#include <algorithm>

namespace db::canopen {

struct NodeMonitor::Entry
{
    NmtState state = NmtState::Unknown;
    bool alive = false;
    QTimer timer; // consumer time, restarted by every heartbeat
    QElapsedTimer sinceLast; // since the last heartbeat
    qint64 longestMs = 0; // longest interval between heartbeats while alive
    int intervals = 0;
};

NodeMonitor::NodeMonitor(CanBus *bus, QObject *parent)
    : QObject(parent)
{
    connect(bus, &CanBus::frameReceived, this, &NodeMonitor::onFrame);
}

NodeMonitor::~NodeMonitor() = default;

void NodeMonitor::setConsumerTime(NodeId node, int ms)
{
    m_consumerMs[node] = qMax(0, ms);
    const auto it = m_nodes.find(node);
    if (it != m_nodes.end() && ms <= 0)
        it->second->timer.stop();
}

int NodeMonitor::consumerTime(NodeId node) const
{
    if (const auto it = m_consumerMs.find(node); it != m_consumerMs.end())
        return it->second;
    if (m_defaultConsumerMs > 0)
        return m_defaultConsumerMs;
    const auto e = m_nodes.find(node);
    if (e == m_nodes.end() || e->second->intervals < kLearnIntervals)
        return 0;
    return int(std::max<qint64>(kLearnedMinMs, e->second->longestMs * kLearnedFactor));
}

NmtState NodeMonitor::state(NodeId node) const
{
    const auto it = m_nodes.find(node);
    return it != m_nodes.end() ? it->second->state : NmtState::Unknown;
}

bool NodeMonitor::isAlive(NodeId node) const
{
    const auto it = m_nodes.find(node);
    return it != m_nodes.end() && it->second->alive;
}

QList<NodeId> NodeMonitor::nodes() const
{
    QList<NodeId> list;
    for (const auto &[node, e] : m_nodes)
        list.append(node);
    return list;
}

void NodeMonitor::clear()
{
    m_nodes.clear();
}

NodeMonitor::Entry &NodeMonitor::entry(NodeId node)
{
    auto &slot = m_nodes[node];
    if (!slot) {
        slot = std::make_unique<Entry>();
        slot->timer.setSingleShot(true);
        connect(&slot->timer, &QTimer::timeout, this, [this, node] { onLost(node); });
    }
    return *slot;
}

void NodeMonitor::onFrame(const QCanBusFrame &frame)
{
    const quint32 id = frame.frameId();
    if (frame.frameType() != QCanBusFrame::DataFrame || frame.hasExtendedFrameFormat()
        || id <= cob::Heartbeat || id > cob::Heartbeat + kMaxNodeId || frame.payload().isEmpty())
        return;
    const NodeId node = NodeId(id - cob::Heartbeat);
    // Bit 7 is the node-guarding toggle; the state is in bits 6..0.
    const auto state = NmtState(quint8(frame.payload().at(0)) & 0x7F);
    const bool first = !m_nodes.contains(node);
    Entry &e = entry(node);
    const bool wasLost = !first && !e.alive;
    if (!first && !wasLost) {
        e.longestMs = std::max(e.longestMs, e.sinceLast.elapsed());
        ++e.intervals;
    }
    e.sinceLast.start();
    e.alive = true;
    if (const int ms = consumerTime(node); ms > 0)
        e.timer.start(ms);
    if (first)
        Q_EMIT nodeSeen(node);
    if (wasLost) {
        qCInfo(lcCanopen).noquote() << "node" << node << "heartbeat resumed";
        Q_EMIT heartbeatResumed(node);
    }
    if (state == NmtState::BootUp) {
        qCInfo(lcCanopen).noquote() << "node" << node << "boot-up";
        Q_EMIT bootUp(node);
    }
    if (state != e.state) {
        e.state = state;
        Q_EMIT stateChanged(node, state);
    }
}

void NodeMonitor::onLost(NodeId node)
{
    const auto it = m_nodes.find(node);
    if (it == m_nodes.end() || !it->second->alive)
        return;
    it->second->alive = false;
    qCInfo(lcCanopen).noquote() << "node" << node << "heartbeat lost after" << consumerTime(node)
                                << "ms";
    Q_EMIT heartbeatLost(node);
}

} // namespace db::canopen
