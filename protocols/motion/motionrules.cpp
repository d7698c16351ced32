#include "motionrules.h"

#include <algorithm>
#include <cmath>

namespace db::motion {

namespace {
double wrap(double x, double cycle)
{
    return x - cycle * std::floor(x / cycle);
}

int sign(double v)
{
    return v > 0 ? 1 : (v < 0 ? -1 : 0);
}

bool blockedByPermitted(double travel, const AxisConfig &c)
{
    if (!c.endless)
        return false; // R2 only for the endless travel range
    return (travel > 0 && c.permitted == PermittedDirection::NegativeOnly)
        || (travel < 0 && c.permitted == PermittedDirection::PositiveOnly);
}

bool blockedByHardwareLimit(double travel, const AxisSnapshot &a)
{
    return (travel > 0 && a.hardwareLimitPositive) || (travel < 0 && a.hardwareLimitNegative);
}

bool moving(const AxisSnapshot &a)
{
    return a.velocity != 0.0
        || (a.state != AxisState::Standstill && a.state != AxisState::Disabled
            && a.state != AxisState::ErrorStop);
}

AxisState stateOnStart(CommandKind kind, int homingMethod)
{
    switch (kind) {
    case CommandKind::MoveAbsolute:
    case CommandKind::MoveRelative:
    case CommandKind::MoveAdditive:
    case CommandKind::Halt:
        return AxisState::DiscreteMotion;
    case CommandKind::MoveVelocity:
    case CommandKind::TorqueControl:
        return AxisState::ContinuousMotion;
    case CommandKind::Stop:
        return AxisState::Stopping;
    case CommandKind::Home:
        // Set reference (35, 37) keeps Standstill; a homing run is Homing (Sec. 3.6).
        return (homingMethod == 35 || homingMethod == 37) ? AxisState::Standstill
                                                          : AxisState::Homing;
    case CommandKind::MotionBlock:
    case CommandKind::GearOut: // the drive brakes the slave to a stop
        return AxisState::DiscreteMotion;
    case CommandKind::GearIn:
        return AxisState::SynchronizedMotion;
    case CommandKind::DoNothing:
    case CommandKind::Power:
    case CommandKind::Reset:
        break;
    }
    return AxisState::Standstill;
}

Refusal positioningRefusal(CommandKind kind, const MoveParams &p, const AxisConfig &c,
                           const AxisSnapshot &a, Plan &plan, double origin)
{
    if (p.velocity == 0 || p.acceleration == 0 || p.deceleration == 0 || p.jerk == 0)
        return Refusal::ZeroProfileValue; // R5
    if (c.maxAcceleration == 0 || c.maxJerk == 0)
        return Refusal::ZeroAxisLimit; // R6
    // Precondition I86 = 1 of MC_MoveAbsolute and R7: warned, not refused (LimitFlags).
    if (!a.referenced && (kind == CommandKind::MoveAbsolute || c.softLimitsUsed))
        plan.flags.notReferenced = true;
    if (kind == CommandKind::MoveAbsolute && c.endless) {
        if (p.position < 0 || p.position >= c.cycleLength)
            return Refusal::TargetOutsideCycle; // R3
        plan.travel = endlessTravel(a.position, p.position, c.cycleLength, p.direction,
                                    c.positionWindow, a.velocity, a.brakingDistance);
        plan.target = a.position + plan.travel;
    } else {
        const double base = kind == CommandKind::MoveAbsolute ? 0.0
            : kind == CommandKind::MoveRelative               ? a.position
                                                              : origin;
        plan.target = base + p.position;
        plan.travel = plan.target - a.position;
    }
    if (!c.endless && c.softLimitsUsed
        && (plan.target < c.softLimitNegative || plan.target > c.softLimitPositive))
        return Refusal::TargetOutsideSoftLimits; // R1
    if (blockedByPermitted(plan.travel, c))
        return Refusal::DirectionNotPermitted; // R2
    if (blockedByHardwareLimit(plan.travel, a))
        return Refusal::HardwareLimitSwitch; // R4
    return Refusal::None;
}
} // namespace

double endlessTravel(double position, double target, double cycle, Direction direction,
                     double window, double velocity, double brakingDistance)
{
    if (velocity != 0.0) {
        const int movingDir = sign(velocity);
        int dir = movingDir; // 0 and 3: the currently active direction
        if (direction == Direction::PositiveOnly)
            dir = 1;
        else if (direction == Direction::NegativeOnly)
            dir = -1;
        const double stopPoint = position + movingDir * std::abs(brakingDistance);
        const double end = dir > 0 ? stopPoint + wrap(target - stopPoint, cycle)
                                   : stopPoint - wrap(stopPoint - target, cycle);
        return end - position;
    }
    const double d = wrap(target - position, cycle);
    const double shortest = d <= cycle / 2 ? d : d - cycle;
    switch (direction) {
    case Direction::Optimised:
    case Direction::KeepDirection:
        return shortest;
    case Direction::PositiveOnly:
        return std::abs(shortest) <= window ? shortest : d;
    case Direction::NegativeOnly:
        return std::abs(shortest) <= window ? shortest : (d == 0 ? 0.0 : d - cycle);
    }
    return shortest;
}

MoveParams clampProfile(const MoveParams &params, const AxisConfig &c, LimitFlags *flags)
{
    MoveParams p = params;
    LimitFlags f;
    const double v = std::abs(params.velocity);
    const double withOverride = v * params.overridePercent / 100.0;
    if (v > c.maxVelocity)
        f.velocityLimited = true; // I190
    else if (withOverride > c.maxVelocity)
        f.overrideLimited = true; // I193: only the override pushes it over I10
    p.velocity = sign(params.velocity) * std::min(withOverride, c.maxVelocity);
    auto clampTo = [&f](double value, double limit) {
        if (std::abs(value) > limit) {
            f.accelerationOrJerkLimited = true; // I191
            return limit;
        }
        return std::abs(value);
    };
    p.acceleration = clampTo(params.acceleration, c.maxAcceleration);
    p.deceleration = clampTo(params.deceleration, c.maxAcceleration);
    p.jerk = clampTo(params.jerk, c.maxJerk);
    if (flags)
        *flags = f;
    return p;
}

HomingParams clampHoming(const HomingParams &params, const AxisConfig &c)
{
    HomingParams h = params;
    h.speedFast = std::min(std::abs(h.speedFast), c.maxVelocity);
    h.speedSlow = std::min(std::abs(h.speedSlow), c.maxVelocity);
    h.acceleration = std::min(std::abs(h.acceleration), c.maxAcceleration);
    return h;
}

Plan planCommand(CommandKind kind, const MoveParams &params, const AxisConfig &config,
                 const AxisSnapshot &axis, double origin)
{
    Plan plan;
    plan.profile = params;
    plan.nextState = stateOnStart(kind, config.homingMethod);
    if (kind == CommandKind::Power || kind == CommandKind::Reset || kind == CommandKind::DoNothing)
        return plan;
    if ((kind == CommandKind::GearIn || kind == CommandKind::GearOut) && !axis.electronicGear) {
        plan.refusal = Refusal::FeatureMissing; // whatever the state: the drive cannot do it
        return plan;
    }
    if (axis.state == AxisState::Stopping) {
        plan.refusal = Refusal::StopActive; // R10
        return plan;
    }
    if (axis.state == AxisState::Disabled || axis.state == AxisState::ErrorStop) {
        plan.refusal = Refusal::AxisNotReady;
        return plan;
    }
    const MoveParams &p = params;
    const bool standstill = axis.state == AxisState::Standstill;
    // A drive that switches its operating mode only at rest: the command is refused before
    // anything is sent, and the running motion is left alone (no quick stop).
    const bool inMotionState = axis.state == AxisState::DiscreteMotion
        || axis.state == AxisState::ContinuousMotion || axis.state == AxisState::Homing
        || axis.state == AxisState::SynchronizedMotion;
    const bool modeBlocked = axis.modeChangeNeeded && (axis.driveMoving || inMotionState);
    switch (kind) {
    case CommandKind::MoveAbsolute:
    case CommandKind::MoveRelative:
    case CommandKind::MoveAdditive:
        if (modeBlocked) {
            plan.refusal = Refusal::ModeChangeWhileMoving;
            return plan;
        }
        plan.refusal = positioningRefusal(kind, p, config, axis, plan, origin);
        plan.quickStop = plan.refused() && moving(axis);
        break;
    case CommandKind::MoveVelocity:
        if (modeBlocked)
            plan.refusal = Refusal::ModeChangeWhileMoving;
        else if (p.acceleration == 0 || p.deceleration == 0 || p.jerk == 0)
            plan.refusal = Refusal::ZeroProfileValue; // R5v: velocity 0 is allowed
        else if (config.maxAcceleration == 0 || config.maxJerk == 0)
            plan.refusal = Refusal::ZeroAxisLimit; // R6
        else if (blockedByPermitted(p.velocity, config))
            plan.refusal = Refusal::DirectionNotPermitted; // R2
        else if (blockedByHardwareLimit(p.velocity, axis))
            plan.refusal = Refusal::HardwareLimitSwitch; // R4
        break;
    case CommandKind::Stop:
    case CommandKind::Halt:
        if ((p.deceleration == 0 || p.jerk == 0) && !standstill)
            plan.refusal = Refusal::ZeroProfileValue; // R5s
        else if (config.maxAcceleration == 0 || config.maxJerk == 0)
            plan.refusal = Refusal::ZeroAxisLimit; // R6
        plan.successAtStandstill = plan.refused() && standstill;
        break;
    case CommandKind::Home:
        if (!standstill)
            plan.refusal = Refusal::NotAtStandstill; // R8
        else if (modeBlocked)
            plan.refusal = Refusal::ModeChangeWhileMoving;
        else if (config.homingMethod == 0)
            plan.refusal = Refusal::HomingInactive; // R9
        return plan; // never refused for zero speeds (S-29); limits via clampHoming
    case CommandKind::MotionBlock:
        // The drive takes the block's own profile; starting it may change the drive's mode.
        if (!standstill)
            plan.refusal = Refusal::NotAtStandstill;
        else if (modeBlocked)
            plan.refusal = Refusal::ModeChangeWhileMoving;
        return plan;
    case CommandKind::TorqueControl:
        if (modeBlocked)
            plan.refusal = Refusal::ModeChangeWhileMoving;
        return plan; // otherwise never refused (Sec. 3.9)
    case CommandKind::GearIn:
    case CommandKind::GearOut:
        if (kind == CommandKind::GearIn && (p.gearNumerator == 0 || p.gearDenominator < 1))
            plan.refusal = Refusal::InvalidGearRatio;
        else if (kind == CommandKind::GearIn && modeBlocked)
            plan.refusal = Refusal::ModeChangeWhileMoving;
        if (!plan.refused()) { // ramps: 0 = the drive's own; limited like any other
            plan.profile.acceleration = std::min(p.acceleration, config.maxAcceleration);
            plan.profile.deceleration = std::min(p.deceleration, config.maxAcceleration);
        }
        return plan;
    case CommandKind::DoNothing:
    case CommandKind::Power:
    case CommandKind::Reset:
        return plan;
    }
    if (!plan.refused()) {
        const bool notReferenced = plan.flags.notReferenced;
        plan.profile = clampProfile(p, config, &plan.flags);
        plan.flags.notReferenced = notReferenced;
    }
    return plan;
}

} // namespace db::motion
