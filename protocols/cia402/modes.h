#pragma once

#include "sequence.h"

#include <optional>

namespace db::cia402 {

// Modes of operation 6060h (CiA 402-2; movingcap.md 5.6).
enum class Mode : qint8 {
    NoMode = 0,
    ProfilePosition = 1,
    ProfileVelocity = 3,
    ProfileTorque = 4,
    Homing = 6,
    CyclicPosition = 8,
    CyclicVelocity = 9,
    CyclicTorque = 10,
};

// Objects of the modes (raw values, in the drive's units).
namespace obj {
constexpr ObjectAddress ModesOfOperation { 0x6060, 0 };
constexpr ObjectAddress ModesDisplay { 0x6061, 0 };
constexpr ObjectAddress PositionActual { 0x6064, 0 };
constexpr ObjectAddress VelocityActual { 0x606C, 0 };
constexpr ObjectAddress TargetTorque { 0x6071, 0 };
constexpr ObjectAddress TargetPosition { 0x607A, 0 };
constexpr ObjectAddress HomeOffset { 0x607C, 0 };
constexpr ObjectAddress ProfileVelocity { 0x6081, 0 };
constexpr ObjectAddress ProfileAcceleration { 0x6083, 0 };
constexpr ObjectAddress ProfileDeceleration { 0x6084, 0 };
constexpr ObjectAddress QuickStopDeceleration { 0x6085, 0 };
constexpr ObjectAddress TorqueSlope { 0x6087, 0 };
constexpr ObjectAddress HomingMethod { 0x6098, 0 };
constexpr ObjectAddress HomingSpeedFast { 0x6099, 1 };
constexpr ObjectAddress HomingSpeedSlow { 0x6099, 2 };
constexpr ObjectAddress HomingAcceleration { 0x609A, 0 };
// Profile jerk: CiA 402 describes 60A4h as an array (sub 1 = the jerk used), some drives (the
// MovingCap) as a single value in sub 0. profileJerk() picks what a description has.
constexpr ObjectAddress ProfileJerkArray { 0x60A4, 1 };
constexpr ObjectAddress ProfileJerkValue { 0x60A4, 0 };
constexpr ObjectAddress DigitalInputs { 0x60FD, 0 };
constexpr ObjectAddress TargetVelocity { 0x60FF, 0 };
constexpr ObjectAddress SupportedModes { 0x6502, 0 };
} // namespace obj

// 6502h bit for a mode (CiA 402-2: bit 0 pp, 2 pv, 3 tq, 5 hm, 7 csp, 8 csv, 9 cst).
quint32 supportedModeBit(Mode mode);
// The profile jerk object a description has (60A4h.1 of the CiA 402 array, else 60A4h.0 of a
// drive that describes it as one value), none when it has neither.
std::optional<ObjectAddress> profileJerk(const ObjectDictionary &dictionary);

// One profile-position set-point in raw drive units.
struct PositionSetPoint
{
    qint64 target = 0;
    quint32 velocity = 0;
    quint32 acceleration = 0;
    quint32 deceleration = 0;
    bool relative = false; // controlword bit 6
    bool immediate = true; // bit 5: replace the running move (63) instead of queueing (31)
    std::optional<ObjectAddress> jerkObject; // written with jerk when set (profileJerk())
    quint32 jerk = 0;
};

struct HomingSetPoint
{
    int method = 35;
    quint32 speedFast = 0;
    std::optional<quint32> speedSlow; // written only when given (6099h.2)
    quint32 acceleration = 0;
    qint64 offset = 0;
    int timeoutMs = 30000;
};

// Timeouts of the mode procedures.
constexpr int kSetPointAcknowledgeTimeoutMs = 1000;

// Profile position (movingcap.md 9.2): selects mode 1, writes the profile and the target, then
// the set-point handshake: 15 -> 31/63 (new set-point), wait for statusword bit 12
// (set-point acknowledge), 15, wait for bit 12 to clear. Finishes when the drive has taken the
// set-point, not when it arrives (watch bit 10 for that).
Sequence *profilePosition(DeviceConnection *c, const PositionSetPoint &sp, QObject *parent);
// Profile velocity (movingcap.md 9.3): mode 3, ramps, target velocity 60FFh, controlword 15.
Sequence *profileVelocity(DeviceConnection *c, qint64 velocity, quint32 acceleration,
                          quint32 deceleration, QObject *parent);
// Homing (movingcap.md 9.4): mode 6, method 6098h, speeds 6099h, acceleration 609Ah, offset
// 607Ch, then 15 -> 31 and wait for homing attained (bits 12 and 10) or homing error (bit 13)
// within sp.timeoutMs, then 15.
Sequence *homing(DeviceConnection *c, const HomingSetPoint &sp, QObject *parent);
// Profile torque (CiA 402-2 mode 4): torque slope 6087h, target torque 6071h [0.1 % rated].
Sequence *profileTorque(DeviceConnection *c, qint16 torque, quint32 slope, QObject *parent);
// Halt (controlword bit 8): the drive brakes with its profile deceleration and stays enabled.
Sequence *halt(DeviceConnection *c, std::optional<quint32> deceleration, QObject *parent);

} // namespace db::cia402
