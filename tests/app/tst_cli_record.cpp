// drivebench-cli record end to end against drivebench-sim on an OS-chosen loopback port: a move
// started with `drivebench-cli refgo ... G` is recorded with position, current and velocity,
// triggered on the start of motion; the CSV is read back and checked. Plus the failures: a
// trigger that never fires, usage errors, a refused connection. And `record --pdo` against
// `drivebench-sim canopen` over SLCAN: passive sampling of a default TPDO (the PDO configuration
// is unchanged afterwards), an object in no TPDO, --configure-tpdo, a pre-operational node.
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

    void pdoSamplesADefaultTpdoPassively();
    void pdoObjectInNoTpdoIsNamed();
    void configureTpdoThenSamples();
    void preoperationalNodeGivesTheReason();
    void pdoNeedsACanopenUri();

private:
    using Run = db::test::CliRun;
    Run cli(const QStringList &args, int timeoutMs = 20000);
    QString uri() const { return QStringLiteral("refgo://127.0.0.1:%1").arg(m_port); }
    QString file(const char *name) const { return m_dir.filePath(QString::fromLatin1(name)); }
    QString canopen(int node) const
    {
        return QStringLiteral("canopen+slcan://127.0.0.1:%1?node=%2&eds=" DRIVEBENCH_SOURCE_DIR
                              "/resources/devices/drivebench_testnode.json")
            .arg(m_canopenPort)
            .arg(node);
    }
    // Runs drivebench-cli and requires exit 0.
    QString ok(const QStringList &args);

    QProcess m_sim;
    QProcess m_canopenSim;
    quint16 m_port = 0;
    quint16 m_canopenPort = 0;
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

    const QString canopenBanner = db::test::startAndReadBanner(
        m_canopenSim, QStringLiteral(DRIVEBENCH_SIM),
        { QStringLiteral("canopen"), QStringLiteral("--slcan-port"), QStringLiteral("0"),
          QStringLiteral("--nodes"), QStringLiteral("1,2,5") },
        1);
    m_canopenPort = db::test::listeningPort(canopenBanner, QStringLiteral("SLCAN"));
    QVERIFY2(m_canopenPort != 0, qPrintable(canopenBanner));
}

QString TestCliRecord::ok(const QStringList &args)
{
    const Run r = cli(args);
    if (r.exitCode != 0)
        qWarning().noquote() << args.join(u' ') << "->" << r.exitCode << r.err;
    return r.exitCode == 0 ? r.out : QStringLiteral("<failed>");
}

void TestCliRecord::cleanupTestCase()
{
    m_sim.terminate();
    m_canopenSim.terminate();
    QVERIFY(m_sim.waitForFinished(5000));
    QVERIFY(m_canopenSim.waitForFinished(5000));
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
    // 0.5 s / 25 ms = 20 slots; the last one's answer may come after the end and is not kept.
    QVERIFY2(n >= 19 && n <= 22, qPrintable(QString::number(n)));
    // The recording ends on its own time base: no sample is stamped after --duration.
    for (const auto &channel : rec->channels)
        QVERIFY2(channel.buffer.lastTime() <= 0.5,
                 qPrintable(QString::number(channel.buffer.lastTime())));
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
    QTest::newRow("bad tpdo number")
        << QStringList { "--obj", "6064:0", "--configure-tpdo", "0", "--duration", "1", "-o", o }
        << "--configure-tpdo takes a TPDO number";
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

void TestCliRecord::pdoSamplesADefaultTpdoPassively()
{
    // The device side, as a PLC would set it up: TPDO1 (6041:0, 6064:0) every 20 ms, started.
    QVERIFY(
        ok({ QStringLiteral("write"), canopen(1), QStringLiteral("1800:5"), QStringLiteral("20") })
            .isEmpty());
    QVERIFY(ok({ QStringLiteral("nmt"), canopen(1), QStringLiteral("start") })
                .contains(QLatin1String("operational")));
    const QString before = ok({ QStringLiteral("pdo"), canopen(1) });
    QVERIFY(before.contains(QLatin1String("TPDO1 cob 0x181 enabled")));

    const QString csvFile = file("pdo.csv");
    const Run r =
        cli({ QStringLiteral("record"), canopen(1), QStringLiteral("--obj"),
              QStringLiteral("6064:0,6041:0"), QStringLiteral("--pdo"),
              QStringLiteral("--duration"), QStringLiteral("0.6"), QStringLiteral("-o"), csvFile });
    QVERIFY2(r.exitCode == 0
                 || (r.exitCode == 1 && r.err.contains(QLatin1String("samples were lost"))),
             qPrintable(r.out + r.err));
    QVERIFY2(r.out.contains(QLatin1String("pdo: 6064:0 from TPDO1 (COB-ID 0x181) bytes 2..5, "
                                          "every 20 ms")),
             qPrintable(r.out));
    QVERIFY(r.out.contains(QLatin1String("pdo: 6041:0 from TPDO1 (COB-ID 0x181) bytes 0..1")));
    QVERIFY(!r.err.contains(QLatin1String("changed")));
    const auto rec = scope::csv::load(csvFile);
    QVERIFY2(rec.ok(), qPrintable(rec.error().toString()));
    QCOMPARE(rec->channels.size(), 2);
    QCOMPARE(rec->channels[0].info.name, QStringLiteral("Position actual value"));
    const scope::TraceBuffer &pos = rec->channels[0].buffer;
    const qint64 n = pos.size() + pos.lostAtSource();
    QVERIFY2(n >= 15 && n <= 35, qPrintable(QString::number(n))); // 0.6 s / 20 ms = 30
    QCOMPARE(pos.value(0), 1234.0); // the test node's default, signed 32 bit
    QCOMPARE(rec->channels[1].buffer.value(0), double(0x0250));
    // Passive: the node's PDO configuration is as before.
    QCOMPARE(ok({ QStringLiteral("pdo"), canopen(1) }), before);
}

void TestCliRecord::pdoObjectInNoTpdoIsNamed()
{
    const QString csvFile = file("unmapped.csv");
    const Run r =
        cli({ QStringLiteral("record"), canopen(1), QStringLiteral("--obj"),
              QStringLiteral("6064:0,2103:0"), QStringLiteral("--pdo"),
              QStringLiteral("--duration"), QStringLiteral("0.3"), QStringLiteral("-o"), csvFile });
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.err.contains(QLatin1String("2103:0 Test integer32 is in no TPDO of node 1; use "
                                          "--configure-tpdo N to map it")),
             qPrintable(r.err));
    QVERIFY(!r.err.contains(QLatin1String("6064:0")));
    QVERIFY(!QFile::exists(csvFile));
}

void TestCliRecord::configureTpdoThenSamples()
{
    QVERIFY(ok({ QStringLiteral("nmt"), canopen(2), QStringLiteral("start") })
                .contains(QLatin1String("operational")));
    const QString csvFile = file("configured.csv");
    const Run r =
        cli({ QStringLiteral("record"), canopen(2), QStringLiteral("--obj"),
              QStringLiteral("2103:0,2101:0"), QStringLiteral("--configure-tpdo"),
              QStringLiteral("2"), QStringLiteral("--event-ms"), QStringLiteral("25"),
              QStringLiteral("--duration"), QStringLiteral("0.5"), QStringLiteral("-o"), csvFile });
    QVERIFY2(r.exitCode == 0
                 || (r.exitCode == 1 && r.err.contains(QLatin1String("samples were lost"))),
             qPrintable(r.out + r.err));
    QVERIFY2(r.err.contains(QLatin1String("the PDO configuration of node 2 was changed")),
             qPrintable(r.err));
    QVERIFY(r.out.contains(QLatin1String("pdo: 2103:0 from TPDO2 (COB-ID 0x282) bytes 0..3, "
                                         "every 25 ms")));
    const auto rec = scope::csv::load(csvFile);
    QVERIFY2(rec.ok(), qPrintable(rec.error().toString()));
    QCOMPARE(rec->channels.size(), 2);
    QVERIFY(rec->channels[0].buffer.size() >= 10);
    QCOMPARE(rec->channels[0].buffer.value(0), -100000.0);
    QCOMPARE(rec->channels[1].buffer.value(0), -300.0);
    // The node keeps the new mapping; a plain --pdo finds it there now.
    QVERIFY(ok({ QStringLiteral("pdo"), canopen(2) })
                .contains(QLatin1String("TPDO2 cob 0x282 enabled type 0xff inhibit 0 event 25 ms: "
                                        "2103:0/32 2101:0/16")));
}

void TestCliRecord::preoperationalNodeGivesTheReason()
{
    QVERIFY(
        ok({ QStringLiteral("write"), canopen(5), QStringLiteral("1800:5"), QStringLiteral("20") })
            .isEmpty());
    QVERIFY(ok({ QStringLiteral("nmt"), canopen(5), QStringLiteral("preop") })
                .contains(QLatin1String("pre-operational")));
    const QStringList args = { QStringLiteral("record"), canopen(5),
                               QStringLiteral("--obj"),  QStringLiteral("6064:0"),
                               QStringLiteral("--pdo"),  QStringLiteral("--duration"),
                               QStringLiteral("5"),      QStringLiteral("-o"),
                               file("preop.csv") };
    Run r = cli(args);
    QCOMPARE(r.exitCode, 4);
    QVERIFY2(r.err.contains(QLatin1String("no PDO arrived from node 5 within 1.5 s (TPDO1 "
                                          "(COB-ID 0x185))")),
             qPrintable(r.err));
    // The node's heartbeat (1017h = 500 ms) tells its state; the cause and the command to fix it.
    QVERIFY2(r.err.contains(QLatin1String("node 5 is pre-operational (heartbeat), not "
                                          "operational: NMT start it (drivebench-cli nmt ")),
             qPrintable(r.err));
    QVERIFY(!r.err.contains(QLatin1String("no event timer"))); // it has one
    QVERIFY(!QFile::exists(file("preop.csv")));
    QVERIFY(r.ms < 4500); // bounded by the first-PDO wait, not by --duration

    // The stated cause is the real one: started, the same command records.
    QVERIFY(ok({ QStringLiteral("nmt"), canopen(5), QStringLiteral("start") })
                .contains(QLatin1String("operational")));
    r = cli({ QStringLiteral("record"), canopen(5), QStringLiteral("--obj"),
              QStringLiteral("6064:0"), QStringLiteral("--pdo"), QStringLiteral("--duration"),
              QStringLiteral("0.3"), QStringLiteral("-o"), file("started.csv") });
    QVERIFY2(r.exitCode == 0 || r.exitCode == 1, qPrintable(r.err));
    QVERIFY(QFile::exists(file("started.csv")));
}

void TestCliRecord::pdoNeedsACanopenUri()
{
    Run r = cli({ QStringLiteral("record"), uri(), QStringLiteral("--obj"),
                  QStringLiteral("6064:0"), QStringLiteral("--pdo"), QStringLiteral("--duration"),
                  QStringLiteral("0.3"), QStringLiteral("-o"), file("refgo-pdo.csv") });
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.err.contains(QLatin1String("need a canopen+... URI")), qPrintable(r.err));
    r = cli({ QStringLiteral("record"), canopen(1), QStringLiteral("--obj"),
              QStringLiteral("6064:0"), QStringLiteral("--event-ms"), QStringLiteral("10"),
              QStringLiteral("--duration"), QStringLiteral("0.3"), QStringLiteral("-o"),
              file("x.csv") });
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.err.contains(QLatin1String("--event-ms goes with --configure-tpdo")),
             qPrintable(r.err));
    // More than a PDO carries: refused before anything is written.
    r = cli({ QStringLiteral("record"), canopen(1), QStringLiteral("--obj"),
              QStringLiteral("6064:0,2102:0,2103:0"), QStringLiteral("--configure-tpdo"),
              QStringLiteral("2"), QStringLiteral("--duration"), QStringLiteral("0.3"),
              QStringLiteral("-o"), file("x.csv") });
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.err.contains(QLatin1String("the objects need 96 bits; a PDO carries at most 64")),
             qPrintable(r.err));
    QVERIFY(!r.err.contains(QLatin1String("was changed")));
}

QTEST_GUILESS_MAIN(TestCliRecord)
#include "tst_cli_record.moc"
