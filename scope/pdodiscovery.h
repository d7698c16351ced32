#pragma once
// Which TPDO carries which object: turns a node's TPDO configuration into PdoSource channels.
#include "canopen/canopenids.h"
#include "canopen/pdomapping.h"
#include "core/reply.h"
#include "pdosource.h"

#include <QList>
#include <QMetaType>

namespace db {
class DeviceConnection;
}

namespace db::scope {

// One requested object found in an enabled TPDO, on a byte boundary.
struct PdoChannelPlanEntry
{
    ObjectAddress address;
    PdoSource::Mapping mapping; // COB-ID, byte offset, type, expected period
    int tpdoNumber = 0; // 0-based: TPDO1 = 0
};

// The result of matching requested objects against a node's TPDOs.
struct PdoChannelPlan
{
    canopen::NodeId node = 0;
    QList<PdoChannelPlanEntry> found; // in the order the objects were asked for
    QList<ObjectAddress> missing; // in no enabled TPDO (or not on a byte boundary)
    QList<canopen::PdoConfig> tpdos; // the node's TPDOs as read (enabled or not)

    bool isComplete() const { return missing.isEmpty(); }
    // "6064:0 Position actual value is in no TPDO of node 5" (one clause per missing object,
    // joined by "; "); empty when nothing is missing. Names come from `dictionary`.
    QString missingText(const ObjectDictionary &dictionary) const;
};

// The period in ms at which `config` is expected on the bus, for loss detection: its event
// timer for event-driven PDOs (transmission type FEh/FFh), type x the SYNC period for cyclic
// synchronous PDOs (1..240; syncPeriodMs 0 = unknown), else 0 (no loss detection by time).
int expectedPeriodMs(const canopen::PdoConfig &config, int syncPeriodMs);

// Pure: for each object of `objects`, the first enabled TPDO of `configs` that maps it whole on
// a byte boundary. The type is the dictionary's when its size matches the mapped bits, else an
// unsigned integer of the mapped size. RPDOs in `configs` are ignored.
PdoChannelPlan planPdoChannels(const QList<canopen::PdoConfig> &configs,
                               const QList<ObjectAddress> &objects,
                               const ObjectDictionary &dictionary, canopen::NodeId node,
                               int syncPeriodMs = 0);

// READ-ONLY: reads the node's PDO configuration through SDO uploads (as `drivebench-cli pdo`)
// and, when a found TPDO is synchronous, the SYNC period 1006h (ignored when unreadable), then
// plans the channels. Nothing is written to the device and its NMT state is untouched. The
// reply (caller owns it) finishes with QVariant::fromValue(PdoChannelPlan) (missing objects
// are NOT an error: see PdoChannelPlan::missing) or with the SDO error of the configuration
// read.
// Works on connections to a CANopen node (others fail with InvalidArgument).
Reply *discoverPdoChannels(DeviceConnection *connection, const QList<ObjectAddress> &objects);

// How long to wait after Start for the first PDO of `entries` before calling them silent:
// 1.5 s, or three expected periods of the slowest one when that is longer. Pure.
int firstPdoTimeoutMs(const QList<PdoChannelPlanEntry> &entries);

// Why the plan's TPDOs stayed silent, from what is known: `heard` is the node's NMT state from
// its heartbeat (NmtState::Unknown when none was heard). Not operational (heard or presumed):
// "... not operational: NMT start it" (PDOs are only sent in Operational); operational: the
// TPDOs' own reasons (no event timer, sent on SYNC without a SYNC producer, ...). Pure.
QString silentPdoCause(const PdoChannelPlan &plan, canopen::NmtState heard);

// Adds the plan's found objects to `source` as channels (names/units/scaling from
// `dictionary`). Returns the source's channel indices, in the plan's order.
Result<QList<int>> addPlannedChannels(PdoSource &source, const PdoChannelPlan &plan,
                                      const ObjectDictionary &dictionary, const QString &device);

} // namespace db::scope

Q_DECLARE_METATYPE(db::scope::PdoChannelPlan)
