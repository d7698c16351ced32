#include "movingcapdrive.h"

#include "movingcapfaults.h"

#include <QScopedValueRollback>
#include <QTimer>

#include <QCoreApplication>
#include <cmath>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::simulation)
};
} // namespace

namespace db::sim {

namespace {
constexpr double kStepSeconds = 0.001; // internal integration step of advance()
constexpr double kMaxRealTimeStep = 0.5; // s: a stalled event loop does not jump the axis
constexpr double kAmbientTemperature = 35.0; // degC
constexpr double kHeatingAtRatedCurrent = 40.0; // degC above ambient at 100 % continuous
constexpr double kThermalTimeConstant = 120.0; // s

// Values the description leaves open, chosen for the simulator (movingcap.md has none):
QHash<ObjectAddress, QVariant> simulatorFactoryValues()
{
    return {
        { { 0x6092, 1 }, 360 }, // feed: positions in degrees, as in the Docklight log
        { { 0x6081, 0 }, 720 }, // profile velocity, units/s
        { { 0x6075, 0 }, 2500 }, // motor rated current, mA
        { { 0x6073, 0 }, 1000 }, // max current = rated
        { { 0x6099, 1 }, 90 }, // homing speed, units/s
        { { 0x609A, 0 }, 1000 }, // homing acceleration, as 6083h
        { { 0x6060, 0 }, 1 }, // profile position after power-up
        { { 0x3401, 3 }, 10 }, // controller position window, increments
        { { 0x3401, 21 }, 1000 }, // acceleration torque = rated
        { { 0x3401, 22 }, 1000 }, // deceleration torque = rated
        { { 0x3301, 1 }, 1 }, // RABBIT control mode "Rabbit"
        { { 0x1018, 2 }, 349 }, // product code: MC349
        { { 0x1018, 3 }, 0x00010000 }, // revision 1.0
        { { 0x1018, 4 }, 1 }, // serial number
    };
}

QHash<ObjectAddress, QVariant> factoryValues(const MovingCapOptions &options)
{
    QHash<ObjectAddress, QVariant> values = simulatorFactoryValues();
    for (auto it = options.initialValues.cbegin(); it != options.initialValues.cend(); ++it)
        values.insert(it.key(), it.value());
    return values;
}
} // namespace

MovingCapDrive::MovingCapDrive(const ObjectDictionary &dictionary, const MovingCapOptions &options,
                               QObject *parent)
    : QObject(parent)
    , m_options(options)
    , m_store(dictionary, factoryValues(options))
    , m_axis(options.axisModel)
{
    m_axis.setHardStops(options.hardStopNegative, options.hardStopPositive);
    applyParameters();
    m_lastStatusword = statusword();
}

MovingCapDrive::~MovingCapDrive() = default;

// ---- time ------------------------------------------------------------------------------------

void MovingCapDrive::advance(double seconds)
{
    if (seconds <= 0)
        return;
    const QScopedValueRollback<bool> inside(m_advancing, true);
    // At rest nothing moves and the temperature's decay is exact over any step: one step does.
    const int steps = resting() ? 1 : std::max(1, int(std::ceil(seconds / kStepSeconds - 1e-9)));
    const double dt = seconds / steps;
    for (int i = 0; i < steps; ++i)
        stepOnce(dt);
    emitStatusIfChanged();
}

void MovingCapDrive::stepOnce(double dt)
{
    m_time += dt;
    m_axis.step(dt);

    // Block detection (ERROR_STROKE) unless 3401h.1Ah masks the current motion phase.
    if (m_axis.blocked() && m_axis.mode() != SimulatedAxis::Mode::Homing && m_machine.powered()) {
        const double v = m_axis.demandVelocity();
        const double a = m_axis.demandPosition() > m_axis.position() ? 1 : -1;
        const int phase = std::abs(v) < 1e-9 ? 4 : (v * a > 0 ? 1 : 2);
        if (!(m_store.integer({ 0x3401, 0x1A }) & phase))
            injectFault(faults::Stroke);
    }
    for (int i = 0; i < m_pending.size();) {
        if (m_pending[i].due <= m_time + 1e-9) {
            const Pending p = m_pending.takeAt(i);
            if (p.generation == m_motionGeneration)
                p.action();
        } else {
            ++i;
        }
    }
    const auto state = m_machine.state();
    if ((state == cia402::State::QuickStopActive || state == cia402::State::FaultReactionActive)
        && !m_axis.isMoving())
        handle(m_machine.stopCompleted());
    stepRepeat();

    const double load = m_axis.current() / 1000.0;
    const double target = kAmbientTemperature + kHeatingAtRatedCurrent * load * load;
    m_temperature += (target - m_temperature) * (1 - std::exp(-dt / kThermalTimeConstant));
}

void MovingCapDrive::schedule(double delaySeconds, std::function<void()> action)
{
    m_pending.append({ m_time + delaySeconds, m_motionGeneration, std::move(action) });
}

void MovingCapDrive::startRealTime(int periodMs)
{
    if (!m_timer) {
        m_timer = new QTimer(this);
        connect(m_timer, &QTimer::timeout, this, [this] {
            catchUp();
            if (resting())
                m_timer->stop();
        });
    }
    m_realTime = true;
    m_periodMs = periodMs;
    m_clock.start();
    m_timer->start(periodMs);
}

void MovingCapDrive::stopRealTime()
{
    m_realTime = false;
    if (m_timer)
        m_timer->stop();
}

bool MovingCapDrive::ticking() const
{
    return m_timer && m_timer->isActive();
}

double MovingCapDrive::time() const
{
    const bool stopped = m_realTime && !m_advancing && !m_timer->isActive();
    return stopped ? m_time + m_clock.elapsed() / 1000.0 : m_time;
}

bool MovingCapDrive::resting() const
{
    const auto state = m_machine.state();
    return !m_machine.powered() && !m_axis.powered() && m_pending.isEmpty() && !m_repeat.active
        && state != cia402::State::QuickStopActive && state != cia402::State::FaultReactionActive;
}

void MovingCapDrive::catchUp()
{
    if (!m_realTime || m_advancing)
        return;
    // Within one integration step the model is current enough: a client reading as fast as it
    // can does not make the model step once per read.
    const qint64 ns = m_clock.nsecsElapsed();
    if (ns < qint64(kStepSeconds * 1e9))
        return;
    m_clock.restart();
    const double elapsed = double(ns) / 1e9;
    // A stalled event loop does not jump a moving axis; a resting one takes the whole gap.
    advance(resting() ? elapsed : std::min(elapsed, kMaxRealTimeStep));
}

void MovingCapDrive::wake()
{
    if (m_realTime && !m_advancing && !m_timer->isActive())
        m_timer->start(m_periodMs);
}

// ---- state machine glue ----------------------------------------------------------------------

void MovingCapDrive::applyControlword(quint16 controlword)
{
    m_store.set({ 0x6040, 0 }, controlword);
    if (!(controlword & cia402::cw::NewSetPoint))
        m_setPointAcknowledge = false; // PP handshake: master clears bit 4, drive clears bit 12
    handle(m_machine.writeControlword(controlword));
}

void MovingCapDrive::handle(const Effects &e)
{
    if (e.softwareEnableMissing) {
        injectFault(faults::SoftwareEnable);
        return;
    }
    if (e.faultReset) {
        m_errorBits = 0;
        m_errorRegister = 0;
    }
    if (e.stop != Cia402Machine::StopRamp::None) {
        noteInterruption();
        ++m_motionGeneration;
        m_repeat.active = false;
        if (e.stop == Cia402Machine::StopRamp::ProfileDeceleration)
            m_axis.stop(accelerationToUser(m_store.integer({ 0x6084, 0 })));
        else if (e.stop == Cia402Machine::StopRamp::QuickStopDeceleration)
            m_axis.stop(accelerationToUser(m_store.integer({ 0x6085, 0 })));
        else
            m_axis.setPowered(false);
    }
    if (e.powerOff) {
        ++m_motionGeneration;
        m_repeat.active = false;
        m_homingRun = false;
        m_axis.setPowered(false);
    }
    if (e.powerOn) {
        m_axis.setPowered(true);
        // Spec 7.1.7: after positioning is switched on, relative moves start from the actual
        // position.
        m_lastTarget = m_axis.position();
        if (m_store.integer({ 0x6060, 0 }) == 3 && !m_machine.halted())
            startVelocity(double(m_store.integer({ 0x60FF, 0 })));
    }
    if (e.newSetPoint) {
        const int mode = int(m_store.integer({ 0x6060, 0 }));
        if (mode == 1) {
            const double value = double(m_store.integer({ 0x607A, 0 }));
            const double target = e.relative ? m_lastTarget + value : absoluteTarget(value);
            const bool accepted = m_axis.moveTo(target, double(m_store.integer({ 0x6081, 0 })),
                                                accelerationToUser(m_store.integer({ 0x6083, 0 })),
                                                accelerationToUser(m_store.integer({ 0x6084, 0 })),
                                                e.changeImmediately);
            if (accepted) {
                m_lastTarget = target;
                m_setPointAcknowledge = true;
            }
        } else if (mode == 6) {
            startHoming(int(m_store.integer({ 0x6098, 0 })),
                        double(m_store.integer({ 0x607C, 0 })));
        }
    }
    if (e.haltChanged) {
        const int mode = int(m_store.integer({ 0x6060, 0 }));
        if (m_machine.halted())
            m_axis.stop(accelerationToUser(m_store.integer({ 0x6084, 0 })));
        else if (mode == 3)
            startVelocity(double(m_store.integer({ 0x60FF, 0 })));
        else if (mode == 1)
            startPositionMove(m_lastTarget, true);
    }
    emitStatusIfChanged();
}

Result<void> MovingCapDrive::ensureOperational(int mode)
{
    if (auto refused = refuseInFault(); !refused)
        return refused;
    setMode(mode);
    if (m_machine.state() == cia402::State::OperationEnabled)
        return {};
    if (m_machine.state() == cia402::State::QuickStopActive)
        applyControlword(0x0000); // through Switch on disabled (12)
    applyControlword(cia402::cw::Shutdown);
    applyControlword(cia402::cw::EnableOperationCmd);
    if (m_machine.state() == cia402::State::OperationEnabled)
        return {};
    if (m_machine.state() == cia402::State::Fault)
        return Error(Error::Kind::DeviceError,
                     Tr::tr("software enable missing (FFF2h), drive in fault state"),
                     faults::SoftwareEnable);
    return Error(Error::Kind::DeviceError, Tr::tr("drive cannot be switched on"));
}

void MovingCapDrive::setMode(int mode)
{
    const int previous = int(m_store.integer({ 0x6060, 0 }));
    m_store.set({ 0x6060, 0 }, mode);
    if (previous == mode || m_machine.state() != cia402::State::OperationEnabled)
        return;
    ++m_motionGeneration;
    m_repeat.active = false;
    m_homingRun = false;
    if (m_axis.isMoving())
        m_axis.stop(accelerationToUser(m_store.integer({ 0x6084, 0 })));
    if (mode == 3)
        startVelocity(double(m_store.integer({ 0x60FF, 0 })));
}

void MovingCapDrive::applyParameters()
{
    // On a rotary axis 607Dh gives the cycle, not limits.
    if (rotaryPositions())
        m_axis.setSoftLimits(0, 0);
    else
        m_axis.setSoftLimits(double(m_store.integer({ 0x607D, 1 })),
                             double(m_store.integer({ 0x607D, 2 })));
    m_axis.setTargetWindow(double(m_store.integer({ 0x6067, 0 })),
                           double(m_store.integer({ 0x6068, 0 })) / 1000.0);
    m_axis.setCurrentLimit(double(m_store.integer({ 0x6073, 0 })));
    m_machine.setQuickStopOption(int(m_store.integer({ 0x605A, 0 })));
    evaluateSoftwareEnable();
}

quint16 MovingCapDrive::statusword() const
{
    Cia402Machine::StatusInputs in;
    const int mode = int(m_store.integer({ 0x6060, 0 }));
    const auto homing = m_axis.homingState();
    in.moving = m_axis.isMoving();
    in.warning = m_warningBits != 0;
    in.internalLimit = m_axis.internalLimitActive();
    if (mode == 6 && m_homingRun) {
        in.targetReached = homing == SimulatedAxis::HomingState::Attained;
        in.modeBit12 = in.targetReached;
        in.modeBit13 = homing == SimulatedAxis::HomingState::Failed;
    } else {
        in.targetReached = m_axis.targetReached();
        in.modeBit12 = mode == 1 && m_setPointAcknowledge;
    }
    return m_machine.statusword(in);
}

void MovingCapDrive::emitStatusIfChanged()
{
    const quint16 word = statusword();
    if (word != m_lastStatusword) {
        m_lastStatusword = word;
        Q_EMIT statusChanged(word);
    }
}

// ---- faults ----------------------------------------------------------------------------------

void MovingCapDrive::injectFault(quint16 emcyCode)
{
    const Present present(this);
    const MovingCapFault fault = faults::lookup(emcyCode);
    const auto state = m_machine.state();
    const bool alreadyFaulted =
        state == cia402::State::Fault || state == cia402::State::FaultReactionActive;
    if (alreadyFaulted && m_lastError == emcyCode)
        return; // a persisting cause does not flood the history
    if (fault.statusBit >= 0)
        m_errorBits |= 1u << fault.statusBit;
    m_errorRegister |= fault.errorRegister;
    m_lastError = emcyCode;
    m_history.prepend(emcyCode);
    while (m_history.size() > 4)
        m_history.removeLast();
    if (fault.needsPowerCycle)
        m_machine.setFaultResetBlocked(true);
    handle(m_machine.raiseFault());
    Q_EMIT emergency(emcyCode, fault.errorRegister,
                     faults::emergencyData(emcyCode, fault.errorRegister));
    emitStatusIfChanged();
}

void MovingCapDrive::setWarnings(quint32 warningBits)
{
    const Present present(this);
    m_warningBits = warningBits & 0xFFFF0000u;
    emitStatusIfChanged();
}

void MovingCapDrive::powerCycle()
{
    const Present present(this);
    m_store.loadFromNvm();
    m_machine = Cia402Machine();
    m_axis.setPowered(false);
    m_pending.clear();
    m_errorBits = 0;
    m_errorRegister = 0;
    m_history.clear();
    m_lastError = 0;
    m_repeat = {};
    m_homingRun = false;
    m_interrupted = Interrupted::None;
    applyParameters();
    processInputs(0);
    emitStatusIfChanged();
}

quint32 MovingCapDrive::tpsr() const
{
    // Spec 3.5: BIT0 error, BIT1 reference (always), BIT2 in motion, BIT3 in position,
    // BIT8 inverter voltage.
    const quint16 word = statusword();
    quint32 bits = 0x0002;
    if (word & cia402::sw::Fault)
        bits |= 0x0001;
    if (word & cia402::sw::Moving)
        bits |= 0x0004;
    if (word & cia402::sw::TargetReached)
        bits |= 0x0008;
    if (m_options.tpsrInverterVoltageBit && m_machine.powered()
        && m_machine.state() != cia402::State::FaultReactionActive)
        bits |= 0x0100;
    return bits;
}

int MovingCapDrive::ts() const
{
    // Spec 3.5 [R] priority: Error 9, Moving 2, Power On 1, Power Off 0.
    const quint16 word = statusword();
    if (word & cia402::sw::Fault)
        return 9;
    if (word & cia402::sw::Moving)
        return 2;
    return m_machine.powered() ? 1 : 0;
}

} // namespace db::sim
