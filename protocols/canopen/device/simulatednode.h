#pragma once

// A simulated CANopen node for tests, benchmarks and the simulators (CiA 301 device side):
// SDO server, NMT slave with boot-up, heartbeat producer (1017h), life guarding (100Ch/100Dh)
// and heartbeat consumer (1016h) with the error behaviour of 1029h:01, EMCY producer (1014h),
// TPDOs (1800h/1A00h) on SYNC or event timer, RPDOs (1400h/1600h), and switchable SDO failure
// modes (ARCHITECTURE.md habit 6). Bus-agnostic: frames in through receive(), out through
// transmit(); attach() wires both to a CanBus, an SlcanServer is wired by its owner.

#include "errorcontrolslave.h"
#include "lssslave.h"
#include "sdoserver.h"

#include <QHash>
#include <QList>
#include <QObject>
#include <QTimer>

#include <functional>
#include <memory>

namespace db {
class CanBus;
}

namespace db::canopen {

// The plain value store of a simulated node: one raw value per object of the dictionary,
// starting at the dictionary's defaults (zero / empty when none). write() validates against the
// definition; set() is the device's own path and does not.
class ObjectValueStore : public ObjectAccess
{
public:
    explicit ObjectValueStore(ObjectDictionary dictionary);

    const ObjectDictionary &dictionary() const override { return m_dictionary; }
    Result<QVariant> read(ObjectAddress address) override;
    Result<void> write(ObjectAddress address, const QVariant &raw) override;

    QVariant value(ObjectAddress address) const { return m_values.value(address); }
    void set(ObjectAddress address, const QVariant &raw);
    // Back to the defaults for the objects `which` accepts (all when empty).
    void resetToDefaults(const std::function<bool(ObjectAddress)> &which = {});

private:
    ObjectDictionary m_dictionary;
    QHash<ObjectAddress, QVariant> m_values;
};

class SimulatedNode : public QObject, public ObjectAccess
{
    Q_OBJECT
public:
    // The node keeps its values in its own ObjectValueStore.
    SimulatedNode(const ObjectDictionary &dictionary, NodeId node, QObject *parent = nullptr);
    // The node serves someone else's objects (e.g. the simulated MovingCap); access must outlive
    // the node. NMT reset node then resets only the node's communication state.
    SimulatedNode(ObjectAccess *access, NodeId node, QObject *parent = nullptr);
    ~SimulatedNode() override;

    NodeId nodeId() const { return m_node; }
    void setNodeId(NodeId node); // takes effect at once (LSS applies it at reset communication)
    NmtState nmtState() const { return m_state; }
    bool isStarted() const { return m_started; }
    SdoServer &sdoServer() { return m_sdo; }
    // The node's LSS slave (CiA 305, 7E5h/7E4h); identity from 1018h. A configured node id
    // takes effect at NMT reset node / reset communication.
    LssSlave &lssSlave() { return m_lss; }
    ObjectValueStore *store() { return m_ownStore.get(); } // null with an external access

    // Power on: boot-up frame (700h + node, 00), then Pre-operational (Operational when
    // 1F80h bit 3 is set); heartbeat and PDO timers start.
    void start();
    // Every frame seen on the bus (the node filters what concerns it). Synchronous.
    void receive(const QCanBusFrame &frame);
    // Wires bus frames to receive() and transmit() to bus->send(). The bus must outlive the node
    // or be detached by deleting the node first.
    void attach(CanBus *bus);

    // EMCY (CiA 301 7.2.7): code LE, error register, 5 manufacturer bytes. With the own store,
    // 1001h and the 1003h history are updated too. Not sent in Stopped or before start().
    void raiseEmergency(quint16 code, quint8 errorRegister, const QByteArray &manufacturer = {});
    // An EMCY frame with exactly these bytes (padded to 8), for devices keeping their own 1001h.
    void sendEmergency(const QByteArray &data);

    // Failure mode: no heartbeat frames (a node that died or lost its bus), everything else
    // keeps working; off again resumes at the 1017h period.
    void setHeartbeatSilenced(bool on) { m_heartbeatSilenced = on; }
    bool isHeartbeatSilenced() const { return m_heartbeatSilenced; }

    // ---- SDO failure modes ----
    void setSdoNoReply(bool on) { m_noReply = on; }
    // Every SDO request initiating a transfer of this object gets this abort code.
    void setSdoAbort(ObjectAddress address, quint32 code) { m_aborts.insert(address, code); }
    void clearSdoAborts() { m_aborts.clear(); }
    // Every SDO response leaves this much later (order kept).
    void setSdoReplyDelayMs(int ms) { m_replyDelayMs = ms; }
    // Answers this many SDO requests, then none (-1 = off). Counting restarts when set.
    void setSdoDropAfter(int requests);
    // SDO responses are replaced by a frame with an invalid command specifier.
    void setSdoGarbage(bool on) { m_garbage = on; }
    int sdoRequestCount() const { return m_sdoRequests; }

    // ---- ObjectAccess: the SDO server's view; reacts to communication objects ----
    const ObjectDictionary &dictionary() const override { return m_access->dictionary(); }
    Result<QVariant> read(ObjectAddress address) override { return m_access->read(address); }
    Result<void> write(ObjectAddress address, const QVariant &raw) override;

    // Content of TPDO n (0-based) as mapped by 1A00h + n, for tests and the CAN monitor.
    QByteArray tpdoPayload(int n);

Q_SIGNALS:
    void transmit(const QCanBusFrame &frame);
    void nmtStateChanged(db::canopen::NmtState state);
    // A write through SDO or RPDO succeeded.
    void objectWritten(db::ObjectAddress address, const QVariant &raw);
    // A life guarding or heartbeat event (errorcontrolslave.h). Emitted before the node's own
    // reaction (EMCY 8130h, the NMT state change of 1029h:01), so that a device profile can
    // react first (CiA 402 6007h).
    void communicationLost(const QString &reason);

private:
    void init();
    void bootUp();
    void setState(NmtState state);
    void handleNmt(const QByteArray &data);
    void onCommunicationError(const QString &reason);
    void handleLss(const QCanBusFrame &frame);
    void handleSdo(const QCanBusFrame &frame);
    void sdoResponse(const QCanBusFrame &frame);
    void handleSync();
    void handleRpdo(int n, const QByteArray &data);
    void configureTimers();
    void sendTpdo(int n);
    quint32 u32(ObjectAddress address, quint32 fallback = 0);
    bool has(ObjectAddress address) const { return dictionary().contains(address); }
    void send(quint32 id, const QByteArray &data);

    std::unique_ptr<ObjectValueStore> m_ownStore;
    ObjectAccess *m_access;
    NodeId m_node;
    SdoServer m_sdo;
    LssSlave m_lss;
    ErrorControlSlave m_errorControl;
    NmtState m_state = NmtState::BootUp;
    bool m_started = false;
    QTimer m_heartbeat;
    QList<QTimer *> m_eventTimers; // per TPDO, owned by this
    QList<int> m_syncCounters;

    bool m_heartbeatSilenced = false;
    bool m_noReply = false;
    QHash<ObjectAddress, quint32> m_aborts;
    int m_replyDelayMs = 0;
    int m_dropAfter = -1;
    bool m_garbage = false;
    int m_sdoRequests = 0;
};

} // namespace db::canopen
