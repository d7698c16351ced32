// Files are written atomically even when the writer dies: drivebench-cli backup, record and dcf
// are killed (SIGKILL) at random moments while they write over an existing good file, and the
// file must afterwards be either that old file, byte for byte, or a complete new one. Never a
// partial file, never an empty one.
#include "clirun.h"
#include "parameters/parameterset.h"
#include "scope/csv.h"

#include <QDir>
#include <QFile>
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

    QStringList argsFor(const QString &kind, const QString &path) const
    {
        if (kind == QLatin1String("backup"))
            return { QStringLiteral("backup"), m_refgo, QStringLiteral("-o"), path };
        if (kind == QLatin1String("record"))
            return { QStringLiteral("record"),     m_refgo,
                     QStringLiteral("--obj"),      QStringLiteral("6064:0"),
                     QStringLiteral("--obj"),      QStringLiteral("6041:0"),
                     QStringLiteral("--duration"), QStringLiteral("0.3"),
                     QStringLiteral("-o"),         path };
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
        QVERIFY2(first.exitCode == 0, qPrintable(first.err));
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
        qInfo("%s: %d runs killed at random moments: %d left the old file, %d a complete new one",
              qPrintable(kind), kRuns, keptOld, wroteNew);
        QCOMPARE(keptOld + wroteNew, kRuns);
    }
};

QTEST_GUILESS_MAIN(TestCliKillWriter)
#include "tst_cli_killwriter.moc"
