#pragma once
// record --pdo / --configure-tpdo: the CANopen PDO part of the record command.
#include "commands.h"
#include "scope/pdodiscovery.h"

#include <memory>

namespace db::cli {

struct PdoRecordRequest
{
    QList<ObjectAddress> objects;
    int configureTpdo = -1; // 0-based TPDO number to write first (opt-in); -1 = none
    int eventMs = 0; // event timer of the configured TPDO
};

// The source for --pdo. With configureTpdo >= 0 (opt-in) that TPDO is written first through
// scope::configureTpdo (CiA 301 safe order) and the change is announced on stderr; then the
// node's TPDO configuration is read (read-only) and every object is sampled from the TPDO that
// carries it (one "pdo: ..." line per object on stdout). Objects in no enabled TPDO are refused
// by name (InvalidArgument). `plan` receives what was found.
Result<std::unique_ptr<scope::PdoSource>> makePdoSource(Context &c, DeviceConnection *connection,
                                                        const PdoRecordRequest &request,
                                                        scope::PdoChannelPlan &plan);

// Timeout error for "no PDO within waitedMs": names the PDOs and the cause, using the node's
// NMT state from its heartbeat when one was heard (scope::silentPdoCause); record never
// changes the NMT state.
Error noPdoError(const Context &c, DeviceConnection *connection, const scope::PdoChannelPlan &plan,
                 int waitedMs);

} // namespace db::cli
