#include "lssslave.h"

#include "canopen/canopenids.h"

#include <QtEndian>

namespace db::canopen {

namespace {
constexpr quint8 kOk = 0;
constexpr quint8 kOutOfRange = 1;
constexpr int kTableSize = 9; // TableSel 0: indices 0..8 (9 = auto detection, not offered)
} // namespace

LssSlave::LssSlave(QObject *parent)
    : QObject(parent)
{ }

void LssSlave::setActiveNodeId(quint8 node)
{
    m_active = node;
    m_pending = node;
}

void LssSlave::answer(quint8 cs, quint8 b1, quint32 value, bool withValue)
{
    QByteArray payload(8, '\0');
    payload[0] = char(cs);
    if (withValue)
        qToLittleEndian(value, payload.data() + 1);
    else
        payload[1] = char(b1);
    Q_EMIT transmit(QCanBusFrame(cob::LssSlave, payload));
}

void LssSlave::receive(const QCanBusFrame &frame)
{
    if (frame.frameId() != cob::LssMaster || frame.frameType() != QCanBusFrame::DataFrame)
        return;
    const QByteArray d = frame.payload();
    if (d.isEmpty())
        return;
    const quint8 cs = quint8(d.at(0));
    const bool config = m_mode == LssMode::Configuration;
    const auto value = [&d] {
        return d.size() >= 5 ? qFromLittleEndian<quint32>(d.constData() + 1) : 0u;
    };

    if (cs >= lss::SelectVendor && cs <= lss::SelectSerial) {
        // The four parts in order; any mismatch or gap starts over (CiA 305 8.3.2.1).
        const int part = cs - lss::SelectVendor;
        m_selectStep = (part == m_selectStep && d.size() >= 5 && value() == m_identity.part(part))
            ? m_selectStep + 1
            : 0;
        if (m_selectStep == 4) {
            m_selectStep = 0;
            m_mode = LssMode::Configuration;
            answer(lss::SelectiveAnswer); // 44 00 00 00 00 00 00 00 (nm170_canopen.md 2.4 step 7)
        }
        return;
    }
    switch (cs) {
    case lss::SwitchGlobal:
        if (d.size() < 2 || quint8(d.at(1)) > 1)
            return;
        if (LssMode(quint8(d.at(1))) == LssMode::Waiting && config && m_active == lss::kUnconfigured
            && m_pending != lss::kUnconfigured) {
            m_active = m_pending;
            Q_EMIT nodeIdActivated(m_active);
        }
        m_mode = LssMode(quint8(d.at(1)));
        return;
    case lss::ConfigureNodeId:
        if (!config || d.size() < 2)
            return;
        {
            const quint8 node = quint8(d.at(1));
            const bool valid =
                (node >= kMinNodeId && node <= kMaxNodeId) || node == lss::kUnconfigured;
            if (valid)
                m_pending = node;
            return answer(lss::ConfigureNodeId, valid ? kOk : kOutOfRange);
        }
    case lss::ConfigureBitTiming:
        if (!config || d.size() < 3)
            return;
        if (quint8(d.at(1)) != 0 || quint8(d.at(2)) >= kTableSize)
            return answer(lss::ConfigureBitTiming, kOutOfRange);
        m_bitTiming = quint8(d.at(2));
        return answer(lss::ConfigureBitTiming, kOk);
    case lss::ActivateBitTiming:
        return; // a simulated bus has no bit rate to switch
    case lss::StoreConfiguration:
        if (!config)
            return;
        ++m_stores;
        Q_EMIT configurationStored(m_pending, m_bitTiming);
        return answer(lss::StoreConfiguration, kOk);
    case lss::InquireNodeId:
        if (config)
            answer(lss::InquireNodeId, m_active);
        return;
    case lss::Fastscan:
        return fastscan(d);
    default:
        if (cs >= lss::InquireVendor && cs <= lss::InquireSerial && config)
            answer(cs, 0, m_identity.part(cs - lss::InquireVendor), true);
        return;
    }
}

// CiA 305 8.3.2.6: only unconfigured slaves in waiting mode take part. BitChecked 80h resets the
// scan; otherwise the slave answers when bits 31..BitChecked of its part LSSSub equal IDNumber's,
// and moves to part LSSNext. Confirming the last part (BitChecked 0, LSSNext back to 0) selects it.
void LssSlave::fastscan(const QByteArray &d)
{
    if (d.size() < 8 || m_active != lss::kUnconfigured || m_mode != LssMode::Waiting)
        return;
    const quint32 id = qFromLittleEndian<quint32>(d.constData() + 1);
    const quint8 bitChecked = quint8(d.at(5));
    const int sub = quint8(d.at(6));
    const int next = quint8(d.at(7));
    if (bitChecked == lss::kFastscanReset) {
        m_fastscanPart = 0;
        return answer(lss::FastscanAnswer);
    }
    if (bitChecked > 31 || sub > 3 || next > 3 || sub != m_fastscanPart)
        return;
    if (((m_identity.part(sub) ^ id) >> bitChecked) != 0)
        return;
    m_fastscanPart = next;
    if (bitChecked == 0 && next < sub)
        m_mode = LssMode::Configuration;
    answer(lss::FastscanAnswer);
}

} // namespace db::canopen
