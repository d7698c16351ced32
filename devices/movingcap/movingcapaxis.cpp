#include "movingcapaxis.h"

namespace db::movingcap {

bool isMovingCap(const ObjectDictionary &dictionary)
{
    return dictionary.identity.productName.contains(QLatin1String("MovingCap"),
                                                    Qt::CaseInsensitive);
}

void applyAxisQuirks(motion::Cia402Axis &axis, const ObjectDictionary &dictionary)
{
    if (isMovingCap(dictionary))
        axis.setAccelerationUnit(motion::Cia402Axis::AccelerationUnit::RotaryMotor);
}

} // namespace db::movingcap
