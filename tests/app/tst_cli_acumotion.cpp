// Level 3: drivebench-cli motion commands on an ACTIVE Cube (vabus://) end to end against
// drivebench-sim acu: enable, absolute and additive moves ending in the target, a velocity move
// and halt, homing, a motion block of the table, refusals, and a fault reset after an F2714 of
// the link watchdog; the simulator's EEPROM counter stays at 0 (every control word went to RAM).

#include "clirun.h"

#include <QElapsedTimer>
#include <QProcess>
#include <QRegularExpression>
#include <QtTest>

using db::test::CliRun;

namespace {

constexpr int kRunMs = 30000;

CliRun cli(const QStringList &args)
{
    return db::test::runProgram(QStringLiteral(DRIVEBENCH_CLI), args, kRunMs);
}

QString startSim(QProcess &process, const QStringList &extra)
{
    const QString banner = db::test::startAndReadBanner(
        process, QStringLiteral(DRIVEBENCH_SIM),
        QStringList { QStringLiteral("acu"), QStringLiteral("--vabus-port"), QStringLiteral("0") }
            + extra,
        1);
    const quint16 port = db::test::listeningPort(banner, QStringLiteral("VABus/TCP"));
    return port ? QStringLiteral("vabus://127.0.0.1:%1").arg(port) : QString();
}

// Stops the simulator and returns what it printed last (the EEPROM count).
QString stopSim(QProcess &process)
{
    process.terminate();
    if (!process.waitForFinished(5000))
        process.kill();
    return QString::fromUtf8(process.readAllStandardOutput());
}

// Sends one --control line and returns the first answer line starting with `answer` (or an
// "error:" line); empty when none came in time.
QString ask(QProcess &sim, QByteArray &pending, const QString &command, const QString &answer,
            int timeoutMs = 5000)
{
    sim.write(command.toUtf8() + '\n');
    QElapsedTimer clock;
    clock.start();
    for (;;) {
        qsizetype nl;
        while ((nl = pending.indexOf('\n')) >= 0) {
            const QString line = QString::fromUtf8(pending.left(nl)).trimmed();
            pending.remove(0, nl + 1);
            if (line.startsWith(answer) || line.startsWith(QLatin1String("error:")))
                return line;
        }
        const qint64 left = timeoutMs - clock.elapsed();
        if (left <= 0 || sim.state() != QProcess::Running)
            return {};
        sim.waitForReadyRead(int(left));
        pending += sim.readAllStandardOutput();
    }
}

// The status word in a "state ..." line of the console.
int statusWordOf(const QString &state)
{
    static const QRegularExpression re(QStringLiteral("statusword 0x([0-9A-F]{4})"));
    const auto m = re.match(state);
    return m.hasMatch() ? m.captured(1).toInt(nullptr, 16) : -1;
}

double lastNumber(const QString &out)
{
    return out.trimmed().split(QLatin1Char('\n')).last().toDouble();
}

} // namespace

class TstCliAcuMotion : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void doneWhen()
    {
        QProcess sim;
        const QString uri = startSim(sim, {});
        QVERIFY(!uri.isEmpty());
        CliRun r = cli({ QStringLiteral("enable"), uri });
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QCOMPARE(r.out.trimmed(), QStringLiteral("Standstill"));

        r = cli({ QStringLiteral("move"), uri, QStringLiteral("--abs"), QStringLiteral("30000") });
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QCOMPARE(lastNumber(r.out), 30000.0); // in the target: Done needs the target window
        r = cli({ QStringLiteral("read"), uri, QStringLiteral("411") });
        QCOMPARE(r.out.trimmed().toUInt() & 0x0400, 0x0400u); // target reached

        r = cli({ QStringLiteral("move"), uri, QStringLiteral("--add"), QStringLiteral("5000") });
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QCOMPARE(lastNumber(r.out), 35000.0);

        r = cli({ QStringLiteral("velocity"), uri, QStringLiteral("--vel"), QStringLiteral("-4000"),
                  QStringLiteral("--time"), QStringLiteral("400") });
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(lastNumber(r.out) < 35000.0, qPrintable(r.out)); // moved backwards, then halted
        r = cli({ QStringLiteral("read"), uri, QStringLiteral("1107") });
        QCOMPARE(r.out.trimmed(), QStringLiteral("0 u/s"));

        r = cli({ QStringLiteral("home"), uri, QStringLiteral("35") });
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QCOMPARE(lastNumber(r.out), 0.0); // the reference position

        r = cli({ QStringLiteral("travel"), uri, QStringLiteral("2") });
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QCOMPARE(lastNumber(r.out), 5000.0); // block 2: absolute 5000 u
        r = cli({ QStringLiteral("travel"), uri, QStringLiteral("3") });
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QCOMPARE(lastNumber(r.out), 7000.0); // block 3: relative 2000 u

        r = cli({ QStringLiteral("disable"), uri });
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QString out = stopSim(sim);
        QVERIFY2(out.contains(QLatin1String("acu: 0 EEPROM writes")), qPrintable(out));
    }

    void refusals()
    {
        QProcess sim;
        const QString uri = startSim(sim, {});
        QVERIFY(!uri.isEmpty());
        QVERIFY(cli({ QStringLiteral("enable"), uri }).exitCode == 0);
        // 1455 = -1 switches the override off: that target cannot be approached.
        CliRun r = cli({ QStringLiteral("move"), uri, QStringLiteral("--abs=-1") });
        QVERIFY(r.exitCode != 0);
        QVERIFY2(r.err.contains(QLatin1String("target -1 u cannot be approached")),
                 qPrintable(r.err));
        r = cli({ QStringLiteral("travel"), uri, QStringLiteral("40") });
        QVERIFY(r.exitCode != 0);
        QVERIFY2(r.err.contains(QLatin1String("motion block 40 does not exist")),
                 qPrintable(r.err));
        stopSim(sim);
    }

    // The electronic gear from the CLI: coupled to the simulated master at 3:2 until "in gear",
    // held, then uncoupled and braked to a stop; bad ratios and a configuration without
    // positioning control are refused by name; nothing went to the EEPROM.
    void gear()
    {
        QProcess sim;
        const QString uri = startSim(sim, { QStringLiteral("--control") });
        QVERIFY(!uri.isEmpty());
        QByteArray pending;
        QCOMPARE(ask(sim, pending, QStringLiteral("master 2000"), QStringLiteral("master")),
                 QStringLiteral("master 2000"));
        QVERIFY(cli({ QStringLiteral("enable"), uri }).exitCode == 0);
        CliRun r =
            cli({ QStringLiteral("gear"), uri, QStringLiteral("--ratio"), QStringLiteral("3:2"),
                  QStringLiteral("--time"), QStringLiteral("300"), QStringLiteral("--acc"),
                  QStringLiteral("200000"), QStringLiteral("--dec"), QStringLiteral("200000") });
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.out.startsWith(QLatin1String("in gear 3:2 after ")), qPrintable(r.out));
        QVERIFY2(lastNumber(r.out) > 900.0, qPrintable(r.out)); // 3000 u/s for 300 ms at least
        QCOMPARE(cli({ QStringLiteral("read"), uri, QStringLiteral("1107") }).out.trimmed(),
                 QStringLiteral("0 u/s"));
        QCOMPARE(cli({ QStringLiteral("read"), uri, QStringLiteral("1123") }).out.trimmed(),
                 QStringLiteral("3"));

        r = cli({ QStringLiteral("gear"), uri, QStringLiteral("--ratio"), QStringLiteral("3:0"),
                  QStringLiteral("--time"), QStringLiteral("100") });
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(QLatin1String("denominator must be at least 1")),
                 qPrintable(r.err));
        r = cli({ QStringLiteral("gear"), uri, QStringLiteral("--ratio"), QStringLiteral("3:2") });
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(QLatin1String("needs --time")), qPrintable(r.err));

        // Velocity-only configuration: no electronic gear.
        QVERIFY(cli({ QStringLiteral("disable"), uri }).exitCode == 0);
        QVERIFY(cli({ QStringLiteral("write"), QStringLiteral("--ram"), uri, QStringLiteral("30"),
                      QStringLiteral("210") })
                    .exitCode
                == 0);
        QVERIFY(cli({ QStringLiteral("enable"), uri }).exitCode == 0);
        r = cli({ QStringLiteral("gear"), uri, QStringLiteral("--ratio"), QStringLiteral("1:1"),
                  QStringLiteral("--time"), QStringLiteral("100") });
        QCOMPARE(r.exitCode, 6);
        QVERIFY2(r.err.contains(QLatin1String("MC_GearIn refused: the drive has no electronic "
                                              "gear (configuration 210 has no positioning")),
                 qPrintable(r.err));
        QVERIFY(cli({ QStringLiteral("disable"), uri }).exitCode == 0);
        const QString out = stopSim(sim);
        QVERIFY2(out.contains(QLatin1String("acu: 0 EEPROM writes")), qPrintable(out));
    }

    void enableNamesMissingInputs_data()
    {
        QTest::addColumn<QString>("inputs");
        QTest::addColumn<QString>("reason");
        QTest::newRow("no mains") << "mains"
                                  << "no mains voltage";
        QTest::newRow("no STO") << "sto"
                                << "hardware enable (STO) is off";
    }
    void enableNamesMissingInputs()
    {
        QFETCH(QString, inputs);
        QFETCH(QString, reason);
        QProcess sim;
        const QString uri = startSim(sim, { QStringLiteral("--acu-inputs"), inputs });
        QVERIFY(!uri.isEmpty());
        const CliRun r = cli({ QStringLiteral("enable"), uri });
        QVERIFY(r.exitCode != 0);
        QVERIFY2(r.err.contains(reason), qPrintable(r.err));
        stopSim(sim);
    }

    void controlConsole();

    void faultResetAfterF2714()
    {
        QProcess sim;
        // Reaction 1 of 388 (the factory setting): F2714 once the PLC link is quiet for 300 ms.
        const QString uri =
            startSim(sim, { QStringLiteral("--watchdog-ms"), QStringLiteral("300") });
        QVERIFY(!uri.isEmpty());
        QVERIFY(cli({ QStringLiteral("enable"), uri }).exitCode == 0);
        // The simulator says when its watchdog reacted (nothing talks to it meanwhile).
        QByteArray log;
        QTRY_VERIFY_WITH_TIMEOUT((log += sim.readAllStandardError()).contains("reaction 1"), 10000);
        CliRun r = cli({ QStringLiteral("read"), uri, QStringLiteral("260") });
        QCOMPARE(r.out.trimmed(), QStringLiteral("10004")); // 0x2714
        r = cli({ QStringLiteral("move"), uri, QStringLiteral("--abs"), QStringLiteral("100") });
        QVERIFY(r.exitCode != 0); // faulted: nothing moves
        // No reaction from now on (RAM): the next CLI process may start later than 300 ms after
        // this one, which would fault the inverter again right after the reset.
        r = cli({ QStringLiteral("write"), uri, QStringLiteral("388"), QStringLiteral("0"),
                  QStringLiteral("--ram") });
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        r = cli({ QStringLiteral("reset"), uri });
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        r = cli({ QStringLiteral("read"), uri, QStringLiteral("260") });
        QCOMPARE(r.out.trimmed().left(1), QStringLiteral("0"));
        r = cli({ QStringLiteral("enable"), uri });
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QString out = stopSim(sim);
        QVERIFY2(out.contains(QLatin1String("acu: 0 EEPROM writes")), qPrintable(out));
    }
};

// The simulator's --control console: the inputs and a fault set while the simulator serves,
// and a cut cable mid-motion: the link watchdog (388 = 1) then faults the inverter, which
// stops the motor without anyone on the link. The watchdog keeps its 10 s until the motion
// runs (one CLI process after the other leaves the link quiet in between), then it is shortened.
void TstCliAcuMotion::controlConsole()
{
    QProcess sim;
    const QString uri = startSim(sim, { QStringLiteral("--control") });
    QVERIFY(!uri.isEmpty());
    QByteArray pending;
    QCOMPARE(ask(sim, pending, QStringLiteral("fly"), QStringLiteral("x")).left(32),
             QStringLiteral("error: unknown command 'fly' (st"));
    QVERIFY(ask(sim, pending, QStringLiteral("fault F0"), QStringLiteral("fault"))
                .startsWith(QLatin1String("error: a fault is a code")));

    QCOMPARE(ask(sim, pending, QStringLiteral("mains off"), QStringLiteral("mains")),
             QStringLiteral("mains off"));
    CliRun r = cli({ QStringLiteral("enable"), uri });
    QVERIFY(r.exitCode != 0);
    QVERIFY2(r.err.contains(QLatin1String("no mains voltage")), qPrintable(r.err));
    QCOMPARE(ask(sim, pending, QStringLiteral("mains on"), QStringLiteral("mains")),
             QStringLiteral("mains on"));
    r = cli({ QStringLiteral("enable"), uri });
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QString state = ask(sim, pending, QStringLiteral("state"), QStringLiteral("state"));
    QCOMPARE(statusWordOf(state) & 0x006F, 0x0027); // operation enabled
    QCOMPARE(ask(sim, pending, QStringLiteral("sto off"), QStringLiteral("sto")),
             QStringLiteral("sto off"));
    state = ask(sim, pending, QStringLiteral("state"), QStringLiteral("state"));
    QCOMPARE(statusWordOf(state) & 0x006F, 0x0023); // STO lost: back to "switched on"
    QCOMPARE(ask(sim, pending, QStringLiteral("sto on"), QStringLiteral("sto")),
             QStringLiteral("sto on"));

    QCOMPARE(ask(sim, pending, QStringLiteral("fault 5"), QStringLiteral("fault")),
             QStringLiteral("fault 0005"));
    r = cli({ QStringLiteral("read"), uri, QStringLiteral("260") });
    QCOMPARE(r.out.trimmed(), QStringLiteral("5"));
    r = cli({ QStringLiteral("reset"), uri });
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    r = cli({ QStringLiteral("enable"), uri });
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));

    // A velocity move runs; the cable is cut. No one stops the motor but the inverter itself.
    QProcess move;
    move.start(QStringLiteral(DRIVEBENCH_CLI),
               { QStringLiteral("velocity"), uri, QStringLiteral("--vel"), QStringLiteral("3000"),
                 QStringLiteral("--time"), QStringLiteral("20000") });
    QTRY_VERIFY_WITH_TIMEOUT(ask(sim, pending, QStringLiteral("state"), QStringLiteral("state"))
                                 .contains(QLatin1String("velocity 3000.0")),
                             10000);
    QCOMPARE(ask(sim, pending, QStringLiteral("watchdog 300"), QStringLiteral("watchdog")),
             QStringLiteral("watchdog 300"));
    const QString dropped = ask(sim, pending, QStringLiteral("drop"), QStringLiteral("dropped"));
    QVERIFY2(dropped.startsWith(QLatin1String("dropped 1 ")), qPrintable(dropped));
    QVERIFY(move.waitForFinished(15000));
    QVERIFY(move.exitCode() != 0); // the link is gone: the CLI says so
    const QString still =
        ask(sim, pending, QStringLiteral("standstill"), QStringLiteral("standstill"), 10000);
    QVERIFY2(still.startsWith(QLatin1String("standstill ")), qPrintable(still));
    // F2714 comes once the watchdog's 300 ms have passed without an exchange: after the CLI
    // has gone, which may be after the standstill (the CLI connects again after the drop and
    // the motor stops at the end of its last lease).
    QTRY_VERIFY2_WITH_TIMEOUT(
        (state = ask(sim, pending, QStringLiteral("state"), QStringLiteral("state")))
            .endsWith(QLatin1String("fault 0x2714")),
        qPrintable(state), 5000);
    const QString out = stopSim(sim);
    QVERIFY2(out.contains(QLatin1String("acu: 0 EEPROM writes")), qPrintable(out));
}

QTEST_GUILESS_MAIN(TstCliAcuMotion)
#include "tst_cli_acumotion.moc"
