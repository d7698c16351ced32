#include "recentfolder.h"

#include <QDir>
#include <QFileInfo>
#include <QSettings>

namespace db::widgets {

namespace {
// The main window's settings file (organisation and application "drivebench").
QSettings settings()
{
    return QSettings(QSettings::IniFormat, QSettings::UserScope, QStringLiteral("drivebench"),
                     QStringLiteral("drivebench"));
}

QString key(const QString &kind)
{
    return QStringLiteral("folders/") + kind;
}
} // namespace

QString recentFolder(const QString &kind)
{
    const QString folder = settings().value(key(kind)).toString();
    return !folder.isEmpty() && QDir(folder).exists() ? folder : QDir::homePath();
}

void rememberFolder(const QString &kind, const QString &filePath)
{
    if (filePath.isEmpty())
        return;
    settings().setValue(key(kind), QFileInfo(filePath).absolutePath());
}

} // namespace db::widgets
