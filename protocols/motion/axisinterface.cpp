#include "axisinterface.h"

#include <QCoreApplication>

namespace db::motion {

Reply *AxisInterface::startMotionBlock(int, bool, bool)
{
    return Reply::failed({},
                         Error(Error::Kind::NotSupported,
                               QCoreApplication::translate("db::motion",
                                                           "this drive has no table of "
                                                           "motion blocks")));
}

Reply *AxisInterface::gearIn(int, int, double, double)
{
    return Reply::failed(
        {},
        Error(Error::Kind::NotSupported,
              QCoreApplication::translate("db::motion", "this drive has no electronic gear")));
}

Reply *AxisInterface::gearOut(double)
{
    return gearIn(0, 0, 0, 0);
}

Reply *AxisInterface::initialize()
{
    auto *reply = new Reply;
    reply->finish();
    return reply;
}

} // namespace db::motion
