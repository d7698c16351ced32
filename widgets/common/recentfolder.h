#pragma once

#include <QString>

namespace db::widgets {

// The folder a file dialog opened or saved in last, per kind of file ("parameters", "dcf"), so
// that the next dialog starts there (kept in the application's settings, group "folders").
// The home folder before the first use, or when the folder no longer exists.
QString recentFolder(const QString &kind);
// Remembers the folder of `filePath` for `kind`; an empty path changes nothing.
void rememberFolder(const QString &kind, const QString &filePath);

} // namespace db::widgets
