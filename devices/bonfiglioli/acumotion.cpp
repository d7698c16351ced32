#include "acumotion.h"

#include "acumotion_p.h"
#include "vabus/vabuscodec.h"

#include <cmath>

namespace db::bonfiglioli {

using namespace acumotion;

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

bool AcuMotion::resting() const
{
    return m_state != State::OperationEnabled && m_state != State::QuickStopActive
        && m_velocity == 0.0;
}

void AcuMotion::wake()
{
    if (m_timer.isActive())
        return;
    m_clock.restart();
    m_timer.start();
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
    case -3: // in gear; with halt: at speed 0
        if (halt ? still : (m_gearCoupledMs >= 0 && m_gearCoupledMs >= param(kGearCoupledTime, 1)))
            s |= 0x0400;
        break;
    default:
        break;
    }
    return s;
}

quint16 AcuMotion::writeControlWord(quint16 word)
{
    wake();
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

} // namespace db::bonfiglioli
