// Temporary files that a killed writer leaves next to its target ("<name>.XXXXXX", QSaveFile's
// pattern) are removed by the next write of that file; nothing else is.
#include "core/filewriter.h"
#include "parameters/parameterset.h"

#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTemporaryFile>
#include <QTest>

using namespace db;

namespace {

bool makeFile(const QString &path, const QByteArray &bytes, int ageSeconds)
{
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly) || f.write(bytes) != bytes.size() || !f.flush())
        return false; // flushed: a later write would set the time again
    const QDateTime when = QDateTime::currentDateTime().addSecs(-ageSeconds);
    return f.setFileTime(when, QFileDevice::FileModificationTime);
}

QStringList names(const QString &dir)
{
    QStringList list = QDir(dir).entryList(QDir::Files | QDir::Hidden | QDir::NoDotAndDotDot);
    list.sort();
    return list;
}

} // namespace

class TestFileWriter : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void removesOnlyStaleTemporariesOfTheTarget()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString target = dir.filePath(QStringLiteral("set.dbp"));
        const int old = 2 * int(files::kStaleTemporaryAge.count());
        QVERIFY(makeFile(target, "old file\n", old));
        QVERIFY(makeFile(target + QStringLiteral(".qWeRtY"), "half", old)); // stale: goes
        QVERIFY(makeFile(target + QStringLiteral(".aBcDeF"), "half", old)); // stale: goes
        QVERIFY(makeFile(target + QStringLiteral(".zXcVbN"), "half", 0)); // a writer at work
        QVERIFY(makeFile(target + QStringLiteral(".backup"), "mine", old)); // words stay
        QVERIFY(makeFile(target + QStringLiteral(".BACKUP"), "mine", old));
        QVERIFY(makeFile(target + QStringLiteral(".Backup"), "mine", old));
        QVERIFY(makeFile(target + QStringLiteral(".aB1dEf"), "mine", old)); // Qt uses no digits
        QVERIFY(makeFile(target + QStringLiteral(".aBcDeFg"), "mine", old)); // seven letters
        QVERIFY(makeFile(target + QStringLiteral("x.aBcDeF"), "mine", old)); // another file's
        QVERIFY(makeFile(dir.filePath(QStringLiteral("other.dbp.qWeRtY")), "x", old));
        QVERIFY(QDir(dir.path()).mkdir(QStringLiteral("set.dbp.fOlDeR")));
        QVERIFY(QFile::link(target, target + QStringLiteral(".lInKeD")));

        QCOMPARE(files::removeStaleTemporaries(target), 2);
        const QStringList left = names(dir.path());
        QVERIFY2(!left.contains(QStringLiteral("set.dbp.qWeRtY")), qPrintable(left.join(' ')));
        QVERIFY(!left.contains(QStringLiteral("set.dbp.aBcDeF")));
        for (const char *kept : { "set.dbp", "set.dbp.zXcVbN", "set.dbp.backup", "set.dbp.BACKUP",
                                  "set.dbp.Backup", "set.dbp.aB1dEf", "set.dbp.aBcDeFg",
                                  "set.dbpx.aBcDeF", "other.dbp.qWeRtY", "set.dbp.lInKeD" })
            QVERIFY2(left.contains(QLatin1String(kept)), kept);
        QVERIFY(QFileInfo(dir.filePath(QStringLiteral("set.dbp.fOlDeR"))).isDir());
        QCOMPARE(QFile(target).size(), qint64(9)); // the target itself untouched
        // Nothing stale left: a second call removes nothing.
        QCOMPARE(files::removeStaleTemporaries(target), 0);
        // Given no minimum age, the fresh one counts as stale too.
        QCOMPARE(files::removeStaleTemporaries(target, std::chrono::seconds(0)), 1);
    }

    void aTargetInAMissingFolderIsNoError()
    {
        QTemporaryDir dir;
        QCOMPARE(files::removeStaleTemporaries(dir.filePath(QStringLiteral("no/such/set.dbp"))), 0);
        QCOMPARE(files::removeStaleTemporaries(QString()), 0);
    }

    // QSaveFile names its temporary after this pattern when it has to name it: the template
    // and the matcher agree on what a temporary of the target looks like.
    void theTemplateMatchesWhatIsRemoved()
    {
        QTemporaryDir dir;
        const QString target = dir.filePath(QStringLiteral("plot.png"));
        QCOMPARE(files::temporaryTemplate(target), target + QStringLiteral(".XXXXXX"));
        int made = 0;
        for (int i = 0; i < 40; ++i) {
            QTemporaryFile temp(files::temporaryTemplate(target));
            QVERIFY(temp.open());
            temp.setAutoRemove(false);
            const QString name = temp.fileName(); // gives the file its name
            QVERIFY(name.startsWith(target + QLatin1Char('.')));
            ++made;
        }
        QCOMPARE(names(dir.path()).size(), made);
        // Most random names are removed (all but those that read like a word, 3 in 64).
        const int removed = files::removeStaleTemporaries(target, std::chrono::seconds(0));
        QVERIFY2(removed >= made * 3 / 4, qPrintable(QString::number(removed)));
        QCOMPARE(names(dir.path()).size(), made - removed);
    }

    // The real writers call it: saving a parameter set clears what an earlier, killed save of
    // the same file left, and the saved file is complete.
    void savingAParameterSetClearsALeftover()
    {
        QTemporaryDir dir;
        const QString target = dir.filePath(QStringLiteral("drive.dbp"));
        const QString leftover = target + QStringLiteral(".kIlLeD");
        QVERIFY(makeFile(leftover, "db-parameter-set 1\n0x6060", 3600));
        const ParameterSet set;
        QVERIFY(set.save(target).ok());
        QVERIFY(!QFile::exists(leftover));
        QVERIFY(ParameterSet::load(target).ok());
        QCOMPARE(names(dir.path()), QStringList { QStringLiteral("drive.dbp") });
    }
};

QTEST_GUILESS_MAIN(TestFileWriter)
#include "tst_filewriter.moc"
