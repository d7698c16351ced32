#pragma once

// LSS slave (CiA 305) for the simulated nodes, answering exactly as nm170_canopen.md 2.4 shows:
// switch mode global/selective (answer 44h 00...), configure node id / bit timing (11h/13h ee),
// activate bit timing, store (17h ee), inquire 5Ah..5Eh (only in configuration mode), fastscan
// (only while unconfigured, as CiA 305 says). Answers are always 8 bytes; requests may be
// shorter (the NM170 manual's DLCs) as long as they carry the bytes the service needs.
//
// A configured node id is pending until the owner applies it (SimulatedNode: at NMT reset
// communication / reset node, CiA 305 8.3.2.2); an unconfigured slave that got a node id
// applies it when it leaves configuration mode (nodeIdActivated()).

#include "canopen/lss.h"

#include <QCanBusFrame>
#include <QObject>

namespace db::canopen {

class LssSlave : public QObject
{
    Q_OBJECT
public:
    explicit LssSlave(QObject *parent = nullptr);

    void setIdentity(const LssAddress &identity) { m_identity = identity; }
    LssAddress identity() const { return m_identity; }
    // The node id in use; lss::kUnconfigured for a slave without one (fastscan finds those).
    void setActiveNodeId(quint8 node);
    quint8 activeNodeId() const { return m_active; }
    // Set by "configure node id"; equals the active one until then.
    quint8 pendingNodeId() const { return m_pending; }
    LssMode mode() const { return m_mode; }
    int bitTimingIndex() const { return m_bitTiming; } // CiA table index, -1 = not set by LSS
    int storeCount() const { return m_stores; }

    // Every frame seen on the bus; the slave reacts to 7E5h only. Synchronous.
    void receive(const QCanBusFrame &frame);

Q_SIGNALS:
    void transmit(const QCanBusFrame &frame);
    // An unconfigured slave left configuration mode with a node id (CiA 305: it then resets its
    // communication with that id).
    void nodeIdActivated(quint8 node);
    void configurationStored(quint8 node, int bitTimingIndex);

private:
    void answer(quint8 cs, quint8 b1 = 0, quint32 value = 0, bool withValue = false);
    void fastscan(const QByteArray &d);

    LssAddress m_identity;
    quint8 m_active = lss::kUnconfigured;
    quint8 m_pending = lss::kUnconfigured;
    LssMode m_mode = LssMode::Waiting;
    int m_selectStep = 0; // 40h..43h matched so far
    int m_fastscanPart = 0;
    int m_bitTiming = -1;
    int m_stores = 0;
};

} // namespace db::canopen
