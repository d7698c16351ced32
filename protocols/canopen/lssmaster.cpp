#include "lssmaster.h"

#include "canopenlogging.h"
#include "transport/canbus.h"

#include <QCanBusFrame>
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

quint32 LssAddress::part(int i) const
{
    switch (i) {
    case 0:
        return vendorId;
    case 1:
        return productCode;
    case 2:
        return revision;
    default:
        return serial;
    }
}

QString LssAddress::toString() const
{
    const auto hex = [](quint32 v) {
        return QStringLiteral("0x%1").arg(v, 8, 16, QLatin1Char('0'));
    };
    return QStringLiteral("vendor %1 product %2 revision %3 serial %4")
        .arg(hex(vendorId), hex(productCode), hex(revision), hex(serial));
}

namespace lss {

namespace {
constexpr int kTable[] = { 1000000, 800000, 500000, 250000, 125000, 100000, 50000, 20000, 10000 };
}

int bitTimingIndex(int bitrate)
{
    for (int i = 0; i < 9; ++i) {
        if (kTable[i] == bitrate)
            return i;
    }
    return -1;
}

int bitrateOfIndex(int index)
{
    return index >= 0 && index < 9 ? kTable[index] : -1;
}

} // namespace lss

namespace {

QByteArray u32(quint32 v)
{
    QByteArray b(4, '\0');
    qToLittleEndian(v, b.data());
    return b;
}

} // namespace

LssMaster::LssMaster(CanBus *bus, QObject *parent)
    : QObject(parent)
    , m_bus(bus)
{
    m_timer.setSingleShot(true);
    connect(&m_timer, &QTimer::timeout, this, &LssMaster::onTimeout);
    connect(bus, &CanBus::frameReceived, this, &LssMaster::onFrame);
}

QCanBusFrame LssMaster::frame(quint8 cs, const QByteArray &data, int compactLength) const
{
    QByteArray payload = QByteArray(1, char(cs)) + data;
    payload.resize(m_frameLength == FrameLength::Full ? 8 : qMax(compactLength, 1), '\0');
    return QCanBusFrame(cob::LssMaster, payload);
}

void LssMaster::send(quint8 cs, const QByteArray &data, int compactLength)
{
    m_bus->send(frame(cs, data, compactLength));
}

bool LssMaster::switchModeGlobal(LssMode mode)
{
    if (!m_bus->isOpen())
        return false;
    send(lss::SwitchGlobal, QByteArray(1, char(mode)), 2);
    return true;
}

Reply *LssMaster::begin(Op op, quint8 answerCs)
{
    auto *reply = new Reply(ObjectAddress(0, 0));
    if (isBusy()) {
        reply->fail(Error(Error::Kind::Busy, Tr::tr("another LSS service is running")));
        return reply;
    }
    if (!m_bus->isOpen()) {
        reply->fail(
            Error(Error::Kind::Disconnected, Tr::tr("CAN bus %1 is not open").arg(m_bus->name())));
        return reply;
    }
    m_reply = reply;
    m_op = op;
    m_answerCs = answerCs;
    m_timer.start(op == Op::Fastscan ? m_fastscanStepMs : m_timeoutMs);
    return reply;
}

Reply *LssMaster::switchModeSelective(const LssAddress &address)
{
    Reply *reply = begin(Op::Confirm, lss::SelectiveAnswer);
    if (m_reply != reply)
        return reply;
    for (int i = 0; i < 4; ++i)
        send(quint8(lss::SelectVendor + i), u32(address.part(i)), 8);
    return reply;
}

Reply *LssMaster::configureNodeId(NodeId node)
{
    if (!((node >= kMinNodeId && node <= kMaxNodeId) || node == lss::kUnconfigured))
        return Reply::failed(
            {}, Error(Error::Kind::OutOfRange, Tr::tr("LSS node id %1 is not 1..127").arg(node)));
    Reply *reply = begin(Op::Confirm, lss::ConfigureNodeId);
    if (m_reply == reply)
        send(lss::ConfigureNodeId, QByteArray(1, char(node)), 2);
    return reply;
}

Reply *LssMaster::configureBitTiming(quint8 tableIndex, quint8 tableSelector)
{
    Reply *reply = begin(Op::Confirm, lss::ConfigureBitTiming);
    if (m_reply == reply) {
        QByteArray data;
        data.append(char(tableSelector)).append(char(tableIndex));
        send(lss::ConfigureBitTiming, data, 3);
    }
    return reply;
}

bool LssMaster::activateBitTiming(quint16 switchDelayMs)
{
    if (!m_bus->isOpen())
        return false;
    QByteArray data(2, '\0');
    qToLittleEndian(switchDelayMs, data.data());
    send(lss::ActivateBitTiming, data, 3);
    return true;
}

Reply *LssMaster::storeConfiguration()
{
    Reply *reply = begin(Op::Confirm, lss::StoreConfiguration);
    if (m_reply == reply)
        send(lss::StoreConfiguration, QByteArray(1, '\0'), 2);
    return reply;
}

Reply *LssMaster::inquire(quint8 cs)
{
    if (cs < lss::InquireVendor || cs > lss::InquireNodeId)
        return Reply::failed({},
                             Error(Error::Kind::InvalidArgument,
                                   Tr::tr("0x%1 is no LSS inquire service").arg(cs, 0, 16)));
    Reply *reply = begin(Op::Inquire, cs);
    if (m_reply == reply)
        send(cs, {}, 1);
    return reply;
}

Reply *LssMaster::fastscan()
{
    Reply *reply = begin(Op::Fastscan, lss::FastscanAnswer);
    if (m_reply != reply)
        return reply;
    std::fill(std::begin(m_id), std::end(m_id), 0u);
    m_sub = 0;
    m_bit = -1;
    fastscanSend();
    return reply;
}

// Graph: reset (BitChecked 80h) -> for part 0..3: probe bit 31..0 (answer: bit is 0, silence:
// bit is 1) -> confirm the part with LSSNext = next part -> after part 3 the slave is selected.
void LssMaster::fastscanSend()
{
    QByteArray data = u32(m_bit < 0 ? 0 : m_id[m_sub]);
    const quint8 bitChecked = m_bit < 0 ? lss::kFastscanReset : m_bit == 32 ? 0 : quint8(m_bit);
    const int next = m_bit == 32 ? (m_sub + 1) % 4 : m_sub;
    data.append(char(bitChecked)).append(char(m_sub)).append(char(next));
    send(lss::Fastscan, data, 8);
    m_timer.start(m_fastscanStepMs);
}

void LssMaster::fastscanStep(bool answered)
{
    if (m_bit < 0) {
        if (!answered)
            return finish(Error(Error::Kind::Timeout,
                                Tr::tr("no unconfigured LSS slave answered the fastscan")));
        m_bit = 31;
    } else if (m_bit == 32) {
        if (!answered)
            return finish(Error(Error::Kind::Malformed,
                                Tr::tr("the LSS slave stopped answering during fastscan")));
        if (m_sub == 3) {
            const LssAddress found { m_id[0], m_id[1], m_id[2], m_id[3] };
            return finish({}, QVariant::fromValue(found));
        }
        ++m_sub;
        m_bit = 31;
    } else {
        if (!answered)
            m_id[m_sub] |= 1u << m_bit;
        m_bit = m_bit == 0 ? 32 : m_bit - 1;
    }
    fastscanSend();
}

void LssMaster::onFrame(const QCanBusFrame &frame)
{
    const QByteArray d = frame.payload();
    if (frame.frameId() != cob::LssSlave || d.isEmpty() || !m_reply
        || quint8(d.at(0)) != m_answerCs)
        return;
    m_timer.stop();
    const QByteArray p = d.size() < 8 ? d + QByteArray(8 - d.size(), '\0') : d;
    switch (m_op) {
    case Op::Fastscan:
        return fastscanStep(true);
    case Op::Inquire:
        return finish(
            {},
            QVariant::fromValue<qulonglong>(m_answerCs == lss::InquireNodeId
                                                ? quint8(p.at(1))
                                                : qFromLittleEndian<quint32>(p.constData() + 1)));
    case Op::Confirm:
        if (m_answerCs != lss::SelectiveAnswer && quint8(p.at(1)) != 0) {
            const quint8 code = quint8(p.at(1));
            return finish(Error(
                Error::Kind::DeviceError,
                Tr::tr("LSS slave refused (error code %1%2)")
                    .arg(code)
                    .arg(code == 1 ? QStringLiteral(": out of range / not supported") : QString()),
                code));
        }
        return finish({});
    case Op::None:
        return;
    }
}

void LssMaster::onTimeout()
{
    if (m_op == Op::Fastscan)
        return fastscanStep(false);
    finish(Error(Error::Kind::Timeout,
                 Tr::tr("no LSS answer (cs 0x%1) within %2 ms on %3")
                     .arg(m_answerCs, 2, 16, QLatin1Char('0'))
                     .arg(m_timeoutMs)
                     .arg(m_bus->name())));
}

void LssMaster::finish(const Error &error, const QVariant &value)
{
    m_timer.stop();
    QPointer<Reply> reply = m_reply;
    m_reply = nullptr;
    m_op = Op::None;
    if (!reply)
        return;
    if (error.isError())
        reply->fail(error);
    else
        reply->finish(value);
}

} // namespace db::canopen
