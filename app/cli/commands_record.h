#pragma once

#include "commands.h"

namespace db::cli {

// record URI --obj INDEX:SUB [--obj ...] [--rate-ms R] --duration S [--trigger SPEC [--pre S]
//        [--post S] [--wait S]] [--capacity N] -o FILE.csv
//
// Polls the objects from the host (scope::PollingSource, one request in flight per object, each
// object every R ms on deadlines that do not drift; 0 = as fast as the link allows) and writes the
// recording as CSV (scope/csv.h: first column time in seconds, one column per object named
// "INDEX:SUB name").
// - Without --trigger: records for --duration seconds on the recorder's time base
//   (Recorder::setDurationS).
// - With --trigger SPEC (scope::Trigger::parse: "6064:0,rising,100", "6041:0,bit3,set", ...;
//   the channel must be one of the --obj): prints "armed: ..." once sampling runs, waits at most
//   --wait seconds (default 30) for the trigger, then keeps --pre seconds before it (default 0)
//   and --post seconds after it (default: --duration, else 1).
// - With --pdo (CANopen only): instead of polling, samples the objects PASSIVELY from the TPDOs
//   that carry them (found by reading the node's PDO configuration, read-only; timestamps when a
//   frame arrives; loss = missed event-timer/SYNC periods). Objects in no TPDO exit 2 naming
//   them. No PDO within max(1.5 s, 3 periods) exits 4 naming the probable cause (node not
//   operational: record never sends NMT commands). --configure-tpdo N [--event-ms MS] (opt-in)
//   first maps the objects into TPDO N (RAM; says so on stderr), then samples as --pdo.
// Prints one summary line. Exit 0 with every sample recorded; lost samples are reported on
// stderr and give exit 1 (the file is still written). A trigger that never fires exits 4 without
// a file; a connection lost while recording writes what was recorded and exits 3.
int record(Context &context);

// --obj, --rate-ms, --duration, --trigger, --pre, --post, --wait, --capacity, --pdo,
// --configure-tpdo, --event-ms.
QList<QCommandLineOption> recordOptions();

} // namespace db::cli
