#pragma once

#include <optional>

namespace db::motion {

// The last valid target position and the starting point of MC_MoveAdditive
// (stoeber_motion.md Sec. 3.3, §1.4.6):
// 1. the origin is the last valid target;
// 2. without a known target, the actual position;
// 3. only MC_MoveAbsolute/Relative/Additive make a target; MC_Stop and MC_Halt keep it;
// 4. after the enable was switched off: the actual position if the axis had not reached the
//    position window or had left it again, the target if it reached the window and stays in it.
// Pure; the owner reports targets, enable-off and actual positions.
class TargetTracker
{
public:
    void setTarget(double target); // a positioning command started
    void enableOff(); // the power stage went off
    // Every actual position seen (also while disabled): tracks window reached / left.
    void observe(double actual, double window);
    void clear(); // e.g. after homing moved the coordinate frame

    std::optional<double> target() const { return m_target; }
    double origin(double actual, double window) const;

private:
    std::optional<double> m_target;
    bool m_reached = false;
    bool m_left = false;
    bool m_disabled = false;
};

} // namespace db::motion
