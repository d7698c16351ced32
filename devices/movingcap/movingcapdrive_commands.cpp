// MovingCapDrive: the RefGo-level operations (movingcap.md 3.3, 3.4) and their motion helpers.
#include "movingcapdrive.h"
#include "movingcapfaults.h"

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
Error outOfRange(const QString &what)
{
    return Error(Error::Kind::OutOfRange, what);
}
} // namespace

Result<void> MovingCapDrive::refuseInFault() const
{
    const auto state = m_machine.state();
    if (state == cia402::State::Fault || state == cia402::State::FaultReactionActive)
        return Error(Error::Kind::DeviceError, Tr::tr("drive in fault state"));
    return {};
}

void MovingCapDrive::startPositionMove(double target, bool immediate, double maxVelocity,
                                       double acceleration, double deceleration)
{
    ++m_motionGeneration;
    m_interrupted = Interrupted::None;
    m_homingRun = false;
    m_axis.moveTo(target, maxVelocity, acceleration, deceleration, immediate);
    m_lastTarget = target;
}

void MovingCapDrive::startPositionMove(double target, bool immediate)
{
    startPositionMove(target, immediate, double(m_store.integer({ 0x6081, 0 })),
                      accelerationToUser(m_store.integer({ 0x6083, 0 })),
                      accelerationToUser(m_store.integer({ 0x6084, 0 })));
}

void MovingCapDrive::startVelocity(double velocity)
{
    m_interrupted = Interrupted::None;
    m_homingRun = false;
    m_axis.moveVelocity(velocity, accelerationToUser(m_store.integer({ 0x6083, 0 })),
                        accelerationToUser(m_store.integer({ 0x6084, 0 })));
}

void MovingCapDrive::startHoming(int method, double offset)
{
    ++m_motionGeneration;
    m_homingRun = true;
    if (method == 35 || method == 37) {
        m_axis.setPosition(offset);
        m_lastTarget = offset;
        return;
    }
    const double speed = double(m_store.integer({ 0x6099, 1 }));
    const double acc = accelerationToUser(m_store.integer({ 0x609A, 0 }));
    m_axis.startHardStopHoming(method == -18 ? 1 : -1, speed, acc, offset);
}

bool MovingCapDrive::rotaryPositions() const
{
    return (m_store.integer({ 0x60F2, 0 }) & 0xC0) != 0
        && m_store.integer({ 0x607D, 2 }) > m_store.integer({ 0x607D, 1 });
}

double MovingCapDrive::shownPosition(double unwrapped) const
{
    if (!rotaryPositions())
        return unwrapped;
    const double min = double(m_store.integer({ 0x607D, 1 }));
    const double cycle = double(m_store.integer({ 0x607D, 2 })) - min;
    return min + (unwrapped - min) - cycle * std::floor((unwrapped - min) / cycle);
}

double MovingCapDrive::absoluteTarget(double target) const
{
    if (!rotaryPositions())
        return target;
    const double cycle =
        double(m_store.integer({ 0x607D, 2 })) - double(m_store.integer({ 0x607D, 1 }));
    const double from = m_axis.demandPosition();
    double delta = shownPosition(target) - shownPosition(from); // (-cycle, cycle)
    switch (m_store.integer({ 0x60F2, 0 }) & 0xC0) {
    case 0x40: // negative direction only
        if (delta > 0)
            delta -= cycle;
        break;
    case 0x80: // positive direction only
        if (delta < 0)
            delta += cycle;
        break;
    default: // shortest way
        if (delta > cycle / 2)
            delta -= cycle;
        else if (delta < -cycle / 2)
            delta += cycle;
        break;
    }
    return from + delta;
}

double MovingCapDrive::relativeBase() const
{
    // 60F2h bits 0-1 (spec 6.2): last target, demand position or actual position.
    switch (m_store.integer({ 0x60F2, 0 }) & 0x3) {
    case 1:
        return m_axis.demandPosition();
    case 2:
        return m_axis.position();
    default:
        break;
    }
    return m_lastTarget;
}

void MovingCapDrive::noteInterruption()
{
    const int mode = int(m_store.integer({ 0x6060, 0 }));
    if (!m_axis.isMoving())
        return;
    if (mode == 1) {
        m_interrupted = Interrupted::Position;
    } else if (mode == 3) {
        m_interrupted = Interrupted::Velocity;
        m_interruptedVelocity = double(m_store.integer({ 0x60FF, 0 }));
    }
}

Result<void> MovingCapDrive::go(std::optional<qint64> target)
{
    const Present present(this);
    if (auto ok = ensureOperational(1); !ok)
        return ok;
    if (target)
        m_store.set({ 0x607A, 0 }, *target);
    startPositionMove(absoluteTarget(double(m_store.integer({ 0x607A, 0 }))), true);
    m_repeat.active = false;
    return {};
}

Result<void> MovingCapDrive::goWay(std::optional<qint64> distance)
{
    const Present present(this);
    if (auto ok = ensureOperational(1); !ok)
        return ok;
    if (distance)
        m_way = *distance;
    const double target = relativeBase() + double(m_way);
    m_store.set({ 0x607A, 0 }, qRound64(target));
    startPositionMove(target, true);
    m_repeat.active = false;
    return {};
}

Result<void> MovingCapDrive::setTargetPosition(qint64 target)
{
    const Present present(this);
    return write({ 0x607A, 0 }, QVariant::fromValue<qlonglong>(target));
}

Result<void> MovingCapDrive::setWay(qint64 distance)
{
    const Present present(this);
    m_way = distance;
    return {};
}

Result<void> MovingCapDrive::setSpeed(qint64 velocity)
{
    const Present present(this);
    // SP: profile velocity in positioning mode, target velocity in velocity mode (spec 3.3).
    const bool velocityMode = m_store.integer({ 0x6060, 0 }) == 3;
    auto ok = velocityMode ? write({ 0x60FF, 0 }, QVariant::fromValue<qlonglong>(velocity))
                           : write({ 0x6081, 0 }, QVariant::fromValue<qlonglong>(velocity));
    if (ok)
        m_speed = velocity;
    return ok;
}

Result<void> MovingCapDrive::stopMotion()
{
    const Present present(this);
    if (auto refused = refuseInFault(); !refused)
        return refused;
    // SM = input function 5 without changing 605Ah: quick stop ramp 6085h, stay in quick stop
    // active (spec 3.4 *10).
    handle(m_machine.quickStop(6));
    return {};
}

void MovingCapDrive::connectionLost()
{
    const Present present(this);
    if (!m_store.dictionary().contains({ 0x6007, 0 }))
        return;
    switch (m_store.integer({ 0x6007, 0 })) {
    case 1:
        injectFault(faults::AbortConnection);
        return;
    case 2:
        applyControlword(0); // disable voltage
        return;
    case 3:
        if (m_machine.state() == cia402::State::OperationEnabled)
            handle(m_machine.quickStop(m_machine.quickStopOption()));
        emitStatusIfChanged();
        return;
    default:
        return; // 0 and the manufacturer-specific values: no action
    }
}

Result<void> MovingCapDrive::continueMotion()
{
    const Present present(this);
    if (auto refused = refuseInFault(); !refused)
        return refused;
    if (m_machine.state() == cia402::State::QuickStopActive)
        applyControlword(cia402::cw::EnableOperationCmd); // 16
    if (m_machine.state() != cia402::State::OperationEnabled)
        return Error(Error::Kind::DeviceError, Tr::tr("nothing to continue"));
    const Interrupted what = m_interrupted;
    if (what == Interrupted::Position)
        startPositionMove(m_lastTarget, true);
    else if (what == Interrupted::Velocity)
        startVelocity(m_interruptedVelocity);
    return {};
}

Result<void> MovingCapDrive::powerContinue()
{
    const Present present(this);
    return ensureOperational(1);
}

Result<void> MovingCapDrive::powerQuit()
{
    const Present present(this);
    if (m_machine.state() != cia402::State::Fault)
        applyControlword(cia402::cw::DisableVoltage);
    return {};
}

Result<void> MovingCapDrive::reference(std::optional<int> method)
{
    const Present present(this);
    if (!method)
        return {}; // spec 3.4 *2: REF without a parameter has no function
    if (*method != 35 && *method != 37 && *method != -18 && *method != -19)
        return Error(Error::Kind::NotSupported,
                     Tr::tr("homing method %1 is not supported").arg(*method));
    if (auto ok = ensureOperational(6); !ok)
        return ok;
    m_store.set({ 0x6098, 0 }, *method);
    m_repeat.active = false;
    startHoming(*method, double(m_store.integer({ 0x607C, 0 })));
    return {};
}

Result<void> MovingCapDrive::jog(int direction, std::optional<int> milliseconds)
{
    const Present present(this);
    if (milliseconds && *milliseconds < 0)
        return outOfRange(QStringLiteral("jog time %1 ms is negative").arg(*milliseconds));
    if (auto ok = ensureOperational(3); !ok)
        return ok;
    const double speed = std::abs(double(m_speed.value_or(m_store.integer({ 0x6081, 0 }))));
    const qint64 velocity = qRound64(direction >= 0 ? speed : -speed);
    ++m_motionGeneration;
    m_repeat.active = false;
    m_store.set({ 0x60FF, 0 }, velocity);
    startVelocity(double(velocity));
    if (milliseconds) {
        schedule(*milliseconds / 1000.0, [this] {
            m_store.set({ 0x60FF, 0 }, 0);
            startVelocity(0.0); // brakes to standstill with 6084h
        });
    }
    return {};
}

Result<void> MovingCapDrive::repeatReverse(std::optional<qint64> distance)
{
    const Present present(this);
    if (distance)
        m_repeatWay = *distance;
    // Spec 9.2: start from the last commanded target (the actual position before any move).
    const double from = m_lastTarget;
    if (auto ok = ensureOperational(1); !ok)
        return ok;
    startPositionMove(from + double(m_repeatWay), true);
    m_repeat = { true, from, from + double(m_repeatWay), -1.0 };
    m_lastTarget = m_repeat.to;
    return {};
}

void MovingCapDrive::setRepeatWay(qint64 distance)
{
    const Present present(this);
    m_repeatWay = distance;
}

void MovingCapDrive::setRepeatWait(qint64 milliseconds)
{
    const Present present(this);
    m_repeatWaitMs = std::max<qint64>(0, milliseconds);
}

void MovingCapDrive::stepRepeat()
{
    if (!m_repeat.active || m_axis.mode() != SimulatedAxis::Mode::Position
        || !m_axis.targetReached())
        return;
    if (m_repeat.waitUntil < 0) {
        m_repeat.waitUntil = m_time + m_repeatWaitMs / 1000.0;
        return;
    }
    if (m_time + 1e-9 < m_repeat.waitUntil)
        return;
    Repeat next = m_repeat;
    std::swap(next.from, next.to);
    next.waitUntil = -1.0;
    startPositionMove(next.to, true);
    m_repeat = next;
}

Result<void> MovingCapDrive::setOutput(int number, bool high)
{
    const Present present(this);
    if (number < 1 || number > 4)
        return outOfRange(QStringLiteral("output %1 does not exist (1..4)").arg(number));
    const quint32 bit = 1u << (15 + number);
    m_manualOutputs = high ? (m_manualOutputs | bit) : (m_manualOutputs & ~bit);
    return {};
}

Result<bool> MovingCapDrive::input(int number) const
{
    if (number < 1 || number > 10)
        return outOfRange(QStringLiteral("input %1 does not exist (1..10)").arg(number));
    return bool(combinedInputs() & (1u << (15 + number)));
}

} // namespace db::sim
