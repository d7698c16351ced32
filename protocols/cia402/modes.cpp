#include "modes.h"

#include "statusword.h"
#include <QCoreApplication>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::cia402)
};
} // namespace

namespace db::cia402 {

quint32 supportedModeBit(Mode mode)
{
    switch (mode) {
    case Mode::ProfilePosition:
        return 1u << 0;
    case Mode::ProfileVelocity:
        return 1u << 2;
    case Mode::ProfileTorque:
        return 1u << 3;
    case Mode::Homing:
        return 1u << 5;
    case Mode::CyclicPosition:
        return 1u << 7;
    case Mode::CyclicVelocity:
        return 1u << 8;
    case Mode::CyclicTorque:
        return 1u << 9;
    case Mode::NoMode:
        break;
    }
    return 0;
}

std::optional<ObjectAddress> profileJerk(const ObjectDictionary &dictionary)
{
    if (dictionary.contains(obj::ProfileJerkArray))
        return obj::ProfileJerkArray;
    if (dictionary.contains(obj::ProfileJerkValue))
        return obj::ProfileJerkValue;
    return std::nullopt;
}

namespace {
QVariant i64(qint64 v)
{
    return QVariant::fromValue<qlonglong>(v);
}

Sequence *selectMode(Sequence *s, Mode mode)
{
    return s->write(obj::ModesOfOperation, i64(qint64(mode)));
}
} // namespace

Sequence *profilePosition(DeviceConnection *c, const PositionSetPoint &sp, QObject *parent)
{
    auto *s = new Sequence(c, Tr::tr("profile position"), parent);
    selectMode(s, Mode::ProfilePosition);
    s->write(obj::ProfileVelocity, i64(sp.velocity));
    s->write(obj::ProfileAcceleration, i64(sp.acceleration));
    s->write(obj::ProfileDeceleration, i64(sp.deceleration));
    if (sp.jerkObject)
        s->write(*sp.jerkObject, i64(sp.jerk));
    s->write(obj::TargetPosition, i64(sp.target));
    const quint16 base = cw::EnableOperationCmd | (sp.relative ? cw::Relative : 0);
    s->controlword(base);
    s->controlword(base | cw::NewSetPoint | (sp.immediate ? cw::ChangeImmediately : 0));
    s->waitFor(QStringLiteral("set-point acknowledge (6041h bit 12)"),
               bitsSet(sw::SetPointAcknowledge), kSetPointAcknowledgeTimeoutMs);
    s->controlword(base);
    s->waitFor(QStringLiteral("set-point acknowledge cleared"), bitsClear(sw::SetPointAcknowledge),
               kSetPointAcknowledgeTimeoutMs);
    return s;
}

Sequence *profileVelocity(DeviceConnection *c, qint64 velocity, quint32 acceleration,
                          quint32 deceleration, QObject *parent)
{
    auto *s = new Sequence(c, Tr::tr("profile velocity"), parent);
    selectMode(s, Mode::ProfileVelocity);
    s->write(obj::ProfileAcceleration, i64(acceleration));
    s->write(obj::ProfileDeceleration, i64(deceleration));
    s->write(obj::TargetVelocity, i64(velocity));
    s->controlword(cw::EnableOperationCmd);
    s->waitFor(Tr::tr("operation enabled"), bitsSet(sw::OperationEnabled));
    return s;
}

Sequence *homing(DeviceConnection *c, const HomingSetPoint &sp, QObject *parent)
{
    auto *s = new Sequence(c, QStringLiteral("homing"), parent);
    selectMode(s, Mode::Homing);
    s->write(obj::HomingMethod, i64(sp.method));
    s->write(obj::HomingSpeedFast, i64(sp.speedFast));
    if (sp.speedSlow)
        s->write(obj::HomingSpeedSlow, i64(*sp.speedSlow));
    s->write(obj::HomingAcceleration, i64(sp.acceleration));
    s->write(obj::HomeOffset, i64(sp.offset));
    s->controlword(cw::EnableOperationCmd);
    s->controlword(cw::EnableOperationCmd | cw::NewSetPoint);
    s->waitFor(
        Tr::tr("homing attained (6041h bits 12 and 10)"),
        [](quint16 word, QString &why) {
            if (word & (sw::FollowingError | sw::Fault)) {
                why = Tr::tr("homing error");
                return WaitVerdict::Failed;
            }
            const quint16 done = sw::SetPointAcknowledge | sw::TargetReached;
            return (word & done) == done ? WaitVerdict::Reached : WaitVerdict::Pending;
        },
        sp.timeoutMs);
    s->controlword(cw::EnableOperationCmd);
    return s;
}

Sequence *profileTorque(DeviceConnection *c, qint16 torque, quint32 slope, QObject *parent)
{
    auto *s = new Sequence(c, Tr::tr("profile torque"), parent);
    selectMode(s, Mode::ProfileTorque);
    s->write(obj::TorqueSlope, i64(slope));
    s->write(obj::TargetTorque, i64(torque));
    s->controlword(cw::EnableOperationCmd);
    return s;
}

Sequence *halt(DeviceConnection *c, std::optional<quint32> deceleration, QObject *parent)
{
    auto *s = new Sequence(c, QStringLiteral("halt"), parent);
    if (deceleration)
        s->write(obj::ProfileDeceleration, i64(*deceleration));
    s->controlword(cw::EnableOperationCmd | cw::Halt);
    return s;
}

} // namespace db::cia402
