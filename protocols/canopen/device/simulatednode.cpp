#include "simulatednode.h"

#include "canopen/pdomapping.h"
#include "canopen/sdoabort.h"
#include "transport/canbus.h"

#include <QCoreApplication>
#include <QtEndian>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::canopen)
};
} // namespace

namespace db::canopen {

namespace {

constexpr int kPdoCount = 8; // TPDO/RPDO 1..8 (1800h-1807h, 1400h-1407h) when described
constexpr quint32 kCobInvalid = 0x80000000u; // bit 31 of a COB-ID entry: not valid
// An invalid SDO response (scs 7 does not exist) for the garbage failure mode.
const QByteArray kGarbage = QByteArray::fromHex("E7DEADBEEF5A5A5A");

QVariant zeroOf(DataType type)
{
    if (datatype::isVariableLength(type))
        return type == DataType::VisibleString || type == DataType::UnicodeString
            ? QVariant(QString())
            : QVariant(QByteArray());
    return codec::normalize(type, 0).valueOr(QVariant());
}

} // namespace

// ---- ObjectValueStore ----

ObjectValueStore::ObjectValueStore(ObjectDictionary dictionary)
    : m_dictionary(std::move(dictionary))
{
    resetToDefaults();
}

Result<QVariant> ObjectValueStore::read(ObjectAddress address)
{
    if (!m_dictionary.contains(address))
        return Error(Error::Kind::InvalidArgument,
                     Tr::tr("object %1 does not exist").arg(address.toString()),
                     abort::NoSuchObject);
    return m_values.value(address);
}

Result<void> ObjectValueStore::write(ObjectAddress address, const QVariant &raw)
{
    const ObjectDef *def = m_dictionary.find(address);
    if (!def)
        return Error(Error::Kind::InvalidArgument,
                     Tr::tr("object %1 does not exist").arg(address.toString()),
                     abort::NoSuchObject);
    auto valid = def->validate(raw);
    if (!valid)
        return valid.error();
    m_values.insert(address, valid.value());
    return {};
}

void ObjectValueStore::set(ObjectAddress address, const QVariant &raw)
{
    if (const ObjectDef *def = m_dictionary.find(address))
        m_values.insert(address, codec::normalize(def->type, raw).valueOr(raw));
}

void ObjectValueStore::resetToDefaults(const std::function<bool(ObjectAddress)> &which)
{
    for (const ObjectDef &def : m_dictionary.objects()) {
        if (which && !which(def.address))
            continue;
        const auto value = def.defaultValue.isValid() ? codec::normalize(def.type, def.defaultValue)
                                                      : Result<QVariant>(zeroOf(def.type));
        m_values.insert(def.address, value.valueOr(zeroOf(def.type)));
    }
}

// ---- SimulatedNode ----

SimulatedNode::SimulatedNode(const ObjectDictionary &dictionary, NodeId node, QObject *parent)
    : QObject(parent)
    , m_ownStore(std::make_unique<ObjectValueStore>(dictionary))
    , m_access(m_ownStore.get())
    , m_node(node)
    , m_sdo(this, node)
    , m_errorControl(this)
{
    init();
}

SimulatedNode::SimulatedNode(ObjectAccess *access, NodeId node, QObject *parent)
    : QObject(parent)
    , m_access(access)
    , m_node(node)
    , m_sdo(this, node)
    , m_errorControl(this)
{
    init();
}

SimulatedNode::~SimulatedNode() = default;

void SimulatedNode::init()
{
    connect(&m_sdo, &SdoServer::response, this, &SimulatedNode::sdoResponse);
    connect(&m_lss, &LssSlave::transmit, this, &SimulatedNode::transmit);
    connect(&m_lss, &LssSlave::nodeIdActivated, this, [this](quint8 node) {
        setNodeId(node);
        bootUp();
    });
    m_lss.setActiveNodeId(m_node);
    m_errorControl.setNodeId(m_node);
    connect(&m_errorControl, &ErrorControlSlave::transmit, this, &SimulatedNode::transmit);
    connect(&m_errorControl, &ErrorControlSlave::lost, this, &SimulatedNode::onCommunicationError);
    connect(&m_heartbeat, &QTimer::timeout, this, [this] {
        if (!m_heartbeatSilenced)
            send(cob::heartbeat(m_node), QByteArray(1, char(m_state)));
    });
    for (int n = 0; n < kPdoCount; ++n) {
        auto *timer = new QTimer(this);
        connect(timer, &QTimer::timeout, this, [this, n] { sendTpdo(n); });
        m_eventTimers.append(timer);
        m_syncCounters.append(0);
    }
}

void SimulatedNode::setNodeId(NodeId node)
{
    m_node = node;
    m_sdo.setNodeId(node);
    m_lss.setActiveNodeId(node);
    m_errorControl.setNodeId(node);
}

void SimulatedNode::start()
{
    m_started = true;
    bootUp();
}

void SimulatedNode::attach(CanBus *bus)
{
    connect(bus, &CanBus::frameReceived, this, &SimulatedNode::receive);
    connect(this, &SimulatedNode::transmit, bus, &CanBus::send);
}

void SimulatedNode::bootUp()
{
    m_sdo.reset();
    m_errorControl.reset();
    m_state = NmtState::BootUp;
    send(cob::heartbeat(m_node), QByteArray(1, '\0')); // boot-up (CiA 301 7.2.8.3.2.1)
    setState((u32({ 0x1F80, 0 }) & 0x08) ? NmtState::Operational : NmtState::PreOperational);
}

void SimulatedNode::setState(NmtState state)
{
    const bool changed = m_state != state;
    m_state = state;
    configureTimers();
    if (changed)
        Q_EMIT nmtStateChanged(state);
}

void SimulatedNode::receive(const QCanBusFrame &frame)
{
    if (m_started && m_errorControl.receive(frame, m_state))
        return;
    if (!m_started || frame.frameType() != QCanBusFrame::DataFrame
        || frame.hasExtendedFrameFormat())
        return;
    const quint32 id = frame.frameId();
    if (id == cob::Nmt)
        return handleNmt(frame.payload());
    if (id == cob::LssMaster)
        return handleLss(frame); // LSS works in every NMT state (nm170_canopen.md 2.3)
    if (id == cob::sdoRequest(m_node) && m_state != NmtState::Stopped)
        return handleSdo(frame);
    if (m_state != NmtState::Operational)
        return;
    if (id == (u32({ 0x1005, 0 }, cob::Sync) & 0x7FF))
        return handleSync();
    for (int n = 0; n < kPdoCount; ++n) {
        const ObjectAddress cobEntry(quint16(0x1400 + n), 1);
        if (has(cobEntry) && !(u32(cobEntry) & kCobInvalid) && (u32(cobEntry) & 0x7FF) == id)
            return handleRpdo(n, frame.payload());
    }
}

// NMT (CiA 301 7.2.8.3.1): [command, node]; node 0 = all.
void SimulatedNode::handleNmt(const QByteArray &data)
{
    if (data.size() < 2 || (quint8(data.at(1)) != 0 && quint8(data.at(1)) != m_node))
        return;
    switch (NmtCommand(quint8(data.at(0)))) {
    case NmtCommand::Start:
        return setState(NmtState::Operational);
    case NmtCommand::Stop:
        m_sdo.reset();
        return setState(NmtState::Stopped);
    case NmtCommand::EnterPreOperational:
        return setState(NmtState::PreOperational);
    case NmtCommand::ResetNode:
        if (m_lss.pendingNodeId() >= kMinNodeId && m_lss.pendingNodeId() <= kMaxNodeId)
            setNodeId(m_lss.pendingNodeId());
        if (m_ownStore)
            m_ownStore->resetToDefaults();
        return bootUp();
    case NmtCommand::ResetCommunication:
        if (m_lss.pendingNodeId() >= kMinNodeId && m_lss.pendingNodeId() <= kMaxNodeId)
            setNodeId(m_lss.pendingNodeId());
        if (m_ownStore)
            m_ownStore->resetToDefaults([](ObjectAddress a) { return a.index < 0x2000; });
        return bootUp();
    }
}

// Life guarding or heartbeat event: EMCY 8130h and the NMT reaction of 1029h:01 (CiA 301
// 7.2.8.3.2; 0 = pre-operational if operational, 1 = no change, 2 = stopped).
void SimulatedNode::onCommunicationError(const QString &reason)
{
    Q_EMIT communicationLost(reason);
    constexpr quint16 kLifeGuardOrHeartbeatError = 0x8130;
    constexpr quint8 kCommunicationErrorRegister = 0x11; // generic + communication
    raiseEmergency(kLifeGuardOrHeartbeatError, kCommunicationErrorRegister);
    const quint32 reaction = u32({ 0x1029, 1 }, 0);
    if (reaction == 0 && m_state == NmtState::Operational)
        setState(NmtState::PreOperational);
    else if (reaction == 2)
        setState(NmtState::Stopped);
}

void SimulatedNode::handleLss(const QCanBusFrame &frame)
{
    m_lss.setIdentity(
        { u32({ 0x1018, 1 }), u32({ 0x1018, 2 }), u32({ 0x1018, 3 }), u32({ 0x1018, 4 }) });
    m_lss.receive(frame);
}

void SimulatedNode::setSdoDropAfter(int requests)
{
    m_dropAfter = requests;
    m_sdoRequests = 0;
}

void SimulatedNode::handleSdo(const QCanBusFrame &frame)
{
    ++m_sdoRequests;
    if (m_noReply || (m_dropAfter >= 0 && m_sdoRequests > m_dropAfter))
        return;
    const QByteArray d = frame.payload();
    const auto cmd = d.isEmpty() ? quint8(0) : quint8(d.at(0));
    const int ccs = cmd >> 5;
    const bool initiate = ccs == sdo::CcsInitiateDownload || ccs == sdo::CcsInitiateUpload
        || (ccs == sdo::CcsBlockDownload && (cmd & 1) == 0)
        || (ccs == sdo::CcsBlockUpload && (cmd & 3) == 0);
    if (initiate && d.size() >= 4 && m_sdo.state() != SdoServer::State::BlockDownload) {
        const ObjectAddress address(qFromLittleEndian<quint16>(d.constData() + 1), quint8(d.at(3)));
        if (const auto it = m_aborts.constFind(address); it != m_aborts.cend()) {
            m_sdo.reset();
            QByteArray payload = d.left(4);
            payload[0] = char(sdo::AbortByte);
            payload.resize(8);
            qToLittleEndian(*it, payload.data() + 4);
            return sdoResponse(QCanBusFrame(cob::sdoResponse(m_node), payload));
        }
    }
    m_sdo.handleRequest(frame);
}

void SimulatedNode::sdoResponse(const QCanBusFrame &frame)
{
    const QCanBusFrame out = m_garbage ? QCanBusFrame(frame.frameId(), kGarbage) : frame;
    if (m_replyDelayMs <= 0)
        return Q_EMIT transmit(out);
    QTimer::singleShot(m_replyDelayMs, this, [this, out] { Q_EMIT transmit(out); });
}

Result<void> SimulatedNode::write(ObjectAddress address, const QVariant &raw)
{
    if (auto written = m_access->write(address, raw); !written)
        return written;
    if (address.index == 0x1017 || (address.index >= 0x1800 && address.index < 0x1800 + kPdoCount)
        || (address.index >= 0x1A00 && address.index < 0x1A00 + kPdoCount))
        configureTimers();
    if (address.index == 0x100C || address.index == 0x100D || address.index == 0x1016)
        m_errorControl.configure();
    Q_EMIT objectWritten(address, raw);
    return {};
}

// ---- heartbeat, EMCY, PDO ----

void SimulatedNode::configureTimers()
{
    const quint32 period = m_started ? u32({ 0x1017, 0 }) & 0xFFFF : 0;
    if (period == 0)
        m_heartbeat.stop();
    else if (!m_heartbeat.isActive() || m_heartbeat.interval() != int(period))
        m_heartbeat.start(int(period));
    for (int n = 0; n < kPdoCount; ++n) {
        const quint16 comm = quint16(0x1800 + n);
        const quint32 cobId = u32({ comm, 1 }, kCobInvalid);
        const quint32 type = u32({ comm, 2 });
        const quint32 eventMs = u32({ comm, 5 });
        const bool run = m_state == NmtState::Operational && has({ comm, 1 })
            && !(cobId & kCobInvalid) && eventMs > 0 && PdoConfig::isEventDrivenType(type);
        QTimer *timer = m_eventTimers.at(n);
        if (!run)
            timer->stop();
        else if (!timer->isActive() || timer->interval() != int(eventMs))
            timer->start(int(eventMs));
    }
}

void SimulatedNode::handleSync()
{
    for (int n = 0; n < kPdoCount; ++n) {
        const quint16 comm = quint16(0x1800 + n);
        const quint32 type = u32({ comm, 2 });
        if (!has({ comm, 1 }) || !PdoConfig::isCyclicSyncType(type))
            continue;
        if (++m_syncCounters[n] >= int(type)) {
            m_syncCounters[n] = 0;
            sendTpdo(n);
        }
    }
}

QByteArray SimulatedNode::tpdoPayload(int n)
{
    QByteArray payload;
    const auto map = quint16(0x1A00 + n);
    const quint32 count = u32({ map, 0 });
    for (quint32 i = 1; i <= count && i <= 64; ++i) {
        const quint32 entry = u32({ map, quint8(i) });
        const ObjectAddress address(quint16(entry >> 16), quint8(entry >> 8));
        const ObjectDef *def = dictionary().find(address);
        const auto value = def ? m_access->read(address) : Result<QVariant>(QVariant());
        QByteArray bytes =
            def && value ? codec::encode(def->type, value.value()).valueOr({}) : QByteArray();
        bytes.resize((entry & 0xFF) / 8, '\0');
        payload += bytes;
    }
    return payload.left(8);
}

void SimulatedNode::sendTpdo(int n)
{
    const quint32 cobId = u32({ quint16(0x1800 + n), 1 }, kCobInvalid);
    if (m_state == NmtState::Operational && !(cobId & kCobInvalid))
        send(cobId & 0x7FF, tpdoPayload(n));
}

void SimulatedNode::handleRpdo(int n, const QByteArray &data)
{
    const auto map = quint16(0x1600 + n);
    const quint32 count = u32({ map, 0 });
    qsizetype at = 0;
    for (quint32 i = 1; i <= count && i <= 64; ++i) {
        const quint32 entry = u32({ map, quint8(i) });
        const ObjectAddress address(quint16(entry >> 16), quint8(entry >> 8));
        const qsizetype size = (entry & 0xFF) / 8;
        const ObjectDef *def = dictionary().find(address);
        if (at + size > data.size())
            return; // too short: CiA 301 would raise EMCY 8210h; the simulator just ignores it
        if (const auto raw = def ? codec::decode(def->type, data.mid(at, size))
                                 : Result<QVariant>(Error(Error::Kind::NotSupported, {}));
            raw && m_access->write(address, raw.value()))
            Q_EMIT objectWritten(address, raw.value());
        at += size;
    }
}

void SimulatedNode::raiseEmergency(quint16 code, quint8 errorRegister,
                                   const QByteArray &manufacturer)
{
    QByteArray data(3, '\0');
    qToLittleEndian(code, data.data());
    data[2] = char(errorRegister);
    data += manufacturer.left(5);
    if (m_ownStore) {
        m_ownStore->set({ 0x1001, 0 }, errorRegister);
        // 1003h: newest in sub 1, older ones move up; sub 0 = number of entries.
        int subs = 0;
        while (has({ 0x1003, quint8(subs + 1) }) && subs < 254)
            ++subs;
        for (int s = subs; s > 1; --s)
            m_ownStore->set({ 0x1003, quint8(s) }, m_ownStore->value({ 0x1003, quint8(s - 1) }));
        if (subs > 0 && code != 0) {
            m_ownStore->set({ 0x1003, 1 }, code);
            const quint32 count = m_ownStore->value({ 0x1003, 0 }).toUInt();
            m_ownStore->set({ 0x1003, 0 }, qMin<quint32>(count + 1, quint32(subs)));
        }
    }
    sendEmergency(data);
}

void SimulatedNode::sendEmergency(const QByteArray &data)
{
    const quint32 cobId = u32({ 0x1014, 0 }, cob::emcy(m_node));
    if (!m_started || m_state == NmtState::Stopped || (cobId & kCobInvalid))
        return;
    QByteArray payload = data.left(8);
    payload.append(QByteArray(8 - payload.size(), '\0'));
    send(cobId & 0x7FF, payload);
}

quint32 SimulatedNode::u32(ObjectAddress address, quint32 fallback)
{
    if (!has(address))
        return fallback;
    const auto value = m_access->read(address);
    return value ? quint32(value.value().toULongLong()) : fallback;
}

void SimulatedNode::send(quint32 id, const QByteArray &data)
{
    Q_EMIT transmit(QCanBusFrame(id, data));
}

} // namespace db::canopen
