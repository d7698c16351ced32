// drivebench-cli motion commands end to end: enable, move --abs/--add/--rel, jog,
// home, disable and refusals against `drivebench-sim movingcap` over RefGo and over CANopen
// (SLCAN on loopback, node 50). The simulated drive has software limits of +-100000 (607Dh).
#include "clirun.h"
#include "simcontrol.h"

#include <QElapsedTimer>
#include <QProcess>
#include <QRegularExpression>
#include <QTest>

#include <cmath>

class TestCliMotion : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void cleanupTestCase();

    void enableMoveJogHomeDisable_data();
    void enableMoveJogHomeDisable();
    void refusedMoveNamesTheRule_data();
    void refusedMoveNamesTheRule();
    void usageErrorsExitWithTwo_data();
    void usageErrorsExitWithTwo();
    void tooShortWaitStopsTheAxis();
    void velocityThenHaltAndStopFromAnotherProcess_data();
    void velocityThenHaltAndStopFromAnotherProcess();
    void killedJogStopsByItself_data();
    void killedJogStopsByItself();
    void rotaryAxisWraps();

private:
    using Run = db::test::CliRun;
    Run cli(const QStringList &args, int timeoutMs = 30000);
    QString uri(const QString &transport) const
    {
        return transport == u"refgo"
            ? QStringLiteral("refgo://127.0.0.1:%1").arg(m_refgoPort)
            : QStringLiteral("canopen+slcan://127.0.0.1:%1?node=50").arg(m_slcanPort);
    }
    static double position(const Run &r)
    {
        bool ok = false;
        const double p = r.out.trimmed().toDouble(&ok);
        return ok ? p : qQNaN();
    }
    void addTransports()
    {
        QTest::addColumn<QString>("transport");
        QTest::newRow("refgo") << QStringLiteral("refgo");
        QTest::newRow("canopen") << QStringLiteral("canopen");
    }

    QProcess m_sim;
    quint16 m_refgoPort = 0;
    quint16 m_slcanPort = 0;
};

TestCliMotion::Run TestCliMotion::cli(const QStringList &args, int timeoutMs)
{
    return db::test::runProgram(QStringLiteral(DRIVEBENCH_CLI), args, timeoutMs);
}

void TestCliMotion::initTestCase()
{
    const QString banner = db::test::startAndReadBanner(
        m_sim, QStringLiteral(DRIVEBENCH_SIM),
        { QStringLiteral("movingcap"), QStringLiteral("--refgo-port"), QStringLiteral("0"),
          QStringLiteral("--slcan-port"), QStringLiteral("0"), QStringLiteral("--set"),
          QStringLiteral("607D:1=-100000"), QStringLiteral("--set"),
          QStringLiteral("607D:2=100000") },
        2);
    const auto refgo =
        QRegularExpression(QStringLiteral("RefGo listening on 127\\.0\\.0\\.1:(\\d+)"))
            .match(banner);
    const auto slcan =
        QRegularExpression(QStringLiteral("SLCAN listening on 127\\.0\\.0\\.1:(\\d+)"))
            .match(banner);
    QVERIFY2(refgo.hasMatch() && slcan.hasMatch(), qPrintable(banner));
    m_refgoPort = quint16(refgo.captured(1).toUInt());
    m_slcanPort = quint16(slcan.captured(1).toUInt());
}

void TestCliMotion::cleanupTestCase()
{
    m_sim.terminate();
    QVERIFY(m_sim.waitForFinished(5000));
}

void TestCliMotion::enableMoveJogHomeDisable_data()
{
    addTransports();
}

void TestCliMotion::enableMoveJogHomeDisable()
{
    QFETCH(QString, transport);
    const QString u = uri(transport);
    Run r = cli({ QStringLiteral("enable"), u });
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QCOMPARE(r.out.trimmed(), QStringLiteral("Standstill"));

    r = cli({ QStringLiteral("move"), u, QStringLiteral("--abs"), QStringLiteral("1000"),
              QStringLiteral("--vel"), QStringLiteral("3000") });
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QVERIFY2(qAbs(position(r) - 1000) <= 2, qPrintable(r.out));

    // MC_MoveAdditive in a new process: no target known, so the actual position is the origin
    // (stoeber_motion.md 3.3 rule 2).
    r = cli({ QStringLiteral("move"), u, QStringLiteral("--add"), QStringLiteral("200"),
              QStringLiteral("--vel"), QStringLiteral("3000") });
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QVERIFY2(qAbs(position(r) - 1200) <= 2, qPrintable(r.out));

    r = cli({ QStringLiteral("move"), u, QStringLiteral("--rel"), QStringLiteral("-700"),
              QStringLiteral("--vel"), QStringLiteral("3000"), QStringLiteral("--acc"),
              QStringLiteral("50000"), QStringLiteral("--dec"), QStringLiteral("50000") });
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QVERIFY2(qAbs(position(r) - 500) <= 2, qPrintable(r.out));

    r = cli({ QStringLiteral("jog"), u, QStringLiteral("--vel"), QStringLiteral("-400"),
              QStringLiteral("--time"), QStringLiteral("400") });
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    const double afterJog = position(r);
    QVERIFY2(afterJog < 480 && afterJog > 0, qPrintable(r.out)); // moved negative, then halted

    r = cli({ QStringLiteral("home"), u, QStringLiteral("35") });
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QVERIFY2(qAbs(position(r)) <= 1, qPrintable(r.out)); // set zero: 607Ch = 0

    r = cli({ QStringLiteral("disable"), u });
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QCOMPARE(r.out.trimmed(), QStringLiteral("Disabled"));
}

void TestCliMotion::refusedMoveNamesTheRule_data()
{
    addTransports();
}

void TestCliMotion::refusedMoveNamesTheRule()
{
    QFETCH(QString, transport);
    const QString u = uri(transport);
    QCOMPARE(cli({ QStringLiteral("disable"), u }).exitCode, 0);
    Run r = cli({ QStringLiteral("move"), u, QStringLiteral("--abs"), QStringLiteral("10"),
                  QStringLiteral("--vel"), QStringLiteral("100") });
    QCOMPARE(r.exitCode, 6);
    QVERIFY2(r.err.contains(QLatin1String("not enabled")), qPrintable(r.err));

    QCOMPARE(cli({ QStringLiteral("enable"), u }).exitCode, 0);
    r = cli({ QStringLiteral("move"), u, QStringLiteral("--abs"), QStringLiteral("150000"),
              QStringLiteral("--vel"), QStringLiteral("1000") });
    QCOMPARE(r.exitCode, 6);
    QVERIFY2(r.err.contains(QLatin1String("MC_MoveAbsolute refused: target outside the software "
                                          "limit")),
             qPrintable(r.err));
    r = cli({ QStringLiteral("move"), u, QStringLiteral("--rel"), QStringLiteral("10"),
              QStringLiteral("--vel"), QStringLiteral("0") });
    QCOMPARE(r.exitCode, 6);
    QVERIFY2(r.err.contains(QLatin1String("is zero")), qPrintable(r.err));
    QCOMPARE(cli({ QStringLiteral("disable"), u }).exitCode, 0);
}

void TestCliMotion::usageErrorsExitWithTwo_data()
{
    QTest::addColumn<QStringList>("args");
    const QString u = QStringLiteral("refgo://127.0.0.1:1");
    QTest::newRow("move without target") << QStringList { QStringLiteral("move"), u };
    QTest::newRow("move with two targets")
        << QStringList { QStringLiteral("move"),  u,
                         QStringLiteral("--abs"), QStringLiteral("1"),
                         QStringLiteral("--rel"), QStringLiteral("2") };
    QTest::newRow("move with a bad number")
        << QStringList { QStringLiteral("move"), u, QStringLiteral("--abs"), QStringLiteral("x") };
    QTest::newRow("jog without time")
        << QStringList { QStringLiteral("jog"), u, QStringLiteral("--vel"), QStringLiteral("5") };
    QTest::newRow("home with a bad method")
        << QStringList { QStringLiteral("home"), u, QStringLiteral("zero") };
}

void TestCliMotion::usageErrorsExitWithTwo()
{
    QFETCH(QStringList, args);
    const Run r = cli(args);
    QCOMPARE(r.exitCode, 2);
    QVERIFY(r.err.startsWith(QLatin1String("drivebench-cli: ")));
}

void TestCliMotion::tooShortWaitStopsTheAxis()
{
    const QString u = uri(QStringLiteral("refgo"));
    QCOMPARE(cli({ QStringLiteral("enable"), u }).exitCode, 0);
    Run r = cli({ QStringLiteral("move"), u, QStringLiteral("--abs"), QStringLiteral("90000"),
                  QStringLiteral("--vel"), QStringLiteral("1000"), QStringLiteral("--wait"),
                  QStringLiteral("300") });
    QCOMPARE(r.exitCode, 4);
    QVERIFY2(r.err.contains(QLatin1String("axis stopped")), qPrintable(r.err));
    // The drive stands (quick stop active): a fault reset enables it again.
    r = cli({ QStringLiteral("read"), u, QStringLiteral("606C:0") });
    QCOMPARE(r.exitCode, 0);
    QTRY_COMPARE_WITH_TIMEOUT(
        cli({ QStringLiteral("read"), u, QStringLiteral("606C:0") }).out.trimmed(),
        QStringLiteral("0"), 5000);
    r = cli({ QStringLiteral("reset"), u });
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QCOMPARE(cli({ QStringLiteral("disable"), u }).exitCode, 0);
}

void TestCliMotion::velocityThenHaltAndStopFromAnotherProcess_data()
{
    addTransports();
}

// velocity moves in leases for --time and halts; halt and stop brake a motion that another
// process started, and that process's move ends at once, short of its target.
void TestCliMotion::velocityThenHaltAndStopFromAnotherProcess()
{
    QFETCH(QString, transport);
    const QString u = uri(transport);
    QCOMPARE(cli({ QStringLiteral("enable"), u }).exitCode, 0);
    const double start = position(cli({ QStringLiteral("read"), u, QStringLiteral("6064:0") }));
    Run r = cli({ QStringLiteral("velocity"), u, QStringLiteral("--vel"), QStringLiteral("-1000"),
                  QStringLiteral("--time"), QStringLiteral("300"), QStringLiteral("--acc"),
                  QStringLiteral("20000"), QStringLiteral("--dec"), QStringLiteral("20000") });
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    const double after = position(r);
    QVERIFY2(after < start - 100 && after > start - 500,
             qPrintable(QStringLiteral("%1 -> %2").arg(start).arg(after)));
    QCOMPARE(cli({ QStringLiteral("read"), u, QStringLiteral("606C:0") }).out.trimmed(),
             QStringLiteral("0"));
    QVERIFY2(!r.err.contains(QLatin1String("nothing on the drive's side stops")),
             qPrintable(r.err));

    for (const QString &brake : { QStringLiteral("halt"), QStringLiteral("stop") }) {
        QProcess move;
        move.start(QStringLiteral(DRIVEBENCH_CLI),
                   { QStringLiteral("move"), u, QStringLiteral("--abs"),
                     QString::number(after + 50000), QStringLiteral("--vel"),
                     QStringLiteral("1000"), QStringLiteral("--wait"), QStringLiteral("30000") });
        QVERIFY(move.waitForStarted());
        QTRY_VERIFY_WITH_TIMEOUT(
            cli({ QStringLiteral("read"), u, QStringLiteral("606C:0") }).out.trimmed().toDouble()
                > 900,
            10000);
        r = cli({ brake, u, QStringLiteral("--dec"), QStringLiteral("20000") });
        QVERIFY2(r.exitCode == 0, qPrintable(brake + QLatin1String(": ") + r.err));
        QCOMPARE(cli({ QStringLiteral("read"), u, QStringLiteral("606C:0") }).out.trimmed(),
                 QStringLiteral("0"));
        // The other process's move ends now, not at its --wait (long enough for a slow start of
        // the processes under the sanitizers).
        QVERIFY(move.waitForFinished(10000));
        const QString err = QString::fromUtf8(move.readAllStandardError());
        QVERIFY2(move.exitCode() != 0, qPrintable(err));
        QVERIFY2(err.contains(QLatin1String("short of the target")), qPrintable(err));
        cli({ QStringLiteral("reset"), u });
        QCOMPARE(cli({ QStringLiteral("enable"), u }).exitCode, 0);
    }
    QCOMPARE(cli({ QStringLiteral("disable"), u }).exitCode, 0);
}

void TestCliMotion::killedJogStopsByItself_data()
{
    addTransports();
}

void TestCliMotion::killedJogStopsByItself()
{
    // jog moves in leases of 300 ms plus the braking distance: killed without a chance to send
    // anything, the CLI leaves a drive that brakes with its own ramp at the end of the lease.
    QFETCH(QString, transport);
    const QString u = uri(transport);
    constexpr double kVelocity = 2000;
    constexpr double kRamp = 20000; // braking: 100 units in 100 ms
    constexpr double kLeaseTravel = kVelocity * 0.3 + kVelocity * kVelocity / (2 * kRamp);
    QCOMPARE(cli({ QStringLiteral("enable"), u }).exitCode, 0);
    QProcess jog;
    jog.start(QStringLiteral(DRIVEBENCH_CLI),
              { QStringLiteral("jog"), u, QStringLiteral("--vel"), QString::number(kVelocity),
                QStringLiteral("--acc"), QString::number(kRamp), QStringLiteral("--dec"),
                QString::number(kRamp), QStringLiteral("--time"), QStringLiteral("60000") });
    QVERIFY(jog.waitForStarted());
    const auto velocity = [&] {
        return cli({ QStringLiteral("read"), u, QStringLiteral("606C:0") })
            .out.trimmed()
            .toDouble();
    };
    // Mid-jog: at the jog velocity for more than a lease.
    QTRY_VERIFY_WITH_TIMEOUT(qAbs(velocity() - kVelocity) < 20, 10000);
    const Run before = cli({ QStringLiteral("read"), u, QStringLiteral("6064:0") });
    QVERIFY2(jog.state() == QProcess::Running, qPrintable(QString::fromUtf8(jog.readAll())));
    jog.kill(); // SIGKILL: no stop, no cleanup
    QElapsedTimer since;
    since.start();
    QVERIFY(jog.waitForFinished(5000));
    QTRY_VERIFY_WITH_TIMEOUT(velocity() == 0.0, 1000 + int(1000 * kVelocity / kRamp));
    qInfo("%s: read 606Ch = 0 %lld ms after SIGKILL", qPrintable(transport), since.elapsed());
    const double stoppedAt =
        cli({ QStringLiteral("read"), u, QStringLiteral("6064:0") }).out.trimmed().toDouble();
    const double beforeKill = before.out.trimmed().toDouble();
    // At most one lease past the position read just before the kill (which is stale by the
    // time that read took).
    QVERIFY2(stoppedAt - beforeKill <= kLeaseTravel + kVelocity * before.ms / 1000.0 + 2,
             qPrintable(QStringLiteral("%1 -> %2").arg(beforeKill).arg(stoppedAt)));
    const auto state = [&] {
        return cli({ QStringLiteral("read"), u, QStringLiteral("6041:0") }).out.trimmed().toInt()
            & 0x6F;
    };
    if (transport == u"refgo") {
        // Operation enabled: the drive ended its own profile move, nobody quick-stopped it.
        QCOMPARE(state(), 0x27);
    } else {
        // On CANopen the drive also missed our node guarding (armed by jog) and reacted with
        // 6007h = quick stop: no longer operation enabled.
        QTRY_VERIFY_WITH_TIMEOUT(state() != 0x27, 2000);
    }
    QCOMPARE(cli({ QStringLiteral("disable"), u }).exitCode, 0);
}

// A rotary MovingCap (60F2h = C0h: shortest way, cycle 0..3600 from 607Dh): the drive shows
// its position wrapped into the cycle, an absolute move takes the shortest way across the wrap,
// and a jog runs on through it. The console shows the simulated axis unwrapped, so the way taken
// is seen.
void TestCliMotion::rotaryAxisWraps()
{
    QProcess sim;
    db::test::SimControl control(sim);
    sim.setStandardErrorFile(QProcess::nullDevice());
    const QString banner = db::test::startAndReadBanner(
        sim, QStringLiteral(DRIVEBENCH_SIM),
        { QStringLiteral("movingcap"), QStringLiteral("--refgo-port"), QStringLiteral("0"),
          QStringLiteral("--set"), QStringLiteral("60F2:0=192"), QStringLiteral("--set"),
          QStringLiteral("607D:1=0"), QStringLiteral("--set"), QStringLiteral("607D:2=3600"),
          QStringLiteral("--control") },
        1);
    const quint16 port = db::test::listeningPort(banner, QStringLiteral("RefGo"));
    QVERIFY2(port, qPrintable(banner));
    const QString u = QStringLiteral("refgo://127.0.0.1:%1").arg(port);
    QCOMPARE(cli({ QStringLiteral("enable"), u }).exitCode, 0);
    const QStringList profile { QStringLiteral("--vel"), QStringLiteral("2000"),
                                QStringLiteral("--acc"), QStringLiteral("20000"),
                                QStringLiteral("--dec"), QStringLiteral("20000") };
    Run r = cli(
        QStringList { QStringLiteral("move"), u, QStringLiteral("--abs"), QStringLiteral("3500") }
        + profile);
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QVERIFY2(qAbs(position(r) - 3500) <= 2, qPrintable(r.out));
    const auto before = control.state();
    QVERIFY2(qAbs(before.position + 100) <= 2, qPrintable(before.line)); // 0 -> -100, not +3500
    r = cli(
        QStringList { QStringLiteral("move"), u, QStringLiteral("--abs"), QStringLiteral("100") }
        + profile);
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QVERIFY2(qAbs(position(r) - 100) <= 2, qPrintable(r.out)); // shown wrapped
    const auto across = control.state();
    QVERIFY2(qAbs(across.position - before.position - 200) <= 2,
             qPrintable(across.line)); // +200 across the wrap, not -3400
    r = cli({ QStringLiteral("jog"), u, QStringLiteral("--vel"), QStringLiteral("2000"),
              QStringLiteral("--time"), QStringLiteral("2500"), QStringLiteral("--acc"),
              QStringLiteral("20000"), QStringLiteral("--dec"), QStringLiteral("20000") });
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    const auto jogged = control.state();
    QVERIFY2(jogged.position > across.position + 3600, qPrintable(jogged.line)); // once round
    QVERIFY2(position(r) >= 0 && position(r) < 3600, qPrintable(r.out));
    QVERIFY2(qAbs(std::fmod(jogged.position, 3600.0) - position(r)) <= 2,
             qPrintable(QStringLiteral("%1 vs %2").arg(jogged.position).arg(position(r))));
    QCOMPARE(cli({ QStringLiteral("disable"), u }).exitCode, 0);
    sim.terminate();
    QVERIFY(sim.waitForFinished(5000));
}

QTEST_GUILESS_MAIN(TestCliMotion)
#include "tst_cli_motion.moc"
