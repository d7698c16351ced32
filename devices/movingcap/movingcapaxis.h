#pragma once

// What makes a MovingCap drive's axis differ from a plain CiA 402 axis.

#include "core/objectdictionary.h"
#include "motion/cia402axis.h"

namespace db::movingcap {

// The dictionary is that of a MovingCap drive (its identity names the product).
bool isMovingCap(const ObjectDictionary &dictionary);

// Rotary MovingCap drives give accelerations (6083h, 6084h, 609Ah, 60C5h) in [100 rpm/min] of
// the motor, not in user units/s^2; the axis converts with the factor group. MovingCap drives
// need no homing: the axis is referenced from the start. Call before Cia402Axis::initialize().
void applyAxisQuirks(motion::Cia402Axis &axis, const ObjectDictionary &dictionary);

} // namespace db::movingcap
