#include "axislimits.h"

#include "cia402/modes.h"

#include <algorithm>

namespace db::motion::axislimits {

namespace {
constexpr ObjectAddress kSoftLimitMin { 0x607D, 1 };
constexpr ObjectAddress kSoftLimitMax { 0x607D, 2 };
constexpr ObjectAddress kMaxProfileVelocity { 0x607F, 0 };
constexpr ObjectAddress kMaxAcceleration { 0x60C5, 0 };
constexpr ObjectAddress kPositionWindow { 0x6067, 0 };
constexpr ObjectAddress kPositionWindowTime { 0x6068, 0 }; // ms
constexpr ObjectAddress kVelocityWindow { 0x606D, 0 };
} // namespace

QList<ObjectAddress> objects(const ObjectDictionary &dictionary)
{
    QList<ObjectAddress> wanted;
    for (ObjectAddress a : { kSoftLimitMin, kSoftLimitMax, kMaxProfileVelocity, kMaxAcceleration,
                             kPositionWindow, kPositionWindowTime, kVelocityWindow })
        if (dictionary.contains(a))
            wanted << a;
    return wanted;
}

AxisConfig fromValues(const QHash<ObjectAddress, QVariant> &values,
                      const ObjectDictionary &dictionary, const cia402::Scaling &scaling,
                      bool rotaryAcceleration)
{
    AxisConfig c;
    if (values.contains(kSoftLimitMin) && values.contains(kSoftLimitMax)) {
        c.softLimitNegative = values.value(kSoftLimitMin).toDouble();
        c.softLimitPositive = values.value(kSoftLimitMax).toDouble();
        c.softLimitsUsed = !(c.softLimitNegative == 0 && c.softLimitPositive == 0);
    }
    if (values.contains(kMaxProfileVelocity)) {
        c.maxVelocity = values.value(kMaxProfileVelocity).toDouble();
    } else if (const ObjectDef *v = dictionary.find(cia402::obj::ProfileVelocity);
               v && v->maximum.isValid()) {
        c.maxVelocity = v->maximum.toDouble();
    }
    if (values.contains(kMaxAcceleration)) {
        c.maxAcceleration = values.value(kMaxAcceleration).toDouble();
    } else if (const ObjectDef *a = dictionary.find(cia402::obj::ProfileAcceleration);
               a && a->maximum.isValid()) {
        const double raw = a->maximum.toDouble();
        c.maxAcceleration = rotaryAcceleration ? scaling.rotaryAccelerationToUser(raw) : raw;
    }
    if (values.contains(kPositionWindow))
        c.positionWindow = std::max(1.0, values.value(kPositionWindow).toDouble());
    if (values.contains(kPositionWindowTime))
        c.positionWindowTimeMs = std::max(0, values.value(kPositionWindowTime).toInt());
    c.velocityWindow = values.contains(kVelocityWindow)
        ? std::max(1.0, values.value(kVelocityWindow).toDouble())
        : kDefaultVelocityWindow;
    return c;
}

} // namespace db::motion::axislimits
