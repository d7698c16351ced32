#pragma once

#include "motiontypes.h"

#include "core/error.h"
#include "core/reply.h"

#include <QObject>

namespace db::motion {

// What the command model needs from one drive, whatever its family (CiA 402 here; VABus motion
// control override and NM170 later). Values are in user units (position, units/s, units/s^2).
//
// Requests return a Reply the caller owns; it finishes exactly once when the drive has TAKEN the
// request (set-point acknowledged, state reached), not when the motion is over: completion is
// seen in status(). A new motion request supersedes an unfinished older one.
// stopNow() must work in every state, without waiting for anything in flight.
class AxisInterface : public QObject
{
    Q_OBJECT
public:
    struct Status
    {
        bool valid = false; // at least one complete status read since connecting
        bool powered = false; // power stage on, operation enabled
        bool fault = false;
        bool quickStopActive = false;
        bool moving = false; // the drive reports motion
        bool targetReached = false;
        // The drive reports its position as referenced: homing attained (bit 12 with target
        // reached, no homing error) read while the drive is in homing mode, or a drive that
        // needs no homing. False where the drive does not tell.
        bool homingAttained = false;
        double position = 0.0;
        double velocity = 0.0;
        bool hardwareLimitPositive = false;
        bool hardwareLimitNegative = false;
        quint16 rawStatus = 0; // the family's status word, for display
    };

    enum class Feature {
        ProfilePosition = 0x1,
        ProfileVelocity = 0x2,
        Homing = 0x4,
        Torque = 0x8,
        Jerk = 0x10,
        MotionBlocks = 0x20, // a table of motion blocks in the drive (startMotionBlock)
        ElectronicGear = 0x40, // follows a master at a ratio (gearIn, gearOut)
    };
    Q_DECLARE_FLAGS(Features, Feature)

    struct Profile
    {
        double velocity = 0.0;
        double acceleration = 0.0;
        double deceleration = 0.0;
        double jerk = 0.0;
    };

    using QObject::QObject;

    virtual Features features() const = 0;
    virtual Status status() const = 0;
    virtual bool isConnected() const = 0;

    virtual Reply *power(bool on) = 0;
    virtual Reply *reset() = 0; // fault reset; leaves the power stage off
    virtual Reply *moveTo(double target, const Profile &profile) = 0;
    virtual Reply *moveVelocity(double velocity, const Profile &profile) = 0;
    virtual Reply *halt(double deceleration) = 0; // brake with the ramp, stay enabled
    virtual Reply *home(const HomingParams &params) = 0; // finishes when homing is complete
    virtual Reply *torque(double torquePerMille, double slope) = 0;
    virtual Reply *stopNow() = 0; // quick stop, always

    // A motion block of the drive's own table (1-based), alone or as the start of its sequence,
    // or the interrupted one resumed; finishes when the block or sequence has ended in its
    // target. The default: the drive has no table (NotSupported).
    virtual Reply *startMotionBlock(int block, bool sequence, bool resume);
    // Electronic gear: couples the axis to the drive's master at numerator / denominator with
    // the ramps (0: the drive's own) and finishes once the drive reports it in gear; gearOut()
    // uncouples it and finishes when the drive has taken that (the drive then brakes the axis
    // with the deceleration to a stop). The default: the drive has none (NotSupported).
    virtual Reply *gearIn(int numerator, int denominator, double acceleration, double deceleration);
    virtual Reply *gearOut(double deceleration);

    // What the axis reads once before its first command: scaling, supported modes, the drive's
    // limits and its own profile. The caller owns the reply; the default has nothing to read.
    // Fails (Timeout or Disconnected) only when the drive answered none of the reads; objects a
    // drive refuses are left at their defaults.
    virtual Reply *initialize();
    // Valid once initialize() finished; defaults (unlimited, zero profile) before and where the
    // drive has none.
    virtual AxisConfig limits() const { return {}; }
    virtual Profile driveProfile() const { return {}; }
    virtual HomingParams driveHoming() const { return {}; }
    // How the drive names its units ("u", "u/s"); empty when it does not say.
    virtual QString positionUnit() const { return {}; }
    virtual QString velocityUnit() const { return {}; }
    // What the drive itself does when the link to it stops ("link watchdog: ..."); empty when
    // the axis does not know.
    virtual QString linkSupervision() const { return {}; }
    // Why a feature is missing ("configuration 210 has no positioning control"), for display.
    virtual QString featureNote() const { return {}; }
    // Whether starting `kind` now would switch the drive to another operating mode. A drive
    // that answers true here cannot switch while the axis moves, so the command model refuses
    // such a command then (Refusal::ModeChangeWhileMoving) before anything is sent.
    virtual bool needsModeChange(CommandKind kind) const
    {
        Q_UNUSED(kind);
        return false;
    }

Q_SIGNALS:
    void statusChanged();
    void connectionLost(const db::Error &error);
    // The link is up but the drive's supervision failed (a CANopen heartbeat not heard within its
    // consumer time): the drive may have died or hung, so whatever runs must end.
    void supervisionLost(const QString &reason);
};

Q_DECLARE_OPERATORS_FOR_FLAGS(AxisInterface::Features)

} // namespace db::motion
