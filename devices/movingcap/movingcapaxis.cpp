#include "movingcapaxis.h"

namespace db::movingcap {

bool isMovingCap(const ObjectDictionary &dictionary)
{
    return dictionary.identity.productName.contains(QLatin1String("MovingCap"),
                                                    Qt::CaseInsensitive);
}

void applyAxisQuirks(motion::Cia402Axis &axis, const ObjectDictionary &dictionary)
{
    if (!isMovingCap(dictionary))
        return;
    axis.setAccelerationUnit(motion::Cia402Axis::AccelerationUnit::RotaryMotor);
    // MovingCap drives keep their absolute position and need no homing: RefGo's TPSR reports
    // REFERENCE always set, and REF35/REF37 only move the zero.
    axis.setReferencedWithoutHoming(true);
}

} // namespace db::movingcap
