// drivebench-cli record end to end against drivebench-sim on an OS-chosen loopback port: a move
// started with `drivebench-cli refgo ... G` is recorded with position, current and velocity,
// triggered on the start of motion; the CSV is read back and checked. Plus the failures: a
// trigger that never fires, usage errors, a refused connection.
#include "clirun.h"

#include "scope/csv.h"

#include <QElapsedTimer>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

using namespace db;

class TestCliRecord : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void cleanupTestCase();

    void recordsAMoveTriggeredOnMotion();
    void recordsForADuration();
    void triggerThatNeverFiresExitsWithFour();
    void usageErrorsExitWithTwo_data();
    void usageErrorsExitWithTwo();
    void refusedConnectionExitsWithThree();

private:
    using Run = db::test::CliRun;
    Run cli(const QStringList &args, int timeoutMs = 20000);
    QString uri() const { return QStringLiteral("refgo://127.0.0.1:%1").arg(m_port); }
    QString file(const char *name) const { return m_dir.filePath(QString::fromLatin1(name)); }

    QProcess m_sim;
    quint16 m_port = 0;
    QTemporaryDir m_dir;
};

TestCliRecord::Run TestCliRecord::cli(const QStringList &args, int timeoutMs)
{
    return db::test::runProgram(QStringLiteral(DRIVEBENCH_CLI), args, timeoutMs);
}

void TestCliRecord::initTestCase()
{
    QVERIFY(m_dir.isValid());
    const QString banner = db::test::startAndReadBanner(
        m_sim, QStringLiteral(DRIVEBENCH_SIM),
        { QStringLiteral("movingcap"), QStringLiteral("--refgo-port"), QStringLiteral("0") }, 1);
    const auto m =
        QRegularExpression(QStringLiteral("listening on 127\\.0\\.0\\.1:(\\d+)")).match(banner);
    QVERIFY2(m.hasMatch(), qPrintable(banner));
    m_port = quint16(m.captured(1).toUInt());
}

void TestCliRecord::cleanupTestCase()
{
    m_sim.terminate();
    QVERIFY(m_sim.waitForFinished(5000));
}

void TestCliRecord::recordsAMoveTriggeredOnMotion()
{
    const Run start = cli({ QStringLiteral("read"), uri(), QStringLiteral("6064:0") });
    QCOMPARE(start.exitCode, 0);
    const qint64 p0 = start.out.trimmed().toLongLong();

    const QString csvFile = file("move.csv");
    QProcess record;
    record.start(QStringLiteral(DRIVEBENCH_CLI),
                 { QStringLiteral("record"),    uri(),
                   QStringLiteral("--obj"),     QStringLiteral("6064:0"),
                   QStringLiteral("--obj"),     QStringLiteral("6078:0"),
                   QStringLiteral("--obj"),     QStringLiteral("606C:0"),
                   QStringLiteral("--rate-ms"), QStringLiteral("20"),
                   QStringLiteral("--trigger"), QStringLiteral("606C:0,rising,50"),
                   QStringLiteral("--pre"),     QStringLiteral("0.2"),
                   QStringLiteral("--post"),    QStringLiteral("1"),
                   QStringLiteral("--wait"),    QStringLiteral("20"),
                   QStringLiteral("-o"),        csvFile });
    QString out;
    QTRY_VERIFY_WITH_TIMEOUT((out += QString::fromUtf8(record.readAllStandardOutput()),
                              out.contains(QLatin1String("armed"))),
                             10000);
    // Let the pre-trigger window fill (a condition on elapsed time, not a fixed sleep).
    QElapsedTimer armed;
    armed.start();
    QTRY_VERIFY(armed.elapsed() >= 300);
    const Run go = cli({ QStringLiteral("refgo"), uri(), QStringLiteral("G%1").arg(p0 + 20000) });
    QCOMPARE(go.exitCode, 0);
    QVERIFY(record.waitForFinished(20000));
    out += QString::fromUtf8(record.readAllStandardOutput());
    const QString err = QString::fromUtf8(record.readAllStandardError());
    // Exit 0, or 1 only when samples were lost (reported, and counted in the file).
    QVERIFY2(record.exitCode() == 0
                 || (record.exitCode() == 1 && err.contains(QLatin1String("samples were lost"))),
             qPrintable(out + err));
    QVERIFY2(out.contains(QLatin1String("triggered at")), qPrintable(out));

    QFile f(csvFile);
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QByteArray text = f.readAll();
    QVERIFY(text.contains("\ntime_s,6064:0 Position actual value,6078:0 Current actual value,"
                          "606C:0 Velocity actual value\n"));
    QVERIFY(text.contains("# trigger: 606C:0,rising,50; pre 0.2 s; post 1 s; at "));
    QVERIFY(text.contains("# device: " + uri().toUtf8()));

    const auto rec = scope::csv::fromCsv(text);
    QVERIFY2(rec.ok(), qPrintable(rec.error().toString()));
    QCOMPARE(rec->channels.size(), 3);
    const double tt = rec->triggerTime;
    QVERIFY(rec->hasTriggerTime());
    const scope::TraceBuffer &pos = rec->channels[0].buffer;
    const scope::TraceBuffer &cur = rec->channels[1].buffer;
    const scope::TraceBuffer &vel = rec->channels[2].buffer;
    QCOMPARE(rec->channels[1].info.unit, QStringLiteral("%"));
    // The window: 0.2 s before the trigger, 1 s after it.
    for (const auto *b : { &pos, &cur, &vel }) {
        QVERIFY(b->size() > 20);
        QVERIFY(b->firstTime() >= tt - 0.2 - 1e-9);
        QVERIFY(b->lastTime() <= tt + 1 + 1e-9);
        QVERIFY(b->firstTime() < tt - 0.1); // the pre-trigger part was recorded
    }
    // The trigger sample is the first with velocity >= 50; before it the axis stood still.
    const qint64 at = vel.lowerBound(tt);
    QCOMPARE(vel.time(at), tt);
    QVERIFY(vel.value(at) >= 50);
    for (qint64 i = 0; i < at; ++i)
        QVERIFY(vel.value(i) < 50);
    QVERIFY(std::abs(pos.value(0) - double(p0)) < 5);
    QVERIFY(pos.value(pos.size() - 1) > double(p0) + 100);
    // Acceleration shows in the current: well above the standstill level of the pre-trigger
    // part (its last 0.1 s may already see the demand accelerate, ahead of the velocity).
    double before = 0, after = 0;
    for (qint64 i = 0; i < cur.size(); ++i) {
        const double a = std::abs(cur.value(i));
        if (cur.time(i) < tt - 0.1)
            before = std::max(before, a);
        else if (cur.time(i) >= tt)
            after = std::max(after, a);
    }
    QVERIFY2(after > before + 20, qPrintable(QStringLiteral("%1 %2").arg(before).arg(after)));

    // Stop the axis for the next tests.
    QCOMPARE(cli({ QStringLiteral("refgo"), uri(), QStringLiteral("SM") }).exitCode, 0);
}

void TestCliRecord::recordsForADuration()
{
    const QString csvFile = file("plain.csv");
    const Run r =
        cli({ QStringLiteral("record"), uri(), QStringLiteral("--obj"),
              QStringLiteral("6041:0,6064:0"), QStringLiteral("--rate-ms"), QStringLiteral("25"),
              QStringLiteral("--duration"), QStringLiteral("0.5"), QStringLiteral("-o"), csvFile });
    QVERIFY2(r.exitCode == 0 || r.exitCode == 1, qPrintable(r.err));
    QVERIFY(r.out.startsWith(QLatin1String("recorded ")));
    const auto rec = scope::csv::load(csvFile);
    QVERIFY(rec.ok());
    QCOMPARE(rec->channels.size(), 2);
    QCOMPARE(rec->channels[0].info.name, QStringLiteral("Statusword"));
    QVERIFY(!rec->trigger.isValid());
    const qint64 n = rec->channels[0].buffer.size() + rec->channels[0].buffer.lostAtSource();
    QVERIFY2(n >= 15 && n <= 22, qPrintable(QString::number(n))); // 0.5 s / 25 ms = 20
}

void TestCliRecord::triggerThatNeverFiresExitsWithFour()
{
    const QString csvFile = file("never.csv");
    const Run r =
        cli({ QStringLiteral("record"), uri(), QStringLiteral("--obj"), QStringLiteral("606C:0"),
              QStringLiteral("--trigger"), QStringLiteral("606C:0,above,1e9"),
              QStringLiteral("--wait"), QStringLiteral("0.5"), QStringLiteral("-o"), csvFile });
    QCOMPARE(r.exitCode, 4);
    QVERIFY(r.err.contains(QLatin1String("did not fire within 0.5 s")));
    QVERIFY(!QFile::exists(csvFile));
}

void TestCliRecord::usageErrorsExitWithTwo_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("cause");
    const QString o = file("x.csv");
    QTest::newRow("no obj") << QStringList { "--duration", "1", "-o", o } << "--obj";
    QTest::newRow("no output") << QStringList { "--obj", "6064:0", "--duration", "1" } << "-o";
    QTest::newRow("no duration") << QStringList { "--obj", "6064:0", "-o", o } << "--duration";
    QTest::newRow("bad address") << QStringList { "--obj", "60G4:0", "--duration", "1", "-o", o }
                                 << "60G4";
    QTest::newRow("bad rate") << QStringList { "--obj",      "6064:0", "--rate-ms", "-5",
                                               "--duration", "1",      "-o",        o }
                              << "--rate-ms";
    QTest::newRow("trigger on other object")
        << QStringList { "--obj", "6064:0", "--trigger", "6041:0,bit3,set", "-o", o }
        << "not one of the recorded channels";
    QTest::newRow("bad trigger") << QStringList {
        "--obj", "6064:0", "--trigger", "6064:0,sideways,3", "-o", o
    } << "unknown condition";
    QTest::newRow("string object")
        << QStringList { "--obj", "1008:0", "--duration", "1", "-o", o } << "not a number";
}

void TestCliRecord::usageErrorsExitWithTwo()
{
    QFETCH(QStringList, args);
    QFETCH(QString, cause);
    const Run r = cli(QStringList { QStringLiteral("record"), uri() } + args);
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.err.contains(cause), qPrintable(r.err));
    QCOMPARE(r.err.count(QLatin1Char('\n')), 1);
}

void TestCliRecord::refusedConnectionExitsWithThree()
{
    const Run r =
        cli({ QStringLiteral("record"), QStringLiteral("refgo://127.0.0.1:1"),
              QStringLiteral("--obj"), QStringLiteral("6064:0"), QStringLiteral("--duration"),
              QStringLiteral("1"), QStringLiteral("-o"), file("refused.csv") });
    QCOMPARE(r.exitCode, 3);
    QVERIFY(!QFile::exists(file("refused.csv")));
}

QTEST_GUILESS_MAIN(TestCliRecord)
#include "tst_cli_record.moc"
