#pragma once

// Helpers shared by the device-description tests (tst_edsloader, tst_xddloader, tst_dcfwriter).
#include "description/devicedescription.h"

#include <QDir>

namespace db::test {

// A file of the shared folder (../shared): DRIVEBENCH_SHARED_DIR as ctest sets it, else next to
// the source tree. The real vendor files are read in place, never copied.
inline QString sharedFile(const QString &relative)
{
    QString dir = qEnvironmentVariable("DRIVEBENCH_SHARED_DIR");
    if (dir.isEmpty())
        dir = QStringLiteral(DRIVEBENCH_SOURCE_DIR "/../shared");
    return QDir(dir).filePath(relative);
}

inline bool hasWarning(const DescriptionLoad &load, const QString &part)
{
    for (const QString &w : load.warnings) {
        if (w.contains(part))
            return true;
    }
    return false;
}

} // namespace db::test
