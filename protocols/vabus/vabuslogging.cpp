#include "vabuslogging.h"

namespace db::vabus {
Q_LOGGING_CATEGORY(lcVabus, "drivebench.vabus")
Q_LOGGING_CATEGORY(lcVabusRaw, "drivebench.vabus.raw", QtWarningMsg)
} // namespace db::vabus
