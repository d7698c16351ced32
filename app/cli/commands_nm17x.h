#pragma once

#include "commands.h"

namespace db::cli {

// Baumer NM170/NM172/NM174 displays on the bus of a CANopen URI (README "NM17x displays"):
//   nm17x URI list | setpoint NODE MM | jog NODE left|right | stop NODE|all | broadcast ... |
//   address --broadcast FIRST | control NODE WORD | watch
int nm17x(Context &context);
QList<QCommandLineOption> nm17xOptions();

} // namespace db::cli
