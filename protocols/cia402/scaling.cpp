#include "scaling.h"
#include <QCoreApplication>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::cia402)
};
} // namespace

namespace db::cia402 {

namespace {
constexpr ObjectAddress kEncoderIncrements { 0x608F, 1 };
constexpr ObjectAddress kEncoderRevolutions { 0x608F, 2 };
constexpr ObjectAddress kGearMotor { 0x6091, 1 };
constexpr ObjectAddress kGearShaft { 0x6091, 2 };
constexpr ObjectAddress kFeed { 0x6092, 1 };
constexpr ObjectAddress kFeedShaft { 0x6092, 2 };
// [100 rpm/min] = 100 / 60 rev/min per s = 100 / 3600 rev/s^2 (movingcap.md 9.1).
constexpr double kRotaryAccelerationUnit = 100.0 / 3600.0;
} // namespace

QList<ObjectAddress> Scaling::objects()
{
    return { kEncoderIncrements, kEncoderRevolutions, kGearMotor, kGearShaft, kFeed, kFeedShaft };
}

Result<Scaling> Scaling::fromValues(const QHash<ObjectAddress, QVariant> &values)
{
    Scaling s;
    const QList<std::pair<ObjectAddress, quint32 *>> fields {
        { kEncoderIncrements, &s.encoderIncrements },
        { kEncoderRevolutions, &s.encoderMotorRevolutions },
        { kGearMotor, &s.gearMotorRevolutions },
        { kGearShaft, &s.gearShaftRevolutions },
        { kFeed, &s.feed },
        { kFeedShaft, &s.feedShaftRevolutions },
    };
    for (const auto &[address, field] : fields) {
        bool ok = false;
        const qulonglong v = values.value(address).toULongLong(&ok);
        if (!ok || v == 0 || v > 0xFFFFFFFFull)
            return Error(Error::Kind::InvalidArgument,
                         Tr::tr("scaling object %1 is missing or zero").arg(address.toString()));
        *field = quint32(v);
    }
    return s;
}

double Scaling::incrementsPerUnit() const
{
    return double(encoderIncrements) * double(gearMotorRevolutions) * double(feedShaftRevolutions)
        / (double(encoderMotorRevolutions) * double(gearShaftRevolutions) * double(feed));
}

double Scaling::unitsPerShaftRevolution() const
{
    return double(feed) / double(feedShaftRevolutions);
}

double Scaling::rotaryAccelerationToUser(double raw) const
{
    const double shaftPerMotor = double(gearShaftRevolutions) / double(gearMotorRevolutions);
    return raw * kRotaryAccelerationUnit * shaftPerMotor * unitsPerShaftRevolution();
}

double Scaling::rotaryAccelerationToRaw(double user) const
{
    return user / rotaryAccelerationToUser(1.0);
}

} // namespace db::cia402
