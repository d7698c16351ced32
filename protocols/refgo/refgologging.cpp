#include "refgologging.h"

namespace db::refgo {
Q_LOGGING_CATEGORY(lcRefgo, "drivebench.refgo")
Q_LOGGING_CATEGORY(lcRefgoRaw, "drivebench.refgo.raw", QtWarningMsg)
} // namespace db::refgo
