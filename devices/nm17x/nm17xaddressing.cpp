#include "nm17xaddressing.h"

#include "nm17xdescription.h"

#include "canopen/lss.h"

#include <QCoreApplication>
#include <QtEndian>

namespace db::nm17x {

using namespace db::canopen;

namespace {
constexpr quint32 kAnyIdentity = 0xFFFFFFFFu;

QByteArray lssFrame(quint8 cs, quint32 value = 0, bool withValue = false, quint8 byte1 = 0)
{
    QByteArray d(8, '\0');
    d[0] = char(cs);
    if (withValue)
        qToLittleEndian(value, d.data() + 1);
    else
        d[1] = char(byte1);
    return d;
}
} // namespace

BroadcastAddressing::BroadcastAddressing(CanNetwork *network, QObject *parent)
    : QObject(parent)
    , m_network(network)
{
    m_timer.setSingleShot(true);
    connect(&m_timer, &QTimer::timeout, this, &BroadcastAddressing::onTimeout);
    network->subscribe(cob::LssSlave, this, [this](const QCanBusFrame &f) { onFrame(f); });
}

bool BroadcastAddressing::send(quint32 id, const QByteArray &payload)
{
    return m_network->send(QCanBusFrame(id, payload));
}

Result<void> BroadcastAddressing::start(NodeId first, int count)
{
    if (m_state == State::Offering || m_state == State::Finishing)
        return Error(Error::Kind::Busy, tr("broadcast addressing is already running"));
    if (first < kMinNodeId || first > kMaxNodeId || count < 0
        || first + qMax(count, 1) - 1 > kMaxNodeId)
        return Error(
            Error::Kind::InvalidArgument,
            tr("node ids %1.. for %2 displays do not fit into 1..127").arg(first).arg(count));
    m_assigned.clear();
    m_error = {};
    m_next = first;
    m_count = count;
    const bool sent = send(cob::Nmt, QByteArray::fromHex("0200"))
        && send(cob::LssMaster, QByteArray::fromHex("0401"))
        && send(cob::LssMaster, lssFrame(lss::SelectVendor, kVendorId, true))
        && send(cob::LssMaster, lssFrame(lss::SelectVendor + 1, kAnyIdentity, true))
        && send(cob::LssMaster, lssFrame(lss::SelectVendor + 2, kAnyIdentity, true))
        && send(cob::LssMaster, lssFrame(lss::SelectSerial, kAnyIdentity, true));
    if (!sent)
        return Error(Error::Kind::Disconnected,
                     tr("the CAN bus %1 is not open").arg(m_network->name()));
    m_state = State::Offering;
    offer();
    return {};
}

void BroadcastAddressing::offer()
{
    send(cob::LssMaster, lssFrame(lss::ConfigureNodeId, 0, false, m_next));
    m_timer.start(m_stepTimeoutMs);
    Q_EMIT offering(m_next);
}

void BroadcastAddressing::onFrame(const QCanBusFrame &frame)
{
    const QByteArray d = frame.payload();
    if (m_state != State::Offering || d.size() < 2 || quint8(d.at(0)) != lss::ConfigureNodeId)
        return;
    m_timer.stop();
    if (quint8(d.at(1)) != 0)
        return finish(Error(
            Error::Kind::DeviceError,
            tr("a display refused node id %1 (LSS error %2)").arg(m_next).arg(quint8(d.at(1))),
            quint8(d.at(1))));
    m_assigned.append(m_next);
    Q_EMIT assigned(m_next);
    if ((m_count > 0 && m_assigned.size() == m_count) || m_next == kMaxNodeId)
        return finish();
    ++m_next;
    offer();
}

void BroadcastAddressing::onTimeout()
{
    if (m_state != State::Offering)
        return;
    if (m_count == 0 && !m_assigned.isEmpty())
        return finish();
    finish(Error(
        Error::Kind::Timeout,
        tr("no display took node id %1 within %2 s").arg(m_next).arg(m_stepTimeoutMs / 1000.0)));
}

void BroadcastAddressing::cancel()
{
    if (m_state == State::Offering)
        finish();
}

void BroadcastAddressing::finish(const Error &error)
{
    m_timer.stop();
    m_state = State::Finishing;
    send(cob::LssMaster, QByteArray::fromHex("0400"));
    send(cob::Nmt, QByteArray::fromHex("8100"));
    m_error = error;
    m_state = error.isError() ? State::Failed : State::Done;
    QMetaObject::invokeMethod(
        this, [this] { Q_EMIT finished(m_state == State::Done); }, Qt::QueuedConnection);
}

} // namespace db::nm17x
