// MotionAxis: the administrative blocks MC_Power and MC_Reset.
#include "motionaxis.h"
#include <QCoreApplication>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::motion)
};
} // namespace

namespace db::motion {

void MotionAxis::startPower(MotionCommand *command)
{
    const quint64 generation = ++command->m_generation;
    command->setStatus(MotionCommand::Status::Busy);
    const bool on = command->m_latchedEnable;
    m_powerWanted = on;
    if (!on) {
        abortActive(MotionCommand::Status::CommandAborted,
                    Error(Error::Kind::Cancelled, Tr::tr("power switched off")));
        m_tracker.enableOff();
    }
    QPointer<MotionCommand> guard(command);
    whenFinished(m_axis->power(on), [=, this](Reply *r) {
        if (!guard || guard->m_generation != generation)
            return;
        if (!r->ok()) {
            guard->setStatus(MotionCommand::Status::Error, r->error());
            return;
        }
        if (!on)
            setState(AxisState::Disabled);
        else if (m_state == AxisState::Disabled)
            setState(AxisState::Standstill);
        guard->setStatus(MotionCommand::Status::Done);
    });
}

void MotionAxis::startReset(MotionCommand *command)
{
    const quint64 generation = ++command->m_generation;
    command->setStatus(MotionCommand::Status::Busy);
    QPointer<MotionCommand> guard(command);
    auto finish = [=, this](Reply *r, AxisState state) {
        if (!guard || guard->m_generation != generation)
            return;
        if (!r->ok()) {
            guard->setStatus(MotionCommand::Status::Error, r->error());
            return;
        }
        m_lastError = {};
        setState(state);
        guard->setStatus(MotionCommand::Status::Done);
    };
    whenFinished(m_axis->reset(), [=, this](Reply *r) {
        if (!r->ok() || !m_powerWanted) {
            finish(r, AxisState::Disabled);
            return;
        }
        // ErrorStop left the power stage in quick stop or off: enable it again.
        whenFinished(m_axis->power(true), [=](Reply *r2) { finish(r2, AxisState::Standstill); });
    });
}

} // namespace db::motion
