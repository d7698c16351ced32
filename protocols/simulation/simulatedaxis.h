#pragma once

#include "motionprofile.h"

#include <optional>

namespace db::sim {

// One simulated axis in user units (position, units/s, units/s^2). Pure: no timers, no Qt
// objects; the owner calls step() with the elapsed time. Not thread-safe.
//
// Model: a set-point generator (MotionProfile) produces the demand position; the actual position
// follows it through a first-order lag (the position loop), integrated in closed form per
// quadratic piece so results do not depend on the step size. Mechanical hard stops clamp the
// actual position; pressing against one is detected as a block (homing -18/-19, ERROR_STROKE).
class SimulatedAxis
{
public:
    enum class Mode { Hold, Position, Velocity, Stopping, Homing };
    enum class HomingState { Idle, Searching, Attained, Failed };

    struct Model
    {
        double followingTimeConstant = 0.0182; // s, position loop lag: 18.2 ms puts the
        // Docklight log's TP -3658 (720 units/s, 5.606 s into G-7200, spec 3.8) in range
        double currentPerAcceleration = 0.01; // 0.1 % of rated per unit/s^2
        double frictionCurrent = 40.0; // 0.1 % of rated while moving
        double holdingCurrent = 8.0; // 0.1 % of rated at standstill
        double noiseAmplitude = 3.0; // +/- 0.1 % of rated
        // +/- units/s on the measured velocity (606Ch) while moving: a real drive estimates the
        // speed from encoder differences, so it ripples. 0 = exact (the factory default, which
        // the simulation tests rely on); the demo drive turns it on.
        double velocityNoise = 0.0;
        double blockDetectionTime = 0.1; // s pressing against a stop before "blocked"
        double blockFollowingError = 1.0; // units demand ahead of actual at a stop
    };

    SimulatedAxis();
    explicit SimulatedAxis(const Model &model);

    // ---- set-points ----
    // Profile position: immediate replaces the running move now; otherwise the target is
    // queued behind it ("set of set-points", one buffered target). Targets are clamped to the
    // soft limits (internal limit flag). Returns false when a target is already queued.
    bool moveTo(double target, double maxVelocity, double acceleration, double deceleration,
                bool immediate = true);
    void moveVelocity(double velocity, double acceleration, double deceleration);
    // Brake to standstill with the deceleration and hold (halt, quick stop, jog end).
    void stop(double deceleration);
    // Power stage off or on: off freezes the demand at the actual position, current 0.
    void setPowered(bool powered);
    // Homing 35/37: the actual (and demand) position becomes position.
    void setPosition(double position);
    // Homing -18 (direction +1) / -19 (direction -1): search the hard stop at speed, then set
    // the position to homeOffset.
    void startHardStopHoming(int direction, double speed, double acceleration, double homeOffset);

    // ---- environment and parameters ----
    void setSoftLimits(double min, double max); // 0/0 = off (607Dh)
    void setHardStops(std::optional<double> negative, std::optional<double> positive);
    void setTargetWindow(double window, double windowTime); // 6067h units, 6068h in s
    void setCurrentLimit(double limit); // 6073h, 0.1 % of rated

    void step(double dt);

    // ---- state ----
    Mode mode() const { return m_mode; }
    double position() const { return m_actual; }
    double velocity() const { return m_actualVelocity; }
    // velocity() plus the measurement ripple (Model::velocityNoise) while moving; what 606Ch shows.
    double measuredVelocity() const { return m_measuredVelocity; }
    double demandPosition() const { return m_demand.position; }
    double demandVelocity() const { return m_demand.velocity; }
    double target() const { return m_target; }
    double current() const { return m_current; }
    bool isMoving() const;
    bool targetReached() const { return m_targetReached; }
    bool internalLimitActive() const { return m_limitActive; }
    bool blocked() const { return m_blockedTime >= m_model.blockDetectionTime; }
    HomingState homingState() const { return m_homing; }
    bool powered() const { return m_powered; }

private:
    void startProfile(const MotionProfile &profile, Mode mode);
    void integrate(double dt);
    void updateStatus(double dt);
    void applySoftLimitInVelocityMode();
    double noise();

    Model m_model;
    MotionProfile m_profile = MotionProfile::hold(0.0);
    double m_time = 0.0; // since the profile started
    MotionSample m_demand;
    Mode m_mode = Mode::Hold;
    double m_actual = 0.0;
    double m_actualVelocity = 0.0;
    double m_measuredVelocity = 0.0;
    quint32 m_velocityNoiseState = 0x6C8E9CF5u; // own sequence: the current noise stays as it was
    double m_target = 0.0;
    double m_stopDeceleration = 1.0;
    struct Queued
    {
        double target, maxVelocity, acceleration, deceleration;
    };
    std::optional<Queued> m_queued;
    double m_minLimit = 0.0;
    double m_maxLimit = 0.0;
    bool m_limitActive = false;
    std::optional<double> m_hardStopNegative;
    std::optional<double> m_hardStopPositive;
    double m_window = 0.0;
    double m_windowTime = 0.0;
    double m_inWindowTime = 0.0;
    bool m_targetReached = true;
    double m_currentLimit = 1000.0;
    double m_current = 0.0;
    double m_blockedTime = 0.0;
    bool m_powered = false;
    HomingState m_homing = HomingState::Idle;
    double m_homeOffset = 0.0;
    quint32 m_noiseState = 0x2545F491u;
};

} // namespace db::sim
