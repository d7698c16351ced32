// MotionAxis: the velocity override I230 (stoeber_motion.md Sec. 2.7, 7.2 K408, 8.3 item 11).
#include "motionaxis.h"

#include <QCoreApplication>
#include <algorithm>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::motion)
};
} // namespace

namespace db::motion {

bool MotionAxis::usesOverride(CommandKind kind)
{
    // Sec. 2.7: considered by 1-4, 6 and 8; MC_Home's speeds are not scaled here [I].
    return isPositioning(kind) || kind == CommandKind::MoveVelocity;
}

void MotionAxis::setVelocityOverride(double percent)
{
    percent = std::clamp(percent, 0.0, kMaxOverridePercent);
    if (percent == m_override)
        return;
    m_override = percent;
    MotionCommand *c = m_active;
    if (!c || !controlsAxis(c) || !usesOverride(c->kind()))
        return; // takes effect at the next start
    MoveParams inputs = m_activeParams;
    inputs.overridePercent *= m_override / 100.0;
    LimitFlags flags;
    const MoveParams p = clampProfile(inputs, m_config, &flags);
    c->m_limits = flags;
    const AxisInterface::Profile profile { p.velocity, p.acceleration, p.deceleration, p.jerk };
    Reply *reply = nullptr;
    if (isPositioning(c->kind())) {
        // The latched target stays; only the profile velocity changes (set-point again).
        m_overrideHeld = p.velocity == 0.0;
        reply =
            m_overrideHeld ? m_axis->halt(p.deceleration) : m_axis->moveTo(c->m_target, profile);
    } else {
        m_activeVelocity = p.velocity;
        reply = m_axis->moveVelocity(p.velocity, profile);
    }
    m_acceptedRound = m_rounds; // rounds read before the new set-point do not count
    const quint64 generation = c->m_generation;
    QPointer<MotionCommand> guard(c);
    whenFinished(reply, [=, this](Reply *r) {
        if (!guard || guard->m_generation != generation || m_active != guard
            || (!r->ok() && r->error().kind() == Error::Kind::Cancelled))
            return;
        if (r->ok()) {
            // The first set-point may have been superseded by this one before it was taken.
            if (guard->status() == MotionCommand::Status::Busy)
                guard->setStatus(MotionCommand::Status::Active);
            return;
        }
        guard->setStatus(MotionCommand::Status::Error,
                         r->error().prefixed(Tr::tr("velocity override")));
        m_lastError = guard->error();
        m_active = nullptr;
        setState(AxisState::ErrorStop);
    });
}

} // namespace db::motion
