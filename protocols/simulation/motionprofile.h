#pragma once

#include <QList>

#include <limits>
#include <optional>

namespace db::sim {

struct MotionSample
{
    double position = 0.0;
    double velocity = 0.0;
    double acceleration = 0.0;
};

// A trapezoidal set-point trajectory: a start state (p0, v0) and segments of constant
// acceleration, evaluated in closed form so the result does not depend on the step size.
// After the last segment the profile either rests exactly at its end position (position moves,
// stops) or cruises at its final velocity (velocity mode).
class MotionProfile
{
public:
    static constexpr double kForever = std::numeric_limits<double>::infinity();

    // Rest at position.
    static MotionProfile hold(double position);
    // From (p0, v0) to rest at target with the velocity limit and acceleration/deceleration.
    // Brakes first when v0 points away from the target or cannot stop in time.
    static MotionProfile toPosition(double p0, double v0, double target, double maxVelocity,
                                    double acceleration, double deceleration);
    // Ramp from v0 to targetVelocity (acceleration while |v| grows, deceleration while it
    // shrinks, through zero when the sign changes), then cruise forever.
    static MotionProfile toVelocity(double p0, double v0, double targetVelocity,
                                    double acceleration, double deceleration);

    MotionSample sample(double t) const;
    // Time when the last segment ends (the move is complete or the cruise velocity reached).
    double duration() const;
    // The next segment boundary after t (kForever when none): a sampled quantity is a single
    // quadratic in time between two boundaries.
    double nextBoundary(double t) const;
    bool endsAtRest() const { return m_endPosition.has_value(); }
    std::optional<double> endPosition() const { return m_endPosition; }
    double finalVelocity() const { return m_finalVelocity; }

private:
    struct Segment
    {
        double duration;
        double acceleration;
    };
    void add(double duration, double acceleration);

    double m_p0 = 0.0;
    double m_v0 = 0.0;
    QList<Segment> m_segments;
    std::optional<double> m_endPosition;
    double m_finalVelocity = 0.0;
};

} // namespace db::sim
