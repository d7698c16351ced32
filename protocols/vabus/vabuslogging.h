#pragma once

#include <QLoggingCategory>

namespace db::vabus {
// "drivebench.vabus": requests, answers, retries, dropped late answers, protocol errors.
Q_DECLARE_LOGGING_CATEGORY(lcVabus)
// "drivebench.vabus.raw": every byte chunk sent and received, debug level (off by default).
Q_DECLARE_LOGGING_CATEGORY(lcVabusRaw)
} // namespace db::vabus
