#pragma once

#include "commands.h"

namespace db::cli {

// Motion commands over any drive the axis factory (devices/axisfactory.h) knows: CiA 402 drives
// and the ACTIVE Cube (vabus://), through the PLCopen command model (protocols/motion). Each run
// opens the connection, reads the drive's scaling, limits and profile, runs one command and waits
// for its end, every wait bounded by --wait (default kDefaultWaitMs). A command the model refuses
// exits with ExitDeviceError and prints "drivebench-cli: MC_... refused: <reason>".
//
//   enable URI                 MC_Power on; prints the PLCopen state
//   disable URI                MC_Power off
//   reset URI                  MC_Reset (fault reset; the power stage stays off: enable)
//   home URI METHOD            MC_Home with the CiA 402 method; prints the position
//   move URI --abs|--rel|--add VALUE [--vel V --acc A --dec D]
//                              waits for Done, prints the final actual position; the profile
//                              defaults to the drive's 6081h/6083h/6084h
//   jog URI --vel V --time MS  leased moves at V for MS ms, then MC_Halt; prints the position
//   velocity URI --vel V --time MS
//                              MC_MoveVelocity (the drive's velocity mode) for MS ms, then
//                              MC_Halt; prints the position
//   halt URI [--dec D]         MC_Halt of whatever moves the drive; prints the position
//   stop URI [--dec D]         MC_Stop (nothing else starts until standstill); prints the position
//   travel URI BLOCK [--sequence] [--resume]
//                              runs motion block BLOCK of the drive's table (alone, or the
//                              sequence it starts) to its end; prints the position
//   gear URI --ratio N:D --time MS [--acc A --dec D]
//                              MC_GearIn (the drive's electronic gear, its own master) until
//                              "in gear", MS ms coupled, then MC_GearOut: the drive brakes the
//                              slave to a stop; prints the position
//   gear URI --out [--dec D]   MC_GearOut of a gear started elsewhere
constexpr int kDefaultWaitMs = 60000;

int enable(Context &context);
int disable(Context &context);
int reset(Context &context);
int home(Context &context);
int move(Context &context);
int jog(Context &context);
int velocity(Context &context);
int halt(Context &context);
int stop(Context &context);
int travel(Context &context);
int gear(Context &context); // commands_gear.cpp
QList<QCommandLineOption> motionOptions();
QList<QCommandLineOption> gearOptions();

} // namespace db::cli
