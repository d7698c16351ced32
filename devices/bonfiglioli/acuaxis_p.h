#pragma once

// Private to the ACU axis (acuaxis*.cpp): the parameters, control and status word bits it uses.

#include <QtGlobal>

#include <algorithm>
#include <cmath>

namespace db::bonfiglioli::acuaxis {

// Parameters of the ACTIVE Cube used here.
inline constexpr quint16 kConfiguration = 30;
inline constexpr quint16 kActualSpeedRpm = 240;
inline constexpr quint16 kCurrentFault = 260;
inline constexpr quint16 kApplicationWarnings = 274;
inline constexpr quint16 kBusErrorBehaviour = 388;
inline constexpr quint16 kLocalRemote = 412;
inline constexpr quint16 kStatusWord = 411;
inline constexpr quint16 kSpeed = 1107; // u/s
inline constexpr quint16 kPosition = 1108; // u
inline constexpr quint16 kGearNumerator = 1123;
inline constexpr quint16 kGearDenominator = 1124;
inline constexpr quint16 kHomingMethod = 1130;
inline constexpr quint16 kFastSpeed = 1132;
inline constexpr quint16 kCreepSpeed = 1133;
inline constexpr quint16 kHomingAcceleration = 1134;
inline constexpr quint16 kTargetWindow = 1165;
inline constexpr quint16 kTargetWindowTime = 1166;
inline constexpr quint16 kActiveBlock = 1246;
inline constexpr quint16 kMode = 1454;
inline constexpr quint16 kTargetPosition = 1455;
inline constexpr quint16 kProfileVelocity = 1456;
inline constexpr quint16 kAcceleration = 1457;
inline constexpr quint16 kDeceleration = 1458;
inline constexpr quint16 kTargetVelocityRpm = 1459;
inline constexpr quint16 kTargetVelocity = 1460;
inline constexpr qint64 kOverrideOff = -1;
inline constexpr int kFaultCheckMs = 100; // a fault that stays this long is not a transient //
                                          // 1455-1460: the MCI value is used instead

// Control word 410 (412 = 1).
inline constexpr quint16 kDisableVoltage = 0x0000;
inline constexpr quint16 kQuickStop = 0x0002;
inline constexpr quint16 kShutdown = 0x0006;
inline constexpr quint16 kSwitchOn = 0x0007;
inline constexpr quint16 kEnableOperation = 0x000F;
inline constexpr quint16 kBit4 =
    0x0010; // new set-point / start homing / sequence / move off switch
inline constexpr quint16 kBit5 = 0x0020; // change immediately (profile position); rfg unlock
inline constexpr quint16 kBit6 = 0x0040; // relative (profile position); resume; rfg use ref
inline constexpr quint16 kFaultReset = 0x0080;
inline constexpr quint16 kHalt = 0x0100;
inline constexpr quint16 kBit9 = 0x0200; // start motion block

// Status word 411.
inline constexpr quint16 kStateMask = 0x006F;
inline constexpr quint16 kSwitchOnDisabled = 0x0040;
inline constexpr quint16 kSwitchOnDisabledQs = 0x0060;
inline constexpr quint16 kReadyToSwitchOn = 0x0021;
inline constexpr quint16 kSwitchedOn = 0x0023;
inline constexpr quint16 kOperationEnabled = 0x0027;
inline constexpr quint16 kQuickStopActive = 0x0007;
inline constexpr quint16 kFaultBit = 0x0008;
inline constexpr quint16 kVoltageEnabled = 0x0010;
inline constexpr quint16 kTargetReached = 0x0400;
inline constexpr quint16 kBit8 = 0x0100; // motion block in progress
inline constexpr quint16 kBit12 = 0x1000; // set-point acknowledged / homing attained
inline constexpr quint16 kBit13 = 0x2000; // homing error / following error
// 274: hardware limit switch warnings.
inline constexpr quint16 kHwLimitPositive = 0x0008;
inline constexpr quint16 kHwLimitNegative = 0x0010;

inline bool inState(quint16 word, quint16 state)
{
    return (word & kStateMask) == state;
}
inline bool switchOnDisabled(quint16 w)
{
    return inState(w, kSwitchOnDisabled) || inState(w, kSwitchOnDisabledQs);
}

inline qint64 positive(double v)
{
    return std::max<qint64>(1, std::llround(std::abs(v)));
}

} // namespace db::bonfiglioli::acuaxis
