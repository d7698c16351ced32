#include "targettracker.h"

#include <cmath>

namespace db::motion {

void TargetTracker::setTarget(double target)
{
    m_target = target;
    m_reached = false;
    m_left = false;
    m_disabled = false;
}

void TargetTracker::enableOff()
{
    m_disabled = true;
}

void TargetTracker::observe(double actual, double window)
{
    if (!m_target)
        return;
    const bool inside = std::abs(actual - *m_target) <= window;
    if (inside && !m_left)
        m_reached = true;
    else if (!inside && m_reached)
        m_left = true;
}

void TargetTracker::clear()
{
    *this = TargetTracker();
}

double TargetTracker::origin(double actual, double window) const
{
    if (!m_target)
        return actual; // rule 2
    if (!m_disabled)
        return *m_target; // rules 1 and 3
    const bool stays = m_reached && !m_left && std::abs(actual - *m_target) <= window;
    return stays ? *m_target : actual; // rule 4
}

} // namespace db::motion
