#include "cia402axis.h"

#include "axislimits.h"

#include "cia402/cia402statussource.h"
#include "cia402/statusword.h"

#include <QCoreApplication>
#include <QTimer>

#include <cmath>
#include <memory>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::motion)
};
} // namespace

namespace db::motion {

using namespace cia402;

namespace {
constexpr quint32 kRawAccelerationMin = 1;
constexpr double kMaxRawJerk = 0xFFFFFFFFu; // UNSIGNED32
// Digital inputs 60FDh (CiA 402-2): bit 0 negative, bit 1 positive limit switch.
constexpr quint32 kNegativeLimitBit = 0x1;
constexpr quint32 kPositiveLimitBit = 0x2;
constexpr quint16 kHomingError = 0x2000; // statusword bit 13 in homing mode

const QList<ObjectAddress> &statusObjects()
{
    static const QList<ObjectAddress> objects { kStatusword, obj::PositionActual,
                                                obj::VelocityActual, obj::DigitalInputs };
    return objects;
}
} // namespace

Cia402Axis::Cia402Axis(DeviceConnection *connection, QObject *parent)
    : ConnectionAxis(connection, parent)
    , m_controller(connection)
{
    m_jerkObject = profileJerk(connection->dictionary());
    if (m_jerkObject)
        m_features |= Feature::Jerk;
    attachStatus(Cia402StatusSource::sourceOf(connection), statusObjects());
}

Cia402Axis::~Cia402Axis() = default;

bool Cia402Axis::takeStatus(const StatusSource &source, Status &status)
{
    if (!source.isFresh(kStatusword) || !source.isFresh(obj::PositionActual))
        return false;
    const quint16 word = quint16(source.value(kStatusword).toULongLong());
    const State state = decodeState(word);
    status.valid = true;
    status.rawStatus = word;
    status.powered = state == State::OperationEnabled;
    status.fault = state == State::Fault || state == State::FaultReactionActive;
    status.quickStopActive = state == State::QuickStopActive;
    status.moving = word & sw::Moving;
    status.targetReached = word & sw::TargetReached;
    // Bit 12 means "homing attained" only in homing mode (set-point acknowledge in PP).
    constexpr quint16 kAttained = sw::SetPointAcknowledge | sw::TargetReached;
    status.homingAttained = m_referencedWithoutHoming
        || (m_homingMode && (word & kAttained) == kAttained && !(word & kHomingError));
    status.position = source.value(obj::PositionActual).toDouble();
    status.velocity = source.value(obj::VelocityActual).toDouble();
    const quint32 inputs = quint32(source.value(obj::DigitalInputs).toULongLong());
    status.hardwareLimitNegative = inputs & kNegativeLimitBit;
    status.hardwareLimitPositive = inputs & kPositiveLimitBit;
    return true;
}

bool Cia402Axis::commandRunning() const
{
    return m_motion && m_motion->isRunning();
}

Reply *Cia402Axis::initialize()
{
    // The reads and the result die with the axis when it goes before they finish.
    auto *result = new Reply(obj::SupportedModes, this);
    auto values = std::make_shared<QHash<ObjectAddress, QVariant>>();
    QList<ObjectAddress> objects = Scaling::objects();
    objects.append(obj::SupportedModes);
    objects.append(obj::ModesDisplay); // a drive still in homing mode tells its reference
    const ObjectDictionary &dict = connection()->dictionary();
    for (ObjectAddress a : axislimits::objects(dict))
        if (!objects.contains(a))
            objects.append(a);
    for (ObjectAddress a : profileObjects())
        if (dict.contains(a) && !objects.contains(a))
            objects.append(a);
    // Only what the description has; without any of them the defaults stay (no scaling, no
    // modes known).
    objects.removeIf([&dict](ObjectAddress a) { return !dict.contains(a); });
    auto pending = std::make_shared<int>(int(objects.size()));
    auto answered = std::make_shared<bool>(false); // a value or a device's refusal
    auto silence = std::make_shared<Error>();
    QPointer<Reply> guard(result);
    if (objects.isEmpty()) {
        QTimer::singleShot(0, this, [guard] {
            if (guard)
                guard->finish();
        });
        return result;
    }
    for (const ObjectAddress &address : objects) {
        Reply *r = connection()->read(address);
        r->setParent(this);
        connect(r, &Reply::finished, this, [=, this] {
            r->deleteLater();
            if (r->ok())
                values->insert(address, r->value());
            const Error::Kind kind = r->error().kind();
            if (r->ok() || (kind != Error::Kind::Timeout && kind != Error::Kind::Disconnected))
                *answered = true;
            else
                *silence = r->error();
            if (--*pending > 0)
                return;
            applyInitialValues(*values);
            if (!guard)
                return;
            // A drive that answered none of the reads has said nothing about itself: the
            // values above are defaults, and the caller is told so.
            if (*answered)
                guard->finish();
            else
                guard->fail(*silence);
        });
    }
    return result;
}

QList<ObjectAddress> Cia402Axis::profileObjects()
{
    return { obj::ProfileVelocity,    obj::ProfileAcceleration, obj::ProfileDeceleration,
             obj::HomingMethod,       obj::HomingSpeedFast,     obj::HomingSpeedSlow,
             obj::HomingAcceleration, obj::HomeOffset };
}

void Cia402Axis::applyInitialValues(const QHash<ObjectAddress, QVariant> &values)
{
    m_homingMode = values.value(obj::ModesDisplay).toInt() == int(Mode::Homing);
    if (auto s = Scaling::fromValues(values))
        m_scaling = s.value();
    if (values.contains(obj::SupportedModes)) {
        const quint32 modes = quint32(values.value(obj::SupportedModes).toULongLong());
        Features f = m_features & Feature::Jerk;
        if (modes & supportedModeBit(Mode::ProfilePosition))
            f |= Feature::ProfilePosition;
        if (modes & supportedModeBit(Mode::ProfileVelocity))
            f |= Feature::ProfileVelocity;
        if (modes & supportedModeBit(Mode::Homing))
            f |= Feature::Homing;
        if (modes & supportedModeBit(Mode::ProfileTorque))
            f |= Feature::Torque;
        m_features = f;
    }
    const bool rotary = m_accelerationUnit == AccelerationUnit::RotaryMotor;
    m_limits = axislimits::fromValues(values, connection()->dictionary(), m_scaling, rotary);
    const auto user = [&](ObjectAddress a, bool acceleration) {
        const double raw = values.value(a).toDouble();
        return acceleration && rotary ? m_scaling.rotaryAccelerationToUser(raw) : raw;
    };
    m_profile.velocity = user(obj::ProfileVelocity, false);
    m_profile.acceleration = user(obj::ProfileAcceleration, true);
    m_profile.deceleration = user(obj::ProfileDeceleration, true);
    m_profile.jerk = m_limits.maxJerk;
    if (values.contains(obj::HomingMethod))
        m_homing.method = values.value(obj::HomingMethod).toInt();
    m_homing.speedFast = user(obj::HomingSpeedFast, false);
    m_homing.speedSlow = values.contains(obj::HomingSpeedSlow) ? user(obj::HomingSpeedSlow, false)
                                                               : m_homing.speedFast;
    m_homing.acceleration = user(obj::HomingAcceleration, true);
    m_homing.offset = user(obj::HomeOffset, false);
}

QString Cia402Axis::positionUnit() const
{
    const ObjectDef *pos = connection()->dictionary().find(obj::PositionActual);
    return pos ? pos->unit : QString();
}

QString Cia402Axis::velocityUnit() const
{
    const ObjectDef *vel = connection()->dictionary().find(obj::VelocityActual);
    return vel ? vel->unit : QString();
}

quint32 Cia402Axis::accelerationRaw(double user) const
{
    const double raw = m_accelerationUnit == AccelerationUnit::RotaryMotor
        ? m_scaling.rotaryAccelerationToRaw(user)
        : user;
    return std::max(kRawAccelerationMin, quint32(std::llround(std::abs(raw))));
}

Reply *Cia402Axis::runMotion(Sequence *sequence, bool homing)
{
    m_homingMode = homing;
    if (m_motion)
        m_motion->cancel(
            Error(Error::Kind::Cancelled,
                  m_motion->name() + QStringLiteral(": superseded by ") + sequence->name()));
    m_motion = sequence;
    return refreshedAfter(sequence->start());
}

Reply *Cia402Axis::power(bool on)
{
    if (m_motion)
        m_motion->cancel(Error(Error::Kind::Cancelled, Tr::tr("power changed")));
    return refreshedAfter(on ? m_controller.enableOperation() : m_controller.disableVoltage());
}

Reply *Cia402Axis::reset()
{
    return refreshedAfter(m_controller.faultReset());
}

Reply *Cia402Axis::moveTo(double target, const Profile &profile)
{
    PositionSetPoint sp;
    sp.target = std::llround(target);
    sp.velocity = quint32(std::llround(std::abs(profile.velocity)));
    sp.acceleration = accelerationRaw(profile.acceleration);
    sp.deceleration = accelerationRaw(profile.deceleration);
    // A jerk beyond what the object holds means "not limited by us": the drive's own stays.
    if (m_jerkObject && profile.jerk > 0 && profile.jerk < kMaxRawJerk) {
        sp.jerkObject = m_jerkObject;
        sp.jerk = quint32(std::llround(profile.jerk));
    }
    sp.immediate = true; // a new command aborts the running one (stoeber_motion.md 2.4)
    return runMotion(profilePosition(connection(), sp, this));
}

Reply *Cia402Axis::moveVelocity(double velocity, const Profile &profile)
{
    return runMotion(profileVelocity(connection(), std::llround(velocity),
                                     accelerationRaw(profile.acceleration),
                                     accelerationRaw(profile.deceleration), this));
}

Reply *Cia402Axis::halt(double deceleration)
{
    std::optional<quint32> dec;
    if (deceleration > 0)
        dec = accelerationRaw(deceleration);
    return runMotion(cia402::halt(connection(), dec, this), m_homingMode); // mode unchanged
}

Reply *Cia402Axis::home(const HomingParams &params)
{
    if (!(m_features & Feature::Homing))
        return Reply::failed(
            obj::HomingMethod,
            Error(Error::Kind::NotSupported, Tr::tr("the drive has no homing mode")));
    HomingSetPoint sp;
    sp.method = params.method;
    sp.speedFast = quint32(std::llround(params.speedFast));
    if (connection()->dictionary().contains(obj::HomingSpeedSlow))
        sp.speedSlow = quint32(std::llround(params.speedSlow));
    sp.acceleration = accelerationRaw(params.acceleration);
    sp.offset = std::llround(params.offset);
    sp.timeoutMs = kHomingTimeoutMs;
    return runMotion(homing(connection(), sp, this), true);
}

Reply *Cia402Axis::torque(double torquePerMille, double slope)
{
    if (!(m_features & Feature::Torque))
        return Reply::failed(
            obj::TargetTorque,
            Error(Error::Kind::NotSupported, Tr::tr("the drive has no profile torque mode")));
    return runMotion(profileTorque(connection(), qint16(std::lround(torquePerMille)),
                                   quint32(std::llround(std::abs(slope))), this));
}

Reply *Cia402Axis::stopNow()
{
    if (m_motion)
        m_motion->cancel(Error(Error::Kind::Cancelled, Tr::tr("stopped")));
    return refreshedAfter(m_controller.quickStop());
}

} // namespace db::motion
