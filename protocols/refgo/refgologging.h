#pragma once

#include <QLoggingCategory>

namespace db::refgo {
// "drivebench.refgo": requests, answers, dropped late replies, protocol errors.
Q_DECLARE_LOGGING_CATEGORY(lcRefgo)
// "drivebench.refgo.raw": every byte chunk sent and received, debug level (off by default).
Q_DECLARE_LOGGING_CATEGORY(lcRefgoRaw)
} // namespace db::refgo
