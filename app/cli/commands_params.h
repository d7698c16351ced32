#pragma once

#include "commands.h"

namespace db::cli {

// Parameter sets (README "Parameter sets"). Loading a file never writes to a device.

// backup URI -o FILE: every storable object into FILE (atomic). Progress on stderr with
// --verbose, objects that could not be read as warnings on stderr, one summary line on stdout.
// Only a complete set is written to FILE: when any object (1018h identity included) could not
// be read, FILE stays as it was, what was read goes to FILE.partial (atomic) with a comment line
// per failed object, and the exit code is the class of the most common cause (4 timeout,
// 5 malformed, 6 device error, 3 connection). Reading no object at all is a failure.
int backup(Context &context);
// restore URI FILE [--only INDEX:SUB,...] [--store] [--no-verify] [--ignore-identity]: writes
// the selected rows in a safe order, verifies each by reading back, stores with 1010h when
// asked; prints the report. Exit 0 only if every selected row succeeded (and was stored when
// asked). A corrupt, foreign or empty FILE is refused before connecting; a set for another
// product, one whose product code is unknown, or a device whose 1018h.2 cannot be read is
// refused unless --ignore-identity.
int restore(Context &context);
// diff A B (each a URI or a file; a URI is backed up first): prints the differing objects with
// name and both values, then the counts. Exit 0 when none differ, 1 when some do; when objects
// of a URI side could not be read, the comparison of the rest is printed and the exit code is
// the class of the read failures.
int diff(Context &context);
// dump URI: every readable object as "ADDRESS  NAME = VALUE UNIT". Objects that could not be
// read are warnings on stderr and make the exit code the class of their most common cause;
// objects the protocol cannot carry (strings over RefGo) are "skipped:" lines, not failures.
int dump(Context &context);

// --only, --store, --no-verify, --ignore-identity.
QList<QCommandLineOption> paramsOptions();

} // namespace db::cli
