#pragma once

#include "commands.h"

namespace db::cli {

// eds-check FILE: loads an EDS/DCF/XDD/XDC/JSON description and prints a summary (format,
// identity, object counts by type and access, PDO-mappable count) and then every warning on a
// line of its own ("warning: ..."). Exit 0 when it loaded, warnings or not; otherwise one error
// line naming the file and the cause.
int edsCheck(Context &context);

} // namespace db::cli
