#pragma once

// Heartbeat and boot-up consumer (CiA 301 7.2.8.3.2): tracks the NMT state of every node heard
// on 700h + node id and reports "heartbeat lost" when a node stays silent longer than its
// consumer time. As in CiA 301, monitoring of a node starts with its first heartbeat.
//
// Every node heard is watched, also one the tool never connected to (found by a scan, or only
// heard): without a consumer time of its own or a default, it gets kLearnedFactor times the
// longest interval between its heartbeats, once kLearnIntervals intervals were seen (silence
// while it was lost does not count), and at least kLearnedMinMs, so that bursts (several nodes on
// one id, frames queued by a busy host) do not make it flap.

#include "canopenids.h"

#include <QObject>

#include <map>
#include <memory>

namespace db {
class CanBus;
}
class QCanBusFrame;

namespace db::canopen {

class NodeMonitor : public QObject
{
    Q_OBJECT
public:
    // The bus is not owned and must outlive the monitor.
    explicit NodeMonitor(CanBus *bus, QObject *parent = nullptr);
    ~NodeMonitor() override;

    static constexpr int kLearnedFactor = 3;
    static constexpr int kLearnIntervals = 2;
    static constexpr int kLearnedMinMs = 500;

    // Silence longer than ms after a heartbeat means "lost"; 0 = not watched. Per node, and a
    // default for nodes without their own setting (0 unless set: then the learned time).
    void setConsumerTime(NodeId node, int ms);
    void setDefaultConsumerTime(int ms) { m_defaultConsumerMs = qMax(0, ms); }
    // The node's own setting, else the default, else the learned time (0 while still learning).
    int consumerTime(NodeId node) const;

    // Unknown for nodes never heard.
    NmtState state(NodeId node) const;
    // Heard at least once and not lost since.
    bool isAlive(NodeId node) const;
    // Nodes heard so far, ascending.
    QList<NodeId> nodes() const;
    // Forget everything (e.g. after a bus reconnect); timers stop.
    void clear();

Q_SIGNALS:
    void nodeSeen(db::canopen::NodeId node); // first frame ever from this node
    void bootUp(db::canopen::NodeId node); // boot-up message (state 00h)
    void stateChanged(db::canopen::NodeId node, db::canopen::NmtState state);
    void heartbeatLost(db::canopen::NodeId node);
    void heartbeatResumed(db::canopen::NodeId node);

private:
    struct Entry;
    void onFrame(const QCanBusFrame &frame);
    Entry &entry(NodeId node);
    void onLost(NodeId node);

    std::map<NodeId, std::unique_ptr<Entry>> m_nodes;
    std::map<NodeId, int> m_consumerMs;
    int m_defaultConsumerMs = 0;
};

} // namespace db::canopen
