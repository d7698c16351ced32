#include "motioncommand.h"

#include "motionaxis.h"

namespace db::motion {

MotionCommand::MotionCommand(MotionAxis *axis, CommandKind kind, QObject *parent)
    : QObject(parent)
    , m_axis(axis)
    , m_kind(kind)
{ }

MotionCommand::~MotionCommand()
{
    if (m_axis)
        m_axis->forget(this);
}

void MotionCommand::setExecute(bool execute)
{
    const bool rising = execute && !m_execute;
    const bool falling = !execute && m_execute;
    m_execute = execute;
    if (!m_axis)
        return;
    if (rising) {
        m_latched = m_params;
        m_latchedHoming = m_homing;
        m_latchedEnable = m_enable;
        m_axis->start(this);
    } else if (falling) {
        m_axis->executeReleased(this);
    }
}

void MotionCommand::setStatus(Status status, const Error &error, Refusal refusal)
{
    if (status == m_status && status != Status::Busy)
        return;
    m_status = status;
    m_error = error;
    m_refusal = refusal;
    Q_EMIT statusChanged(status);
}

} // namespace db::motion
