#pragma once

#include "commands.h"

namespace db::cli {

// record URI --obj INDEX:SUB [--obj ...] [--rate-ms R] --duration S [--trigger SPEC [--pre S]
//        [--post S] [--wait S]] [--capacity N] -o FILE.csv
//
// Polls the objects from the host (scope::PollingSource, one request in flight, each object
// every R ms; 0 = as fast as the link allows) and writes the recording as CSV (scope/csv.h:
// first column time in seconds, one column per object named "INDEX:SUB name").
// - Without --trigger: records for --duration seconds.
// - With --trigger SPEC (scope::Trigger::parse: "6064:0,rising,100", "6041:0,bit3,set", ...;
//   the channel must be one of the --obj): prints "armed: ..." once sampling runs, waits at most
//   --wait seconds (default 30) for the trigger, then keeps --pre seconds before it (default 0)
//   and --post seconds after it (default: --duration, else 1).
// Prints one summary line. Exit 0 with every sample recorded; lost samples are reported on
// stderr and give exit 1 (the file is still written). A trigger that never fires exits 4 without
// a file; a connection lost while recording writes what was recorded and exits 3.
int record(Context &context);

// --obj, --rate-ms, --duration, --trigger, --pre, --post, --wait, --capacity.
QList<QCommandLineOption> recordOptions();

} // namespace db::cli
