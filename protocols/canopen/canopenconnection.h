#pragma once

// A CANopen node as a DeviceConnection: read/write by index:sub through SDO with the
// dictionary's types. A connection is a CanNetwork (the bus and its master services, shared by
// every connection to a node of the same bus) plus a node id plus the node's dictionary.
//
// URI query: node=N (1..127, required), probe=1 (on open, read 1000h and fail with "node N does
// not answer" when it stays silent), block=1 (block SDO for large objects), sdo=auto|expedited|
// segmented|block (force the SDO mode of every read and write; default auto), toolnode=N (1..127,
// default 127: the node id of the tool's own heartbeat, which drives with 1016h watch; must differ
// from node=; it applies to the whole bus, the last connection opened sets it).
// Connected as soon as the bus is open (after the probe when asked for, and after choosing the
// description when a chooser is set). Opening acquires the
// network's bus, closing releases it: the bus closes with the last connection that used it.

#include "cannetwork.h"
#include "canopenids.h"
#include "core/deviceconnection.h"
#include "description/descriptionlibrary.h"
#include "sdoclient.h"

#include <functional>
#include <memory>
#include <optional>

namespace db {
class CanBus;
}

namespace db::canopen {

class EmcyConsumer;
class NmtMaster;
class NodeMonitor;
class SyncProducer;

class CanopenConnection : public DeviceConnection
{
    Q_OBJECT
public:
    static constexpr ObjectAddress kDeviceType { 0x1000, 0x00 };
    static constexpr ObjectAddress kProducerHeartbeat { 0x1017, 0x00 };
    // Once connected, the node's heartbeat (1017h, when described and > 0) is watched by the
    // network's NodeMonitor with this many periods of silence allowed.
    static constexpr int kHeartbeatConsumerFactor = 2;

    // A node on a shared network (see CanNetworkPool). A bad ?node= makes open() fail with
    // InvalidArgument.
    CanopenConnection(const ConnectionUri &uri, std::shared_ptr<CanNetwork> network,
                      QObject *parent = nullptr);
    // A node on a network of its own around bus (taken over).
    CanopenConnection(const ConnectionUri &uri, CanBus *bus, QObject *parent = nullptr);
    ~CanopenConnection() override;

    // The ?node= of a URI, checked (InvalidArgument names the problem).
    static Result<NodeId> nodeFromUri(const ConnectionUri &uri);
    // The ?toolnode= of a URI (HeartbeatProducer::kDefaultNodeId when absent), checked against
    // the range and against ?node=.
    static Result<NodeId> toolNodeFromUri(const ConnectionUri &uri);

    QString protocolKey() const override { return QStringLiteral("canopen"); }
    Capabilities capabilities() const override { return Capability::StoreNonVolatile; }
    // 1010h / 1011h sub 1 = "save" / "load" (CiA 301).
    Reply *storeNonVolatile() override;
    Reply *restoreFactoryDefaults() override;

    NodeId node() const { return m_node; }
    // The network this node is on, with the master services of its bus (shared).
    CanNetwork *network() const override { return m_network.get(); }
    int networkAddress() const override { return m_node; }
    CanBus *bus() const;
    SdoClient *sdo() const;
    NmtMaster *nmt() const;
    NodeMonitor *monitor() const;
    EmcyConsumer *emcy() const;
    SyncProducer *sync() const;

    // A connection without a description (an empty dictionary: no ?eds=) that has a chooser
    // identifies its node before it reports Connected: it reads 1018h sub 1..3 and takes the
    // dictionary the chooser returns. Without one, the dictionary stays empty and carries the
    // identity numbers that were read (objects are then read by index and type). The text goes to
    // the log either way ("description for node 5: NM172 (built-in)").
    struct DescriptionChoice
    {
        std::optional<ObjectDictionary> dictionary;
        QString text;
    };
    using DescriptionChooser =
        std::function<DescriptionChoice(const IdentityNumbers &identity, NodeId node)>;
    void setDescriptionChooser(DescriptionChooser chooser) { m_chooser = std::move(chooser); }
    // What the last identification found (nullopt: none done, or the node did not tell its
    // vendor and product) and what it concluded.
    const std::optional<IdentityNumbers> &identity() const { return m_identity; }
    const QString &descriptionNote() const { return m_descriptionNote; }

    // The SDO mode of later reads and writes (Auto: by size and type, block when enabled).
    SdoClient::Mode sdoMode() const { return m_sdoMode; }
    void setSdoMode(SdoClient::Mode mode) { m_sdoMode = mode; }
    // "auto", "expedited", "segmented", "block" (InvalidArgument otherwise).
    static Result<SdoClient::Mode> sdoModeFromText(const QString &text);

    // Raw bytes -> value for objects the dictionary does not know: 1..4 and 8 bytes as an
    // unsigned integer (qlonglong), anything else as the QByteArray (pure).
    static QVariant valueFromUnknownBytes(const QByteArray &bytes);
    // Value -> bytes for objects the dictionary does not know: QByteArray as is, strings as
    // UTF-8, integers by their C++ width (int: 4 bytes; qlonglong: 4 bytes if it fits, else 8).
    static Result<QByteArray> bytesFromUnknownValue(const QVariant &value);

protected:
    void doOpen() override;
    void doClose() override;
    void doRead(Reply *reply, const ObjectDef *def) override;
    void doWrite(Reply *reply, const QVariant &raw, const ObjectDef *def) override;

private:
    void onBusOpened();
    void onBusClosed(const Error &error);
    void probe();
    // After the bus (and the probe): identify() when a chooser waits for it, else Connected.
    void finishConnecting();
    void identify();
    void onIdentified(const std::optional<IdentityNumbers> &identity, const QString &why);
    void watchHeartbeat();
    void releaseNetwork();
    void prepareSdo() const;

    std::shared_ptr<CanNetwork> m_network;
    bool m_acquired = false;
    bool m_blockEnabled = false;
    Result<NodeId> m_nodeResult;
    NodeId m_node = 0;
    Result<NodeId> m_toolNodeResult;
    bool m_probe = false;
    Result<SdoClient::Mode> m_sdoModeResult = SdoClient::Mode::Auto;
    SdoClient::Mode m_sdoMode = SdoClient::Mode::Auto;
    DescriptionChooser m_chooser;
    std::optional<IdentityNumbers> m_identity;
    QString m_descriptionNote;
};

} // namespace db::canopen
