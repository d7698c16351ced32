#include "acuaxis.h"

#include "acuaxis_p.h"
#include "acustatussource.h"
#include "acusteps.h"
#include "core/connectionhealth.h"

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

namespace {

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
        | Feature::MotionBlocks | Feature::ElectronicGear;
}

QString AcuAxis::featureNote() const
{
    if (hasPositioning())
        return {};
    return Tr::tr("configuration %1 has no positioning control (30 is not x40): velocity mode "
                  "(rpm) only")
        .arg(m_configuration);
}

AcuAxis::Mode AcuAxis::modeFor(motion::CommandKind kind) const
{
    using motion::CommandKind;
    if (!hasPositioning())
        return Mode::None; // 1454 stays at 2; the other commands fail with featureNote()
    switch (kind) {
    case CommandKind::MoveAbsolute:
    case CommandKind::MoveRelative:
    case CommandKind::MoveAdditive:
        return Mode::ProfilePosition;
    case CommandKind::MoveVelocity:
        return Mode::ProfileVelocity;
    case CommandKind::Home:
        return Mode::Homing;
    case CommandKind::MotionBlock:
        return Mode::TableTravel;
    case CommandKind::GearIn:
        return Mode::ElectronicGear;
    default:
        return Mode::None;
    }
}

bool AcuAxis::needsModeChange(motion::CommandKind kind) const
{
    const Mode mode = modeFor(kind);
    return mode != Mode::None && mode != m_mode;
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
    // The reads and the result die with the axis when it goes before they finish.
    auto *result = new Reply(ObjectAddress(kConfiguration, 0), this);
    const QList<quint16> wanted { kConfiguration,   kBusErrorBehaviour, kMode,
                                  kProfileVelocity, kAcceleration,      kDeceleration,
                                  kTargetWindow,    kTargetWindowTime,  kHomingMethod,
                                  kFastSpeed,       kCreepSpeed,        kHomingAcceleration };
    auto values = std::make_shared<QHash<quint16, QVariant>>();
    auto configurationError = std::make_shared<Error>();
    auto pending = std::make_shared<int>(int(wanted.size()));
    auto reads = std::make_shared<QList<QPointer<Reply>>>();
    QPointer<Reply> guard(result);
    for (const quint16 p : wanted) {
        Reply *r = connection()->read(ObjectAddress(p, 0));
        r->setParent(this);
        reads->append(r);
        connect(r, &Reply::finished, this, [=, this] {
            r->deleteLater();
            if (r->ok())
                values->insert(p, r->value());
            else if (p == kConfiguration)
                *configurationError = r->error();
            if (!r->ok() && ConnectionHealth::isNoAnswer(r->error())) {
                // The inverter did not answer (or the link is gone): the reads queued behind
                // this one would only wait out their own time limits. Deleting an unsent
                // request withdraws it.
                for (const QPointer<Reply> &other : std::as_const(*reads))
                    if (other && other != r)
                        delete other.data();
                reads->clear();
                *pending = 0;
                if (guard)
                    guard->fail(r->error());
                return;
            }
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
            // The read's own cause (no answer, closed link, device error) where there is one.
            if (!values->contains(kConfiguration))
                guard->fail(
                    configurationError->isError()
                        ? *configurationError
                        : Error(Error::Kind::DeviceError,
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
    // Not the polled status, which may predate the end of the last motion: the speeds read
    // now decide, before anything is written.
    const QString refused = Tr::tr("refused: mode change while moving");
    const auto still = [](qint64 speed) {
        return speed == 0;
    };
    steps->checkValue(kSpeed, still, refused);
    steps->checkValue(kActualSpeedRpm, still, refused);
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

} // namespace db::bonfiglioli
