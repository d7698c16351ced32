#pragma once

#include "motiontypes.h"

#include "cia402/scaling.h"
#include "core/objectdictionary.h"

#include <QHash>
#include <QList>
#include <QVariant>

namespace db::motion {

// The axis configuration from a CiA 402 drive's own limit objects (stoeber_motion.md Sec. 7.3
// item 6): software limits 607Dh (movingcap.md 9.2: both 0 = none), maximum profile velocity
// 607Fh, maximum acceleration 60C5h, position window 6067h with its time 6068h, velocity window
// 606Dh, and the rotary bits of the position option code 60F2h (endless axis, cycle = 607Dh.2 -
// 607Dh.1, permitted direction). Where the drive has no object, the dictionary's maximum of 6081h /
// 6083h stands in; what neither gives stays unlimited. Pure.
namespace axislimits {

constexpr double kDefaultVelocityWindow = 10.0; // user units/s, when the drive has no 606Dh

// The objects worth reading: those of the list above that the dictionary knows.
QList<ObjectAddress> objects(const ObjectDictionary &dictionary);
// rotaryAcceleration: 6083h is in [100 rpm/min] of the motor (MovingCap rotary, movingcap.md
// 9.1) and is converted with scaling; else it is taken as user units/s^2.
AxisConfig fromValues(const QHash<ObjectAddress, QVariant> &values,
                      const ObjectDictionary &dictionary, const cia402::Scaling &scaling,
                      bool rotaryAcceleration);

} // namespace axislimits
} // namespace db::motion
