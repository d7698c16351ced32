#pragma once

// One CAN bus and the CANopen master services on it (CiA 301): SDO client (one channel per
// node, different nodes in parallel), NMT master, node monitor (boot-up, heartbeat), EMCY
// consumer, SYNC producer, LSS master, the tool's own heartbeat producer and node guarding
// (what drives watch to stop when the tool goes away), and frame subscriptions by COB-ID. Every
// node connection on the same bus shares one network, so N nodes behind one SLCAN link use one
// socket, one NMT master and one node monitor; broadcast services (NMT to all, LSS, raw frames) go
// through the network, not through a node.
//
// Contracts:
// - The network owns its bus and services; they live as long as the network.
// - The bus opens when the first user asks for it (acquire()) and closes when the last one lets
//   go (release()); opened()/closed() are the bus's own signals. A user that acquires an open
//   bus is told synchronously by isOpen().
// - subscribe() handlers run from the event loop in the order frames arrive; a handler whose
//   context object is destroyed is dropped.

#include "canopenids.h"
#include "core/deviceconnection.h"
#include "core/error.h"
#include "core/objectdictionary.h"

#include <QCanBusFrame>
#include <QMap>
#include <QObject>
#include <QPointer>

#include <functional>
#include <unordered_map>
#include <vector>

namespace db {
class CanBus;
}

namespace db::canopen {

class EmcyConsumer;
class HeartbeatProducer;
class LssMaster;
class NmtMaster;
class NodeGuarding;
class NodeMonitor;
class SdoClient;
class SyncProducer;

class CanNetwork : public QObject
{
    Q_OBJECT
public:
    using FrameHandler = std::function<void(const QCanBusFrame &)>;

    // Takes ownership of bus (closed or open). bitrate: what the bus was made with (0 unknown),
    // so that a second connection asking for another bitrate on the same bus can be refused.
    explicit CanNetwork(CanBus *bus, int bitrate = 0, QObject *parent = nullptr);
    ~CanNetwork() override;

    CanBus *bus() const { return m_bus; }
    QString name() const;
    int bitrate() const { return m_bitrate; }
    bool isOpen() const;

    SdoClient *sdo() const { return m_sdo; }
    NmtMaster *nmt() const { return m_nmt; }
    NodeMonitor *monitor() const { return m_monitor; }
    EmcyConsumer *emcy() const { return m_emcy; }
    SyncProducer *sync() const { return m_sync; }
    LssMaster *lss() const { return m_lss; }
    HeartbeatProducer *heartbeat() const { return m_heartbeat; }
    NodeGuarding *guarding() const { return m_guarding; }

    // Opens the bus unless it is open or opening; counts the users who need it open.
    void acquire();
    // One user less; the bus closes when none is left (closed() follows).
    void release();
    int users() const { return m_users; }
    // Blocks in a local event loop until the bus is open or failed (CLI, benchmarks, tests).
    Result<void> acquireAndWait(int timeoutMs);

    // One frame out on the bus (raw, for the CAN monitor's sender and broadcast PDOs). False
    // when the bus is not open.
    bool send(const QCanBusFrame &frame);
    // Frames with this COB-ID (11-bit or 29-bit id) call handler until context is destroyed.
    void subscribe(quint32 cobId, QObject *context, FrameHandler handler);

    // The description of one node, for everything that reads its frames (EMCY texts, the CAN
    // monitor's PDO fields): set by its connection, or by a device family's services that
    // identified it (e.g. the NM17x line). Emits dictionaryChanged().
    void setDictionary(NodeId node, const ObjectDictionary &dictionary);
    // Null for nodes nobody described.
    const ObjectDictionary *dictionary(NodeId node) const;
    QList<NodeId> describedNodes() const;

Q_SIGNALS:
    void opened();
    void closed(const db::Error &error);
    // A bus problem that does not close it (error frame, overrun), for every user's log.
    void warning(const QString &text);
    void dictionaryChanged(db::canopen::NodeId node);

private:
    struct Subscription
    {
        QPointer<QObject> context;
        FrameHandler handler;
    };
    void dispatch(const QCanBusFrame &frame);

    CanBus *m_bus;
    int m_bitrate = 0;
    int m_users = 0;
    bool m_closing = false; // close() asked for by release(), not a failure
    SdoClient *m_sdo;
    NmtMaster *m_nmt;
    NodeMonitor *m_monitor;
    EmcyConsumer *m_emcy;
    SyncProducer *m_sync;
    LssMaster *m_lss;
    HeartbeatProducer *m_heartbeat;
    NodeGuarding *m_guarding;
    std::unordered_map<quint32, std::vector<Subscription>> m_subscriptions;
    QMap<NodeId, ObjectDictionary> m_dictionaries;
};

// A node on a CAN network: what the services that work on the bus need of a connection.
struct NetworkNode
{
    CanNetwork *network = nullptr;
    NodeId node = 0;
    explicit operator bool() const { return network != nullptr; }
};

// The network and node id of a connection to a CANopen node; empty for any other connection
// (and for null).
inline NetworkNode networkNodeOf(const DeviceConnection *connection)
{
    if (!connection)
        return {};
    auto *network = qobject_cast<CanNetwork *>(connection->network());
    if (!network)
        return {};
    return { network, NodeId(connection->networkAddress()) };
}

} // namespace db::canopen
