#pragma once

#include "motiontypes.h"

namespace db::motion {

// The pure rules of the command model (stoeber_motion.md Sec. 2.5 refusal, 2.6 limitation,
// 3.1-3.3 targets, 4.2 direction): what a command does when it starts, decided from its latched
// inputs, the axis configuration and a snapshot of the axis. No I/O; table-tested.
struct Plan
{
    Refusal refusal = Refusal::None;
    // MC_Stop / MC_Halt refused at standstill report success instead (Sec. 2.5: I91 = 0, I92 = 1).
    bool successAtStandstill = false;
    // A positioning command refused while the axis moves stops it by quick stop (Sec. 2.3).
    bool quickStop = false;
    double target = 0.0; // absolute target (1-3); unwrapped on an endless axis
    double travel = 0.0; // signed distance from the actual position (1-3)
    MoveParams profile; // clamped profile values
    LimitFlags flags;
    AxisState nextState = AxisState::Standstill;

    bool refused() const { return refusal != Refusal::None; }
};

// origin: the starting point of MC_MoveAdditive (TargetTracker::origin()).
Plan planCommand(CommandKind kind, const MoveParams &params, const AxisConfig &config,
                 const AxisSnapshot &axis, double origin);

// Clamps |v| to I10, |a| and decel to I11, jerk to I16 and applies the override (Sec. 2.6).
MoveParams clampProfile(const MoveParams &params, const AxisConfig &config, LimitFlags *flags);
// MC_Home: clamped like the others, but I190/I191 stay 0 (Sec. 3.6, D-16).
HomingParams clampHoming(const HomingParams &params, const AxisConfig &config);

// Signed travel of MC_MoveAbsolute on an endless axis (Sec. 4.2). position is unwrapped,
// target in [0, cycle). From motion (velocity != 0) the target is approached past the point
// where the axis could stop (position + brakingDistance in the direction of motion).
double endlessTravel(double position, double target, double cycle, Direction direction,
                     double window, double velocity, double brakingDistance);

} // namespace db::motion
