// Fail-safe motion end to end: `drivebench-cli jog` against `drivebench-sim movingcap --control`
// over RefGo and over CANopen (SLCAN on loopback, node 50) is killed (SIGKILL), frozen (SIGSTOP,
// a hung PC) or cut off (the simulator aborts its sockets, a pulled cable) mid-jog. The drive must
// stand still within 1 s of the event, having travelled at most one lease (300 ms at the jog
// velocity) plus the braking distance. Times and positions come from the simulator's own clock
// and axis through its control console, so test and pipe latencies are not part of the figures.
#include "clirun.h"
#include "simcontrol.h"

#include <QElapsedTimer>
#include <QProcess>
#include <QTest>

#include <csignal>
#include <sys/types.h>

class TestCliFailsafe : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void cleanupTestCase();
    void jogEndsByItself_data();
    void jogEndsByItself();
    void moveEndsWithHeartbeatLost();
    void moveHaltedElsewhereEnds_data();
    void moveHaltedElsewhereEnds();
    void faultsInjectedAtStartAndWhileRunning();
    void consoleRefusesBadCommands();

private:
    using Run = db::test::CliRun;
    using Sample = db::test::SimControl::Sample;

    Run cli(const QStringList &args, int timeoutMs = 30000)
    {
        return db::test::runProgram(QStringLiteral(DRIVEBENCH_CLI), args, timeoutMs);
    }
    QString uri(const QString &transport) const
    {
        return transport == u"refgo"
            ? QStringLiteral("refgo://127.0.0.1:%1").arg(m_refgoPort)
            : QStringLiteral("canopen+slcan://127.0.0.1:%1?node=50").arg(m_slcanPort);
    }
    QString ask(const QString &command, const QString &answer, int timeoutMs = 3000)
    {
        return m_control.ask(command, answer, timeoutMs);
    }
    Sample sample(const QString &command, const QString &answer, int timeoutMs = 3000)
    {
        return m_control.sample(command, answer, timeoutMs);
    }

    QProcess m_sim;
    db::test::SimControl m_control { m_sim };
    quint16 m_refgoPort = 0;
    quint16 m_slcanPort = 0;
};

void TestCliFailsafe::initTestCase()
{
    const QString banner = db::test::startAndReadBanner(
        m_sim, QStringLiteral(DRIVEBENCH_SIM),
        { QStringLiteral("movingcap"), QStringLiteral("--refgo-port"), QStringLiteral("0"),
          QStringLiteral("--slcan-port"), QStringLiteral("0"), QStringLiteral("--set"),
          QStringLiteral("607D:1=-1000000"), QStringLiteral("--set"),
          QStringLiteral("607D:2=1000000"), QStringLiteral("--control") },
        2);
    m_refgoPort = db::test::listeningPort(banner, QStringLiteral("RefGo"));
    m_slcanPort = db::test::listeningPort(banner, QStringLiteral("SLCAN"));
    QVERIFY2(m_refgoPort && m_slcanPort, qPrintable(banner));
}

void TestCliFailsafe::cleanupTestCase()
{
    m_sim.terminate();
    QVERIFY(m_sim.waitForFinished(5000));
}

void TestCliFailsafe::jogEndsByItself_data()
{
    QTest::addColumn<QString>("transport");
    QTest::addColumn<QString>("event");
    QTest::addColumn<QString>("command");
    for (const char *transport : { "refgo", "canopen" }) {
        for (const char *event : { "SIGKILL", "SIGSTOP", "cable cut" })
            QTest::addRow("%s %s", transport, event)
                << QString::fromLatin1(transport) << QString::fromLatin1(event) << "jog";
        // `velocity` moves in leases too on a drive with profile position.
        QTest::addRow("%s SIGKILL velocity", transport)
            << QString::fromLatin1(transport) << QStringLiteral("SIGKILL") << "velocity";
    }
}

void TestCliFailsafe::jogEndsByItself()
{
    QFETCH(QString, transport);
    QFETCH(QString, event);
    QFETCH(QString, command);
    const QString u = uri(transport);
    constexpr double kVelocity = 2000;
    constexpr double kRamp = 20000; // braking: 100 units in 100 ms
    constexpr double kLeaseTravel = kVelocity * 0.3 + kVelocity * kVelocity / (2 * kRamp);
    constexpr qint64 kStandstillWithinMs = 1000;

    cli({ QStringLiteral("reset"), u }); // a quick stop left by the row before
    Run r = cli({ QStringLiteral("enable"), u });
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QProcess jog;
    jog.start(QStringLiteral(DRIVEBENCH_CLI),
              { command, u, QStringLiteral("--vel"), QString::number(kVelocity),
                QStringLiteral("--acc"), QString::number(kRamp), QStringLiteral("--dec"),
                QString::number(kRamp), QStringLiteral("--time"), QStringLiteral("60000") });
    QVERIFY(jog.waitForStarted());
    // Mid-jog: at the jog velocity, with leases renewed for a while.
    QTRY_VERIFY_WITH_TIMEOUT(
        qAbs(sample(QStringLiteral("state"), QStringLiteral("state")).velocity - kVelocity) < 20,
        10000);
    const Sample running = sample(QStringLiteral("state"), QStringLiteral("state"));
    QTRY_VERIFY_WITH_TIMEOUT(
        sample(QStringLiteral("state"), QStringLiteral("state")).ms > running.ms + 300, 2000);
    QVERIFY2(jog.state() == QProcess::Running, qPrintable(QString::fromUtf8(jog.readAll())));

    Sample at;
    if (event == u"SIGKILL") {
        jog.kill(); // no stop, no cleanup
        at = sample(QStringLiteral("state"), QStringLiteral("state"));
    } else if (event == u"SIGSTOP") {
        QCOMPARE(::kill(pid_t(jog.processId()), SIGSTOP), 0); // alive, connected, silent
        at = sample(QStringLiteral("state"), QStringLiteral("state"));
    } else {
        at = sample(QStringLiteral("drop"), QStringLiteral("dropped"));
        QVERIFY2(!at.line.startsWith(QLatin1String("dropped 0 ")), qPrintable(at.line));
    }
    QVERIFY2(at.ok, qPrintable(at.line));
    const Sample stood = sample(QStringLiteral("standstill"), QStringLiteral("standstill"), 5000);
    QVERIFY2(stood.ok, qPrintable(stood.line));
    const qint64 ms = stood.ms - at.ms;
    const double travel = stood.position - at.position;
    qInfo("%s, %s, %s: standstill %lld ms after the event, %.1f units travelled (at %.0f "
          "units/s; lease + braking = %.0f units)",
          qPrintable(command), qPrintable(transport), qPrintable(event), ms, travel, at.velocity,
          kLeaseTravel);
    QVERIFY2(ms <= kStandstillWithinMs, qPrintable(QStringLiteral("%1 ms").arg(ms)));
    QVERIFY2(travel >= 0 && travel <= kLeaseTravel + 1,
             qPrintable(QStringLiteral("%1 -> %2").arg(at.position).arg(stood.position)));

    if (transport == u"canopen") {
        // The drive also missed our node guarding (armed by jog) and quick-stopped (6007h = 3).
        QTRY_VERIFY_WITH_TIMEOUT(
            (sample(QStringLiteral("state"), QStringLiteral("state")).statusword & 0x6F) != 0x27,
            2000);
    }
    if (event == u"cable cut") {
        // The jog found its link gone and says so; it does not reconnect and move on. It may
        // have ended already while the checks above ran the event loop.
        QVERIFY(jog.state() == QProcess::NotRunning || jog.waitForFinished(10000));
        QVERIFY2(jog.exitCode() != 0, qPrintable(QString::fromUtf8(jog.readAllStandardOutput())));
        qInfo("%s", qPrintable(QString::fromUtf8(jog.readAllStandardError()).trimmed()));
    } else if (jog.state() != QProcess::NotRunning) {
        jog.kill(); // SIGKILL also ends a stopped process
        QVERIFY(jog.waitForFinished(5000));
    }
    const Sample still = sample(QStringLiteral("state"), QStringLiteral("state"));
    QCOMPARE(still.position, stood.position); // and it stays where it stopped
    cli({ QStringLiteral("reset"), u });
    r = cli({ QStringLiteral("disable"), u });
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
}

// The drive beats every 100 ms (1017h), so drivebench-cli watches it with 200 ms; when it falls
// silent mid-move, the move ends with the cause and the drive is told to stop.
void TestCliFailsafe::moveEndsWithHeartbeatLost()
{
    const QString u = uri(QStringLiteral("canopen"));
    Run r = cli({ QStringLiteral("write"), u, QStringLiteral("1017:0"), QStringLiteral("100") });
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    cli({ QStringLiteral("reset"), u });
    r = cli({ QStringLiteral("enable"), u });
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    const double from = sample(QStringLiteral("state"), QStringLiteral("state")).position;
    QProcess move;
    move.start(QStringLiteral(DRIVEBENCH_CLI),
               { QStringLiteral("move"), u, QStringLiteral("--abs"), QString::number(from + 500000),
                 QStringLiteral("--vel"), QStringLiteral("2000"), QStringLiteral("--acc"),
                 QStringLiteral("20000"), QStringLiteral("--dec"), QStringLiteral("20000") });
    QVERIFY(move.waitForStarted());
    QTRY_VERIFY_WITH_TIMEOUT(
        qAbs(sample(QStringLiteral("state"), QStringLiteral("state")).velocity - 2000) < 20, 10000);
    QElapsedTimer since;
    since.start();
    QCOMPARE(ask(QStringLiteral("heartbeat off"), QStringLiteral("heartbeat")),
             QStringLiteral("heartbeat off"));
    QVERIFY(move.waitForFinished(5000));
    const qint64 endedMs = since.elapsed();
    const QString err = QString::fromUtf8(move.readAllStandardError());
    QVERIFY2(move.exitCode() != 0, qPrintable(err));
    QVERIFY2(err.contains(QLatin1String("heartbeat lost: node 50 silent for more than 200 ms")),
             qPrintable(err));
    const Sample stood = sample(QStringLiteral("standstill"), QStringLiteral("standstill"), 5000);
    QVERIFY2(stood.ok, qPrintable(stood.line));
    qInfo("move ended %lld ms after the heartbeat stopped (consumer time 200 ms): %s", endedMs,
          qPrintable(err.trimmed()));
    QCOMPARE(ask(QStringLiteral("heartbeat on"), QStringLiteral("heartbeat")),
             QStringLiteral("heartbeat on"));
    QCOMPARE(
        cli({ QStringLiteral("write"), u, QStringLiteral("1017:0"), QStringLiteral("0") }).exitCode,
        0);
    cli({ QStringLiteral("reset"), u });
    QCOMPARE(cli({ QStringLiteral("disable"), u }).exitCode, 0);
}

// Another drivebench-cli halts the drive mid-move: the move ends at once with the cause, not
// only when its --wait runs out.
void TestCliFailsafe::moveHaltedElsewhereEnds_data()
{
    QTest::addColumn<QString>("transport");
    QTest::newRow("refgo") << QStringLiteral("refgo");
    QTest::newRow("canopen") << QStringLiteral("canopen");
}

void TestCliFailsafe::moveHaltedElsewhereEnds()
{
    QFETCH(QString, transport);
    const QString u = uri(transport);
    cli({ QStringLiteral("reset"), u });
    QCOMPARE(cli({ QStringLiteral("enable"), u }).exitCode, 0);
    const double from = m_control.state().position;
    QProcess move;
    move.start(QStringLiteral(DRIVEBENCH_CLI),
               { QStringLiteral("move"), u, QStringLiteral("--abs"), QString::number(from + 500000),
                 QStringLiteral("--vel"), QStringLiteral("2000"), QStringLiteral("--acc"),
                 QStringLiteral("20000"), QStringLiteral("--dec"), QStringLiteral("20000"),
                 QStringLiteral("--wait"), QStringLiteral("60000") });
    QVERIFY(move.waitForStarted());
    QTRY_VERIFY_WITH_TIMEOUT(qAbs(m_control.state().velocity - 2000) < 20, 10000);
    const Run halted = cli({ QStringLiteral("halt"), u });
    QVERIFY2(halted.exitCode == 0, qPrintable(halted.err));
    QElapsedTimer since;
    since.start();
    QVERIFY(move.waitForFinished(5000));
    const QString err = QString::fromUtf8(move.readAllStandardError());
    qInfo("move ended %lld ms after the other halt finished: %s", since.elapsed(),
          qPrintable(err.trimmed()));
    QVERIFY2(move.exitCode() != 0, qPrintable(err));
    QVERIFY2(err.contains(QLatin1String("short of the target")), qPrintable(err));
    QVERIFY(m_control.standstill().ok);
    cli({ QStringLiteral("reset"), u });
    QCOMPARE(cli({ QStringLiteral("disable"), u }).exitCode, 0);
}

// --fault CODE starts the drive in fault; "fault CODE" on the console faults it while it runs.
// 603Fh holds the last EMCY code, and a fault reset clears it from the drive state.
void TestCliFailsafe::faultsInjectedAtStartAndWhileRunning()
{
    QProcess faulted;
    const QString banner = db::test::startAndReadBanner(
        faulted, QStringLiteral(DRIVEBENCH_SIM),
        { QStringLiteral("movingcap"), QStringLiteral("--refgo-port"), QStringLiteral("0"),
          QStringLiteral("--fault"), QStringLiteral("4210") },
        1);
    const quint16 port = db::test::listeningPort(banner, QStringLiteral("RefGo"));
    QVERIFY2(port, qPrintable(banner));
    const QString at = QStringLiteral("refgo://127.0.0.1:%1").arg(port);
    Run r = cli({ QStringLiteral("read"), at, QStringLiteral("603F:0") });
    QCOMPARE(r.out.trimmed().toInt(), 0x4210);
    QCOMPARE(cli({ QStringLiteral("read"), at, QStringLiteral("6041:0") }).out.trimmed().toInt()
                 & 0x4F,
             0x08); // Fault
    faulted.terminate();
    QVERIFY(faulted.waitForFinished(5000));
    QCOMPARE(db::test::runProgram(QStringLiteral(DRIVEBENCH_SIM),
                                  { QStringLiteral("movingcap"), QStringLiteral("--refgo-port"),
                                    QStringLiteral("0"), QStringLiteral("--fault"),
                                    QStringLiteral("zz") },
                                  5000)
                 .exitCode,
             2);

    const QString u = uri(QStringLiteral("canopen"));
    cli({ QStringLiteral("reset"), u });
    QCOMPARE(cli({ QStringLiteral("enable"), u }).exitCode, 0);
    QCOMPARE(ask(QStringLiteral("fault 7121"), QStringLiteral("fault")),
             QStringLiteral("fault 7121"));
    QCOMPARE(cli({ QStringLiteral("read"), u, QStringLiteral("603F:0") }).out.trimmed().toInt(),
             0x7121);
    QTRY_COMPARE(sample(QStringLiteral("state"), QStringLiteral("state")).statusword & 0x4F, 0x08);
    r = cli({ QStringLiteral("reset"), u });
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QCOMPARE(sample(QStringLiteral("state"), QStringLiteral("state")).statusword & 0x4F, 0x40);
}

void TestCliFailsafe::consoleRefusesBadCommands()
{
    QVERIFY(ask(QStringLiteral("fly"), QStringLiteral("x")).contains(u"unknown command 'fly'"));
    QVERIFY(ask(QStringLiteral("fault zz"), QStringLiteral("fault"))
                .contains(u"hexadecimal EMCY code"));
}

QTEST_GUILESS_MAIN(TestCliFailsafe)
#include "tst_cli_failsafe.moc"
