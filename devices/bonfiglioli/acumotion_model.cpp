// The simulated ACU's motion model: one step of the ramps every kTickMs for the mode in 1454,
// and the actual values it publishes.
#include "acumotion.h"

#include "acumotion_p.h"

#include <cmath>

namespace db::bonfiglioli {

using namespace acumotion;

// Accelerates or brakes towards `target` velocity with constant ramps.
void AcuMotion::rampVelocity(double target, double acc, double dec, double dt)
{
    const bool speedingUp = std::abs(target) > std::abs(m_velocity) && (target * m_velocity >= 0.0);
    const double step = (speedingUp ? acc : dec) * dt;
    if (std::abs(target - m_velocity) <= step)
        m_velocity = target;
    else
        m_velocity += target > m_velocity ? step : -step;
}

// Trapezoidal profile to `target`: brakes when the remaining distance is the braking distance.
void AcuMotion::moveTowards(double target, double vmax, double acc, double dec, double dt)
{
    const double remaining = target - m_position;
    const double braking = m_velocity * m_velocity / (2.0 * dec);
    double wanted = remaining > 0 ? vmax : -vmax;
    if (std::abs(remaining) <= braking + std::abs(m_velocity) * dt)
        wanted = remaining > 0 ? std::sqrt(2.0 * dec * std::abs(remaining))
                               : -std::sqrt(2.0 * dec * std::abs(remaining));
    rampVelocity(wanted, acc, dec, dt);
    const double travel = m_velocity * dt;
    if (std::abs(remaining) <= std::abs(travel) || std::abs(remaining) < 0.5) {
        m_position = target;
        m_velocity = 0.0;
        m_positioning = false;
        return;
    }
    m_position += travel;
}

void AcuMotion::tick()
{
    const double dt = std::min(0.05, m_clock.restart() / 1000.0) * m_timeScale;
    if (mode() != -3 || m_state != State::OperationEnabled || bit(m_word, 8))
        m_gearCoupledMs = -1.0; // halt (or leaving the gear) uncouples
    if (m_state == State::QuickStopActive) {
        rampVelocity(0.0, 1.0, param(kQuickStopRamp, 200000), dt);
        m_positioning = m_homing = false;
    } else if (m_state != State::OperationEnabled) {
        m_velocity = 0.0;
    } else if (bit(m_word, 8)) { // halt: brake with the mode's ramp, stay enabled
        const double dec = mode() == 6 || mode() == -2 ? param(kHomingAcceleration, 50000)
            : mode() == -1                             ? m_blockDec
                           : overrideParam(kDeceleration, kDefaultAcceleration);
        rampVelocity(0.0, 1.0, std::max(1.0, dec), dt);
    } else {
        const double acc = overrideParam(kAcceleration, kDefaultAcceleration);
        const double dec = overrideParam(kDeceleration, kDefaultAcceleration);
        switch (mode()) {
        case 1:
            if (m_positioning) {
                moveTowards(m_target, overrideParam(kProfileVelocity, kDefaultVelocity), acc, dec,
                            dt);
                if (!m_positioning && m_pending) {
                    m_pending = false;
                    m_target = m_pendingTarget;
                    m_positioning = true;
                }
            } else {
                rampVelocity(0.0, acc, dec, dt);
            }
            break;
        case 2: {
            // Velocity mode [rpm]: bit 6 uses 1459, bit 5 unlocks the ramp; ramps 420/421 in
            // Hz/s (2 decimals) converted with the pole pairs.
            const double rpm = bit(m_word, 6) ? overrideParam(kTargetVelocityRpm, 0.0) : 0.0;
            const double rpmPerHz = 60.0 / std::max(1.0, param(kPolePairs, 2));
            const double a = std::max(1.0, param(kAccelerationCw, 5000)) / 100.0 * rpmPerHz;
            const double d = std::max(1.0, param(kDecelerationCw, 5000)) / 100.0 * rpmPerHz;
            if (bit(m_word, 5)) {
                double rpmNow = m_velocity / uPerRpm();
                const double step = (std::abs(rpm) > std::abs(rpmNow) ? a : d) * dt;
                rpmNow =
                    std::abs(rpm - rpmNow) <= step ? rpm : rpmNow + (rpm > rpmNow ? step : -step);
                m_velocity = rpmNow * uPerRpm();
            }
            m_position += m_velocity * dt;
            break;
        }
        case 3:
            rampVelocity(overrideParam(kTargetVelocity, 0.0), acc, dec, dt);
            m_position += m_velocity * dt;
            break;
        case 6:
            if (m_homing) {
                // The reference switch is 2000 u below where homing starts: fast towards it,
                // then the position is set to 0 (1185 not simulated).
                if (m_homingFails) {
                    m_homing = false;
                    m_homingError = true;
                    break;
                }
                if (!m_positioning) {
                    m_target = m_position - 2000.0;
                    m_positioning = true;
                }
                const double a = param(kHomingAcceleration, 50000);
                moveTowards(m_target, param(kFastSpeed, 20000), a, a, dt);
                if (!m_positioning) {
                    m_position = 0.0;
                    m_homing = false;
                    m_homed = true;
                }
            } else {
                m_positioning = false;
                const double a = param(kHomingAcceleration, 50000);
                rampVelocity(0.0, a, a, dt);
                m_position += m_velocity * dt;
            }
            break;
        case -1:
            if (m_block != 0 && m_positioning) {
                moveTowards(m_target, m_blockSpeed, m_blockAcc, m_blockDec, dt);
                if (!m_positioning)
                    finishBlock();
            } else {
                rampVelocity(0.0, 1.0, std::max(1.0, m_blockDec), dt);
                m_position += m_velocity * dt;
            }
            break;
        case -2:
            if (m_leavingSwitch) {
                const double a = param(kHomingAcceleration, 50000);
                moveTowards(m_limitClearAt, param(kCreepSpeed, 2000), a, a, dt);
                if (!m_positioning && m_position == m_limitClearAt) {
                    m_leavingSwitch = false;
                    m_limitPositive = m_limitNegative = false;
                }
                m_positioning = m_leavingSwitch;
            }
            break;
        case -3: { // electronic gear slave
            const double geared = m_masterSpeed * param(kGearNumerator, 0)
                / std::max(1.0, param(kGearDenominator, 1));
            const double target = bit(m_word, 4) ? geared : 0.0;
            rampVelocity(target, acc, dec, dt);
            m_position += m_velocity * dt;
            if (!bit(m_word, 4) || m_velocity != target)
                m_gearCoupledMs = -1.0;
            else
                m_gearCoupledMs = m_gearCoupledMs < 0 ? 0.0 : m_gearCoupledMs + dt * 1000.0;
            break;
        }
        default:
            rampVelocity(0.0, acc, dec, dt);
            break;
        }
    }
    publish();
    if (resting())
        m_timer.stop();
}

void AcuMotion::publish()
{
    const auto i = [](double v) {
        return QVariant::fromValue<qlonglong>(std::llround(v));
    };
    m_store.set(kPosition, 0, i(m_position));
    m_store.set(kSpeed, 0, i(m_velocity));
    m_store.set(kActiveBlock, 0, i(m_block));
    m_store.set(kResumeBlock, 0, i(m_resumeBlock));
    const double rpm = m_velocity / uPerRpm();
    const double previousRpm = param(kActualSpeedRpm, 0.0);
    m_store.set(kActualSpeedRpm, 0, i(rpm));
    // The motor's electrical side, simple enough for a trace that follows the motion: the
    // stator frequency from the speed and the pole pairs, a current of a no-load part plus one
    // growing with the speed, and none at standstill. Until the motor first turns, the preset
    // values stand.
    if (std::llround(rpm) == 0 && std::llround(previousRpm) == 0)
        return;
    const double hz = rpm * param(kPolePairs, 2) / 60.0;
    m_store.set(kStatorFrequency, 0, i(hz * 100.0));
    const double amps = std::abs(rpm) < 0.5 ? 0.0 : 1.2 + 0.004 * std::abs(rpm);
    m_store.set(kRmsCurrent, 0, i(amps * 10.0));
}

} // namespace db::bonfiglioli
