#pragma once

#include "commands.h"

namespace db::cli {

// Parameter sets (README "Parameter sets"). Loading a file never writes to a device.

// backup URI -o FILE: every storable object into FILE (atomic). Progress on stderr with
// --verbose, objects that could not be read as warnings on stderr, one summary line on stdout.
int backup(Context &context);
// restore URI FILE [--only INDEX:SUB,...] [--store] [--no-verify]: writes the selected rows in a
// safe order, verifies each by reading back, stores with 1010h when asked; prints the report.
// Exit 0 only if every selected row succeeded (and was stored when asked). A corrupt or foreign
// FILE is refused before connecting.
int restore(Context &context);
// diff A B (each a URI or a file; a URI is backed up first): prints the differing objects with
// name and both values, then the counts. Exit 0 when none differ, 1 when some do.
int diff(Context &context);
// dump URI: every readable object as "ADDRESS  NAME = VALUE UNIT".
int dump(Context &context);

// --only, --store, --no-verify.
QList<QCommandLineOption> paramsOptions();

} // namespace db::cli
