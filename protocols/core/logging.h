#pragma once

#include <QLoggingCategory>

namespace db {
// One category per module (ARCHITECTURE.md); raw traffic goes to "<module>.raw" at debug level.
Q_DECLARE_LOGGING_CATEGORY(lcCore)
} // namespace db
