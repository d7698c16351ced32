#include "motionaxis.h"

#include <QCoreApplication>
#include <algorithm>
#include <cmath>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::motion)
};

// How far the position is from the target. On an endless axis modulo the cycle: the drive may
// report its position wrapped into the cycle (a rotary MovingCap) while targets are unwrapped.
double offTarget(const db::motion::AxisConfig &c, double position, double target)
{
    const double d = position - target;
    if (!c.endless || c.cycleLength <= 0)
        return std::abs(d);
    const double m = d - c.cycleLength * std::floor(d / c.cycleLength); // [0, cycle)
    return std::min(m, c.cycleLength - m);
}
} // namespace

namespace db::motion {

MotionAxis::MotionAxis(AxisInterface *axis, QObject *parent)
    : QObject(parent)
    , m_axis(axis)
{
    m_watchdog.setSingleShot(true);
    connect(&m_watchdog, &QTimer::timeout, this, [this] {
        if (!motionInProgress())
            return;
        Q_EMIT watchdogExpired();
        emergencyStop(Error(Error::Kind::Timeout,
                            Tr::tr("deadman watchdog: no keep-alive for %1 ms, axis stopped")
                                .arg(m_watchdogMs)),
                      true);
    });
    connect(axis, &AxisInterface::statusChanged, this, &MotionAxis::onStatus);
    connect(axis, &AxisInterface::connectionLost, this, &MotionAxis::onConnectionLost);
    connect(axis, &AxisInterface::supervisionLost, this, &MotionAxis::onSupervisionLost);
}

MotionAxis::~MotionAxis() = default;

// ---- safety ----------------------------------------------------------------------------------

void MotionAxis::setWatchdogTimeout(int ms)
{
    m_watchdogMs = ms <= 0 ? 0 : std::clamp(ms, 1, kMaxWatchdogMs);
    if (m_watchdogMs == 0)
        m_watchdog.stop();
    else
        m_watchdog.start(m_watchdogMs);
}

void MotionAxis::keepAlive()
{
    if (m_watchdogMs > 0)
        m_watchdog.start(m_watchdogMs);
}

void MotionAxis::stopNow()
{
    emergencyStop(Error(Error::Kind::Cancelled, Tr::tr("stopped (stop now)")), false);
}

void MotionAxis::emergencyStop(const Error &cause, bool asError)
{
    whenFinished(m_axis->stopNow(), [](Reply *) {});
    abortActive(asError ? MotionCommand::Status::Error : MotionCommand::Status::CommandAborted,
                cause);
    m_lastError = cause;
    if (m_state != AxisState::Disabled)
        setState(AxisState::ErrorStop);
}

bool MotionAxis::controlsAxis(const MotionCommand *command) const
{
    // A done MC_MoveVelocity still drives the axis (Done = velocity reached, Sec. 6.4).
    return command->isBusy()
        || (command->kind() == CommandKind::MoveVelocity
            && command->status() == MotionCommand::Status::Done
            && m_state == AxisState::ContinuousMotion)
        // A done MC_GearIn (in gear) keeps the axis coupled to its master.
        || (command->kind() == CommandKind::GearIn
            && command->status() == MotionCommand::Status::Done
            && m_state == AxisState::SynchronizedMotion);
}

bool MotionAxis::motionInProgress() const
{
    if (m_active && controlsAxis(m_active))
        return true;
    const auto s = m_axis->status();
    if (s.valid && (s.moving || std::abs(s.velocity) > m_config.velocityWindow))
        return true;
    return m_state == AxisState::DiscreteMotion || m_state == AxisState::ContinuousMotion
        || m_state == AxisState::SynchronizedMotion || m_state == AxisState::Homing
        || m_state == AxisState::Stopping;
}

// ---- starting commands -----------------------------------------------------------------------

void MotionAxis::start(MotionCommand *command)
{
    if (command->kind() != CommandKind::DoNothing)
        Q_EMIT commandStarted(command);
    switch (command->kind()) {
    case CommandKind::Power:
        startPower(command);
        return;
    case CommandKind::Reset:
        startReset(command);
        return;
    case CommandKind::DoNothing:
        return; // no status information (Sec. 3.0)
    default:
        startMotion(command);
        return;
    }
}

AxisSnapshot MotionAxis::snapshot(CommandKind kind) const
{
    const auto s = m_axis->status();
    AxisSnapshot a;
    // A round read while the last command was taken may still show the motion it ended.
    a.driveMoving = s.valid && (s.moving || std::abs(s.velocity) > m_config.velocityWindow)
        && m_rounds > m_acceptedRound + 1;
    a.modeChangeNeeded = m_axis->needsModeChange(kind);
    a.electronicGear = m_axis->features().testFlag(AxisInterface::Feature::ElectronicGear);
    a.state = m_state;
    a.position = s.position;
    a.velocity = std::abs(s.velocity) > m_config.velocityWindow ? s.velocity : 0.0;
    a.referenced = m_referenced;
    a.hardwareLimitPositive = s.hardwareLimitPositive;
    a.hardwareLimitNegative = s.hardwareLimitNegative;
    // [I] braking distance with the maximum deceleration.
    if (m_config.maxAcceleration > 0)
        a.brakingDistance = a.velocity * a.velocity / (2 * m_config.maxAcceleration);
    return a;
}

Plan MotionAxis::preview(CommandKind kind, const MoveParams &params) const
{
    const AxisSnapshot axis = snapshot(kind);
    MoveParams inputs = params;
    if (usesOverride(kind))
        inputs.overridePercent *= m_override / 100.0;
    return planCommand(kind, inputs, m_config, axis,
                       m_tracker.origin(axis.position, m_config.positionWindow));
}

void MotionAxis::startMotion(MotionCommand *command)
{
    const quint64 generation = ++command->m_generation;
    command->m_limits = {};
    command->setStatus(MotionCommand::Status::Busy); // S-30: Busy (no error) first
    const AxisSnapshot axis = snapshot(command->kind());
    AxisConfig config = m_config;
    if (command->kind() == CommandKind::Home)
        config.homingMethod = command->m_latchedHoming.method;
    MoveParams inputs = command->m_latched;
    if (usesOverride(command->kind()))
        inputs.overridePercent *= m_override / 100.0;
    const Plan plan = planCommand(command->kind(), inputs, config, axis,
                                  m_tracker.origin(axis.position, m_config.positionWindow));
    command->m_limits = plan.flags;
    if (plan.refused()) {
        refuse(command, plan);
        return;
    }
    const bool renewal = m_active == command && controlsAxis(command);
    if (m_active && m_active != command && controlsAxis(m_active))
        m_active->setStatus(
            MotionCommand::Status::CommandAborted,
            Error(Error::Kind::Cancelled, Tr::tr("aborted by %1").arg(command->name())));
    m_active = command;
    m_activeVelocity = plan.profile.velocity;
    m_activeParams = command->m_latched;
    m_overrideHeld = false;
    m_inWindow.invalidate();
    if (isPositioning(command->kind())) {
        command->m_target = plan.target;
        m_tracker.setTarget(plan.target);
    }
    setState(plan.nextState);
    if (command->kind() == CommandKind::Home)
        m_referenced = false; // until this homing completes
    if (!renewal)
        keepAlive(); // a new motion gets a full watchdog period; a renewed set-point does not
    QPointer<MotionCommand> guard(command);
    whenFinished(request(command, plan), [=, this](Reply *r) { onAccepted(guard, generation, r); });
}

Reply *MotionAxis::request(MotionCommand *command, const Plan &plan)
{
    const AxisInterface::Profile p { plan.profile.velocity, plan.profile.acceleration,
                                     plan.profile.deceleration, plan.profile.jerk };
    switch (command->kind()) {
    case CommandKind::MoveAbsolute:
    case CommandKind::MoveRelative:
    case CommandKind::MoveAdditive:
        if (plan.profile.velocity == 0.0) { // override 0 at the start: stand until it rises
            m_overrideHeld = true;
            return m_axis->halt(plan.profile.deceleration);
        }
        return m_axis->moveTo(plan.target, p);
    case CommandKind::MoveVelocity:
        return m_axis->moveVelocity(plan.profile.velocity, p);
    case CommandKind::Stop:
    case CommandKind::Halt:
        return m_axis->halt(plan.profile.deceleration);
    case CommandKind::Home:
        return m_axis->home(clampHoming(command->m_latchedHoming, m_config));
    case CommandKind::TorqueControl:
        return m_axis->torque(command->m_latched.torque, command->m_latched.acceleration);
    case CommandKind::MotionBlock:
        return m_axis->startMotionBlock(command->m_latched.block, command->m_latched.sequence,
                                        command->m_latched.resume);
    case CommandKind::GearIn:
        return m_axis->gearIn(command->m_latched.gearNumerator, command->m_latched.gearDenominator,
                              plan.profile.acceleration, plan.profile.deceleration);
    case CommandKind::GearOut:
        return m_axis->gearOut(plan.profile.deceleration);
    case CommandKind::DoNothing:
    case CommandKind::Power:
    case CommandKind::Reset:
        break;
    }
    return Reply::failed({}, Error(Error::Kind::NotSupported, command->name()));
}

void MotionAxis::refuse(MotionCommand *command, const Plan &plan)
{
    QString reason = refusalText(plan.refusal);
    if (plan.refusal == Refusal::FeatureMissing && !m_axis->featureNote().isEmpty())
        reason += QStringLiteral(" (%1)").arg(m_axis->featureNote());
    const Error error(Error::Kind::InvalidArgument,
                      Tr::tr("%1 refused: %2").arg(command->name(), reason));
    QPointer<MotionCommand> guard(command);
    auto later = [guard](MotionCommand::Status status, Error e, Refusal refusal) {
        // After Busy, from the event loop: every start shows a fresh edge (S-30).
        const quint64 generation = guard->m_generation;
        QMetaObject::invokeMethod(
            guard,
            [=] {
                if (guard && guard->m_generation == generation)
                    guard->setStatus(status, e, refusal);
            },
            Qt::QueuedConnection);
    };
    if (plan.successAtStandstill) {
        later(MotionCommand::Status::Done, {}, Refusal::None); // S-22b, S-25
        return;
    }
    // R10 leaves the running MC_Stop alone; a mode change the drive cannot make now leaves the
    // running motion alone.
    if (plan.refusal != Refusal::StopActive && plan.refusal != Refusal::ModeChangeWhileMoving
        && plan.refusal != Refusal::FeatureMissing) {
        if (motionInProgress())
            emergencyStop(error, false); // D-10: quick stop of the running motion
        m_lastError = error;
        if (m_state != AxisState::Disabled)
            setState(AxisState::ErrorStop);
    }
    later(MotionCommand::Status::Error, error, plan.refusal);
}

void MotionAxis::onAccepted(MotionCommand *command, quint64 generation, Reply *reply)
{
    if (!command || command->m_generation != generation || m_active != command)
        return;
    if (!reply->ok()) {
        if (reply->error().kind() == Error::Kind::Cancelled)
            return; // superseded: whoever superseded it has set the status
        command->setStatus(MotionCommand::Status::Error, reply->error());
        m_lastError = reply->error();
        m_active = nullptr;
        setState(AxisState::ErrorStop);
        return;
    }
    m_acceptedRound = m_rounds;
    switch (command->kind()) {
    case CommandKind::Home:
        m_referenced = true;
        m_tracker.clear();
        m_active = nullptr;
        setState(AxisState::Standstill);
        command->setStatus(MotionCommand::Status::Done);
        return;
    case CommandKind::TorqueControl:
        command->setStatus(MotionCommand::Status::Active);
        command->setStatus(MotionCommand::Status::Done); // [I] at once (S-31 "2nd cycle")
        return;
    case CommandKind::GearIn: // its reply finishes when the drive reports "in gear"
        m_tracker.clear(); // the master decides where the axis goes
        command->setStatus(MotionCommand::Status::Active);
        command->setStatus(MotionCommand::Status::Done); // PLCopen's InGear
        return;
    case CommandKind::MotionBlock: // its reply finishes when the block (or sequence) ended
        m_tracker.clear(); // the drive chose the target
        m_active = nullptr;
        setState(AxisState::Standstill);
        command->setStatus(MotionCommand::Status::Active);
        command->setStatus(MotionCommand::Status::Done);
        return;
    default:
        command->setStatus(MotionCommand::Status::Active);
        return;
    }
}

// ---- status ----------------------------------------------------------------------------------

void MotionAxis::onStatus()
{
    const auto s = m_axis->status();
    if (!s.valid)
        return;
    ++m_rounds;
    m_tracker.observe(s.position, m_config.positionWindow);
    if (s.homingAttained && !(m_active && m_active->kind() == CommandKind::Home))
        m_referenced = true; // the drive says so (not a stale bit of the homing just started)
    // The drive was enabled before this model saw it (e.g. by an earlier CLI call), or by
    // someone else (web UI, another tool): PLCopen's state follows the drive. Two rounds in a
    // row, so that a status read still in flight while MC_Power switched off does not count.
    m_externalOnRounds = s.powered && !s.fault && m_state == AxisState::Disabled && !m_powerWanted
        ? m_externalOnRounds + 1
        : 0;
    if (s.powered && !s.fault && m_state == AxisState::Disabled
        && (m_rounds == 1 || m_externalOnRounds >= 2)) {
        m_powerWanted = true;
        m_externalOnRounds = 0;
        setState(AxisState::Standstill);
    }
    if (s.fault && m_state != AxisState::ErrorStop) {
        const Error e(
            Error::Kind::DeviceError,
            Tr::tr("drive fault (statusword 0x%1)").arg(s.rawStatus, 4, 16, QLatin1Char('0')));
        abortActive(MotionCommand::Status::Error, e);
        m_lastError = e;
        m_tracker.enableOff();
        setState(AxisState::ErrorStop);
        return;
    }
    if (!s.powered) {
        if (m_powerWanted && m_state != AxisState::Disabled && m_state != AxisState::ErrorStop) {
            const Error e(Error::Kind::DeviceError, Tr::tr("power stage switched off"));
            abortActive(MotionCommand::Status::Error, e);
            m_lastError = e;
            m_tracker.enableOff();
            setState(s.quickStopActive ? AxisState::ErrorStop : AxisState::Disabled);
        }
        return;
    }
    evaluateActive(s);
}

void MotionAxis::evaluateActive(const AxisInterface::Status &s)
{
    MotionCommand *c = m_active;
    // Only rounds read completely after the drive took the set-point count.
    if (!c || c->status() != MotionCommand::Status::Active || m_rounds <= m_acceptedRound + 1)
        return;
    switch (c->kind()) {
    case CommandKind::MoveAbsolute:
    case CommandKind::MoveRelative:
    case CommandKind::MoveAdditive:
        // The drive stands with its profile finished (target reached) away from our target:
        // halted or stopped by someone else (another program, the web page, an input). The
        // command ends now instead of waiting for a target that no longer comes. A round more
        // than above: a new set-point clears target reached only once the drive has taken it.
        if (!m_overrideHeld && s.targetReached && !s.moving
            && std::abs(s.velocity) <= m_config.velocityWindow
            && offTarget(m_config, s.position, c->m_target) > m_config.positionWindow
            && m_rounds > m_acceptedRound + 2) {
            m_active = nullptr;
            setState(AxisState::Standstill);
            c->setStatus(MotionCommand::Status::CommandAborted,
                         Error(Error::Kind::DeviceError,
                               Tr::tr("%1: the drive stopped at %2, short of the target %3 "
                                      "(halted by another program or the drive itself)")
                                   .arg(c->name())
                                   .arg(s.position, 0, 'f', 1)
                                   .arg(c->m_target, 0, 'f', 1)));
            return;
        }
        // I180 (in window) may rise while still moving; Done = profile finished (not moving)
        // and in the window for I87 since I180 rose (S-03, S-04).
        if (m_overrideHeld
            || offTarget(m_config, s.position, c->m_target) > m_config.positionWindow) {
            m_inWindow.invalidate();
            return;
        }
        if (!m_inWindow.isValid())
            m_inWindow.start();
        if (!s.moving && m_inWindow.elapsed() >= m_config.positionWindowTimeMs) {
            m_active = nullptr;
            setState(AxisState::Standstill); // [I] A12
            c->setStatus(MotionCommand::Status::Done);
        }
        return;
    case CommandKind::MoveVelocity:
        if (std::abs(s.velocity - m_activeVelocity) <= m_config.velocityWindow)
            c->setStatus(MotionCommand::Status::Done); // velocity reached; keeps moving
        return;
    case CommandKind::GearOut: // uncoupled: the drive brakes the slave to a stop
        if (!s.moving && std::abs(s.velocity) <= m_config.velocityWindow) {
            m_active = nullptr;
            setState(AxisState::Standstill);
            c->setStatus(MotionCommand::Status::Done);
        }
        return;
    case CommandKind::Stop:
    case CommandKind::Halt:
        if (!s.moving && std::abs(s.velocity) <= m_config.velocityWindow) {
            c->setStatus(MotionCommand::Status::Done);
            if (!c->execute()) {
                m_active = nullptr;
                setState(AxisState::Standstill);
            }
        }
        return;
    default:
        return;
    }
}

void MotionAxis::executeReleased(MotionCommand *command)
{
    // MC_Stop / MC_Halt hold their state until standstill AND Execute released (Sec. 3.12).
    const bool stopOrHalt =
        command->kind() == CommandKind::Stop || command->kind() == CommandKind::Halt;
    if (command == m_active && stopOrHalt && command->status() == MotionCommand::Status::Done) {
        m_active = nullptr;
        setState(AxisState::Standstill);
    }
}

void MotionAxis::forget(MotionCommand *command)
{
    if (m_active == command)
        m_active = nullptr;
}

void MotionAxis::onConnectionLost(const Error &error)
{
    const Error cause = error.prefixed(Tr::tr("connection lost"));
    abortActive(MotionCommand::Status::Error, cause);
    m_lastError = cause;
    if (m_state != AxisState::Disabled)
        setState(AxisState::ErrorStop);
}

// The drive may still hear us (only its heartbeat is missing): it is told to stop, and the
// running command ends with the cause. An axis at rest is left alone.
void MotionAxis::onSupervisionLost(const QString &reason)
{
    if (!m_active && !motionInProgress())
        return;
    emergencyStop(Error(Error::Kind::Disconnected, reason), true);
}

void MotionAxis::abortActive(MotionCommand::Status status, const Error &error)
{
    if (m_active && controlsAxis(m_active)) {
        ++m_active->m_generation; // late drive answers no longer count
        m_active->setStatus(status, error);
    }
    m_active = nullptr;
}

void MotionAxis::setState(AxisState state)
{
    if (state == m_state)
        return;
    m_state = state;
    Q_EMIT stateChanged(state);
}

void MotionAxis::whenFinished(Reply *reply, std::function<void(Reply *)> done)
{
    reply->setParent(this); // an axis that goes first takes its requests with it
    connect(reply, &Reply::finished, this, [reply, done = std::move(done)] {
        done(reply);
        reply->deleteLater();
    });
}

} // namespace db::motion
