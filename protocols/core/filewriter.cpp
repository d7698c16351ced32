#include "filewriter.h"

#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QFileInfo>

namespace {

constexpr int kRandomChars = 6; // the XXXXXX of QTemporaryFile's and QSaveFile's template

bool isTemporaryOf(const QString &candidate, const QString &targetName)
{
    if (candidate.size() != targetName.size() + 1 + kRandomChars
        || !candidate.startsWith(targetName) || candidate.at(targetName.size()) != u'.')
        return false;
    int upper = 0;
    bool upperAfterFirst = false;
    for (qsizetype i = targetName.size() + 1; i < candidate.size(); ++i) {
        const char16_t c = candidate.at(i).unicode();
        const bool isUpper = c >= u'A' && c <= u'Z';
        if (!isUpper && !(c >= u'a' && c <= u'z'))
            return false; // Qt's random part is letters only
        upper += isUpper ? 1 : 0;
        upperAfterFirst = upperAfterFirst || (isUpper && i > targetName.size() + 1);
    }
    // "backup", "BACKUP" and "Backup" read as words: a user's file.
    return upper != 0 && upper != kRandomChars && upperAfterFirst;
}

} // namespace

namespace db::files {

int removeStaleTemporaries(const QString &target, std::chrono::seconds minAge)
{
    const QFileInfo info(target);
    const QString name = info.fileName();
    if (name.isEmpty())
        return 0;
    const QDateTime before = QDateTime::currentDateTimeUtc().addSecs(-minAge.count());
    int removed = 0;
    const QFileInfoList entries =
        info.absoluteDir().entryInfoList(QDir::Files | QDir::Hidden | QDir::NoDotAndDotDot);
    for (const QFileInfo &entry : entries) {
        if (entry.isSymLink() || !entry.isFile() || !isTemporaryOf(entry.fileName(), name))
            continue;
        if (entry.lastModified().toUTC() > before)
            continue;
        if (QFile::remove(entry.absoluteFilePath()))
            ++removed;
    }
    return removed;
}

QString temporaryTemplate(const QString &target)
{
    return QFileInfo(target).absoluteFilePath() + QStringLiteral(".XXXXXX");
}

} // namespace db::files
