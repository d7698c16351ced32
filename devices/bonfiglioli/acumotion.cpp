#include "acumotion.h"

#include "vabus/vabuscodec.h"

#include <cmath>

namespace db::bonfiglioli {

namespace {

constexpr quint16 kConfiguration = 30;
constexpr quint16 kStatorFrequency = 210; // Hz, 2 decimals
constexpr quint16 kRmsCurrent = 211; // A, 1 decimal
constexpr quint16 kActualSpeedRpm = 240;
constexpr quint16 kDigitalInputs = 250;
constexpr quint16 kPolePairs = 373;
constexpr quint16 kLocalRemote = 412;
constexpr quint16 kAccelerationCw = 420; // Hz/s, 2 decimals
constexpr quint16 kDecelerationCw = 421;
constexpr quint16 kSpeed = 1107;
constexpr quint16 kPosition = 1108;
constexpr quint16 kFeed = 1115;
constexpr quint16 kGearShaft = 1116;
constexpr quint16 kGearMotor = 1117;
constexpr quint16 kFastSpeed = 1132;
constexpr quint16 kCreepSpeed = 1133;
constexpr quint16 kHomingAcceleration = 1134;
constexpr quint16 kTargetWindow = 1165;
constexpr quint16 kQuickStopRamp = 1179;
constexpr quint16 kBlockTarget = 1202;
constexpr quint16 kBlockSpeed = 1203;
constexpr quint16 kBlockAcceleration = 1204;
constexpr quint16 kBlockDeceleration = 1206;
constexpr quint16 kBlockMode = 1208; // 2 = relative (a simulator convention)
constexpr quint16 kBlockNext = 1213; // next block after the wait time; 0 = end
constexpr quint16 kActiveBlock = 1246;
constexpr quint16 kResumeBlock = 1249;
constexpr quint16 kVelocityWindow = 1276;
constexpr quint16 kMode = 1454;
constexpr quint16 kTargetPosition = 1455;
constexpr quint16 kProfileVelocity = 1456;
constexpr quint16 kAcceleration = 1457;
constexpr quint16 kDeceleration = 1458;
constexpr quint16 kTargetVelocityRpm = 1459;
constexpr quint16 kTargetVelocity = 1460;
constexpr quint16 kBothDirectionsBlocked = 0x1449; // F1449

constexpr double kDefaultVelocity = 10000.0; // u/s, when an override is off (-1)
constexpr double kDefaultAcceleration = 50000.0; // u/s^2

bool bit(quint16 word, int n)
{
    return word & (1u << n);
}
bool rising(quint16 old, quint16 word, int n)
{
    return !bit(old, n) && bit(word, n);
}
bool falling(quint16 old, quint16 word, int n)
{
    return bit(old, n) && !bit(word, n);
}

} // namespace

AcuMotion::AcuMotion(AcuStore &store, AcuIndexed &indexed, QObject *parent)
    : QObject(parent)
    , m_store(store)
    , m_indexed(indexed)
{
    m_timer.setInterval(kTickMs);
    connect(&m_timer, &QTimer::timeout, this, &AcuMotion::tick);
    m_timer.start();
    m_clock.start();
    publish();
}

// The value the drive works with: data set 1 (the active one) of a data-set parameter.
double AcuMotion::param(quint16 p, double fallback) const
{
    const QVariant v = m_store.value(p, m_store.hasDataSets(p) ? 1 : 0);
    return v.isValid() ? v.toDouble() : fallback;
}

// 1455-1460: -1 means "override off", the drive then uses its MCI value (here: a default).
double AcuMotion::overrideParam(quint16 p, double fallback) const
{
    const double v = param(p, -1);
    return v == -1 ? fallback : v;
}

bool AcuMotion::positioningConfig() const
{
    return int(param(kConfiguration, 0)) % 100 == 40;
}

qint16 AcuMotion::mode() const
{
    if (!positioningConfig())
        return 2;
    return qint16(qint8(int(param(kMode, 0)) & 0xFF));
}

// n [rpm] -> v [u/s] = n x (1115 / 60) x (1116 / 1117).
double AcuMotion::uPerRpm() const
{
    return param(kFeed, 1) / 60.0 * param(kGearShaft, 1) / std::max(1.0, param(kGearMotor, 1));
}

quint16 AcuMotion::checkMode(qint64 mode) const
{
    switch (mode) {
    case 0:
    case 1:
    case 2:
    case 3:
    case 6:
    case 253:
    case 254:
    case 255:
        return positioningConfig() || mode == 2 ? 0 : vabus::InvalidValue;
    default:
        return vabus::InvalidValue; // 7, 8, 9: not available with the override
    }
}

quint16 AcuMotion::statusWord() const
{
    quint16 s = 0;
    switch (m_state) {
    case State::SwitchOnDisabled:
        s = 0x0040;
        break;
    case State::ReadyToSwitchOn:
        s = 0x0021;
        break;
    case State::SwitchedOn:
        s = 0x0023;
        break;
    case State::OperationEnabled:
        s = 0x0027;
        if (int(param(kLocalRemote, 0)) == 1)
            s |= 0x0200; // remote: 412 = 1 and the controller enabled
        break;
    case State::QuickStopActive:
        s = 0x0007;
        break;
    case State::Fault:
        s = 0x0008;
        break;
    }
    if (m_mains)
        s |= 0x0010;
    if (m_state != State::OperationEnabled && m_state != State::QuickStopActive)
        return s;
    const bool halt = bit(m_word, 8);
    const bool still = m_velocity == 0.0;
    switch (mode()) {
    case 1: // profile position
        if (halt ? still : (!m_positioning && still))
            s |= 0x0400;
        if (m_setPointAck)
            s |= 0x1000;
        break;
    case 2: // velocity: bit 10 not used
        break;
    case 3: {
        const double target = halt ? 0.0 : overrideParam(kTargetVelocity, 0.0);
        if (std::abs(m_velocity - target) <= param(kVelocityWindow, 10))
            s |= 0x0400;
        if (std::abs(m_velocity) > 0.0)
            s |= 0x1000;
        break;
    }
    case 6:
        if (halt ? still : (m_homed && still))
            s |= 0x0400;
        if (m_homed)
            s |= 0x1000;
        if (m_homingError)
            s |= 0x2000;
        break;
    case -1:
        if (m_block != 0)
            s |= 0x0100;
        if (halt ? still : (!m_positioning && still))
            s |= 0x0400;
        break;
    case -2:
        if (halt ? still : (!m_limitPositive && !m_limitNegative && still))
            s |= 0x0400;
        break;
    default:
        break;
    }
    return s;
}

quint16 AcuMotion::writeControlWord(quint16 word)
{
    const quint16 old = m_word;
    m_word = word;
    const int control = int(param(kLocalRemote, 0));
    if (control == 2) {
        // Remote contacts: bits 0-9 are S1IND..EM-S3IND; S1IND needs the STO enable.
        m_store.set(kDigitalInputs, 0, QVariant::fromValue<qulonglong>(word & 0x03FF));
        if (m_state == State::Fault) {
            if (rising(old, word, 7))
                m_state = State::SwitchOnDisabled;
            return 0;
        }
        const bool start = bit(word, 0) && m_sto && m_mains && (bit(word, 1) || bit(word, 2));
        m_state = start ? State::OperationEnabled : State::SwitchedOn;
        return 0;
    }
    if (control != 1)
        return 0; // the control word does nothing in the other control modes
    if (m_state == State::Fault) {
        if (rising(old, word, 7)) { // transition 15
            m_fault = 0;
            m_state = State::SwitchOnDisabled;
        }
        return 0;
    }
    const bool switchOn = bit(word, 0), enableVoltage = bit(word, 1);
    const bool noQuickStop = bit(word, 2), enableOperation = bit(word, 3);
    const State before = m_state;
    if (!enableVoltage) { // 7, 9, 10, 12
        m_state = State::SwitchOnDisabled;
    } else if (!noQuickStop) { // 7, 10, 11
        m_state = m_state == State::OperationEnabled || m_state == State::QuickStopActive
            ? State::QuickStopActive
            : State::SwitchOnDisabled;
    } else if (m_state == State::QuickStopActive) {
        // only "disable voltage" leaves quick stop active
    } else if (!switchOn) { // 2, 6, 8
        m_state = State::ReadyToSwitchOn;
    } else if (!enableOperation) { // 3 (needs mains), 5
        if (m_state == State::ReadyToSwitchOn && m_mains)
            m_state = State::SwitchedOn;
        else if (m_state == State::OperationEnabled)
            m_state = State::SwitchedOn;
    } else if (m_state == State::SwitchedOn && m_sto) { // 4 (needs STO)
        m_state = State::OperationEnabled;
    } else if (!positioningConfig() && m_mains && m_sto
               && (m_state == State::SwitchOnDisabled || m_state == State::ReadyToSwitchOn)) {
        m_state = State::OperationEnabled; // 4': only without positioning control
    } else if (m_state == State::ReadyToSwitchOn && m_mains) {
        m_state = State::SwitchedOn;
    }
    if (m_state != State::OperationEnabled && m_state != State::QuickStopActive) {
        m_positioning = m_homing = m_leavingSwitch = false;
        m_pending = false;
        m_velocity = 0.0; // the power stage is off: the axis coasts to standstill at once
        if (m_block != 0)
            m_resumeBlock = m_block;
        m_block = 0;
    }
    if (m_state == State::OperationEnabled && before == State::OperationEnabled)
        modeEdges(old, word);
    else if (m_state == State::OperationEnabled)
        modeEdges(0, word);
    if (!bit(word, 4))
        m_setPointAck = false;
    publish();
    return 0;
}

// The mode-specific bits, taken in "operation enabled".
void AcuMotion::modeEdges(quint16 old, quint16 word)
{
    switch (mode()) {
    case 1:
        if (rising(old, word, 4) && !m_setPointAck) {
            const double value = param(kTargetPosition, 0);
            const double base = m_positioning ? m_target : m_position;
            const double target = bit(word, 6) ? base + value : value;
            if (m_positioning && !bit(word, 5) && !bit(word, 9)) {
                m_pending = true; // finish the running positioning first
                m_pendingTarget = target;
            } else {
                m_target = target;
                m_positioning = true;
            }
            m_setPointAck = true;
        }
        break;
    case 6:
        if (rising(old, word, 4)) {
            m_homing = true;
            m_homed = m_homingError = false;
        } else if (falling(old, word, 4)) {
            m_homing = false; // interrupted
        }
        break;
    case -1:
        if (rising(old, word, 9)) {
            m_sequence = bit(word, 4);
            const int selected = ((word >> 11) & 0x1F) + 1;
            startBlock(bit(word, 6) && m_resumeBlock > 0 ? m_resumeBlock : selected);
        } else if (falling(old, word, 9) && m_block != 0) {
            m_resumeBlock = m_block; // interrupted: stop with the block's ramp
            m_positioning = false;
        }
        break;
    case -2:
        if (rising(old, word, 4)) {
            if (m_limitPositive && m_limitNegative) {
                raiseFault(kBothDirectionsBlocked);
                return;
            }
            m_leavingSwitch = m_limitPositive || m_limitNegative;
            m_limitClearAt = m_position + (m_limitPositive ? -1 : 1) * kLimitSwitchTravel;
        } else if (falling(old, word, 4)) {
            m_leavingSwitch = false;
        }
        break;
    default:
        break;
    }
}

void AcuMotion::startBlock(int block)
{
    const double target = double(m_indexed.value(kBlockTarget, block));
    const bool relative = m_indexed.value(kBlockMode, block) == 2;
    m_block = block;
    m_target = relative ? m_position + target : target;
    m_blockSpeed = std::max<double>(1, double(m_indexed.value(kBlockSpeed, block)));
    m_blockAcc = std::max<double>(1, double(m_indexed.value(kBlockAcceleration, block)));
    m_blockDec = std::max<double>(1, double(m_indexed.value(kBlockDeceleration, block)));
    m_positioning = true;
    m_resumeBlock = -1;
}

void AcuMotion::finishBlock()
{
    const int next = int(m_indexed.value(kBlockNext, m_block));
    if (m_sequence && next > 0 && next <= 32) {
        startBlock(next);
        return;
    }
    m_block = 0;
}

void AcuMotion::raiseFault(quint16 code)
{
    m_fault = code;
    m_state = State::Fault;
    m_positioning = m_homing = m_leavingSwitch = m_pending = false;
    m_velocity = 0.0;
    if (m_block != 0)
        m_resumeBlock = m_block;
    m_block = 0;
    publish();
}

void AcuMotion::switchOff(bool quickStop)
{
    if (m_state == State::Fault)
        return;
    Q_UNUSED(quickStop) // the quick stop ends in the same state; the model stops at once
    m_state = State::SwitchOnDisabled;
    m_positioning = m_homing = m_leavingSwitch = false;
    m_velocity = 0.0;
    publish();
}

void AcuMotion::powerCycle()
{
    m_state = State::SwitchOnDisabled;
    m_word = 0;
    m_fault = 0;
    m_positioning = m_homing = m_homed = m_homingError = m_leavingSwitch = false;
    m_pending = m_setPointAck = false;
    m_velocity = 0.0;
    m_block = 0;
    m_resumeBlock = -1;
    publish();
}

void AcuMotion::setMains(bool on)
{
    m_mains = on;
    if (!on && m_state != State::Fault)
        switchOff(false);
}

void AcuMotion::setSto(bool on)
{
    m_sto = on;
    if (!on && m_state == State::OperationEnabled) {
        m_state = State::SwitchedOn; // the inverter drops back to "switched on" (0x33)
        m_positioning = m_homing = m_leavingSwitch = false;
        m_velocity = 0.0;
    }
}

void AcuMotion::setLimitSwitches(bool positive, bool negative)
{
    m_limitPositive = positive;
    m_limitNegative = negative;
}

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
    const double dt = std::min(0.05, m_clock.restart() / 1000.0);
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
        default:
            rampVelocity(0.0, acc, dec, dt);
            break;
        }
    }
    publish();
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
