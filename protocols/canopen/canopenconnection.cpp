#include "canopenconnection.h"

#include "canbusfactory.h"
#include "cannetwork.h"
#include "canopenlogging.h"
#include "emcyconsumer.h"
#include "heartbeatproducer.h"
#include "nmtmaster.h"
#include "nodemonitor.h"
#include "sdoclient.h"
#include "storesignatures.h"
#include "syncproducer.h"
#include "transport/canbus.h"

#include <QCoreApplication>
#include <QPointer>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::canopen)
};
} // namespace

namespace db::canopen {

CanopenConnection::CanopenConnection(const ConnectionUri &uri, std::shared_ptr<CanNetwork> network,
                                     QObject *parent)
    : DeviceConnection(uri, parent)
    , m_network(std::move(network))
    , m_blockEnabled(uri.queryValue(QStringLiteral("block")) == u"1")
    , m_nodeResult(nodeFromUri(uri))
    , m_node(m_nodeResult.valueOr(0))
    , m_toolNodeResult(toolNodeFromUri(uri))
    , m_probe(uri.queryValue(QStringLiteral("probe")) == u"1")
    , m_sdoModeResult(sdoModeFromText(uri.queryValue(QStringLiteral("sdo"))))
    , m_sdoMode(m_sdoModeResult.valueOr(SdoClient::Mode::Auto))
{
    CanNetwork *net = m_network.get();
    connect(net, &CanNetwork::opened, this, &CanopenConnection::onBusOpened);
    connect(net, &CanNetwork::closed, this, &CanopenConnection::onBusClosed);
    connect(net, &CanNetwork::warning, this,
            [this](const QString &text) { Q_EMIT logLine(QStringLiteral("! ") + text); });
    connect(net->sdo(), &SdoClient::logLine, this, &DeviceConnection::logLine);
    connect(net->emcy(), &EmcyConsumer::emergency, this, [this](const Emergency &e) {
        if (e.node == m_node)
            Q_EMIT logLine(QStringLiteral("EMCY ") + e.toString());
    });
    // The network decodes this node's frames with the description in use.
    connect(this, &DeviceConnection::dictionaryChanged, this, [this] {
        if (m_nodeResult)
            m_network->setDictionary(m_node, dictionary());
    });
    connect(net->monitor(), &NodeMonitor::bootUp, this, [this](NodeId node) {
        if (node == m_node)
            Q_EMIT logLine(QStringLiteral("node %1 boot-up").arg(node));
    });
    connect(net->monitor(), &NodeMonitor::heartbeatLost, this, [this](NodeId node) {
        if (node != m_node)
            return;
        Q_EMIT logLine(QStringLiteral("! node %1 heartbeat lost").arg(node));
        if (isConnected())
            Q_EMIT supervisionLost(Tr::tr("heartbeat lost: node %1 silent for more than %2 ms")
                                       .arg(node)
                                       .arg(m_network->monitor()->consumerTime(node)));
    });
}

CanopenConnection::CanopenConnection(const ConnectionUri &uri, CanBus *bus, QObject *parent)
    : CanopenConnection(
        uri, std::make_shared<CanNetwork>(bus, CanBusFactory::bitrateOf(uri).valueOr(0)), parent)
{ }

CanopenConnection::~CanopenConnection()
{
    // This node's transfers fail while the bus still exists; the network may outlive us.
    m_network->disconnect(this);
    m_network->sdo()->disconnect(this);
    m_network->sdo()->cancelNode(
        m_node, Error(Error::Kind::Cancelled, Tr::tr("connection to node %1 deleted").arg(m_node)));
    releaseNetwork();
    m_network.reset();
}

Reply *CanopenConnection::storeNonVolatile()
{
    return write(store::kStoreAll, QVariant::fromValue<qulonglong>(store::kSaveSignature));
}

Reply *CanopenConnection::restoreFactoryDefaults()
{
    return write(store::kRestoreDefaultsAll,
                 QVariant::fromValue<qulonglong>(store::kLoadSignature));
}

CanBus *CanopenConnection::bus() const
{
    return m_network->bus();
}

SdoClient *CanopenConnection::sdo() const
{
    return m_network->sdo();
}

NmtMaster *CanopenConnection::nmt() const
{
    return m_network->nmt();
}

NodeMonitor *CanopenConnection::monitor() const
{
    return m_network->monitor();
}

EmcyConsumer *CanopenConnection::emcy() const
{
    return m_network->emcy();
}

SyncProducer *CanopenConnection::sync() const
{
    return m_network->sync();
}

void CanopenConnection::releaseNetwork()
{
    if (!m_acquired)
        return;
    m_acquired = false;
    m_network->release();
}

void CanopenConnection::prepareSdo() const
{
    SdoClient *sdo = m_network->sdo();
    sdo->setTimeoutMs(requestTimeoutMs());
    sdo->setBlockEnabled(m_blockEnabled);
}

Result<NodeId> CanopenConnection::nodeFromUri(const ConnectionUri &uri)
{
    if (!uri.hasQuery(QStringLiteral("node")))
        return Error(Error::Kind::InvalidArgument,
                     Tr::tr("%1 needs the node id: ?node=N (1..127)").arg(uri.toString()));
    const auto node = uri.queryInt(QStringLiteral("node"), kMinNodeId, kMaxNodeId);
    if (!node)
        return node.error();
    return NodeId(*node);
}

Result<NodeId> CanopenConnection::toolNodeFromUri(const ConnectionUri &uri)
{
    const QString key = QStringLiteral("toolnode");
    if (!uri.hasQuery(key))
        return HeartbeatProducer::kDefaultNodeId;
    const auto tool = uri.queryInt(key, kMinNodeId, kMaxNodeId);
    if (!tool)
        return tool.error();
    if (const auto node = nodeFromUri(uri); node && *node == *tool)
        return Error(Error::Kind::InvalidArgument,
                     QStringLiteral("?toolnode=%1 is the drive's own node id (?node=%1); the tool "
                                    "needs a node id of its own on the bus")
                         .arg(*tool));
    return NodeId(*tool);
}

Result<SdoClient::Mode> CanopenConnection::sdoModeFromText(const QString &text)
{
    if (text.isEmpty() || text == u"auto")
        return SdoClient::Mode::Auto;
    if (text == u"expedited")
        return SdoClient::Mode::Expedited;
    if (text == u"segmented")
        return SdoClient::Mode::Segmented;
    if (text == u"block")
        return SdoClient::Mode::Block;
    return Error(Error::Kind::InvalidArgument,
                 Tr::tr("unknown SDO mode '%1' (auto, expedited, segmented or block)").arg(text));
}

void CanopenConnection::doOpen()
{
    if (!m_nodeResult || !m_sdoModeResult || !m_toolNodeResult) {
        setState(State::Disconnected,
                 !m_nodeResult          ? m_nodeResult.error()
                     : !m_sdoModeResult ? m_sdoModeResult.error()
                                        : m_toolNodeResult.error());
        return;
    }
    m_network->setDictionary(m_node, dictionary());
    m_network->heartbeat()->setNodeId(*m_toolNodeResult);
    Q_EMIT logLine(QStringLiteral("opening %1 for node %2").arg(m_network->name()).arg(m_node));
    if (!m_acquired) {
        m_acquired = true;
        m_network->bus()->setConnectTimeoutMs(connectTimeoutMs());
        m_network->acquire();
    }
    if (m_network->isOpen())
        onBusOpened();
}

void CanopenConnection::doClose()
{
    m_network->sdo()->cancelNode(
        m_node, Error(Error::Kind::Cancelled, Tr::tr("connection to node %1 closed").arg(m_node)));
    releaseNetwork();
    // Other connections may keep the bus open; then this node is done at once.
    if (m_network->users() > 0 || m_network->bus()->state() == CanBus::State::Closed)
        setState(State::Disconnected);
}

void CanopenConnection::onBusOpened()
{
    if (state() != State::Connecting)
        return;
    if (m_probe) {
        probe();
        return;
    }
    finishConnecting();
}

void CanopenConnection::finishConnecting()
{
    if (m_chooser && dictionary().isEmpty()) {
        identify();
        return;
    }
    qCInfo(lcCanopen).noquote() << "connected to node" << m_node << "on" << m_network->name();
    Q_EMIT logLine(Tr::tr("connected to node %1 on %2").arg(m_node).arg(m_network->name()));
    setState(State::Connected);
    watchHeartbeat();
}

// The node's own heartbeat period (1017h) sets how long our NodeMonitor waits before it reports
// "heartbeat lost" (supervisionLost()): kHeartbeatConsumerFactor periods.
void CanopenConnection::watchHeartbeat()
{
    if (!dictionary().contains(kProducerHeartbeat))
        return;
    Reply *r = read(kProducerHeartbeat);
    r->setParent(this);
    connect(r, &Reply::finished, this, [this, r] {
        r->deleteLater();
        const int period = r->ok() ? r->value().toInt() : 0;
        if (period <= 0 || !isConnected())
            return;
        const int consumer = period * kHeartbeatConsumerFactor;
        m_network->monitor()->setConsumerTime(m_node, consumer);
        Q_EMIT logLine(QStringLiteral("node %1 sends its heartbeat every %2 ms (1017h): "
                                      "watched, lost after %3 ms of silence")
                           .arg(m_node)
                           .arg(period)
                           .arg(consumer));
    });
}

// Reads 1000h: any answer, even an abort, shows the node is there.
void CanopenConnection::probe()
{
    prepareSdo();
    Reply *reply = m_network->sdo()->upload(m_node, kDeviceType, SdoClient::Mode::Expedited);
    reply->setParent(this);
    connect(reply, &Reply::finished, this, [this, reply] {
        reply->deleteLater();
        if (state() != State::Connecting)
            return;
        if (reply->ok() || reply->error().kind() == Error::Kind::DeviceError) {
            Q_EMIT logLine(
                QStringLiteral("node %1 answers on %2").arg(m_node).arg(m_network->name()));
            finishConnecting();
            return;
        }
        const Error why = reply->error().kind() == Error::Kind::Timeout
            ? Error(Error::Kind::Timeout,
                    Tr::tr("node %1 does not answer on %2 (no SDO answer to 1000h within "
                           "%3 ms)")
                        .arg(m_node)
                        .arg(m_network->name())
                        .arg(requestTimeoutMs()))
            : reply->error();
        setState(State::Closing);
        setState(State::Disconnected, why);
        releaseNetwork();
    });
}

void CanopenConnection::onBusClosed(const Error &error)
{
    m_acquired = false; // a closed bus has no users left
    const State previous = state();
    if (previous == State::Disconnected)
        return;
    if (previous == State::Closing || !error.isError()) {
        Q_EMIT logLine(Tr::tr("disconnected from %1").arg(m_network->name()));
        setState(State::Disconnected,
                 previous == State::Closing
                     ? Error()
                     : Error(Error::Kind::Disconnected,
                             Tr::tr("CAN bus %1 closed").arg(m_network->name())));
        return;
    }
    Q_EMIT logLine(QStringLiteral("! ") + error.message());
    setState(State::Disconnected, error);
}

QVariant CanopenConnection::valueFromUnknownBytes(const QByteArray &bytes)
{
    const qsizetype n = bytes.size();
    if ((n >= 1 && n <= 4) || n == 8) {
        quint64 v = 0;
        for (qsizetype i = n - 1; i >= 0; --i)
            v = (v << 8) | quint8(bytes.at(i));
        return QVariant::fromValue<qlonglong>(qlonglong(v));
    }
    return bytes;
}

Result<QByteArray> CanopenConnection::bytesFromUnknownValue(const QVariant &value)
{
    int size = 0;
    switch (value.typeId()) {
    case QMetaType::QByteArray:
        return value.toByteArray();
    case QMetaType::QString:
        return value.toString().toUtf8();
    case QMetaType::Bool:
    case QMetaType::Char:
    case QMetaType::SChar:
    case QMetaType::UChar:
        size = 1;
        break;
    case QMetaType::Short:
    case QMetaType::UShort:
        size = 2;
        break;
    case QMetaType::Int:
    case QMetaType::UInt:
        size = 4;
        break;
    case QMetaType::LongLong:
    case QMetaType::ULongLong: {
        const qlonglong v = value.toLongLong();
        const bool fits = value.typeId() == QMetaType::ULongLong
            ? value.toULongLong() <= 0xFFFFFFFFull
            : (v >= -qlonglong(0x80000000LL) && v <= qlonglong(0xFFFFFFFFLL));
        size = fits ? 4 : 8;
        break;
    }
    default:
        return Error(Error::Kind::InvalidArgument,
                     Tr::tr("cannot write a %1 to an object of unknown type (give its "
                            "type)")
                         .arg(QString::fromLatin1(value.typeName())));
    }
    const quint64 bits = value.toULongLong();
    QByteArray bytes(size, '\0');
    for (int i = 0; i < size; ++i)
        bytes[i] = char((bits >> (8 * i)) & 0xFF);
    return bytes;
}

void CanopenConnection::doRead(Reply *reply, const ObjectDef *def)
{
    prepareSdo();
    const bool variable = def && datatype::isVariableLength(def->type);
    const int size = def && !variable ? datatype::byteSize(def->type) : -1;
    // Unknown objects: a normal upload (the server picks expedited or segmented).
    const auto mode = m_sdoMode != SdoClient::Mode::Auto ? m_sdoMode
        : def                                            ? SdoClient::Mode::Auto
                                                         : SdoClient::Mode::Segmented;
    // The reply is the request's context: deleted before it is sent, the read is withdrawn.
    const auto upload = [&](std::function<Result<QVariant>(const QVariant &)> convert) {
        m_network->sdo()->upload(m_node, reply->address(),
                                 Completion::finishing(reply, std::move(convert)), mode, size);
    };
    if (!def) {
        upload([](const QVariant &v) { return valueFromUnknownBytes(v.toByteArray()); });
        return;
    }
    upload([type = def->type, size](const QVariant &v) -> Result<QVariant> {
        const QByteArray bytes = v.toByteArray();
        // An expedited answer without size indication carries 4 bytes for smaller types.
        return codec::decode(type, size > 0 && bytes.size() > size ? bytes.left(size) : bytes);
    });
}

void CanopenConnection::doWrite(Reply *reply, const QVariant &raw, const ObjectDef *def)
{
    const Result<QByteArray> bytes =
        def ? codec::encode(def->type, raw) : bytesFromUnknownValue(raw);
    if (!bytes) {
        reply->fail(bytes.error());
        return;
    }
    prepareSdo();
    Reply::forward(m_network->sdo()->download(m_node, reply->address(), *bytes, m_sdoMode), reply,
                   this);
}

} // namespace db::canopen
