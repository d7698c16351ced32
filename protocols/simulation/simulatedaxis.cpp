#include "simulatedaxis.h"

#include <algorithm>
#include <cmath>

namespace db::sim {

namespace {
constexpr double kStandstillVelocity = 0.5; // units/s: below this the axis counts as standing
constexpr double kEpsilon = 1e-9;
} // namespace

SimulatedAxis::SimulatedAxis()
    : SimulatedAxis(Model {})
{ }

SimulatedAxis::SimulatedAxis(const Model &model)
    : m_model(model)
{ }

void SimulatedAxis::startProfile(const MotionProfile &profile, Mode mode)
{
    m_profile = profile;
    m_time = 0.0;
    m_mode = mode;
    m_inWindowTime = 0.0;
    m_targetReached = false;
    if (profile.endPosition())
        m_target = *profile.endPosition();
}

bool SimulatedAxis::moveTo(double target, double maxVelocity, double acceleration,
                           double deceleration, bool immediate)
{
    const bool limitsOn = !(m_minLimit == 0.0 && m_maxLimit == 0.0);
    const double clamped = limitsOn ? std::clamp(target, m_minLimit, m_maxLimit) : target;
    const bool busy = m_mode == Mode::Position && m_time < m_profile.duration();
    if (!immediate && busy) {
        if (m_queued)
            return false;
        m_queued = Queued { clamped, maxVelocity, acceleration, deceleration };
        return true;
    }
    m_queued.reset();
    m_limitActive = clamped != target;
    m_homing = HomingState::Idle;
    startProfile(MotionProfile::toPosition(m_demand.position, m_demand.velocity, clamped,
                                           maxVelocity, acceleration, deceleration),
                 Mode::Position);
    return true;
}

void SimulatedAxis::moveVelocity(double velocity, double acceleration, double deceleration)
{
    m_queued.reset();
    m_limitActive = false;
    m_homing = HomingState::Idle;
    m_stopDeceleration = deceleration;
    startProfile(MotionProfile::toVelocity(m_demand.position, m_demand.velocity, velocity,
                                           acceleration, deceleration),
                 Mode::Velocity);
}

void SimulatedAxis::stop(double deceleration)
{
    m_queued.reset();
    if (m_homing == HomingState::Searching)
        m_homing = HomingState::Failed;
    const double v = m_demand.velocity;
    const double stopAt =
        m_demand.position + (deceleration > kEpsilon ? v * std::abs(v) / (2 * deceleration) : 0);
    if (std::abs(v) < kEpsilon || deceleration <= kEpsilon) {
        startProfile(MotionProfile::hold(m_demand.position), Mode::Stopping);
        return;
    }
    startProfile(MotionProfile::toPosition(m_demand.position, v, stopAt, std::abs(v), deceleration,
                                           deceleration),
                 Mode::Stopping);
}

void SimulatedAxis::setPowered(bool powered)
{
    m_powered = powered;
    if (!powered) {
        m_queued.reset();
        if (m_homing == HomingState::Searching)
            m_homing = HomingState::Failed;
        m_demand = { m_actual, 0.0, 0.0 };
        startProfile(MotionProfile::hold(m_actual), Mode::Hold);
        m_actualVelocity = 0.0;
        m_current = 0.0;
    }
}

void SimulatedAxis::setPosition(double position)
{
    // A new coordinate frame: the mechanical stops stay where they are physically.
    const double shift = position - m_actual;
    if (m_hardStopPositive)
        *m_hardStopPositive += shift;
    if (m_hardStopNegative)
        *m_hardStopNegative += shift;
    m_queued.reset();
    m_actual = position;
    m_actualVelocity = 0.0;
    m_demand = { position, 0.0, 0.0 };
    m_limitActive = false;
    startProfile(MotionProfile::hold(position), Mode::Hold);
    m_homing = HomingState::Attained;
    m_blockedTime = 0.0;
}

void SimulatedAxis::startHardStopHoming(int direction, double speed, double acceleration,
                                        double homeOffset)
{
    m_queued.reset();
    m_limitActive = false;
    m_homeOffset = homeOffset;
    m_blockedTime = 0.0;
    startProfile(MotionProfile::toVelocity(m_demand.position, m_demand.velocity,
                                           direction >= 0 ? speed : -speed, acceleration,
                                           acceleration),
                 Mode::Homing);
    m_homing = HomingState::Searching;
}

void SimulatedAxis::setSoftLimits(double min, double max)
{
    m_minLimit = min;
    m_maxLimit = max;
}

void SimulatedAxis::setHardStops(std::optional<double> negative, std::optional<double> positive)
{
    // In the current coordinate frame; setPosition() shifts them with the frame.
    m_hardStopNegative = negative;
    m_hardStopPositive = positive;
}

void SimulatedAxis::setTargetWindow(double window, double windowTime)
{
    m_window = window;
    m_windowTime = windowTime;
}

void SimulatedAxis::setCurrentLimit(double limit)
{
    m_currentLimit = std::max(0.0, limit);
}

bool SimulatedAxis::isMoving() const
{
    if (std::abs(m_actualVelocity) > kStandstillVelocity)
        return true;
    if (m_mode == Mode::Hold)
        return false;
    return m_time < m_profile.duration() || std::abs(m_demand.velocity) > kEpsilon;
}

double SimulatedAxis::noise()
{
    // xorshift32: deterministic, so tests see the same "noise" on every run.
    m_noiseState ^= m_noiseState << 13;
    m_noiseState ^= m_noiseState >> 17;
    m_noiseState ^= m_noiseState << 5;
    return (double(m_noiseState % 2001) / 1000.0 - 1.0) * m_model.noiseAmplitude;
}

void SimulatedAxis::integrate(double dt)
{
    // The actual position x follows the demand u through x' = (u - x) / tau. Between two segment
    // boundaries u is quadratic, so x has the closed form
    //   x(h) = xp(h) + (x0 - xp(0)) e^(-h/tau),  xp(s) = u(s) - tau u'(s) + tau^2 u''(s).
    const double tau = m_model.followingTimeConstant;
    double remaining = dt;
    while (remaining > kEpsilon) {
        const double h = std::min(remaining, m_profile.nextBoundary(m_time) - m_time);
        const MotionSample u = m_profile.sample(m_time);
        const double a = u.acceleration;
        const double xp0 = u.position - tau * u.velocity + tau * tau * a;
        const double xph = u.position + u.velocity * h + a * h * h / 2 - tau * (u.velocity + a * h)
            + tau * tau * a;
        const double decay = tau > 0 ? std::exp(-h / tau) : 0.0;
        const double x0 = m_actual;
        m_actual = xph + (x0 - xp0) * decay;
        m_actualVelocity =
            (u.velocity + a * h - tau * a) - (tau > 0 ? (x0 - xp0) / tau * decay : 0.0);
        m_time += h;
        remaining -= h;
    }
    m_demand = m_profile.sample(m_time);
}

void SimulatedAxis::applySoftLimitInVelocityMode()
{
    if ((m_minLimit == 0.0 && m_maxLimit == 0.0) || m_mode != Mode::Velocity)
        return;
    const double v = m_demand.velocity;
    const double dec = std::max(m_stopDeceleration, kEpsilon);
    const double stopDistance = v * v / (2 * dec);
    const double limit = v > 0 ? m_maxLimit : m_minLimit;
    if (std::abs(v) < kEpsilon || std::abs(limit - m_demand.position) > stopDistance + kEpsilon)
        return;
    if ((v > 0 && m_demand.position > limit) || (v < 0 && m_demand.position < limit))
        return; // already outside and moving out: nothing sensible to brake towards
    startProfile(MotionProfile::toPosition(m_demand.position, v, limit, std::abs(v), dec, dec),
                 Mode::Position);
    m_limitActive = true;
}

void SimulatedAxis::step(double dt)
{
    if (dt <= 0)
        return;
    if (!m_powered) {
        m_current = 0.0;
        m_measuredVelocity = m_actualVelocity;
        return;
    }
    applySoftLimitInVelocityMode();
    integrate(dt);

    // Hard stops clamp the mechanics; a demand running ahead counts as pressing (block).
    bool pressing = false;
    if (m_hardStopPositive && m_actual >= *m_hardStopPositive) {
        m_actual = *m_hardStopPositive;
        m_actualVelocity = std::min(m_actualVelocity, 0.0);
        pressing = m_demand.position > m_actual + m_model.blockFollowingError;
    }
    if (m_hardStopNegative && m_actual <= *m_hardStopNegative) {
        m_actual = *m_hardStopNegative;
        m_actualVelocity = std::max(m_actualVelocity, 0.0);
        pressing = m_demand.position < m_actual - m_model.blockFollowingError;
    }
    m_blockedTime = pressing ? m_blockedTime + dt : 0.0;

    if (pressing) {
        m_current = m_demand.position > m_actual ? m_currentLimit : -m_currentLimit;
    } else {
        const bool moving = std::abs(m_actualVelocity) > kStandstillVelocity;
        double current = m_model.currentPerAcceleration * m_demand.acceleration;
        if (moving)
            current += (m_actualVelocity > 0 ? 1 : -1) * m_model.frictionCurrent;
        else
            current += m_model.holdingCurrent;
        m_current = std::clamp(current + noise(), -m_currentLimit, m_currentLimit);
    }

    m_measuredVelocity = m_actualVelocity;
    if (m_model.velocityNoise > 0 && std::abs(m_actualVelocity) > kStandstillVelocity) {
        m_velocityNoiseState ^= m_velocityNoiseState << 13;
        m_velocityNoiseState ^= m_velocityNoiseState >> 17;
        m_velocityNoiseState ^= m_velocityNoiseState << 5;
        m_measuredVelocity +=
            (double(m_velocityNoiseState % 2001) / 1000.0 - 1.0) * m_model.velocityNoise;
    }

    if (m_mode == Mode::Homing && blocked()) {
        // Hard-stop homing: the stop position becomes the home offset (spec 9.4 [R]).
        setPosition(m_homeOffset);
    }
    updateStatus(dt);
}

void SimulatedAxis::updateStatus(double dt)
{
    const bool profileDone = m_time >= m_profile.duration();
    if (profileDone && m_queued && m_mode == Mode::Position) {
        const Queued q = *m_queued;
        m_queued.reset();
        moveTo(q.target, q.maxVelocity, q.acceleration, q.deceleration, true);
        return;
    }
    switch (m_mode) {
    case Mode::Velocity:
        m_targetReached = profileDone;
        return;
    case Mode::Homing:
        m_targetReached = false;
        return;
    case Mode::Hold:
    case Mode::Position:
    case Mode::Stopping:
        break;
    }
    if (profileDone && std::abs(m_actual - m_demand.position) <= m_window) {
        m_inWindowTime += dt;
        m_targetReached = m_inWindowTime + kEpsilon >= m_windowTime;
    } else {
        m_inWindowTime = 0.0;
        m_targetReached = false;
    }
}

} // namespace db::sim
