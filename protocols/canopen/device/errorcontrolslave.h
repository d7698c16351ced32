#pragma once

// Device side of CiA 301 error control besides the own heartbeat (7.2.8.3.2): life guarding
// and heartbeat consumption, for the simulated nodes.
//
// - Life guarding: the master's remote frame on 700h + node is answered with the NMT state and a
//   toggle bit (bit 7, starting at 0 after boot-up). With node life time = 100Ch guard time x
//   100Dh life time factor > 0, a node that has been guarded once and then sees no guard request
//   for the node life time has a life guarding event.
// - Heartbeat consumer: each 1016h sub-index holds node id (bits 16-23) and consumer time in ms
//   (bits 0-15); a producer heard once and then silent for longer than its time is a heartbeat
//   event.
// Monitoring starts with the first guard request / heartbeat, as in CiA 301. lost() fires once
// per event; the next guard request or heartbeat re-arms it.

#include "canopen/canopenids.h"
#include "sdoserver.h"

#include <QCanBusFrame>
#include <QObject>
#include <QTimer>

#include <map>
#include <memory>

namespace db::canopen {

class ErrorControlSlave : public QObject
{
    Q_OBJECT
public:
    // access must outlive this object.
    explicit ErrorControlSlave(ObjectAccess *access, QObject *parent = nullptr);
    ~ErrorControlSlave() override;

    void setNodeId(NodeId node) { m_node = node; }
    // Re-reads 100Ch, 100Dh and 1016h (after a write to one of them).
    void configure();
    // Boot-up: toggle bit back to 0, objects re-read, all supervision idle until the first
    // message again.
    void reset();
    // A frame seen on the bus in NMT state `state`; true when it was a guard request for this
    // node (answered through transmit()).
    bool receive(const QCanBusFrame &frame, NmtState state);

    int lifeTimeMs() const;
    bool isGuarded() const { return m_lifeTimer.isActive(); }

Q_SIGNALS:
    void transmit(const QCanBusFrame &frame);
    // A life guarding or heartbeat event; reason names which and how long it was silent.
    void lost(const QString &reason);

private:
    quint32 u32(ObjectAddress address) const;

    ObjectAccess *m_access;
    NodeId m_node = 0;
    bool m_toggle = false;
    QTimer m_lifeTimer;
    std::map<NodeId, std::unique_ptr<QTimer>> m_consumers; // producer node -> silence timer
};

} // namespace db::canopen
