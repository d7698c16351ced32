#include "logging.h"

namespace db {
Q_LOGGING_CATEGORY(lcCore, "drivebench.core")
}
