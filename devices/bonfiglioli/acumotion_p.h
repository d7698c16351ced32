#pragma once

// Private to the simulated ACU's motion model (acumotion*.cpp): the parameters it uses and the
// control word bit helpers.

#include <QtGlobal>

namespace db::bonfiglioli::acumotion {

inline constexpr quint16 kConfiguration = 30;
inline constexpr quint16 kStatorFrequency = 210; // Hz, 2 decimals
inline constexpr quint16 kRmsCurrent = 211; // A, 1 decimal
inline constexpr quint16 kActualSpeedRpm = 240;
inline constexpr quint16 kDigitalInputs = 250;
inline constexpr quint16 kPolePairs = 373;
inline constexpr quint16 kLocalRemote = 412;
inline constexpr quint16 kAccelerationCw = 420; // Hz/s, 2 decimals
inline constexpr quint16 kDecelerationCw = 421;
inline constexpr quint16 kSpeed = 1107;
inline constexpr quint16 kPosition = 1108;
inline constexpr quint16 kFeed = 1115;
inline constexpr quint16 kGearShaft = 1116;
inline constexpr quint16 kGearMotor = 1117;
inline constexpr quint16 kGearNumerator = 1123;
inline constexpr quint16 kGearDenominator = 1124;
inline constexpr quint16 kFastSpeed = 1132;
inline constexpr quint16 kCreepSpeed = 1133;
inline constexpr quint16 kHomingAcceleration = 1134;
inline constexpr quint16 kTargetWindow = 1165;
inline constexpr quint16 kGearCoupledTime = 1169; // ms
inline constexpr quint16 kQuickStopRamp = 1179;
inline constexpr quint16 kBlockTarget = 1202;
inline constexpr quint16 kBlockSpeed = 1203;
inline constexpr quint16 kBlockAcceleration = 1204;
inline constexpr quint16 kBlockDeceleration = 1206;
inline constexpr quint16 kBlockMode = 1208; // 2 = relative (a simulator convention)
inline constexpr quint16 kBlockNext = 1213; // next block after the wait time; 0 = end
inline constexpr quint16 kActiveBlock = 1246;
inline constexpr quint16 kResumeBlock = 1249;
inline constexpr quint16 kVelocityWindow = 1276;
inline constexpr quint16 kMode = 1454;
inline constexpr quint16 kTargetPosition = 1455;
inline constexpr quint16 kProfileVelocity = 1456;
inline constexpr quint16 kAcceleration = 1457;
inline constexpr quint16 kDeceleration = 1458;
inline constexpr quint16 kTargetVelocityRpm = 1459;
inline constexpr quint16 kTargetVelocity = 1460;
inline constexpr quint16 kBothDirectionsBlocked = 0x1449; // F1449

inline constexpr double kDefaultVelocity = 10000.0; // u/s, when an override is off (-1)
inline constexpr double kDefaultAcceleration = 50000.0; // u/s^2

inline bool bit(quint16 word, int n)
{
    return word & (1u << n);
}
inline bool rising(quint16 old, quint16 word, int n)
{
    return !bit(old, n) && bit(word, n);
}
inline bool falling(quint16 old, quint16 word, int n)
{
    return bit(old, n) && !bit(word, n);
}

} // namespace db::bonfiglioli::acumotion
