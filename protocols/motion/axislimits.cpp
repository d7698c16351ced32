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
constexpr ObjectAddress kPositionOptionCode { 0x60F2, 0 };
// 60F2h bits 6-7 (movingcap.md 6.2): 00 linear; 01 rotary, negative direction only; 10 rotary,
// positive direction only; 11 rotary, shortest way.
constexpr quint32 kRotaryMask = 0xC0;
constexpr quint32 kRotaryNegativeOnly = 0x40;
constexpr quint32 kRotaryPositiveOnly = 0x80;
} // namespace

QList<ObjectAddress> objects(const ObjectDictionary &dictionary)
{
    QList<ObjectAddress> wanted;
    for (ObjectAddress a :
         { kSoftLimitMin, kSoftLimitMax, kMaxProfileVelocity, kMaxAcceleration, kPositionWindow,
           kPositionWindowTime, kVelocityWindow, kPositionOptionCode })
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
    // A rotary axis (60F2h) is endless: 607Dh.1/.2 are the smallest and largest rotary position,
    // so they give the cycle and bound nothing.
    const quint32 option = quint32(values.value(kPositionOptionCode, 0).toULongLong());
    if (option & kRotaryMask) {
        c.endless = true;
        const double span = c.softLimitPositive - c.softLimitNegative;
        if (c.softLimitsUsed && span > 0)
            c.cycleLength = span;
        c.softLimitsUsed = false;
        const quint32 rotary = option & kRotaryMask;
        c.permitted = rotary == kRotaryNegativeOnly ? PermittedDirection::NegativeOnly
            : rotary == kRotaryPositiveOnly         ? PermittedDirection::PositiveOnly
                                                    : PermittedDirection::Both;
    }
    c.velocityWindow = values.contains(kVelocityWindow)
        ? std::max(1.0, values.value(kVelocityWindow).toDouble())
        : kDefaultVelocityWindow;
    return c;
}

} // namespace db::motion::axislimits
