// Files are written atomically even when the writer dies: drivebench-cli backup, record and dcf
// are killed (SIGKILL) at random moments while they write over an existing good file, and the
// file must afterwards be either that old file, byte for byte, or a complete new one. Never a
// partial file, never an empty one.
#include "clirun.h"
#include "parameters/parameterset.h"
#include "scope/csv.h"

#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QRandomGenerator>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

#include <csignal>

using namespace db;

namespace {

QByteArray contents(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

bool writeFile(const QString &path, const QByteArray &bytes)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly | QIODevice::Truncate) && f.write(bytes) == bytes.size();
}

// Files next to `path` named like a temporary of it: "<name>." and six more characters.
QStringList temporariesOf(const QString &path)
{
    const QFileInfo info(path);
    QStringList found;
    for (const QString &name : info.dir().entryList(QDir::Files | QDir::Hidden)) {
        if (name.size() == info.fileName().size() + 7
            && name.startsWith(info.fileName() + QLatin1Char('.')))
            found.append(name);
    }
    return found;
}

} // namespace

class TestCliKillWriter : public QObject
{
    Q_OBJECT

private:
    QProcess m_sim;
    QString m_refgo;
    QTemporaryDir m_dir;

    // "complete" when `path` holds a whole file of the writer's kind.
    static QString judge(const QString &kind, const QString &path)
    {
        if (kind == QLatin1String("backup")) {
            const auto set = ParameterSet::load(path);
            return set ? QStringLiteral("complete") : set.error().toString();
        }
        if (kind == QLatin1String("record")) {
            const auto rec = scope::csv::load(path);
            if (!rec)
                return rec.error().toString();
            return rec.value().channels.size() == 2 ? QStringLiteral("complete")
                                                    : QStringLiteral("wrong channels");
        }
        // A DCF: an INI file that ends with its last section complete.
        const QByteArray bytes = contents(path);
        return bytes.contains("[DeviceInfo]") && bytes.endsWith('\n') ? QStringLiteral("complete")
                                                                      : QStringLiteral("cut");
    }

    // A run that ended normally. A recording that lost samples on a busy machine says so and
    // exits with 1, but still writes its whole file (the gaps marked): that counts too.
    static bool wroteItsFile(const test::CliRun &run)
    {
        return run.exitCode == 0
            || (run.exitCode == 1 && run.err.contains(QLatin1String("samples were lost")));
    }

    QStringList argsFor(const QString &kind, const QString &path) const
    {
        if (kind == QLatin1String("backup"))
            return { QStringLiteral("backup"), m_refgo, QStringLiteral("-o"), path };
        if (kind == QLatin1String("record"))
            return { QStringLiteral("record"), m_refgo, QStringLiteral("--obj"),
                     QStringLiteral("6064:0"), QStringLiteral("--obj"), QStringLiteral("6041:0"),
                     QStringLiteral("--duration"), QStringLiteral("0.3"),
                     // 50 ms: a busy machine (or a sanitizer build) keeps up, so the run that
                     // must succeed does not fail for lost samples; the file is what counts.
                     QStringLiteral("--rate-ms"), QStringLiteral("50"), QStringLiteral("-o"),
                     path };
        return { QStringLiteral("dcf"), m_refgo, QStringLiteral("-o"), path };
    }

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        m_sim.setStandardErrorFile(m_dir.filePath(QStringLiteral("sim.log")));
        m_sim.start(QStringLiteral(DRIVEBENCH_SIM),
                    { QStringLiteral("movingcap"), QStringLiteral("--refgo-port"),
                      QStringLiteral("0"), QStringLiteral("--slcan-port"), QStringLiteral("0") });
        QVERIFY(m_sim.waitForStarted());
        const QRegularExpression re(QStringLiteral("\\((refgo://[^)]+)\\)"));
        QString banner;
        QRegularExpressionMatch m;
        for (int i = 0; i < 100 && !(m = re.match(banner)).hasMatch(); ++i) {
            m_sim.waitForReadyRead(100);
            banner += QString::fromUtf8(m_sim.readAllStandardOutput());
        }
        QVERIFY2(m.hasMatch(), qPrintable(banner));
        m_refgo = m.captured(1);
    }

    void cleanupTestCase()
    {
        m_sim.terminate();
        if (!m_sim.waitForFinished(3000))
            m_sim.kill();
    }

    void killedWriterLeavesOldOrNewFile_data()
    {
        QTest::addColumn<QString>("kind");
        QTest::newRow("backup") << QStringLiteral("backup");
        QTest::newRow("record") << QStringLiteral("record");
        QTest::newRow("dcf") << QStringLiteral("dcf");
    }

    void killedWriterLeavesOldOrNewFile()
    {
        QFETCH(QString, kind);
        const QString path = m_dir.filePath(kind + QStringLiteral(".out"));
        // A good file of this kind first, and how long a whole run takes.
        const test::CliRun first =
            test::runProgram(QStringLiteral(DRIVEBENCH_CLI), argsFor(kind, path), 30000);
        QVERIFY2(wroteItsFile(first), qPrintable(first.err));
        QCOMPARE(judge(kind, path), QStringLiteral("complete"));
        const QByteArray old = contents(path);
        QVERIFY(!old.isEmpty());

        int keptOld = 0;
        int wroteNew = 0;
        constexpr int kRuns = 12;
        for (int i = 0; i < kRuns; ++i) {
            QVERIFY(writeFile(path, old));
            QProcess writer;
            writer.setStandardOutputFile(QProcess::nullDevice());
            writer.setStandardErrorFile(QProcess::nullDevice());
            writer.start(QStringLiteral(DRIVEBENCH_CLI), argsFor(kind, path));
            QVERIFY(writer.waitForStarted());
            // Anywhere from start-up to just past the end of a normal run.
            const int at = int(QRandomGenerator::global()->bounded(qint64(first.ms * 12 / 10 + 1)));
            writer.waitForFinished(at);
            if (writer.state() != QProcess::NotRunning) {
                ::kill(pid_t(writer.processId()), SIGKILL);
                QVERIFY(writer.waitForFinished(5000));
            }
            const QByteArray now = contents(path);
            if (now == old) {
                ++keptOld;
                continue;
            }
            const QString verdict = judge(kind, path);
            QVERIFY2(verdict == QLatin1String("complete"),
                     qPrintable(QStringLiteral("killed after %1 ms: %2 bytes, %3")
                                    .arg(at)
                                    .arg(now.size())
                                    .arg(verdict)));
            ++wroteNew;
        }
        const QStringList leftovers = temporariesOf(path);
        qInfo("%s: %d runs killed at random moments: %d left the old file, %d a complete new "
              "one; %lld temporary files left",
              qPrintable(kind), kRuns, keptOld, wroteNew, qlonglong(leftovers.size()));
        QCOMPARE(keptOld + wroteNew, kRuns);

        // Temporaries a killed writer left (named ones exist where the file system has no
        // unnamed files, and for an instant during the rename) go with the next complete
        // write once they are a minute old; one more is planted so that this is always tried.
        const QDateTime stale = QDateTime::currentDateTime().addSecs(-120);
        QFile planted(path + QStringLiteral(".kIlLeD"));
        QVERIFY(planted.open(QIODevice::WriteOnly) && planted.write(old.left(old.size() / 2)) > 0
                && planted.flush());
        planted.close();
        for (const QString &name : temporariesOf(path)) {
            QFile f(m_dir.filePath(name));
            QVERIFY(f.open(QIODevice::ReadWrite)
                    && f.setFileTime(stale, QFileDevice::FileModificationTime));
        }
        const test::CliRun last =
            test::runProgram(QStringLiteral(DRIVEBENCH_CLI), argsFor(kind, path), 30000);
        QVERIFY2(wroteItsFile(last), qPrintable(last.err));
        QCOMPARE(judge(kind, path), QStringLiteral("complete"));
        QCOMPARE(temporariesOf(path), QStringList());
    }
};

QTEST_GUILESS_MAIN(TestCliKillWriter)
#include "tst_cli_killwriter.moc"
