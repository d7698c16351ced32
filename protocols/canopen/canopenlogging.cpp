#include "canopenlogging.h"

namespace db::canopen {
Q_LOGGING_CATEGORY(lcCanopen, "drivebench.canopen")
Q_LOGGING_CATEGORY(lcSdo, "drivebench.canopen.sdo")
Q_LOGGING_CATEGORY(lcSdoRaw, "drivebench.canopen.sdo.raw", QtWarningMsg)
} // namespace db::canopen
