#include "pdodiscovery.h"

#include "canopen/cannetwork.h"
#include "canopen/pdoclient.h"
#include "canopen/sdoclient.h"
#include "core/valuecodec.h"

#include <QCoreApplication>
#include <QPointer>

#include <algorithm>

namespace db::scope {

namespace {

struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::scope::PdoDiscovery)
};

constexpr ObjectAddress kSyncPeriod { 0x1006, 0 }; // communication cycle period, us
constexpr int kFirstPdoMs = 1500; // see firstPdoTimeoutMs()

// The type a channel decodes `bits` with: the dictionary's when it has that size, else an
// unsigned integer of that size; nullopt when no numeric type fits.
std::optional<DataType> typeFor(const ObjectDef *def, int bits)
{
    if (def && datatype::isNumeric(def->type) && datatype::byteSize(def->type) * 8 == bits)
        return def->type;
    switch (bits) {
    case 8:
        return DataType::Unsigned8;
    case 16:
        return DataType::Unsigned16;
    case 32:
        return DataType::Unsigned32;
    case 64:
        return DataType::Unsigned64;
    default:
        return std::nullopt;
    }
}

bool needsSyncPeriod(const PdoChannelPlan &plan)
{
    for (const PdoChannelPlanEntry &e : plan.found) {
        for (const canopen::PdoConfig &c : plan.tpdos) {
            if (c.number == e.tpdoNumber && c.isCyclicSync())
                return true;
        }
    }
    return false;
}

} // namespace

QString PdoChannelPlan::missingText(const ObjectDictionary &dictionary) const
{
    QStringList parts;
    for (ObjectAddress address : missing) {
        const ObjectDef *def = dictionary.find(address);
        const QString label = def && !def->name.isEmpty()
            ? QStringLiteral("%1 %2").arg(address.toString(), def->displayName())
            : address.toString();
        parts.append(Tr::tr("%1 is in no TPDO of node %2").arg(label).arg(node));
    }
    return parts.join(QStringLiteral("; "));
}

int expectedPeriodMs(const canopen::PdoConfig &config, int syncPeriodMs)
{
    if (config.isEventDriven())
        return config.eventTimer.value_or(0);
    if (config.isCyclicSync() && syncPeriodMs > 0)
        return int(config.transmissionType) * syncPeriodMs;
    return 0;
}

PdoChannelPlan planPdoChannels(const QList<canopen::PdoConfig> &configs,
                               const QList<ObjectAddress> &objects,
                               const ObjectDictionary &dictionary, canopen::NodeId node,
                               int syncPeriodMs)
{
    PdoChannelPlan plan;
    plan.node = node;
    for (const canopen::PdoConfig &c : configs) {
        if (c.direction == canopen::PdoDirection::Transmit)
            plan.tpdos.append(c);
    }
    for (ObjectAddress address : objects) {
        std::optional<PdoChannelPlanEntry> hit;
        for (const canopen::PdoConfig &c : std::as_const(plan.tpdos)) {
            if (!c.isEnabled())
                continue;
            int bit = 0;
            for (const canopen::PdoMappingEntry &entry : c.entries) {
                const int at = bit;
                bit += entry.bits;
                if (entry.address != address || at % 8 != 0 || at + entry.bits > 64)
                    continue;
                const auto type = typeFor(dictionary.find(address), entry.bits);
                if (!type)
                    continue;
                hit = PdoChannelPlanEntry { address,
                                            { c.canId(), at / 8, *type,
                                              expectedPeriodMs(c, syncPeriodMs) },
                                            c.number };
                break;
            }
            if (hit)
                break;
        }
        if (hit)
            plan.found.append(*hit);
        else
            plan.missing.append(address);
    }
    return plan;
}

Reply *discoverPdoChannels(DeviceConnection *connection, const QList<ObjectAddress> &objects)
{
    const ObjectAddress first = objects.value(0);
    if (!connection || !connection->isConnected())
        return Reply::failed(first,
                             Error(Error::Kind::Disconnected,
                                   Tr::tr("cannot read the PDO configuration: not connected")));
    const canopen::NetworkNode at = canopen::networkNodeOf(connection);
    if (!at)
        return Reply::failed(first,
                             Error(Error::Kind::InvalidArgument,
                                   Tr::tr("PDOs need a connection to a CANopen node")));
    auto *outer = new Reply(first);
    // Everything below lives as children of `outer`: deleting the reply early cancels the rest.
    auto *client = new canopen::PdoClient(at.network->sdo(), outer);
    const canopen::NodeId node = at.node;
    const ObjectDictionary dictionary = connection->dictionary();
    QPointer<canopen::SdoClient> sdo = at.network->sdo();
    Reply *all = client->readAll(node, dictionary, canopen::PdoDirection::Transmit);
    all->setParent(outer);
    QObject::connect(all, &Reply::finished, outer, [=] {
        all->deleteLater();
        if (!all->ok()) {
            outer->fail(all->error().prefixed(
                Tr::tr("reading the PDO configuration of node %1").arg(node)));
            return;
        }
        const auto configs = all->value().value<QList<canopen::PdoConfig>>();
        PdoChannelPlan plan = planPdoChannels(configs, objects, dictionary, node);
        if (!needsSyncPeriod(plan) || !sdo) {
            outer->finish(QVariant::fromValue(plan));
            return;
        }
        Reply *period = sdo->upload(node, kSyncPeriod);
        period->setParent(outer);
        QObject::connect(period, &Reply::finished, outer, [=] {
            period->deleteLater();
            int syncMs = 0;
            const QByteArray bytes = period->value().toByteArray();
            if (period->ok() && bytes.size() >= 4) {
                const quint32 us =
                    codec::decode(DataType::Unsigned32, bytes.left(4)).valueOr(0u).toUInt();
                syncMs = int((us + 500) / 1000);
            }
            outer->finish(
                QVariant::fromValue(planPdoChannels(configs, objects, dictionary, node, syncMs)));
        });
    });
    return outer;
}

int firstPdoTimeoutMs(const QList<PdoChannelPlanEntry> &entries)
{
    int ms = kFirstPdoMs;
    for (const PdoChannelPlanEntry &e : entries)
        ms = std::max(ms, 3 * e.mapping.expectedPeriodMs);
    return ms;
}

QString silentPdoCause(const PdoChannelPlan &plan, canopen::NmtState heard)
{
    // Each used TPDO's own reason for staying silent in Operational.
    QStringList own;
    QList<int> seen;
    for (const PdoChannelPlanEntry &e : plan.found) {
        if (seen.contains(e.tpdoNumber))
            continue;
        seen.append(e.tpdoNumber);
        for (const canopen::PdoConfig &c : plan.tpdos) {
            if (c.number != e.tpdoNumber)
                continue;
            const quint8 type = c.transmissionType;
            if (c.isEventDriven() && c.eventTimer.value_or(0) == 0)
                own.append(Tr::tr("%1 has no event timer and is sent only on device events")
                               .arg(c.name()));
            else if (c.isCyclicSync())
                own.append(Tr::tr("%1 is sent on SYNC (transmission type %2) and no SYNC was "
                                  "produced")
                               .arg(c.name())
                               .arg(type));
            else if (type == 0 || type == 0xFC || type == 0xFD)
                own.append(Tr::tr("%1 is sent only on events or remote requests (type 0x%2)")
                               .arg(c.name())
                               .arg(type, 2, 16, QLatin1Char('0')));
        }
    }
    const QString node = QString::number(plan.node);
    if (heard == canopen::NmtState::Operational)
        return own.isEmpty()
            ? Tr::tr("node %1 is operational (heartbeat), yet its TPDOs did not come").arg(node)
            : Tr::tr("node %1 is operational (heartbeat), but %2")
                  .arg(node, own.join(Tr::tr("; ")));
    QString text;
    switch (heard) {
    case canopen::NmtState::PreOperational:
        text = Tr::tr("node %1 is pre-operational (heartbeat), not operational: NMT start it");
        break;
    case canopen::NmtState::Stopped:
        text = Tr::tr("node %1 is stopped (heartbeat), not operational: NMT start it");
        break;
    default:
        text = Tr::tr("node %1 is probably not operational (no heartbeat heard): NMT start it");
        break;
    }
    text = text.arg(node);
    if (heard == canopen::NmtState::Unknown && !own.isEmpty())
        text += Tr::tr("; or %1").arg(own.join(Tr::tr("; or ")));
    return text;
}

Result<QList<int>> addPlannedChannels(PdoSource &source, const PdoChannelPlan &plan,
                                      const ObjectDictionary &dictionary, const QString &device)
{
    QList<int> added;
    for (const PdoChannelPlanEntry &e : plan.found) {
        const auto index = source.addChannel(
            ChannelInfo::forObject(e.address, dictionary, device, e.mapping.expectedPeriodMs),
            e.mapping);
        if (!index)
            return index.error();
        added.append(*index);
    }
    return added;
}

} // namespace db::scope
