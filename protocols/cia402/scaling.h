#pragma once

#include "core/objectaddress.h"
#include "core/result.h"

#include <QHash>
#include <QList>
#include <QVariant>

namespace db::cia402 {

// Position units through the CiA 402 factor group (movingcap.md 9.7):
//   Encoder_resolution = 608Fh.1 / 608Fh.2, Gear_ratio = 6091h.1 / 6091h.2,
//   Feed_constant = 6092h.1 / 6092h.2
//   Pos_internal = Pos_user x Encoder_resolution x Gear_ratio / Feed_constant
// Velocities follow the same scaling per second. Rotary MovingCap accelerations are not
// user-scaled: they are in [100 rpm/min] of the motor (movingcap.md 9.1).
struct Scaling
{
    quint32 encoderIncrements = 1; // 608Fh.1
    quint32 encoderMotorRevolutions = 1; // 608Fh.2
    quint32 gearMotorRevolutions = 1; // 6091h.1
    quint32 gearShaftRevolutions = 1; // 6091h.2
    quint32 feed = 1; // 6092h.1
    quint32 feedShaftRevolutions = 1; // 6092h.2

    // The objects fromValues() needs.
    static QList<ObjectAddress> objects();
    // From raw values of objects(); a missing or zero divisor is an InvalidArgument error.
    static Result<Scaling> fromValues(const QHash<ObjectAddress, QVariant> &values);

    // Internal increments per user unit.
    double incrementsPerUnit() const;
    double toIncrements(double user) const { return user * incrementsPerUnit(); }
    double toUser(double increments) const { return increments / incrementsPerUnit(); }
    // User units per revolution of the gearbox output shaft (the feed constant).
    double unitsPerShaftRevolution() const;

    // Rotary acceleration [100 rpm/min of the motor] <-> user units/s^2.
    double rotaryAccelerationToUser(double raw) const;
    double rotaryAccelerationToRaw(double user) const;
};

} // namespace db::cia402
