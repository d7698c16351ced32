#pragma once

#include <QLoggingCategory>

namespace db::canopen {
// drivebench.canopen: NMT, heartbeat, EMCY, SYNC, the connection.
Q_DECLARE_LOGGING_CATEGORY(lcCanopen)
// drivebench.canopen.sdo: transfers, aborts, dropped late responses.
Q_DECLARE_LOGGING_CATEGORY(lcSdo)
// drivebench.canopen.sdo.raw: every SDO frame, at debug level.
Q_DECLARE_LOGGING_CATEGORY(lcSdoRaw)
} // namespace db::canopen
