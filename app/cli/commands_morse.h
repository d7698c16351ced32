#pragma once

#include "commands.h"

namespace db::cli {

// morse FILE [X,Y,W,H]: decodes the LED Morse message (movingcap.md section 2) from a video or
// a CSV of samples (time_s,brightness). Prints the decoded text, the unit, and
// "ip: A.B.C.D (confidence N %, M messages)". Exit 0 with a confident IP; otherwise one line
// "drivebench-cli: <file>: <reason>" on stderr and exit 1 (2 for a bad region argument).
int morse(Context &context);

} // namespace db::cli
