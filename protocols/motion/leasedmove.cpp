#include "leasedmove.h"

#include <algorithm>
#include <cmath>

namespace db::motion {

LeasedMove::LeasedMove(MotionAxis *axis, QObject *parent)
    : QObject(parent)
    , m_axis(axis)
    , m_move(std::make_unique<MotionCommand>(axis, CommandKind::MoveRelative))
    , m_halt(std::make_unique<MotionCommand>(axis, CommandKind::Halt))
{
    m_timer.setObjectName(QStringLiteral("leaseRenewTimer"));
    m_timer.setInterval(kRenewMs);
    connect(&m_timer, &QTimer::timeout, this, &LeasedMove::renew);
    connect(m_move.get(), &MotionCommand::statusChanged, this, [this](MotionCommand::Status s) {
        if (m_direction == 0)
            return;
        const bool over = s == MotionCommand::Status::Error
            || s == MotionCommand::Status::CommandAborted
            || (s == MotionCommand::Status::Done && (m_lastLeg || !m_timer.isActive()));
        if (!over)
            return;
        m_timer.stop();
        m_direction = 0;
        Q_EMIT ended(s);
    });
    connect(m_halt.get(), &MotionCommand::statusChanged, this, [this](MotionCommand::Status s) {
        if (s == MotionCommand::Status::Done)
            m_halt->setExecute(false); // MC_Halt holds its state until Execute is released
    });
}

LeasedMove::~LeasedMove() = default;

double LeasedMove::effectiveVelocity() const
{
    const double v = std::abs(m_profile.velocity) * m_axis->velocityOverride() / 100.0;
    return std::min(v, m_axis->config().maxVelocity);
}

double LeasedMove::effectiveDeceleration() const
{
    return std::min(std::abs(m_profile.deceleration), m_axis->config().maxAcceleration);
}

double LeasedMove::leaseTravel() const
{
    const double v = effectiveVelocity();
    const double dec = effectiveDeceleration();
    if (v <= 0 || dec <= 0)
        return 0.0;
    return v * kLeaseMs / 1000.0 + v * v / (2 * dec);
}

double LeasedMove::leaseTimeMs() const
{
    const double v = effectiveVelocity();
    const double dec = effectiveDeceleration();
    return kLeaseMs + (dec > 0 ? 1000.0 * v / dec : 0.0);
}

void LeasedMove::jog(int direction, const MoveParams &profile)
{
    const AxisConfig &c = m_axis->config();
    std::optional<double> goal;
    if (c.softLimitsUsed && !c.endless)
        goal = direction > 0 ? c.softLimitPositive : c.softLimitNegative;
    begin(direction, goal, profile);
}

void LeasedMove::step(double distance, const MoveParams &profile)
{
    const auto s = m_axis->axis()->status();
    begin(distance >= 0 ? 1 : -1, s.position + distance, profile);
}

void LeasedMove::begin(int direction, std::optional<double> goal, const MoveParams &profile)
{
    m_profile = profile;
    m_profile.velocity = std::abs(profile.velocity);
    m_goal = goal;
    m_direction = direction > 0 ? 1 : -1;
    m_lastLeg = false;
    m_move->setExecute(false); // a fresh edge, also when the previous lease still runs
    m_timer.start();
    renew();
}

void LeasedMove::renew()
{
    if (m_direction == 0 || m_lastLeg) {
        m_timer.stop();
        return;
    }
    if (m_move->status() == MotionCommand::Status::Busy)
        return; // the drive has not taken the previous renewal yet
    const AxisInterface::Status s = m_axis->axis()->status();
    double travel = leaseTravel();
    if (travel <= 0 && m_move->execute())
        return; // override 0: the running command holds the axis until it rises again
    if (m_goal) {
        const double remaining = (*m_goal - s.position) * m_direction;
        if (remaining <= travel) {
            travel = std::max(remaining, 0.0);
            m_lastLeg = true;
            m_timer.stop();
        }
    }
    MoveParams p = m_profile;
    p.position = m_direction * travel;
    m_renewedAt = s.position;
    m_move->setParams(p);
    m_move->setExecute(false);
    m_move->setExecute(true);
}

void LeasedMove::halt()
{
    const bool running = m_direction != 0;
    stopRenewing();
    if (!running)
        return;
    m_halt->setParams(m_profile);
    m_halt->setExecute(false);
    m_halt->setExecute(true);
}

void LeasedMove::stopRenewing()
{
    m_timer.stop();
    m_direction = 0;
}

} // namespace db::motion
