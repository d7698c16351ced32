#include "spindle.h"

#include "devices/nm17x/nm17xcodes.h"

#include <cmath>

namespace db::nm17x {

namespace {
// 204Eh:02 bits
constexpr quint16 kEr1 = 1u << 0;
constexpr quint16 kEr2 = 1u << 1;
constexpr quint16 kEr3 = 1u << 2;
constexpr quint16 kEr4 = 1u << 3;
constexpr quint16 kEr5 = 1u << 4;
constexpr quint16 kEr6 = 1u << 5;
// Er 3 and Er 6 stay shown until the next command that drives the motor.
constexpr quint16 kDriveErrors = kEr3 | kEr6;
constexpr qint32 kMaxSwitchOff = 9999; // 2042h:03
constexpr quint16 kEr8 = 1u << 8;
constexpr quint16 kEr9 = 1u << 9;
constexpr quint16 kErA = 1u << 10;
constexpr quint16 kErB = 1u << 11;
constexpr quint16 kErC = 1u << 12;

// The limit a motor move towards `direction` must not pass.
double limitTowards(int direction, const SpindleSettings &s)
{
    if (direction > 0)
        return s.collision ? qMin(s.endMax, s.collisionMax) : s.endMax;
    return s.collision ? qMax(s.endMin, s.collisionMin) : s.endMin;
}
} // namespace

quint16 Spindle::setTarget(qint32 target, bool withLoop, std::optional<Speed> speed,
                           const SpindleSettings &s)
{
    m_errors &= ~(kEr5 | kEr8 | kEr9 | kErB | kDriveErrors);
    const bool needLoop = withLoop && s.loop > 0 && !s.arrowsWithoutLoop
        && (s.approachDown ? target > m_position : target < m_position);
    const double loopPoint = s.approachDown ? double(target) + s.loop : double(target) - s.loop;
    // The target and, with a loop, the loop point must lie inside the limits.
    quint16 refused = 0;
    for (const double check : { double(target), needLoop ? loopPoint : double(target) }) {
        if (!m_motor)
            break;
        if (check > s.endMax)
            refused |= kEr8;
        else if (check < s.endMin)
            refused |= kEr9;
        else if (s.collision && (check > s.collisionMax || check < s.collisionMin))
            refused |= kErB;
    }
    if (m_phase != Phase::Idle)
        stop(); // a new setpoint ends the running positioning
    m_target = target;
    m_hasTarget = true;
    m_accepted = refused == 0;
    m_inPosition = false;
    m_manualAbort = false;
    m_loopPending = needLoop;
    m_cap = speed;
    m_loopPoint = needLoop ? std::optional<double>(loopPoint) : std::nullopt;
    m_errors |= refused;
    return refused;
}

bool Spindle::driveRefused()
{
    if (m_motorFault) {
        m_errors |= kEr4;
        m_er4Ms = kMotorFaultShownMs;
    }
    return m_motorFault || m_sensorFault;
}

void Spindle::setSensorFault(bool on)
{
    m_sensorFault = on;
    if (on) {
        m_errors |= kErC;
        stop();
    } else {
        m_errors &= ~kErC;
    }
}

bool Spindle::release(const SpindleSettings &s)
{
    if (!m_motor || !m_hasTarget || !m_accepted || driveRefused())
        return false;
    m_jog = 0;
    m_manualAbort = false;
    if (!m_loopPoint && std::abs(m_position - m_target) < 0.5) {
        arrive(s);
        return true;
    }
    if (m_phase == Phase::Running || m_phase == Phase::Dwell)
        return true;
    m_phase = Phase::ClampOpening;
    m_phaseMs = 0;
    return true;
}

quint16 Spindle::start(qint32 target, bool withLoop, std::optional<Speed> speed,
                       const SpindleSettings &s)
{
    const quint16 refused = setTarget(target, withLoop, speed, s);
    if (!refused)
        release(s);
    return refused;
}

void Spindle::jog(int direction, Speed speed, const SpindleSettings &s)
{
    if (!m_motor || direction == 0 || driveRefused())
        return;
    m_errors &= ~kDriveErrors;
    const double limit = limitTowards(direction, s);
    if ((limit - m_position) * direction <= 0)
        return; // already at the limit: the motor may only move back inside
    m_jog = direction;
    m_cap = speed;
    m_loopPoint.reset();
    m_inPosition = false;
    if (m_phase == Phase::Idle || m_phase == Phase::ClampClosing) {
        m_phase = Phase::ClampOpening;
        m_phaseMs = 0;
    } else {
        enterRunning();
    }
}

void Spindle::failWith(quint16 error)
{
    m_errors |= error;
    m_direction = 0;
    stop();
}

double Spindle::speedOfStage() const
{
    return m_speedStage == Speed::Fast  ? m_model.fast
        : m_speedStage == Speed::Medium ? m_model.medium
                                        : m_model.slow;
}

void Spindle::stop()
{
    m_jog = 0;
    m_loopPoint.reset();
    if (m_phase == Phase::Running && m_direction != 0 && !m_blocked)
        m_position +=
            (m_reversed ? -m_direction : m_direction) * speedOfStage() * m_model.coastMs / 1000.0;
    m_direction = 0;
    if (m_phase == Phase::Idle || m_phase == Phase::ClampClosing)
        return;
    m_phase = Phase::ClampClosing;
    m_phaseMs = 0;
}

void Spindle::abortByKey()
{
    if (m_phase == Phase::Idle)
        return;
    stop();
    m_manualAbort = true;
}

void Spindle::turnByHand(double delta, const SpindleSettings &s)
{
    if (m_phase == Phase::Running)
        return; // the motor holds the shaft
    m_position += delta;
    if (m_hasTarget) {
        const double loopPoint =
            s.approachDown ? double(m_target) + s.loop : double(m_target) - s.loop;
        if (m_loopPending && (s.approachDown ? m_position >= loopPoint : m_position <= loopPoint))
            m_loopPending = false;
        const bool fromLoopSide =
            s.loop == 0 || s.arrowsWithoutLoop || (s.approachDown ? delta < 0 : delta > 0);
        const bool inWindow = std::abs(m_position - m_target) <= s.tolerance;
        m_inPosition = inWindow && !m_loopPending && (m_inPosition || fromLoopSide);
    }
    checkLimits(s);
}

void Spindle::checkLimits(const SpindleSettings &s)
{
    m_errors &= ~(kEr1 | kEr2 | kErA);
    if (!m_motor)
        return;
    if (m_position > s.endMax)
        m_errors |= kEr1;
    else if (m_position < s.endMin)
        m_errors |= kEr2;
    else if (s.collision && (m_position > s.collisionMax || m_position < s.collisionMin))
        m_errors |= kErA;
}

double Spindle::speedFor(double remaining, const SpindleSettings &s)
{
    Speed stage = Speed::Slow;
    if (s.slowPoint > s.creepPoint)
        stage = remaining > s.slowPoint ? Speed::Fast
            : remaining > s.creepPoint  ? Speed::Medium
                                        : Speed::Slow;
    else
        stage = remaining > s.creepPoint ? Speed::Fast : Speed::Slow;
    if (m_cap && int(*m_cap) < int(stage))
        stage = *m_cap;
    m_speedStage = stage;
    return stage == Speed::Fast  ? m_model.fast
        : stage == Speed::Medium ? m_model.medium
                                 : m_model.slow;
}

void Spindle::arrive(const SpindleSettings &s)
{
    m_inPosition = std::abs(m_position - m_target) <= s.tolerance;
    m_loopPending = false;
    if (!m_inPosition)
        m_errors |= kEr5;
    m_direction = 0;
    m_phase = Phase::ClampClosing;
    m_phaseMs = 0;
}

void Spindle::tick(int ms, const SpindleSettings &s)
{
    if (m_er4Ms > 0 && (m_er4Ms -= ms) <= 0)
        m_errors &= ~kEr4;
    switch (m_phase) {
    case Phase::Idle:
        return;
    case Phase::ClampOpening:
        m_phaseMs += ms;
        if (m_phaseMs >= s.clampMs)
            enterRunning();
        return;
    case Phase::Dwell:
        m_phaseMs += ms;
        if (m_phaseMs >= s.dwellMs)
            enterRunning();
        return;
    case Phase::ClampClosing:
        m_direction = 0;
        m_phaseMs += ms;
        if (m_phaseMs >= s.clampMs)
            m_phase = Phase::Idle;
        return;
    case Phase::Running:
        break;
    }
    const double goal =
        m_jog != 0 ? limitTowards(m_jog, s) : (m_loopPoint ? *m_loopPoint : double(m_target));
    const int direction = m_jog != 0 ? m_jog : (goal >= m_position ? 1 : -1);
    m_direction = direction;
    // The switch-off point applies at the target only, not at the loop point or a limit.
    const double stopAt = (m_jog == 0 && !m_loopPoint) ? s.switchOff : 0.0;
    const double remaining = (goal - m_position) * direction;
    const double step = speedFor(remaining, s) * ms / 1000.0;
    if (m_blocked) {
        // Driven, but the shaft stands: the following error time runs out (Er 3).
        if ((m_stuckMs += ms) >= s.followingErrorMs)
            failWith(kEr3);
        return;
    }
    if (m_reversed) {
        // The shaft turns against the direction signal; the device notices it after a short
        // travel (Er 6).
        m_position -= direction * step;
        if ((m_wrongWay += step) >= m_model.directionErrorTravel)
            failWith(kEr6);
        return;
    }
    if (remaining - step > stopAt) {
        m_position += direction * step;
        return;
    }
    // Motor off at the switch-off point; the spindle runs on by its coasting.
    m_position = goal - direction * stopAt + direction * speedOfStage() * m_model.coastMs / 1000.0;
    if (m_jog != 0) {
        m_direction = 0;
        stop(); // Tippen ends at the limit
    } else if (m_loopPoint) {
        m_loopPoint.reset();
        m_phase = Phase::Dwell;
        m_phaseMs = 0;
    } else {
        if (s.preShutdown) {
            // Dynamic pre-shutdown: half the miss moves the switch-off point (an overshoot
            // switches off earlier next time). Our reading: the device keeps the adapted value
            // in 2042h:03, so the master reads what is used.
            const double miss = (m_position - m_target) * direction;
            m_newSwitchOff =
                qBound(-kMaxSwitchOff, s.switchOff + qint32(qRound(miss / 2)), kMaxSwitchOff);
        }
        arrive(s);
    }
}

void Spindle::enterRunning()
{
    m_phase = Phase::Running;
    m_stuckMs = 0;
    m_wrongWay = 0;
}

quint16 Spindle::status(const SpindleSettings &s) const
{
    quint16 bits = 0;
    if (m_phase != Phase::Idle)
        bits |= status::Moving;
    if (m_manualAbort)
        bits |= status::ManualAbort;
    if (m_phase == Phase::Running) {
        bits |= m_speedStage == Speed::Fast ? (status::In3 | status::In4)
            : m_speedStage == Speed::Medium ? status::In4
                                            : status::In3;
        bits |= m_direction > 0 ? status::In2Right : status::In1Left;
    }
    const bool away = m_hasTarget && std::abs(m_position - m_target) > s.tolerance;
    if (m_hasTarget && (away || !m_inPosition))
        bits |= status::ArrowsActive;
    if (m_inPosition)
        bits |= status::InPosition;
    return bits;
}

} // namespace db::nm17x
