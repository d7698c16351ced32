#pragma once

// The tool's own heartbeat (CiA 301 7.2.8.3.2.2, producer side) on 700h + its node id, state
// Operational, so that drives can watch it with their consumer heartbeat time (1016h). It runs
// while at least one user needs it (acquire/release), at the shortest period asked for; frames
// go out only while the bus is open. When the process dies or the link breaks, the heartbeat
// stops, which is the point.

#include "canopenids.h"

#include <QObject>
#include <QTimer>

namespace db {
class CanBus;
}

namespace db::canopen {

class HeartbeatProducer : public QObject
{
    Q_OBJECT
public:
    // The highest node id: a master rarely shares it with a drive.
    static constexpr NodeId kDefaultNodeId = 127;

    // The bus is not owned and must outlive the producer.
    explicit HeartbeatProducer(CanBus *bus, QObject *parent = nullptr);
    ~HeartbeatProducer() override;

    void setNodeId(NodeId node) { m_node = node; }
    NodeId nodeId() const { return m_node; }
    // One more user; the heartbeat runs every periodMs (the shortest of all users).
    void acquire(int periodMs);
    // One user less; the heartbeat stops with the last one.
    void release();
    bool isRunning() const { return m_timer.isActive(); }
    int periodMs() const { return m_timer.interval(); }

private:
    void beat();

    CanBus *m_bus;
    NodeId m_node = kDefaultNodeId;
    int m_users = 0;
    QTimer m_timer;
};

} // namespace db::canopen
