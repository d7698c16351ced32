#include "simulatednm17x.h"

#include "devices/nm17x/nm17xcodes.h"

#include "canopen/lss.h"
#include "canopen/sdoabort.h"
#include "canopen/storesignatures.h"

#include <QtEndian>

namespace db::nm17x {

using namespace db::canopen;

namespace {
constexpr quint32 kCobInvalid = 0x80000000u;
constexpr quint32 kRevision = 0x00010001;
constexpr quint8 kLssOk = 0;
constexpr quint8 kLssOutOfRange = 1;
constexpr quint32 kBroadcastIdentity = 0xFFFFFFFFu;
constexpr quint16 kHeartbeatError = 0x8130;
constexpr quint8 kRegGeneric = 0x01;
constexpr quint8 kRegCommunication = 0x10;
constexpr quint8 kRegManufacturer = 0x80;
// The communication objects whose COB-ID follows the node id (and 1014h, which we let follow
// too while it has its default form).
constexpr ObjectAddress kNodeCobIds[] = {
    { 0x1014, 0 }, { 0x1401, 1 }, { 0x1800, 1 }, { 0x1801, 1 }
};

ObjectDictionary withoutRanges(ObjectDictionary d)
{
    ObjectDictionary view;
    view.identity = d.identity;
    for (ObjectDef def : d.objects()) {
        def.minimum = {};
        def.maximum = {};
        view.insert(def);
    }
    return view;
}
} // namespace

SimulatedNm17x::SimulatedNm17x(Variant variant, quint32 serial, NodeId node, QObject *parent)
    : QObject(parent)
    , m_variant(variant)
    , m_serial(serial)
    , m_node(node)
    , m_dictionary(nm17x::dictionary(variant, node))
    , m_serverView(withoutRanges(m_dictionary))
    , m_store(std::make_unique<ObjectValueStore>(m_dictionary))
    , m_sdo(this, node)
    , m_errorControl(this)
    , m_spindle(hasMotor(variant))
{
    m_store->set({ 0x1018, 3 }, kRevision);
    m_store->set({ 0x1018, 4 }, serial);
    m_store->set({ 0x1009, 0 }, QStringLiteral("/A"));
    m_store->set({ 0x100A, 0 }, QStringLiteral("1.05"));
    m_store->set({ 0x2006, 1 }, 105);
    m_store->set({ 0x2101, 0 }, node);
    m_flash.insert({ 0x2101, 0 }, node);
    m_lss.setIdentity({ kVendorId, productCode(variant), kRevision, serial });
    m_lss.setActiveNodeId(node);
    m_errorControl.setNodeId(node);
    connect(&m_sdo, &SdoServer::response, this, &SimulatedNm17x::transmit);
    connect(&m_lss, &LssSlave::transmit, this, &SimulatedNm17x::transmit);
    connect(&m_lss, &LssSlave::configurationStored, this, [this](quint8 id, int bitTiming) {
        if (id >= kMinNodeId && id <= kMaxNodeId)
            setValue({ 0x2101, 0 }, id);
        if (bitTiming >= 0 && bitTiming <= 8)
            setValue({ 0x2100, 0 }, 8 - bitTiming); // 2100h counts up from 10 kbit/s
    });
    connect(&m_errorControl, &ErrorControlSlave::transmit, this, &SimulatedNm17x::transmit);
    connect(&m_errorControl, &ErrorControlSlave::lost, this, [this] {
        m_spindle.stop();
        raiseEmergency(kHeartbeatError, 0);
        const quint32 reaction = u32({ 0x1029, 1 });
        if (reaction == 0 && m_state == NmtState::Operational)
            setState(NmtState::PreOperational);
        else if (reaction == 2)
            setState(NmtState::Stopped);
    });
    connect(&m_heartbeat, &QTimer::timeout, this,
            [this] { send(cob::heartbeat(m_node), QByteArray(1, char(m_state))); });
    m_cycle.setInterval(kCycleMs);
    connect(&m_cycle, &QTimer::timeout, this, &SimulatedNm17x::cycle);
}

SimulatedNm17x::~SimulatedNm17x() = default;

void SimulatedNm17x::start()
{
    m_started = true;
    m_cycle.start();
    bootUp();
}

void SimulatedNm17x::bootUp()
{
    m_sdo.reset();
    m_errorControl.configure();
    m_errorControl.reset();
    m_state = NmtState::BootUp;
    send(cob::heartbeat(m_node), QByteArray(1, '\0'));
    setState(u32({ 0x1F80, 0 }) == 8 ? NmtState::Operational : NmtState::PreOperational);
}

void SimulatedNm17x::setState(NmtState state)
{
    // A lower state ends a positioning; Pre-operational -> Operational does not.
    if ((state == NmtState::Stopped)
        || (state == NmtState::PreOperational && m_state == NmtState::Operational))
        m_spindle.stop();
    m_state = state;
    const quint32 period = u32({ 0x1017, 0 }) & 0xFFFF;
    if (period == 0)
        m_heartbeat.stop();
    else if (!m_heartbeat.isActive() || m_heartbeat.interval() != int(period))
        m_heartbeat.start(int(period));
    for (int n = 0; n < 2; ++n) {
        m_lastTpdo[n].clear(); // the first PDO after entering Operational goes out
        m_sinceTpdoMs[n] = 1 << 20;
    }
}

void SimulatedNm17x::applyNodeId(NodeId node)
{
    const NodeId old = m_node;
    m_node = node;
    m_sdo.setNodeId(node);
    m_lss.setActiveNodeId(node);
    m_errorControl.setNodeId(node);
    if (old == node)
        return;
    for (const ObjectAddress a : kNodeCobIds) {
        const quint32 v = u32(a);
        if ((v & 0x7F) == old)
            setValue(a, (v & ~0x7Fu) | node);
    }
    Q_EMIT nodeIdChanged(node);
}

// Reset node (application) or reset communication: a pending node id (2101h, LSS) and a pending
// restore (1011h) take effect; the communication objects come back from flash.
void SimulatedNm17x::resetNode(bool application)
{
    if (m_restorePending) {
        m_restorePending = false;
        m_flash.clear();
        m_flash.insert({ 0x2101, 0 }, kDeliveryNodeId);
        m_flash.insert({ 0x2100, 0 }, m_dictionary.find({ 0x2100, 0 })->defaultValue);
    }
    // Communication objects not saved by 1010h come back with their defaults.
    const ObjectDictionary current = nm17x::dictionary(m_variant, m_node);
    for (const ObjectDef &def : current.objects()) {
        const quint16 i = def.address.index;
        if (i < 0x2000 && def.writable() && i != 0x1003 && i != 0x1010 && i != 0x1011)
            m_store->set(def.address, m_flash.value(def.address, def.defaultValue));
    }
    for (const ObjectAddress a : { ObjectAddress(0x2100, 0), ObjectAddress(0x2101, 0) }) {
        if (m_flash.contains(a))
            m_store->set(a, m_flash.value(a));
    }
    NodeId node = NodeId(m_flash.value({ 0x2101, 0 }, m_node).toUInt());
    if (m_lss.pendingNodeId() != m_node && m_lss.pendingNodeId() >= kMinNodeId
        && m_lss.pendingNodeId() <= kMaxNodeId)
        node = m_lss.pendingNodeId();
    applyNodeId(node);
    m_addressing = false;
    m_addressedByBroadcast = false;
    m_offered = 0;
    m_broadcastStep = 0;
    if (application) {
        m_spindle.stop();
        m_oscillating = false;
        m_d3Released = false; // D3 is 0 and locked after power-on
        m_externPosiRunning = false;
        m_writes.clear();
        m_showNodeId = false;
        for (const ObjectDef &def : m_dictionary.objects()) {
            if (storageOf(def.address) == Storage::Ram || def.address.index == 0x2500
                || def.address.index == 0x2501 || def.address.index == 0x1003)
                m_store->set(def.address, def.defaultValue.isValid() ? def.defaultValue : 0);
        }
        if (m_dictionary.contains({ 0x2020, 3 })) {
            m_store->set({ 0x2020, 3 }, m_store->value({ 0x2020, 1 }));
            m_store->set({ 0x2020, 6 }, m_store->value({ 0x2020, 1 }));
        }
        m_store->set({ 0x1001, 0 }, 0);
    }
    bootUp();
}

void SimulatedNm17x::receive(const QCanBusFrame &frame)
{
    if (!m_started || frame.frameType() != QCanBusFrame::DataFrame
        || frame.hasExtendedFrameFormat())
        return;
    // A frame the display acts on wakes its cycle; other nodes' traffic does not.
    if (m_errorControl.receive(frame, m_state))
        return wake();
    const quint32 id = frame.frameId();
    const QByteArray d = frame.payload();
    if (id == cob::Nmt) {
        wake();
        return handleNmt(d);
    }
    if (id == cob::LssMaster) {
        wake();
        return handleLss(frame); // every NMT state
    }
    if (id == cob::LssSlave && m_addressing && d.size() >= 2
        && quint8(d.at(0)) == lss::ConfigureNodeId && d.at(1) == 0) {
        m_offered = 0; // another display took the offered id; wait for the next offer
        return;
    }
    if (id == cob::sdoRequest(m_node)) {
        wake();
        if (m_state != NmtState::Stopped)
            m_sdo.handleRequest(frame);
        return;
    }
    if (m_state != NmtState::Operational)
        return;
    if (id == (u32({ 0x1005, 0 }) & 0x7FF)) {
        wake();
        return sendTpdos(true);
    }
    const quint32 rpdo1 = u32({ 0x1400, 1 });
    const quint32 rpdo2 = u32({ 0x1401, 1 });
    if (!(rpdo1 & kCobInvalid) && id == (rpdo1 & 0x7FF)) {
        wake();
        return handleBroadcast(d);
    }
    if (!(rpdo2 & kCobInvalid) && id == (rpdo2 & 0x7FF)) {
        wake();
        return handleRpdo2(d);
    }
}

void SimulatedNm17x::handleNmt(const QByteArray &d)
{
    if (d.size() < 2 || (quint8(d.at(1)) != 0 && quint8(d.at(1)) != m_node))
        return;
    switch (NmtCommand(quint8(d.at(0)))) {
    case NmtCommand::Start:
        return setState(NmtState::Operational);
    case NmtCommand::Stop:
        m_sdo.reset();
        return setState(NmtState::Stopped);
    case NmtCommand::EnterPreOperational:
        return setState(NmtState::PreOperational);
    case NmtCommand::ResetNode:
        return resetNode(true);
    case NmtCommand::ResetCommunication:
        return resetNode(false);
    }
}

// CiA 305 through the LssSlave, plus the device's broadcast addressing: 40h with the vendor id,
// then 41h, 42h, 43h each with FFFFFFFFh put every display into addressing mode (no answer);
// "11 nn" offers node id nn, and the display whose shaft is turned (or key pressed) takes it and
// answers "11 00". A display that took an id ignores further offers until it leaves
// configuration mode or is reset.
void SimulatedNm17x::handleLss(const QCanBusFrame &frame)
{
    const QByteArray d = frame.payload();
    if (d.isEmpty())
        return;
    const quint8 cs = quint8(d.at(0));
    const quint32 value = d.size() >= 5 ? qFromLittleEndian<quint32>(d.constData() + 1) : 0;
    if (cs >= lss::SelectVendor && cs <= lss::SelectSerial) {
        const int part = cs - lss::SelectVendor;
        const bool match = part == 0 ? value == kVendorId : value == kBroadcastIdentity;
        m_broadcastStep = (part == m_broadcastStep && match) ? m_broadcastStep + 1 : 0;
        if (m_broadcastStep == 4) {
            m_broadcastStep = 0;
            m_addressing = true;
            m_addressedByBroadcast = false;
            m_offered = 0;
            return;
        }
    }
    if (cs == lss::SwitchGlobal && d.size() >= 2 && quint8(d.at(1)) == 0) {
        m_addressing = false;
        m_addressedByBroadcast = false;
        m_offered = 0;
    }
    if (cs == lss::ConfigureNodeId && (m_addressing || m_addressedByBroadcast)) {
        if (!m_addressing || d.size() < 2)
            return;
        const quint8 node = quint8(d.at(1));
        if (node < kMinNodeId || node > kMaxNodeId)
            return lssAnswer(lss::ConfigureNodeId, kLssOutOfRange);
        m_offered = node; // shown in the upper line; the operator picks the display
        return;
    }
    m_lss.receive(frame);
}

bool SimulatedNm17x::selectForAddressing()
{
    if (!m_addressing || m_offered == 0)
        return false;
    setValue({ 0x2101, 0 }, m_offered); // non-volatile at once, active after Reset Node
    m_addressing = false;
    m_addressedByBroadcast = true;
    m_offered = 0;
    lssAnswer(lss::ConfigureNodeId, kLssOk);
    return true;
}

void SimulatedNm17x::lssAnswer(quint8 cs, quint8 code)
{
    QByteArray payload(8, '\0');
    payload[0] = char(cs);
    payload[1] = char(code);
    send(cob::LssSlave, payload);
}

void SimulatedNm17x::turnShaft(double delta)
{
    wake();
    if (selectForAddressing())
        return;
    m_spindle.turnByHand(delta, settings());
}

void SimulatedNm17x::pressKey(int direction, int ms)
{
    wake();
    if (selectForAddressing() || !hasMotor(m_variant))
        return;
    if (m_spindle.isMoving())
        return m_spindle.abortByKey();
    constexpr int kShortPressMs = 400;
    const int counting = u32({ 0x2040, 1 }) == 0 ? direction : -direction;
    if (ms >= kShortPressMs) {
        // A held key runs the motor until it is let go, at the speed of the key mode 2041h:04
        // (1 slow, 2 middle, 3 fast; 0 standard: slow, our reading of "slow and fast, switched by
        // briefly releasing the key" for one press). The press (status bits 5/6) lasts ms.
        const quint32 mode = u32({ 0x2041, 4 });
        m_keyDown = direction;
        m_spindle.jog(counting, mode == 0 ? Speed::Slow : Speed(mode), settings());
        QTimer::singleShot(ms, this, [this, direction] {
            if (m_keyDown != direction)
                return;
            m_keyDown = 0;
            if (m_spindle.isJogging())
                m_spindle.stop();
        });
        return;
    }
    {
        // Jog step (2046h; 0 = 50) in the direction the key counts, when 2040h:03 allows it.
        const quint32 activation = u32({ 0x2040, 3 });
        const bool allowed = activation == 2 || (activation == 0 && counting > 0)
            || (activation == 1 && counting < 0);
        if (!allowed)
            return;
        const qint32 width = qint32(u32({ 0x2046, 0 })) == 0 ? 50 : qint32(u32({ 0x2046, 0 }));
        const qint32 off = qint32(u32({ 0x2042, 3 }));
        const qint32 step = off >= width ? 1 : width - off;
        const SpindleSettings s = settings();
        m_spindle.start(qint32(qRound(m_spindle.position())) + counting * step, false, {}, s);
    }
}

void SimulatedNm17x::cycle()
{
    // One queued SDO write reaches the application per cycle.
    if (!m_writes.isEmpty()) {
        const auto [address, raw] = m_writes.dequeue();
        applyWrite(address, raw);
    }
    m_spindle.tick(kCycleMs, settings());
    if (const auto switchOff = m_spindle.takeSwitchOff())
        m_store->set({ 0x2042, 3 }, *switchOff); // dynamic pre-shutdown
    readSensor();
    oscillate();
    followExternPosi();
    const quint16 errors = errorWord();
    const quint8 reg = quint8(m_store->value({ 0x1001, 0 }).toUInt());
    m_store->set({ 0x1001, 0 }, errors ? (reg | kRegManufacturer) : (reg & ~kRegManufacturer));
    const bool correctionOn = u32({ 0x2000, 6 }) != 0;
    const qint32 correction = m_store->value({ 0x2010, 0 }).toInt();
    m_store->set({ 0x2501, 4 }, quint16(correctionOn ? qBound(-32768, correction, 32767) : 0));
    for (int n = 0; n < 2; ++n)
        m_sinceTpdoMs[n] = qMin(m_sinceTpdoMs[n] + kCycleMs, 1 << 20);
    if (m_state == NmtState::Operational)
        sendTpdos(false);
    if (resting()) {
        m_cycle.stop();
        m_restClock.start();
    }
}

// A cycle that would change nothing: no queued write, the spindle still, no disturbance, no
// oscillation or key, and no TxPDO waiting for its inhibit time or sent by its event timer.
bool SimulatedNm17x::resting() const
{
    if (!m_writes.isEmpty() || !m_spindle.resting() || m_glitchSteps != 0 || m_acceptedGlitch != 0
        || m_glitchReadings != 0 || m_discarded != 0 || m_oscillating || m_externPosiRunning
        || m_keyDown != 0)
        return false;
    if (m_state != NmtState::Operational)
        return true;
    const auto payloads = tpdoPayloads();
    for (int n = 0; n < 2; ++n) {
        const auto comm = quint16(0x1800 + n);
        if (u32({ comm, 1 }) & kCobInvalid)
            continue;
        const quint32 type = u32({ comm, 2 });
        if (type == 0xFE && u32({ comm, 5 }) > 0)
            return false;
        if (type == 0xFF && payloads[n] != m_lastTpdo[n])
            return false;
    }
    return true;
}

void SimulatedNm17x::wake()
{
    if (!m_started || m_cycle.isActive())
        return;
    // The cycles of the rest count for the TxPDO inhibit and event times.
    const int restedMs = int(qMin<qint64>(m_restClock.elapsed(), 1 << 20)) / kCycleMs * kCycleMs;
    for (int n = 0; n < 2; ++n)
        m_sinceTpdoMs[n] = qMin(m_sinceTpdoMs[n] + restedMs, 1 << 20);
    m_cycle.start();
}

std::array<QByteArray, 2> SimulatedNm17x::tpdoPayloads() const
{
    const qint32 pos = position();
    const quint16 status = statusWord();
    return {
        encodeTpdo1({ pos, status, errorWord() }),
        encodeTpdo2({ pos, qint16(m_store->value({ 0x2501, 4 }).toUInt()), status }),
    };
}

// TxPDO1/TxPDO2: 0xFF on change of data (event timer ignored), 0xFE cyclic per event timer,
// both no more often than the inhibit time (ms); 1..240 every n-th SYNC.
void SimulatedNm17x::sendTpdos(bool sync)
{
    const auto payloads = tpdoPayloads();
    for (int n = 0; n < 2; ++n) {
        const auto comm = quint16(0x1800 + n);
        const quint32 cobId = u32({ comm, 1 });
        if (cobId & kCobInvalid)
            continue;
        const quint32 type = u32({ comm, 2 });
        const int inhibit = int(u32({ comm, 3 }));
        const int event = int(u32({ comm, 5 }));
        bool due = false;
        if (sync) {
            due = type >= 1 && type <= 240 && ++m_syncCount[n] >= int(type);
            if (due)
                m_syncCount[n] = 0;
        } else if (type == 0xFF) {
            due = payloads[n] != m_lastTpdo[n] && m_sinceTpdoMs[n] >= inhibit;
        } else if (type == 0xFE) {
            due = event > 0 && m_sinceTpdoMs[n] >= qMax(event, inhibit);
        }
        if (!due)
            continue;
        m_lastTpdo[n] = payloads[n];
        m_sinceTpdoMs[n] = 0;
        send(cobId & 0x7FF, payloads[n]);
    }
}

// EMCY: code (LE), error register 1001h, four unused bytes, the sub-code in byte 7. The history
// 1003h keeps code | sub-code << 16, newest first.
void SimulatedNm17x::raiseEmergency(quint16 code, quint8 subCode)
{
    quint8 reg = quint8(m_store->value({ 0x1001, 0 }).toUInt()) | kRegGeneric;
    if ((code & 0xFF00) == 0x8100)
        reg |= kRegCommunication;
    m_store->set({ 0x1001, 0 }, reg);
    for (int s = 8; s > 1; --s)
        m_store->set({ 0x1003, quint8(s) }, m_store->value({ 0x1003, quint8(s - 1) }));
    m_store->set({ 0x1003, 1 }, quint32(code) | (quint32(subCode) << 16));
    m_store->set({ 0x1003, 0 }, qMin(m_store->value({ 0x1003, 0 }).toUInt() + 1, 8u));
    const quint32 cobId = u32({ 0x1014, 0 });
    if (!m_started || m_state == NmtState::Stopped || (cobId & kCobInvalid))
        return;
    QByteArray payload(8, '\0');
    qToLittleEndian(code, payload.data());
    payload[2] = char(reg);
    payload[7] = char(subCode);
    send(cobId & 0x7FF, payload);
}

void SimulatedNm17x::send(quint32 id, const QByteArray &data)
{
    Q_EMIT transmit(QCanBusFrame(id, data));
}

quint32 SimulatedNm17x::u32(ObjectAddress address) const
{
    return quint32(m_store->value(address).toULongLong());
}

void SimulatedNm17x::setValue(ObjectAddress address, const QVariant &raw)
{
    m_store->set(address, raw);
    if (storageOf(address) == Storage::Flash
        && (address.index == 0x2100 || address.index == 0x2101))
        m_flash.insert(address, m_store->value(address)); // flashed at once
}

} // namespace db::nm17x
