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

Reply *AxisInterface::initialize()
{
    auto *reply = new Reply;
    reply->finish();
    return reply;
}

} // namespace db::motion
