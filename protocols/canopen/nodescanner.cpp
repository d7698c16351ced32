#include "nodescanner.h"

#include "canopenlogging.h"
#include "nmtmaster.h"
#include "nodemonitor.h"
#include "sdoabort.h"
#include "sdoclient.h"

#include <QtEndian>

#include <functional>

namespace db::canopen {

namespace {

constexpr ObjectAddress kDeviceType { 0x1000, 0 };
constexpr ObjectAddress kDeviceName { 0x1008, 0 };
constexpr quint16 kIdentity = 0x1018;

quint32 u32Of(const QByteArray &bytes)
{
    QByteArray b = bytes.left(4);
    b.resize(4, '\0');
    return qFromLittleEndian<quint32>(b.constData());
}

QString hex8(quint32 v)
{
    return QStringLiteral("0x")
        + QString::number(v, 16).toUpper().rightJustified(8, QLatin1Char('0'));
}

} // namespace

QString NodeInfo::toString() const
{
    QString line = QStringLiteral("%1  %2").arg(id, 3).arg(
        (state == NmtState::Unknown ? QStringLiteral("-") : nmtStateName(state)), -15);
    if (hasIdentity)
        line += QStringLiteral("  vendor %1 product %2 rev %3 serial %4")
                    .arg(hex8(vendorId), hex8(productCode), hex8(revision), hex8(serial));
    else if (!answersSdo)
        line += QStringLiteral("  (heard, no SDO answer)");
    if (!name.isEmpty())
        line += QStringLiteral("  \"%1\"").arg(name);
    return line;
}

NodeScanner::NodeScanner(SdoClient *sdo, NodeMonitor *monitor, QObject *parent)
    : QObject(parent)
    , m_sdo(sdo)
    , m_monitor(monitor)
{ }

void NodeScanner::setRange(NodeId first, NodeId last)
{
    m_first = qBound(kMinNodeId, first, kMaxNodeId);
    m_last = qBound(m_first, last, kMaxNodeId);
}

bool NodeScanner::start()
{
    if (m_running)
        return false;
    m_running = true;
    m_found.clear();
    m_result.clear();
    m_nextId = m_first;
    m_outstanding = 0;
    m_probesInFlight = 0;
    launchProbes();
    if (m_outstanding == 0)
        requestDone();
    return true;
}

void NodeScanner::launchProbes()
{
    while (m_probesInFlight < m_window && m_nextId <= m_last) {
        const NodeId id = NodeId(m_nextId++);
        ++m_probesInFlight;
        ++m_outstanding;
        Reply *reply = m_sdo->upload(id, kDeviceType, SdoClient::Mode::Expedited);
        reply->setParent(this);
        connect(reply, &Reply::finished, this, [this, reply, id] {
            reply->deleteLater();
            --m_probesInFlight;
            const bool answered = reply->ok() || reply->error().kind() == Error::Kind::DeviceError;
            onProbe(id, answered, reply->ok() ? u32Of(reply->value().toByteArray()) : 0);
            launchProbes();
            requestDone();
        });
    }
}

void NodeScanner::onProbe(NodeId id, bool found, quint32 deviceType)
{
    if (!found)
        return;
    NodeInfo &info = m_found[id];
    info.id = id;
    info.answersSdo = true;
    info.deviceType = deviceType;
    qCDebug(lcCanopen) << "scan: node" << id << "answers";
    Q_EMIT nodeFound(info);
    readIdentity(id);
}

void NodeScanner::readIdentity(NodeId id)
{
    const auto read = [this, id](ObjectAddress address,
                                 std::function<void(NodeInfo &, const QByteArray &)> apply) {
        ++m_outstanding;
        Reply *reply = m_sdo->upload(id, address);
        reply->setParent(this);
        connect(reply, &Reply::finished, this, [this, reply, id, address, apply] {
            reply->deleteLater();
            NodeInfo &info = m_found[id];
            if (reply->ok())
                apply(info, reply->value().toByteArray());
            else if (reply->error().deviceCode() != abort::NoSuchObject
                     && reply->error().deviceCode() != abort::NoSuchSubIndex)
                info.problems.append(
                    QStringLiteral("%1: %2").arg(address.toString(), reply->error().message()));
            requestDone();
        });
    };
    for (quint8 sub = 1; sub <= 4; ++sub) {
        read({ kIdentity, sub }, [sub](NodeInfo &info, const QByteArray &bytes) {
            const quint32 v = u32Of(bytes);
            (sub == 1       ? info.vendorId
                 : sub == 2 ? info.productCode
                 : sub == 3 ? info.revision
                            : info.serial) = v;
            info.hasIdentity = true;
        });
    }
    read(kDeviceName, [](NodeInfo &info, const QByteArray &bytes) {
        QByteArray text = bytes;
        while (text.endsWith('\0'))
            text.chop(1);
        info.name = QString::fromUtf8(text);
    });
}

void NodeScanner::requestDone()
{
    if (m_outstanding > 0)
        --m_outstanding;
    if (m_outstanding > 0 || m_nextId <= m_last || !m_running)
        return;
    for (const NodeId id : m_monitor ? m_monitor->nodes() : QList<NodeId>()) {
        if (id >= m_first && id <= m_last && !m_found.contains(id))
            m_found[id].id = id;
    }
    for (auto it = m_found.begin(); it != m_found.end(); ++it) {
        if (m_monitor)
            it->state = m_monitor->state(it.key());
        // A node enters pre-operational by itself right after its boot-up (CiA 301 7.3.2.2).
        if (it->state == NmtState::BootUp)
            it->state = NmtState::PreOperational;
        m_result.append(*it);
    }
    m_running = false;
    Q_EMIT finished();
}

} // namespace db::canopen
