#pragma once

// Private to the ParameterRestore sources: one unit of work of a restore.

#include "parameterrunner.h"

namespace db {

namespace restore {
constexpr quint32 kCobIdInvalid = 0x80000000u; // CiA 301 7.5.2.35: bit 31 = PDO not valid

// Errors that end a run rather than fail one object.
bool isFatal(const Error &error);
// The PDO communication index (1400h-15FFh RPDO, 1800h-19FFh TPDO) of a comm or mapping
// index, or 0.
quint16 pdoCommIndex(quint16 index);
bool isMapping(quint16 index);
} // namespace restore

struct ParameterRestore::Step
{
    enum class Kind {
        Row, // write report row `row` (value from the set), then read it back
        ReadCurrent, // read `address` and keep it for a later step
        Disable, // write the kept COB-ID | bit 31
        ClearMapping, // write mapping sub 0 := 0
        Previous, // write back the value ReadCurrent kept for `address`
    };
    // Where in a PDO group the step is: a failure blocks the rest of the group (Disable) or the
    // rest of the mapping (Mapping); the Enable part still runs after a mapping failure.
    enum class Part { None, Disable, Comm, Mapping, Enable };

    Kind kind = Kind::Row;
    ObjectAddress address;
    int row = -1; // index into the report's rows; -1 for helper steps
    quint16 pdo = 0; // communication index of the PDO group, 0 outside one
    Part part = Part::None;
};

} // namespace db
