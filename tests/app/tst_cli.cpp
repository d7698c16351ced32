// drivebench-cli end to end against drivebench-sim on an OS-chosen loopback port, and against
// peers that refuse, stay silent or answer garbage. Every failure must end quickly with a
// one-line error that names the cause and a non-zero exit code.
#include "clirun.h"
#include "peers.h"

#include <QElapsedTimer>
#include <QProcess>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QTest>

class TestCli : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void cleanupTestCase();

    void listsProtocols();
    void readsTheStatusword();
    void readsInHexAndVerbose();
    void writesAndReadsBack();
    void docklightObjectRowsEndToEnd();
    void rawRefgoTellsThePosition();
    void movesTheSimulatedDrive();
    void deviceErrorExitsWithSix();
    void readOnlyObjectRefusedBeforeSending();
    void refusedConnectionExitsWithThree();
    void silentDeviceTimesOutWithFour();
    void garbageAnswerExitsWithFive();
    void usageErrorsExitWithTwo_data();
    void usageErrorsExitWithTwo();
    void simRefusesBadArguments();

private:
    using Run = db::test::CliRun;
    Run cli(const QStringList &args, int timeoutMs = 15000);
    QString uri() const { return QStringLiteral("refgo://127.0.0.1:%1").arg(m_port); }

    QProcess m_sim;
    quint16 m_port = 0;
};

TestCli::Run TestCli::cli(const QStringList &args, int timeoutMs)
{
    return db::test::runProgram(QStringLiteral(DRIVEBENCH_CLI), args, timeoutMs);
}

void TestCli::initTestCase()
{
    const QString banner = db::test::startAndReadBanner(
        m_sim, QStringLiteral(DRIVEBENCH_SIM),
        { QStringLiteral("movingcap"), QStringLiteral("--refgo-port"), QStringLiteral("0"),
          QStringLiteral("--set"), QStringLiteral("3511:8=110") },
        1);
    const auto m =
        QRegularExpression(QStringLiteral("listening on 127\\.0\\.0\\.1:(\\d+)")).match(banner);
    QVERIFY2(m.hasMatch(), qPrintable(banner));
    m_port = quint16(m.captured(1).toUInt());
    QVERIFY(m_port > 0);
}

void TestCli::cleanupTestCase()
{
    m_sim.terminate(); // SIGTERM: the simulator quits cleanly
    QVERIFY(m_sim.waitForFinished(5000));
    QCOMPARE(m_sim.exitStatus(), QProcess::NormalExit);
    QCOMPARE(m_sim.exitCode(), 0);
}

void TestCli::listsProtocols()
{
    const Run r = cli({ QStringLiteral("list-protocols") });
    QCOMPARE(r.exitCode, 0);
    QVERIFY(r.out.contains(QLatin1String("refgo://HOST[:PORT]")));
    QVERIFY(r.out.contains(QLatin1String("10001")));
}

void TestCli::readsTheStatusword()
{
    const Run r = cli({ QStringLiteral("read"), uri(), QStringLiteral("6041:0") });
    QCOMPARE(r.exitCode, 0);
    QVERIFY2(r.err.isEmpty(), qPrintable(r.err));
    bool ok = false;
    const uint sw = r.out.trimmed().toUInt(&ok);
    QVERIFY2(ok, qPrintable(r.out));
    QCOMPARE(sw & 0x4F, 0x40u); // a fresh drive is in "switch on disabled"
}

void TestCli::readsInHexAndVerbose()
{
    Run r =
        cli({ QStringLiteral("read"), QStringLiteral("--hex"), uri(), QStringLiteral("6041:0") });
    QCOMPARE(r.exitCode, 0);
    QVERIFY2(
        QRegularExpression(QStringLiteral("^0x[0-9A-F]{4}$")).match(r.out.trimmed()).hasMatch(),
        qPrintable(r.out));
    r = cli(
        { QStringLiteral("read"), QStringLiteral("--verbose"), uri(), QStringLiteral("6060:0") });
    QCOMPARE(r.exitCode, 0);
    QVERIFY2(r.out.contains(QLatin1String("6060:0 Modes of operation = ")), qPrintable(r.out));
}

void TestCli::writesAndReadsBack()
{
    Run r =
        cli({ QStringLiteral("write"), uri(), QStringLiteral("6067:0"), QStringLiteral("100") });
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    r = cli({ QStringLiteral("read"), uri(), QStringLiteral("6067:0") });
    QCOMPARE(r.out.trimmed(), QStringLiteral("100"));
    r = cli({ QStringLiteral("write"), uri(), QStringLiteral("6060:0"), QStringLiteral("homing") });
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    r = cli({ QStringLiteral("read"), uri(), QStringLiteral("6060:0") });
    QCOMPARE(r.out.trimmed(), QStringLiteral("6"));
}

void TestCli::docklightObjectRowsEndToEnd()
{
    // movingcap.md 3.8 rows 12-14 over a real socket (the simulator was started with 3511:8=110)
    Run r = cli({ QStringLiteral("refgo"), uri(), QStringLiteral("OR3511,8") });
    QCOMPARE(r.exitCode, 0);
    QCOMPARE(r.out, QStringLiteral("OR3511,8,110\n"));
    r = cli({ QStringLiteral("refgo"), uri(), QStringLiteral("OW3511,8,120") });
    QCOMPARE(r.out, QStringLiteral("OW3511,8,120,OK\n"));
    r = cli({ QStringLiteral("refgo"), uri(), QStringLiteral("OR3511,8") });
    QCOMPARE(r.out, QStringLiteral("OR3511,8,120\n"));
}

void TestCli::rawRefgoTellsThePosition()
{
    const Run r = cli({ QStringLiteral("refgo"), uri(), QStringLiteral("TP") });
    QCOMPARE(r.exitCode, 0);
    QVERIFY2(QRegularExpression(QStringLiteral("^-?\\d+\\n$")).match(r.out).hasMatch(),
             qPrintable(r.out));
    const Run tpsr = cli({ QStringLiteral("refgo"), uri(), QStringLiteral("TPSR") });
    QVERIFY2(QRegularExpression(QStringLiteral("^[0-9a-f]{8}\\n$")).match(tpsr.out).hasMatch(),
             qPrintable(tpsr.out));
}

void TestCli::movesTheSimulatedDrive()
{
    // G switches the drive on and into positioning mode by itself (movingcap.md 3.3)
    QCOMPARE(cli({ QStringLiteral("refgo"), uri(), QStringLiteral("SP3600") }).exitCode, 0);
    QCOMPARE(cli({ QStringLiteral("refgo"), uri(), QStringLiteral("G90") }).out, QString());
    QString position;
    QTRY_COMPARE_WITH_TIMEOUT(
        (position = cli({ QStringLiteral("read"), uri(), QStringLiteral("6064:0") }).out.trimmed()),
        QStringLiteral("90"), 10000);
    const Run sw = cli({ QStringLiteral("read"), uri(), QStringLiteral("6041:0") });
    QCOMPARE(sw.out.trimmed().toUInt() & 0x6F, 0x27u); // operation enabled
    QCOMPARE(cli({ QStringLiteral("refgo"), uri(), QStringLiteral("PQ") }).exitCode, 0);
}

void TestCli::deviceErrorExitsWithSix()
{
    // 2000:0 is not in the MovingCap dictionary: the CLI sends it, the drive refuses it
    const Run r =
        cli({ QStringLiteral("write"), uri(), QStringLiteral("2000:0"), QStringLiteral("5") });
    QCOMPARE(r.exitCode, 6);
    QVERIFY2(r.err.startsWith(QLatin1String("drivebench-cli: device error")), qPrintable(r.err));
    QVERIFY(r.err.contains(QLatin1String("2000")));
    QCOMPARE(r.err.count(QLatin1Char('\n')), 1);
}

void TestCli::readOnlyObjectRefusedBeforeSending()
{
    const Run r =
        cli({ QStringLiteral("write"), uri(), QStringLiteral("6041:0"), QStringLiteral("6") });
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.err.contains(QLatin1String("read-only")), qPrintable(r.err));
}

void TestCli::refusedConnectionExitsWithThree()
{
    const quint16 closedPort = db::test::closedLoopbackPort();
    QVERIFY(closedPort != 0);
    const Run r =
        cli({ QStringLiteral("read"), QStringLiteral("refgo://127.0.0.1:%1").arg(closedPort),
              QStringLiteral("6041:0") });
    QCOMPARE(r.exitCode, 3);
    QVERIFY2(r.err.contains(QLatin1String("refused")), qPrintable(r.err));
    QVERIFY(r.err.contains(QString::number(closedPort)));
}

void TestCli::silentDeviceTimesOutWithFour()
{
    db::test::RawPeer silent(db::test::RawPeer::Behaviour::Silent);
    QVERIFY(silent.isListening());
    QProcess p;
    p.start(QStringLiteral(DRIVEBENCH_CLI),
            { QStringLiteral("--timeout"), QStringLiteral("300"), QStringLiteral("read"),
              QStringLiteral("refgo://127.0.0.1:%1").arg(silent.serverPort()),
              QStringLiteral("6041:0") });
    QTRY_VERIFY_WITH_TIMEOUT(p.state() == QProcess::NotRunning, 10000);
    QCOMPARE(p.exitCode(), 4);
    const QString err = QString::fromUtf8(p.readAllStandardError());
    QVERIFY2(err.contains(QLatin1String("timeout")), qPrintable(err));
    QVERIFY2(err.contains(QLatin1String("300 ms")), qPrintable(err));
}

void TestCli::garbageAnswerExitsWithFive()
{
    db::test::RawPeer liar(db::test::RawPeer::Behaviour::Garbage, "HELLO WORLD\r\n12\r\n>");
    QVERIFY(liar.isListening());
    QProcess p;
    p.start(QStringLiteral(DRIVEBENCH_CLI),
            { QStringLiteral("read"), QStringLiteral("refgo://127.0.0.1:%1").arg(liar.serverPort()),
              QStringLiteral("6041:0") });
    QTRY_VERIFY_WITH_TIMEOUT(p.state() == QProcess::NotRunning, 10000);
    const QString err = QString::fromUtf8(p.readAllStandardError());
    QCOMPARE(p.exitCode(), 5);
    QVERIFY2(err.contains(QLatin1String("malformed")), qPrintable(err));
}

void TestCli::usageErrorsExitWithTwo_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("mentions");
    QTest::newRow("no command") << QStringList() << "no command";
    QTest::newRow("unknown command") << QStringList { QStringLiteral("fly") } << "unknown command";
    QTest::newRow("missing args") << QStringList { QStringLiteral("read") } << "usage";
    QTest::newRow("bad address") << QStringList {
        QStringLiteral("read"), QStringLiteral("refgo://127.0.0.1"), QStringLiteral("statusword")
    } << "6041:0";
    QTest::newRow("bad uri") << QStringList { QStringLiteral("read"), QStringLiteral("drive7"),
                                              QStringLiteral("6041:0") }
                             << "not a connection URI";
    QTest::newRow("unknown scheme")
        << QStringList { QStringLiteral("read"), QStringLiteral("ftp://127.0.0.1"),
                         QStringLiteral("6041:0") }
        << "unknown protocol";
    QTest::newRow("bad timeout") << QStringList { QStringLiteral("--timeout"), QStringLiteral("x"),
                                                  QStringLiteral("list-protocols") }
                                 << "timeout";
}

void TestCli::usageErrorsExitWithTwo()
{
    QFETCH(QStringList, args);
    QFETCH(QString, mentions);
    const Run r = cli(args);
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.err.contains(mentions), qPrintable(r.err));
}

void TestCli::simRefusesBadArguments()
{
    QProcess p;
    p.start(QStringLiteral(DRIVEBENCH_SIM), { QStringLiteral("movingcap") });
    QVERIFY(p.waitForFinished(5000));
    QCOMPARE(p.exitCode(), 2);
    QVERIFY(QString::fromUtf8(p.readAllStandardError()).contains(QLatin1String("--refgo-port")));
    p.start(QStringLiteral(DRIVEBENCH_SIM),
            { QStringLiteral("movingcap"), QStringLiteral("--refgo-port"), QStringLiteral("0"),
              QStringLiteral("--set"), QStringLiteral("nonsense") });
    QVERIFY(p.waitForFinished(5000));
    QCOMPARE(p.exitCode(), 2);
}

QTEST_GUILESS_MAIN(TestCli)
#include "tst_cli.moc"
