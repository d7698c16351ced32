#include "motionprofile.h"

#include <cmath>

namespace db::sim {

namespace {
constexpr double kEpsilon = 1e-9;

double sign(double x)
{
    return x > 0 ? 1.0 : (x < 0 ? -1.0 : 0.0);
}
} // namespace

void MotionProfile::add(double duration, double acceleration)
{
    if (duration > kEpsilon)
        m_segments.append({ duration, acceleration });
}

MotionProfile MotionProfile::hold(double position)
{
    MotionProfile p;
    p.m_p0 = position;
    p.m_endPosition = position;
    return p;
}

MotionProfile MotionProfile::toPosition(double p0, double v0, double target, double maxVelocity,
                                        double acceleration, double deceleration)
{
    MotionProfile p;
    p.m_p0 = p0;
    p.m_v0 = v0;
    p.m_endPosition = target;
    if (maxVelocity <= kEpsilon || acceleration <= kEpsilon || deceleration <= kEpsilon)
        return hold(p0);

    double pos = p0;
    double vel = v0;
    // 1. Brake to standstill when moving away from the target or too fast to stop before it.
    const double distance = target - pos;
    if (std::abs(vel) > kEpsilon
        && (sign(vel) != sign(distance)
            || vel * vel / (2 * deceleration) > std::abs(distance) + kEpsilon)) {
        const double t = std::abs(vel) / deceleration;
        p.add(t, -sign(vel) * deceleration);
        pos += vel * t / 2;
        vel = 0;
    }
    const double s = sign(target - pos);
    if (s == 0.0)
        return p;
    // 2. Above the velocity limit (limit lowered during a move): brake down to it.
    if (std::abs(vel) > maxVelocity) {
        const double t = (std::abs(vel) - maxVelocity) / deceleration;
        p.add(t, -s * deceleration);
        pos += (vel + s * maxVelocity) * t / 2;
        vel = s * maxVelocity;
    }
    // 3. Trapezoid (or triangle when the way is too short for the velocity limit).
    const double u = std::abs(vel);
    const double remaining = std::abs(target - pos);
    const double accDist = (maxVelocity * maxVelocity - u * u) / (2 * acceleration);
    const double decDist = maxVelocity * maxVelocity / (2 * deceleration);
    double peak = maxVelocity;
    double cruise = 0.0;
    if (accDist + decDist <= remaining) {
        cruise = (remaining - accDist - decDist) / maxVelocity;
    } else {
        peak = std::sqrt((remaining + u * u / (2 * acceleration))
                         / (1 / (2 * acceleration) + 1 / (2 * deceleration)));
        peak = std::max(peak, u);
    }
    p.add((peak - u) / acceleration, s * acceleration);
    p.add(cruise, 0.0);
    p.add(peak / deceleration, -s * deceleration);
    return p;
}

MotionProfile MotionProfile::toVelocity(double p0, double v0, double targetVelocity,
                                        double acceleration, double deceleration)
{
    MotionProfile p;
    p.m_p0 = p0;
    p.m_v0 = v0;
    p.m_finalVelocity = targetVelocity;
    if (acceleration <= kEpsilon || deceleration <= kEpsilon) {
        p.m_v0 = targetVelocity;
        return p;
    }
    double vel = v0;
    if (std::abs(vel) > kEpsilon && sign(vel) != sign(targetVelocity)) {
        p.add(std::abs(vel) / deceleration, -sign(vel) * deceleration); // through zero
        vel = 0;
    }
    const double delta = targetVelocity - vel;
    if (std::abs(targetVelocity) >= std::abs(vel))
        p.add(std::abs(delta) / acceleration, sign(delta) * acceleration);
    else
        p.add(std::abs(delta) / deceleration, sign(delta) * deceleration);
    return p;
}

MotionSample MotionProfile::sample(double t) const
{
    double pos = m_p0;
    double vel = m_v0;
    double elapsed = 0.0;
    for (const Segment &seg : m_segments) {
        const double dt = std::min(seg.duration, t - elapsed);
        if (dt <= 0)
            return { pos, vel, seg.acceleration };
        pos += vel * dt + seg.acceleration * dt * dt / 2;
        vel += seg.acceleration * dt;
        elapsed += dt;
        if (dt < seg.duration)
            return { pos, vel, seg.acceleration };
    }
    if (m_endPosition) // exact end, free of rounding
        return { *m_endPosition, 0.0, 0.0 };
    return { pos + m_finalVelocity * std::max(0.0, t - elapsed), m_finalVelocity, 0.0 };
}

double MotionProfile::duration() const
{
    double total = 0.0;
    for (const Segment &seg : m_segments)
        total += seg.duration;
    return total;
}

double MotionProfile::nextBoundary(double t) const
{
    double total = 0.0;
    for (const Segment &seg : m_segments) {
        total += seg.duration;
        if (total > t + kEpsilon)
            return total;
    }
    return kForever;
}

} // namespace db::sim
