#include "acuaxis.h"

#include "acustatussource.h"
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

namespace {

// Parameters of the ACTIVE Cube used here.
constexpr quint16 kConfiguration = 30;
constexpr quint16 kActualSpeedRpm = 240;
constexpr quint16 kCurrentFault = 260;
constexpr quint16 kApplicationWarnings = 274;
constexpr quint16 kBusErrorBehaviour = 388;
constexpr quint16 kLocalRemote = 412;
constexpr quint16 kStatusWord = 411;
constexpr quint16 kSpeed = 1107; // u/s
constexpr quint16 kPosition = 1108; // u
constexpr quint16 kHomingMethod = 1130;
constexpr quint16 kFastSpeed = 1132;
constexpr quint16 kCreepSpeed = 1133;
constexpr quint16 kHomingAcceleration = 1134;
constexpr quint16 kTargetWindow = 1165;
constexpr quint16 kTargetWindowTime = 1166;
constexpr quint16 kActiveBlock = 1246;
constexpr quint16 kMode = 1454;
constexpr quint16 kTargetPosition = 1455;
constexpr quint16 kProfileVelocity = 1456;
constexpr quint16 kAcceleration = 1457;
constexpr quint16 kDeceleration = 1458;
constexpr quint16 kTargetVelocityRpm = 1459;
constexpr quint16 kTargetVelocity = 1460;
constexpr qint64 kOverrideOff = -1;
constexpr int kFaultCheckMs = 100; // a fault that stays this long is not a transient // 1455-1460:
                                   // the MCI value is used instead

// Control word 410 (412 = 1).
constexpr quint16 kDisableVoltage = 0x0000;
constexpr quint16 kQuickStop = 0x0002;
constexpr quint16 kShutdown = 0x0006;
constexpr quint16 kSwitchOn = 0x0007;
constexpr quint16 kEnableOperation = 0x000F;
constexpr quint16 kBit4 = 0x0010; // new set-point / start homing / sequence / move off switch
constexpr quint16 kBit5 = 0x0020; // change immediately (profile position); rfg unlock
constexpr quint16 kBit6 = 0x0040; // relative (profile position); resume; rfg use ref
constexpr quint16 kFaultReset = 0x0080;
constexpr quint16 kHalt = 0x0100;
constexpr quint16 kBit9 = 0x0200; // start motion block

// Status word 411.
constexpr quint16 kStateMask = 0x006F;
constexpr quint16 kSwitchOnDisabled = 0x0040;
constexpr quint16 kSwitchOnDisabledQs = 0x0060;
constexpr quint16 kReadyToSwitchOn = 0x0021;
constexpr quint16 kSwitchedOn = 0x0023;
constexpr quint16 kOperationEnabled = 0x0027;
constexpr quint16 kQuickStopActive = 0x0007;
constexpr quint16 kFaultBit = 0x0008;
constexpr quint16 kVoltageEnabled = 0x0010;
constexpr quint16 kTargetReached = 0x0400;
constexpr quint16 kBit8 = 0x0100; // motion block in progress
constexpr quint16 kBit12 = 0x1000; // set-point acknowledged / homing attained
constexpr quint16 kBit13 = 0x2000; // homing error / following error
// 274: hardware limit switch warnings.
constexpr quint16 kHwLimitPositive = 0x0008;
constexpr quint16 kHwLimitNegative = 0x0010;

bool inState(quint16 word, quint16 state)
{
    return (word & kStateMask) == state;
}
bool switchOnDisabled(quint16 w)
{
    return inState(w, kSwitchOnDisabled) || inState(w, kSwitchOnDisabledQs);
}

QList<ObjectAddress> statusObjects()
{
    return { ObjectAddress(kStatusWord, 0), ObjectAddress(kPosition, 0), ObjectAddress(kSpeed, 0),
             ObjectAddress(kActualSpeedRpm, 0), ObjectAddress(kApplicationWarnings, 0) };
}

// The connection's status source; an ACU one, made now, when it has none.
StatusSource *statusSourceOf(DeviceConnection *connection)
{
    if (!connection->statusSource())
        connection->setStatusSource(new AcuStatusSource(connection));
    return connection->statusSource();
}

qint64 positive(double v)
{
    return std::max<qint64>(1, std::llround(std::abs(v)));
}

} // namespace

AcuAxis::AcuAxis(DeviceConnection *connection, QObject *parent)
    : ConnectionAxis(connection, parent)
{
    m_limits.positionWindow = 182.0; // 1165 factory setting
    m_limits.positionWindowTimeMs = 1;
    m_limits.velocityWindow = 10.0;
    attachStatus(statusSourceOf(connection), statusObjects());
}

AcuAxis::~AcuAxis() = default;

AxisInterface::Features AcuAxis::features() const
{
    if (!hasPositioning())
        return Feature::ProfileVelocity;
    return Feature::ProfilePosition | Feature::ProfileVelocity | Feature::Homing
        | Feature::MotionBlocks;
}

QString AcuAxis::featureNote() const
{
    if (hasPositioning())
        return {};
    return Tr::tr("configuration %1 has no positioning control (30 is not x40): velocity mode "
                  "(rpm) only")
        .arg(m_configuration);
}

QString AcuAxis::linkSupervision() const
{
    QString reaction;
    switch (m_busErrorBehaviour) {
    case 0:
        return Tr::tr("Link watchdog off (388 = 0): the inverter keeps running when the link "
                      "stops.");
    case 1:
        reaction = Tr::tr("fault F2714");
        break;
    case 2:
        reaction = Tr::tr("switch off");
        break;
    case 3:
        reaction = Tr::tr("quick stop");
        break;
    case 4:
        reaction = Tr::tr("stop, then fault F2714");
        break;
    case 5:
        reaction = Tr::tr("quick stop, then fault F2714");
        break;
    default:
        return {};
    }
    QString text = Tr::tr("Link watchdog (388 = %1): %2 10 s after the last exchange.")
                       .arg(m_busErrorBehaviour)
                       .arg(reaction);
    if (m_lastAnswer.isValid() && m_lastAnswer.elapsed() >= kSilenceShownMs) {
        const qint64 left = std::max<qint64>(0, kLinkWatchdogMs - m_lastAnswer.elapsed());
        text += QLatin1Char(' ')
            + Tr::tr("No answer for %1 s: the inverter reacts in %2 s at the latest.")
                  .arg(m_lastAnswer.elapsed() / 1000.0, 0, 'f', 1)
                  .arg(left / 1000.0, 0, 'f', 1);
    }
    return text;
}

QString AcuAxis::positionUnit() const
{
    return QStringLiteral("u");
}

QString AcuAxis::velocityUnit() const
{
    return hasPositioning() ? QStringLiteral("u/s") : QStringLiteral("rpm");
}

void AcuAxis::onDisconnected()
{
    if (m_running)
        m_running->cancel(Error(Error::Kind::Disconnected, Tr::tr("connection closed")));
}

bool AcuAxis::takeStatus(const StatusSource &source, Status &status)
{
    const auto value = [&source](quint16 parameter) {
        return source.value(ObjectAddress(parameter, 0));
    };
    if (!source.isFresh(ObjectAddress(kStatusWord, 0))
        || !source.isFresh(ObjectAddress(kPosition, 0)))
        return false;
    const quint16 word = quint16(value(kStatusWord).toUInt());
    const quint16 state = word & kStateMask;
    const bool velocityMode = m_mode == Mode::Velocity || !hasPositioning();
    m_lastAnswer.start();
    status.valid = true;
    status.rawStatus = word;
    status.powered =
        state == kOperationEnabled || (m_modeChanging && m_running && state == kSwitchedOn);
    status.fault = word & kFaultBit;
    status.quickStopActive = state == kQuickStopActive;
    status.position = value(kPosition).toDouble();
    status.velocity = velocityMode ? value(kActualSpeedRpm).toDouble() : value(kSpeed).toDouble();
    status.moving = value(kSpeed).toLongLong() != 0 || value(kActualSpeedRpm).toLongLong() != 0;
    status.targetReached = word & kTargetReached;
    if (m_mode == Mode::Homing)
        status.homingAttained = (word & kBit12) && !(word & kBit13);
    const quint16 app = quint16(value(kApplicationWarnings).toUInt());
    status.hardwareLimitPositive = app & kHwLimitPositive;
    status.hardwareLimitNegative = app & kHwLimitNegative;
    return true;
}

Reply *AcuAxis::initialize()
{
    auto *result = new Reply(ObjectAddress(kConfiguration, 0));
    const QList<quint16> wanted { kConfiguration,   kBusErrorBehaviour, kMode,
                                  kProfileVelocity, kAcceleration,      kDeceleration,
                                  kTargetWindow,    kTargetWindowTime,  kHomingMethod,
                                  kFastSpeed,       kCreepSpeed,        kHomingAcceleration };
    auto values = std::make_shared<QHash<quint16, QVariant>>();
    auto pending = std::make_shared<int>(int(wanted.size()));
    QPointer<Reply> guard(result);
    for (const quint16 p : wanted) {
        Reply *r = connection()->read(ObjectAddress(p, 0));
        connect(r, &Reply::finished, this, [=, this] {
            r->deleteLater();
            if (r->ok())
                values->insert(p, r->value());
            if (--*pending > 0)
                return;
            const auto v = [&](quint16 p, double fallback) {
                return values->contains(p) ? values->value(p).toDouble() : fallback;
            };
            m_configuration = int(v(kConfiguration, 0));
            m_busErrorBehaviour = int(v(kBusErrorBehaviour, -1));
            m_mode = Mode(qint16(qint8(int(v(kMode, 0)))));
            // -1 = override off: the drive then uses its MCI values, unknown here.
            const auto override = [&](quint16 p) {
                const double x = v(p, kOverrideOff);
                return x == kOverrideOff ? 0.0 : x;
            };
            m_profile.velocity = override(kProfileVelocity);
            m_profile.acceleration = override(kAcceleration);
            m_profile.deceleration = override(kDeceleration);
            m_limits.positionWindow = v(kTargetWindow, 182);
            m_limits.positionWindowTimeMs = int(v(kTargetWindowTime, 1));
            m_homing.method = int(v(kHomingMethod, 0));
            m_homing.speedFast = v(kFastSpeed, 0);
            m_homing.speedSlow = v(kCreepSpeed, 0);
            m_homing.acceleration = v(kHomingAcceleration, 0);
            m_limits.homingMethod = m_homing.method;
            if (!guard)
                return;
            if (!values->contains(kConfiguration))
                guard->fail(Error(Error::Kind::DeviceError,
                                  Tr::tr("the inverter did not give its configuration (30)")));
            else
                guard->finish();
        });
    }
    return result;
}

Reply *AcuAxis::run(AcuSteps *steps)
{
    m_modeChanging = false;
    if (m_running)
        m_running->cancel(
            Error(Error::Kind::Cancelled, Tr::tr("superseded by %1").arg(steps->name())));
    m_running = steps;
    return refreshedAfter(steps->start());
}

void AcuAxis::requireEnabled(AcuSteps *steps) const
{
    steps->checkStatus([](quint16 w) { return inState(w, kOperationEnabled); },
                       Tr::tr("the inverter is not in 'operation enabled': enable it first"));
}

Result<void> AcuAxis::addModeChange(AcuSteps *steps, Mode mode)
{
    if (m_mode == mode)
        return {};
    if (status().moving)
        return Error(Error::Kind::Busy, Tr::tr("refused: mode change while moving"));
    // 1454 changes only in "switched on" (0x0007): the inverter is safe there. The axis's own
    // pass through it does not count as the power stage going off.
    AcuAxis *self = this;
    steps->call([self] {
        self->m_modeChanging = true;
        return Result<void>();
    });
    steps->control(kSwitchOn);
    steps->waitStatus([](quint16 w) { return inState(w, kSwitchedOn); }, kStateTimeoutMs,
                      Tr::tr("the inverter did not go to 'switched on' for the mode change"));
    steps->write(kMode, qint64(quint8(qint8(mode))));
    steps->control(kEnableOperation);
    steps->waitStatus([](quint16 w) { return inState(w, kOperationEnabled); }, kStateTimeoutMs,
                      Tr::tr("the inverter did not return to 'operation enabled'"));
    steps->call([self] {
        self->m_modeChanging = false;
        return Result<void>();
    });
    return {};
}

Reply *AcuAxis::power(bool on)
{
    auto *steps = new AcuSteps(this, on ? Tr::tr("enable") : Tr::tr("disable"));
    if (!on) {
        steps->control(kDisableVoltage);
        steps->waitStatus(switchOnDisabled, kStateTimeoutMs,
                          Tr::tr("the inverter did not go to 'switch on disabled'"), true);
        return run(steps);
    }
    // A fault first needs a reset (the status read now, not the last poll's).
    steps->checkStatus([](quint16 w) { return !(w & kFaultBit); },
                       Tr::tr("the inverter is in fault: reset it first"));
    // Control through the state machine; the RAM copy of all data sets, so nothing is stored.
    steps->write(kLocalRemote, 1);
    if (status().valid && status().powered)
        return run(steps);
    steps->control(kDisableVoltage); // from any state (quick stop active too) to the start
    steps->control(kShutdown);
    steps->waitStatus(
        [](quint16 w) { return inState(w, kReadyToSwitchOn) || inState(w, kSwitchedOn); },
        kStateTimeoutMs, Tr::tr("the inverter did not go to 'ready to switch on'"));
    steps->waitStatus([](quint16 w) { return w & kVoltageEnabled; }, kStateTimeoutMs,
                      Tr::tr("no mains voltage (status bit 4 'voltage enabled' is 0): the "
                             "inverter cannot switch on"));
    steps->control(kSwitchOn);
    steps->waitStatus([](quint16 w) { return inState(w, kSwitchedOn); }, kStateTimeoutMs,
                      Tr::tr("the inverter did not go to 'switched on'"));
    steps->control(kEnableOperation);
    steps->waitStatus([](quint16 w) { return inState(w, kOperationEnabled); }, kStateTimeoutMs,
                      Tr::tr("the hardware enable (STO) is off: the inverter stays in "
                             "'switched on'"));
    return run(steps);
}

Reply *AcuAxis::reset()
{
    auto *steps = new AcuSteps(this, Tr::tr("fault reset"));
    auto code = std::make_shared<quint16>(0);
    // 260 first, so that the reset names what it cleared.
    Reply *fault = connection()->read(ObjectAddress(kCurrentFault, 0));
    connect(fault, &Reply::finished, this, [this, fault, code] {
        fault->deleteLater();
        if (fault->ok())
            *code = m_faultCode = quint16(fault->value().toUInt());
    });
    steps->control(kDisableVoltage); // bit 7 low, so that the next write is a rising edge
    steps->control(kFaultReset);
    steps->waitStatus([](quint16 w) { return !(w & kFaultBit); }, kStateTimeoutMs,
                      Tr::tr("the fault stays after the reset: remove its cause first"), true);
    steps->control(kDisableVoltage);
    steps->setResult([code] { return QVariant(*code); });
    return run(steps);
}

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
    // Judged by the 411 that ended the wait: the status of the last cycle may be older.
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

} // namespace db::bonfiglioli
