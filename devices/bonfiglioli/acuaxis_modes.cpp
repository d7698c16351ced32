// The ACU axis's motion commands: one MCO mode each, with its handshake (see acuaxis.h).
#include "acuaxis.h"

#include "acuaxis_p.h"
#include "acusteps.h"

#include <QCoreApplication>

#include <cmath>
#include <memory>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::bonfiglioli)
};
} // namespace

namespace db::bonfiglioli {

using motion::AxisInterface;
using namespace acuaxis;

Reply *AcuAxis::moveTo(double target, const Profile &profile)
{
    if (!hasPositioning())
        return Reply::failed(ObjectAddress(kTargetPosition, 0),
                             Error(Error::Kind::NotSupported, featureNote()));
    const qint64 t = std::llround(target);
    if (t == kOverrideOff)
        return Reply::failed(
            ObjectAddress(kTargetPosition, 0),
            Error(Error::Kind::OutOfRange,
                  Tr::tr("target -1 u cannot be approached: 1455 = -1 switches the override "
                         "off")));
    auto *steps = new AcuSteps(this, Tr::tr("profile position"));
    if (auto ok = addModeChange(steps, Mode::ProfilePosition); !ok) {
        delete steps;
        return Reply::failed(ObjectAddress(kMode, 0), ok.error());
    }
    requireEnabled(steps);
    // The last set-point's bit 4 falls first; the drive then clears bit 12 and takes a new one.
    steps->control(kEnableOperation | kBit5);
    steps->waitStatus([](quint16 w) { return !(w & kBit12); }, kHandshakeTimeoutMs,
                      Tr::tr("the inverter did not clear 'set-point acknowledged' (bit 12)"));
    steps->write(kProfileVelocity, positive(profile.velocity));
    steps->write(kAcceleration, positive(profile.acceleration));
    steps->write(kDeceleration, positive(profile.deceleration));
    steps->write(kTargetPosition, t);
    steps->control(kEnableOperation | kBit5 | kBit4); // absolute, change immediately
    steps->waitStatus([](quint16 w) { return w & kBit12; }, kHandshakeTimeoutMs,
                      Tr::tr("the inverter did not acknowledge the set-point (bit 12)"));
    steps->control(kEnableOperation | kBit5);
    return run(steps);
}

Reply *AcuAxis::moveVelocity(double velocity, const Profile &profile)
{
    auto *steps = new AcuSteps(this, Tr::tr("velocity"));
    const Mode mode = hasPositioning() ? Mode::ProfileVelocity : Mode::Velocity;
    if (hasPositioning()) {
        if (auto ok = addModeChange(steps, mode); !ok) {
            delete steps;
            return Reply::failed(ObjectAddress(kMode, 0), ok.error());
        }
    }
    const qint64 v = std::llround(velocity);
    if (v == kOverrideOff) {
        delete steps;
        return Reply::failed(
            ObjectAddress(kTargetVelocity, 0),
            Error(Error::Kind::OutOfRange,
                  Tr::tr("velocity -1 cannot be set: -1 switches the override off")));
    }
    requireEnabled(steps);
    if (mode == Mode::ProfileVelocity) {
        steps->write(kAcceleration, positive(profile.acceleration));
        steps->write(kDeceleration, positive(profile.deceleration));
        steps->write(kTargetVelocity, v);
        steps->control(kEnableOperation);
    } else {
        steps->write(kTargetVelocityRpm, v);
        steps->control(kEnableOperation | kBit4 | kBit5 | kBit6); // ramp follows 1459
    }
    return run(steps);
}

Reply *AcuAxis::halt(double deceleration)
{
    auto *steps = new AcuSteps(this, Tr::tr("halt"));
    if (deceleration > 0 && hasPositioning()
        && (m_mode == Mode::ProfilePosition || m_mode == Mode::ProfileVelocity))
        steps->write(kDeceleration, positive(deceleration));
    // Bit 9 stays as it is: in table travel mode its fall would start another stop.
    steps->control(quint16((m_controlWord & ~kBit4) | kHalt | kEnableOperation));
    return run(steps);
}

Reply *AcuAxis::home(const motion::HomingParams &params)
{
    if (!hasPositioning())
        return Reply::failed(ObjectAddress(kHomingMethod, 0),
                             Error(Error::Kind::NotSupported, featureNote()));
    auto *steps = new AcuSteps(this, Tr::tr("homing"));
    if (auto ok = addModeChange(steps, Mode::Homing); !ok) {
        delete steps;
        return Reply::failed(ObjectAddress(kMode, 0), ok.error());
    }
    requireEnabled(steps);
    steps->write(kHomingMethod, params.method);
    if (params.speedFast > 0)
        steps->write(kFastSpeed, positive(params.speedFast));
    if (params.speedSlow > 0)
        steps->write(kCreepSpeed, positive(params.speedSlow));
    if (params.acceleration > 0)
        steps->write(kHomingAcceleration, positive(params.acceleration));
    steps->control(kEnableOperation);
    steps->control(kEnableOperation | kBit4); // rising edge: start homing
    steps->waitStatus([](quint16 w) { return (w & kBit12) || (w & kBit13); }, kHomingTimeoutMs,
                      Tr::tr("homing not finished within %1 s").arg(kHomingTimeoutMs / 1000));
    steps->call([steps]() -> Result<void> {
        if (steps->lastStatus() & kBit13)
            return Error(Error::Kind::DeviceError, Tr::tr("homing error (status bit 13)"));
        return {};
    });
    steps->control(kEnableOperation);
    return run(steps);
}

Reply *AcuAxis::torque(double, double)
{
    return Reply::failed(ObjectAddress(kMode, 0),
                         Error(Error::Kind::NotSupported,
                               Tr::tr("the ACTIVE Cube has no torque mode over the override")));
}

Reply *AcuAxis::stopNow()
{
    if (m_running)
        m_running->cancel(Error(Error::Kind::Cancelled, Tr::tr("stopped")));
    auto *steps = new AcuSteps(this, Tr::tr("quick stop"));
    steps->control(kQuickStop);
    m_running = nullptr; // nothing supersedes a quick stop
    return refreshedAfter(steps->start());
}

Reply *AcuAxis::startMotionBlock(int block, bool sequence, bool resume)
{
    if (!hasPositioning())
        return Reply::failed(ObjectAddress(kActiveBlock, 0),
                             Error(Error::Kind::NotSupported, featureNote()));
    if (block < 1 || block > 32)
        return Reply::failed(ObjectAddress(kActiveBlock, 0),
                             Error(Error::Kind::InvalidArgument,
                                   Tr::tr("motion block %1 does not exist (1-32)").arg(block)));
    auto *steps = new AcuSteps(this, Tr::tr("table travel block %1").arg(block));
    if (auto ok = addModeChange(steps, Mode::TableTravel); !ok) {
        delete steps;
        return Reply::failed(ObjectAddress(kMode, 0), ok.error());
    }
    requireEnabled(steps);
    const quint16 select = quint16((block - 1) << 11);
    const quint16 word =
        quint16(kEnableOperation | select | (sequence ? kBit4 : 0) | (resume ? kBit6 : 0));
    steps->control(word); // bit 9 low first: the block is taken on its rising edge
    steps->control(quint16(word | kBit9));
    steps->waitStatus([](quint16 w) { return w & kBit8; }, kHandshakeTimeoutMs,
                      Tr::tr("the inverter did not start the motion block (status bit 8)"));
    steps->waitStatus(
        [](quint16 w) { return !(w & kBit8) && (w & kTargetReached); }, kTableTravelTimeoutMs,
        Tr::tr("the motion block did not end within %1 s").arg(kTableTravelTimeoutMs / 1000));
    steps->control(kEnableOperation);
    auto last = std::make_shared<int>(block);
    steps->setResult([last] { return QVariant(*last); });
    return run(steps);
}

Reply *AcuAxis::moveAwayFromLimitSwitch()
{
    if (!hasPositioning())
        return Reply::failed(ObjectAddress(kMode, 0),
                             Error(Error::Kind::NotSupported, featureNote()));
    auto *steps = new AcuSteps(this, Tr::tr("move away from limit switch"));
    if (auto ok = addModeChange(steps, Mode::LimitSwitch); !ok) {
        delete steps;
        return Reply::failed(ObjectAddress(kMode, 0), ok.error());
    }
    requireEnabled(steps);
    steps->control(kEnableOperation);
    steps->control(kEnableOperation | kBit4);
    steps->waitStatus([](quint16 w) { return w & kTargetReached; }, kHomingTimeoutMs,
                      Tr::tr("the limit switch was not cleared"));
    steps->control(kEnableOperation);
    return run(steps);
}

Reply *AcuAxis::gearIn(int numerator, int denominator, double acceleration, double deceleration)
{
    if (!hasPositioning())
        return Reply::failed(ObjectAddress(kMode, 0),
                             Error(Error::Kind::NotSupported, featureNote()));
    if (numerator == 0 || denominator < 1)
        return Reply::failed(ObjectAddress(kGearNumerator, 0),
                             Error(Error::Kind::InvalidArgument,
                                   Tr::tr("gear ratio %1:%2: the numerator must not be 0 and the "
                                          "denominator must be at least 1")
                                       .arg(numerator)
                                       .arg(denominator)));
    auto *steps = new AcuSteps(this, Tr::tr("electronic gear"));
    if (auto ok = addModeChange(steps, Mode::ElectronicGear); !ok) {
        delete steps;
        return Reply::failed(ObjectAddress(kMode, 0), ok.error());
    }
    requireEnabled(steps);
    steps->write(kGearNumerator, numerator);
    steps->write(kGearDenominator, denominator);
    if (acceleration > 0)
        steps->write(kAcceleration, positive(acceleration));
    if (deceleration > 0)
        steps->write(kDeceleration, positive(deceleration));
    steps->control(kEnableOperation); // bit 4 low first: the gear starts on its rise
    steps->control(kEnableOperation | kBit4);
    steps->waitStatus([](quint16 w) { return w & kTargetReached; }, kGearTimeoutMs,
                      Tr::tr("the inverter did not report 'in gear' (status bit 10) within %1 s")
                          .arg(kGearTimeoutMs / 1000));
    return run(steps);
}

Reply *AcuAxis::gearOut(double deceleration)
{
    if (m_mode != Mode::ElectronicGear)
        return Reply::failed(ObjectAddress(kMode, 0),
                             Error(Error::Kind::InvalidArgument,
                                   Tr::tr("not coupled: the inverter is not in electronic gear "
                                          "mode (1454 = -3)")));
    auto *steps = new AcuSteps(this, Tr::tr("leaving the electronic gear"));
    requireEnabled(steps);
    if (deceleration > 0)
        steps->write(kDeceleration, positive(deceleration));
    steps->control(kEnableOperation); // bit 4 low: the inverter brakes with 1458
    return run(steps);
}

} // namespace db::bonfiglioli
