// drivebench-cli nm17x end to end against `drivebench-sim nm17x` with three displays delivered
// as node 127: broadcast addressing by turning shafts (through the simulator's control socket),
// listing, positioning from the loop side, jogging and stopping, preset by broadcast, the refusal
// of a forbidden control word, and an EMCY shown with its text.
#include "clirun.h"

#include <QProcess>
#include <QRegularExpression>
#include <QTcpSocket>
#include <QTest>
#include <QTimer>

using db::test::CliRun;

class TestCliNm17x : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void cleanupTestCase();
    void addressedByBroadcast();
    void listedWithVariants();
    void positionedFromTheLoopSide();
    void joggedAndStopped();
    void presetByBroadcast();
    void forbiddenControlWordIsRefused();
    void emergencyShownWithText();
    void wideCorrectionGoesThrough2010();
    void usageErrors();
    void oscillatedAndStopped();
    void settingsReadAndWritten();
    void displayErrorsNamed();
    void scanFindsTheBitrate();
    void thirdPartyMasterByteExact();

private:
    CliRun cli(const QStringList &args, int timeoutMs = 30000);
    QString uri() const
    {
        return QStringLiteral("canopen+slcan://127.0.0.1:%1?bitrate=125000").arg(m_slcan);
    }
    // Sends one control command and returns its reply lines (up to "ok" / "error: ...").
    QStringList control(const QString &command);
    // display index (1-based) -> {position, status}, from the simulator's "list".
    QPair<int, int> display(int index);

    QProcess m_sim;
    quint16 m_slcan = 0;
    QTcpSocket m_control;
};

CliRun TestCliNm17x::cli(const QStringList &args, int timeoutMs)
{
    return db::test::runServing(QStringLiteral(DRIVEBENCH_CLI), args, timeoutMs);
}

void TestCliNm17x::initTestCase()
{
    const QString banner = db::test::startAndReadBanner(
        m_sim, QStringLiteral(DRIVEBENCH_SIM),
        { QStringLiteral("nm17x"), QStringLiteral("--slcan-port"), QStringLiteral("0"),
          QStringLiteral("--control-port"), QStringLiteral("0"), QStringLiteral("--devices"),
          QStringLiteral("nm172@127,nm172@127,nm174@127") },
        2);
    m_slcan = db::test::listeningPort(banner, QStringLiteral("SLCAN"));
    const quint16 controlPort = db::test::listeningPort(banner, QStringLiteral("control"));
    QVERIFY2(m_slcan && controlPort, qPrintable(banner));
    QVERIFY(banner.contains(QLatin1String("NM172 node 127, NM172 node 127, NM174 node 127")));
    m_control.connectToHost(QHostAddress::LocalHost, controlPort);
    QVERIFY(m_control.waitForConnected(5000));
}

void TestCliNm17x::cleanupTestCase()
{
    m_control.disconnectFromHost();
    m_sim.terminate();
    QVERIFY(m_sim.waitForFinished(5000));
    QCOMPARE(m_sim.exitCode(), 0);
}

QStringList TestCliNm17x::control(const QString &command)
{
    m_control.write(command.toUtf8() + '\n');
    QStringList lines;
    QElapsedTimer clock;
    clock.start();
    while (clock.elapsed() < 5000) {
        while (m_control.canReadLine()) {
            const QString line = QString::fromUtf8(m_control.readLine()).trimmed();
            lines.append(line);
            if (line == u"ok" || line.startsWith(u"error: "))
                return lines;
        }
        m_control.waitForReadyRead(100);
    }
    return lines;
}

QPair<int, int> TestCliNm17x::display(int index)
{
    const QRegularExpression re(QStringLiteral("^%1 \\S+ serial \\S+ node \\d+ position (-?\\d+) "
                                               "status 0x([0-9a-f]{4})")
                                    .arg(index));
    for (const QString &line : control(QStringLiteral("list"))) {
        const auto m = re.match(line);
        if (m.hasMatch())
            return { m.captured(1).toInt(), m.captured(2).toInt(nullptr, 16) };
    }
    return { INT_MIN, -1 };
}

void TestCliNm17x::addressedByBroadcast()
{
    // The operator's choice: node 2 = the NM174 (display 3), 3 = display 1, 4 = display 2.
    const QMap<QString, int> chosen = { { QStringLiteral("2"), 3 },
                                        { QStringLiteral("3"), 1 },
                                        { QStringLiteral("4"), 2 } };
    // Like the operator, who turns the shaft once the display shows the offered id.
    QProcess p;
    QString out;
    QStringList replies;
    QStringList pending; // offers seen on the CLI's output, not yet served
    int offers = 0;
    connect(&p, &QProcess::readyReadStandardOutput, this, [&] {
        out += QString::fromUtf8(p.readAllStandardOutput());
        static const QRegularExpression offer(QStringLiteral("offering node (\\d+):"));
        auto it = offer.globalMatch(out);
        int seen = 0;
        while (it.hasNext()) {
            const QString node = it.next().captured(1);
            if (++seen > offers) {
                ++offers;
                pending.append(node);
            }
        }
    });
    QTimer operatorHand;
    connect(&operatorHand, &QTimer::timeout, this, [&] {
        if (pending.isEmpty())
            return;
        const int index = chosen.value(pending.first());
        const QString shown = QStringLiteral("addressing offered %1").arg(pending.first());
        if (!control(QStringLiteral("list")).value(index - 1).endsWith(shown))
            return;
        pending.removeFirst();
        replies.append(control(QStringLiteral("turn %1 10").arg(index)).join(u' '));
    });
    operatorHand.start(20);
    p.start(QStringLiteral(DRIVEBENCH_CLI),
            { QStringLiteral("nm17x"), uri(), QStringLiteral("address"),
              QStringLiteral("--broadcast"), QStringLiteral("2"), QStringLiteral("--count"),
              QStringLiteral("3"), QStringLiteral("--step-timeout"), QStringLiteral("20") });
    QTRY_VERIFY_WITH_TIMEOUT(p.state() == QProcess::NotRunning, 60000);
    out += QString::fromUtf8(p.readAllStandardOutput());
    QVERIFY2(p.exitCode() == 0, qPrintable(out + p.readAllStandardError()));
    QCOMPARE(replies,
             (QStringList { QStringLiteral("ok"), QStringLiteral("ok"), QStringLiteral("ok") }));
    QVERIFY2(out.contains(QLatin1String("assigned node ids: 2, 3, 4")), qPrintable(out));
    const QStringList list = control(QStringLiteral("list"));
    QVERIFY2(list.size() == 4, qPrintable(list.join(u'\n')));
    QVERIFY2(list.at(1).contains(QLatin1String("node 4 ")), qPrintable(list.join(u'\n') + out));
    QVERIFY(list.at(0).contains(QLatin1String("node 3 ")));
    QVERIFY(list.at(1).contains(QLatin1String("node 4 ")));
    QVERIFY(list.at(2).contains(QLatin1String("node 2 ")));
}

void TestCliNm17x::listedWithVariants()
{
    const CliRun r = cli({ QStringLiteral("nm17x"), uri(), QStringLiteral("list") });
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    const QStringList lines = r.out.trimmed().split(u'\n');
    QCOMPARE(lines.size(), 3);
    QVERIFY2(lines.at(0).contains(QRegularExpression(
                 QStringLiteral("node +2  NM174  serial 0x4D52F569  position 0\\.00 mm"))),
             qPrintable(r.out));
    QVERIFY(lines.at(1).contains(
        QRegularExpression(QStringLiteral("node +3  NM172  serial 0x4D52F567"))));
    QVERIFY(lines.at(2).contains(
        QRegularExpression(QStringLiteral("node +4  NM172  serial 0x4D52F568"))));
}

void TestCliNm17x::positionedFromTheLoopSide()
{
    // Up to 20.00 mm (direct), then down to 10.00 mm: below the target by the loop (1.00 mm),
    // then up into the tolerance window.
    CliRun r = cli({ QStringLiteral("nm17x"), uri(), QStringLiteral("setpoint"),
                     QStringLiteral("3"), QStringLiteral("20"), QStringLiteral("--release") });
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QVERIFY2(r.out.contains(QLatin1String("position 20.00 mm  status In Position")),
             qPrintable(r.out));
    int lowest = INT_MAX;
    QTimer poll;
    connect(&poll, &QTimer::timeout, this, [&] { lowest = qMin(lowest, display(1).first); });
    poll.start(20);
    r = cli({ QStringLiteral("nm17x"), uri(), QStringLiteral("setpoint"), QStringLiteral("3"),
              QStringLiteral("10"), QStringLiteral("--release") });
    poll.stop();
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QVERIFY2(r.out.contains(QLatin1String("position 10.00 mm  status In Position")),
             qPrintable(r.out));
    QVERIFY2(lowest <= 905 && lowest >= 895, qPrintable(QString::number(lowest)));
    const auto [position, status] = display(1);
    QVERIFY(qAbs(position - 1000) <= 5); // tolerance window 0.05 mm
    QVERIFY(status & 0x8000);

    // A negative position needs no "--" (it is no option), also beside options with values.
    r = cli({ QStringLiteral("nm17x"), uri(), QStringLiteral("setpoint"), QStringLiteral("3"),
              QStringLiteral("-2.5"), QStringLiteral("--release"), QStringLiteral("--correction"),
              QStringLiteral("-0") });
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QVERIFY2(r.out.contains(QLatin1String("position -2.50 mm  status In Position")),
             qPrintable(r.out));
    QVERIFY(qAbs(display(1).first + 250) <= 5);
}

void TestCliNm17x::joggedAndStopped()
{
    const int start = display(2).first;
    CliRun r = cli({ QStringLiteral("nm17x"), uri(), QStringLiteral("jog"), QStringLiteral("4"),
                     QStringLiteral("right"), QStringLiteral("--speed"), QStringLiteral("fast") });
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QTRY_VERIFY(display(2).first > start + 200);
    QVERIFY(display(2).second & 0x0001); // Moving
    r = cli({ QStringLiteral("nm17x"), uri(), QStringLiteral("stop"), QStringLiteral("4") });
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QTRY_VERIFY(!(display(2).second & 0x0001));
    const int stopped = display(2).first;
    QTest::qWait(200);
    QCOMPARE(display(2).first, stopped);
}

void TestCliNm17x::presetByBroadcast()
{
    const CliRun r = cli({ QStringLiteral("nm17x"), uri(), QStringLiteral("broadcast"),
                           QStringLiteral("preset"), QStringLiteral("100") });
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    for (int i = 1; i <= 3; ++i)
        QTRY_COMPARE(display(i).first, 10000);
}

void TestCliNm17x::forbiddenControlWordIsRefused()
{
    const CliRun r = cli({ QStringLiteral("nm17x"), uri(), QStringLiteral("control"),
                           QStringLiteral("3"), QStringLiteral("0x0005") });
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.err.contains(QLatin1String("0x0005 is not an allowed combination")),
             qPrintable(r.err));
    // The display never saw it: its RxPDO2 image still holds the last setpoint's control word.
    const CliRun read =
        cli({ QStringLiteral("read"), uri() + QStringLiteral("&node=3"), QStringLiteral("2501:3"),
              QStringLiteral("--type"), QStringLiteral("u16") });
    QVERIFY2(read.exitCode == 0, qPrintable(read.err));
    QCOMPARE(read.out.trimmed(), QStringLiteral("3"));
}

void TestCliNm17x::emergencyShownWithText()
{
    QProcess watch;
    QString out;
    connect(&watch, &QProcess::readyReadStandardOutput, this,
            [&] { out += QString::fromUtf8(watch.readAllStandardOutput()); });
    watch.start(QStringLiteral(DRIVEBENCH_CLI),
                { QStringLiteral("nm17x"), uri(), QStringLiteral("watch"),
                  QStringLiteral("--duration"), QStringLiteral("3") });
    QTRY_VERIFY_WITH_TIMEOUT(out.contains(QLatin1String("watching")), 10000);
    // Another master sends node 3 a forbidden control word anyway.
    QTcpSocket other;
    other.connectToHost(QHostAddress::LocalHost, m_slcan);
    QVERIFY(other.waitForConnected(5000));
    other.write("t3038E803000000000500\r");
    QVERIFY(other.waitForBytesWritten(2000));
    QTRY_VERIFY_WITH_TIMEOUT(watch.state() == QProcess::NotRunning, 15000);
    QCOMPARE(watch.exitCode(), 0);
    QVERIFY2(out.contains(QLatin1String(
                 "node 3 EMCY 8230h sub 01: RxPDO2: invalid value in the control word")),
             qPrintable(out));
}

void TestCliNm17x::wideCorrectionGoesThrough2010()
{
    // 500.00 mm does not fit the PDO's 16 bits: written to 2010h, the PDO keeps it.
    const CliRun r =
        cli({ QStringLiteral("nm17x"), uri(), QStringLiteral("setpoint"), QStringLiteral("2"),
              QStringLiteral("50"), QStringLiteral("--correction"), QStringLiteral("500") });
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    const CliRun read =
        cli({ QStringLiteral("read"), uri() + QStringLiteral("&node=2"), QStringLiteral("2010:0"),
              QStringLiteral("--type"), QStringLiteral("s32") });
    QVERIFY2(read.exitCode == 0, qPrintable(read.err));
    QCOMPARE(read.out.trimmed(), QStringLiteral("50000"));
    // The node's description (chosen from its identity) types 2501h:02 UNSIGNED16, as the
    // manual does: the PDO's -32768 ("keep 2010h") reads as 8000h.
    const CliRun pdo = cli({ QStringLiteral("read"), uri() + QStringLiteral("&node=2"),
                             QStringLiteral("2501:2"), QStringLiteral("--hex") });
    QCOMPARE(pdo.out.trimmed(), QStringLiteral("0x8000"));
}

void TestCliNm17x::usageErrors()
{
    CliRun r = cli({ QStringLiteral("nm17x"), uri(), QStringLiteral("fly") });
    QCOMPARE(r.exitCode, 2);
    QVERIFY(r.err.contains(QLatin1String("unknown nm17x command 'fly'")));
    r = cli({ QStringLiteral("nm17x"), uri(), QStringLiteral("jog"), QStringLiteral("4"),
              QStringLiteral("right") });
    QCOMPARE(r.exitCode, 2);
    QVERIFY(r.err.contains(QLatin1String("--speed")));
    r = cli({ QStringLiteral("nm17x"), uri(), QStringLiteral("broadcast"), QStringLiteral("start"),
              QStringLiteral("9") });
    QCOMPARE(r.exitCode, 2);
    r = cli({ QStringLiteral("nm17x"), uri(), QStringLiteral("setpoint"), QStringLiteral("3"),
              QStringLiteral("12000") });
    QCOMPARE(r.exitCode, 2);
    r = cli({ QStringLiteral("nm17x"), uri(), QStringLiteral("address") });
    QCOMPARE(r.exitCode, 2);
    QVERIFY(r.err.contains(QLatin1String("--broadcast FIRST")));
}

// D1/D2 written by the generic CLI (the node's description comes from its identity), then
// oscillation started and stopped by 204Dh:02.
void TestCliNm17x::oscillatedAndStopped()
{
    const QString node3 = QStringLiteral("canopen+slcan://127.0.0.1:%1?node=3").arg(m_slcan);
    CliRun r =
        cli({ QStringLiteral("write"), node3, QStringLiteral("2045:1"), QStringLiteral("500") });
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QVERIFY2(r.err.isEmpty(), qPrintable(r.err)); // described: no note about a missing description
    r = cli({ QStringLiteral("write"), node3, QStringLiteral("2045:2"), QStringLiteral("900") });
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    r = cli({ QStringLiteral("nm17x"), uri(), QStringLiteral("oscillate"), QStringLiteral("3"),
              QStringLiteral("start") });
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QTRY_VERIFY(display(1).second & 0x0004); // status bit 2: oscillating
    // Up to D2, then on the way back down to D1 (the reversal itself is too short to catch).
    QTRY_VERIFY_WITH_TIMEOUT(display(1).first >= 895, 10000);
    QTRY_VERIFY_WITH_TIMEOUT(display(1).first <= 600, 10000);
    r = cli({ QStringLiteral("nm17x"), uri(), QStringLiteral("oscillate"), QStringLiteral("3"),
              QStringLiteral("stop") });
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QTRY_VERIFY(!(display(1).second & 0x0004));
    r = cli({ QStringLiteral("nm17x"), uri(), QStringLiteral("oscillate"), QStringLiteral("3"),
              QStringLiteral("sideways") });
    QCOMPARE(r.exitCode, 2);
}

// Input and key modes, scaling from the pitch, jump filter and dynamic pre-shutdown of one
// display: written by name, shown as the display has them, and back to the defaults.
void TestCliNm17x::settingsReadAndWritten()
{
    CliRun r = cli(
        { QStringLiteral("nm17x"), uri(), QStringLiteral("settings"), QStringLiteral("4"),
          QStringLiteral("--input-mode"), QStringLiteral("takten"), QStringLiteral("--key-mode"),
          QStringLiteral("fast"), QStringLiteral("--pitch"), QStringLiteral("8"),
          QStringLiteral("--filter-width"), QStringLiteral("40"), QStringLiteral("--filter-count"),
          QStringLiteral("3"), QStringLiteral("--pre-shutdown"), QStringLiteral("on") });
    QVERIFY2(r.exitCode == 0, qPrintable(r.out + r.err));
    for (const char *expected :
         { "node 4  NM172", "2041:3 Input modes: 1 (Takten)", "2041:4 Key modes: 3 (Fast)",
           "2004:0 Scaling (spindle pitch): 3472222 = 8.00 mm/rev at 2304 steps/rev",
           "2005:1 Filter width: 40 steps", "2005:2 Filter count: 3",
           "2041:2 Dynamic pre-shutdown: 1 (On)", "2042:3 Switch-off point: 0" })
        QVERIFY2(r.out.contains(QLatin1String(expected)), qPrintable(expected + (u'\n' + r.out)));
    // Out of range: refused before it is sent, naming the object.
    r = cli({ QStringLiteral("nm17x"), uri(), QStringLiteral("settings"), QStringLiteral("4"),
              QStringLiteral("--filter-width"), QStringLiteral("5000") });
    QVERIFY(r.exitCode != 0);
    QVERIFY2(r.err.contains(QLatin1String("2005:1")), qPrintable(r.err));
    r = cli({ QStringLiteral("nm17x"), uri(), QStringLiteral("settings"), QStringLiteral("4"),
              QStringLiteral("--input-mode"), QStringLiteral("sideways") });
    QCOMPARE(r.exitCode, 2);
    r = cli({ QStringLiteral("nm17x"), uri(), QStringLiteral("settings"), QStringLiteral("4"),
              QStringLiteral("--input-mode"), QStringLiteral("standard"),
              QStringLiteral("--key-mode"), QStringLiteral("0"), QStringLiteral("--pitch"),
              QStringLiteral("4"), QStringLiteral("--filter-width"), QStringLiteral("100"),
              QStringLiteral("--filter-count"), QStringLiteral("5"),
              QStringLiteral("--pre-shutdown"), QStringLiteral("off") });
    QVERIFY2(r.exitCode == 0, qPrintable(r.out + r.err));
    QVERIFY2(r.out.contains(QLatin1String("1736111 = 4.00 mm/rev")), qPrintable(r.out));
    QVERIFY2(r.out.contains(QLatin1String("Input modes: 0 (Standard / Oscillating)")),
             qPrintable(r.out));
}

// A blocked shaft (Er 3) and a motor wired the wrong way round (Er 6), set on the simulator's
// control socket: the setpoint fails naming the display error.
void TestCliNm17x::displayErrorsNamed()
{
    QCOMPARE(control(QStringLiteral("fault 1 blocked")).constLast(), QStringLiteral("ok"));
    const QStringList setpoint = { QStringLiteral("nm17x"),    uri(),
                                   QStringLiteral("setpoint"), QStringLiteral("3"),
                                   QStringLiteral("12.5"),     QStringLiteral("--release") };
    CliRun r = cli(setpoint);
    QVERIFY2(r.exitCode != 0, qPrintable(r.out));
    QVERIFY2(r.err.contains(QLatin1String("node 3: Er 3 (shaft does not turn despite the drive "
                                          "signal)")),
             qPrintable(r.err));
    QCOMPARE(control(QStringLiteral("fault 1 wiring")).constLast(), QStringLiteral("ok"));
    r = cli(setpoint);
    QVERIFY(r.exitCode != 0);
    QVERIFY2(r.err.contains(QLatin1String("node 3: Er 6 (direction error")), qPrintable(r.err));
    QCOMPARE(control(QStringLiteral("fault 1 none")).constLast(), QStringLiteral("ok"));
    r = cli(setpoint);
    QVERIFY2(r.exitCode == 0, qPrintable(r.out + r.err));
    QVERIFY2(r.out.contains(QLatin1String("In Position")), qPrintable(r.out));
    QVERIFY(control(QStringLiteral("fault 1 loose")).constLast().startsWith(u"error: "));
    QCOMPARE(control(QStringLiteral("glitch 1 1000 3")).constLast(), QStringLiteral("ok"));
    QVERIFY(control(QStringLiteral("glitch 1 many")).constLast().startsWith(u"error: "));
    QCOMPARE(control(QStringLiteral("coast 1 0")).constLast(), QStringLiteral("ok"));
}

// A display left at 250 kbit/s (its 2100h default): list at 125 kbit/s finds nothing, scan
// looks at both rates and tells at which it answers.
void TestCliNm17x::scanFindsTheBitrate()
{
    QProcess sim;
    const QString banner = db::test::startAndReadBanner(
        sim, QStringLiteral(DRIVEBENCH_SIM),
        { QStringLiteral("nm17x"), QStringLiteral("--slcan-port"), QStringLiteral("0"),
          QStringLiteral("--devices"), QStringLiteral("nm174@127"), QStringLiteral("--bitrate"),
          QStringLiteral("250000") },
        1);
    const quint16 port = db::test::listeningPort(banner, QStringLiteral("SLCAN"));
    QVERIFY2(port, qPrintable(banner));
    const QString at125 = QStringLiteral("canopen+slcan://127.0.0.1:%1?bitrate=125000").arg(port);
    CliRun r = cli({ QStringLiteral("nm17x"), at125, QStringLiteral("list") });
    QCOMPARE(r.exitCode, 4);
    r = cli({ QStringLiteral("nm17x"), at125, QStringLiteral("scan") });
    sim.terminate();
    QVERIFY(sim.waitForFinished(5000));
    QVERIFY2(r.exitCode == 0, qPrintable(r.out + r.err));
    const QStringList lines = r.out.split(u'\n', Qt::SkipEmptyParts);
    QVERIFY2(lines.size() == 3, qPrintable(r.out));
    QCOMPARE(lines.at(0), QStringLiteral("125 kbit/s: 0 display(s)"));
    QCOMPARE(lines.at(1), QStringLiteral("250 kbit/s: 1 display(s)"));
    QVERIFY2(lines.at(2).contains(QRegularExpression(QStringLiteral("node +127  NM174"))),
             qPrintable(lines.at(2)));
}

// python-can (a CAN stack of its own, SLCAN over TCP) addresses a display by LSS and reads and
// writes it by SDO with exactly the documented frames (tests/app/nm17x_thirdparty.py).
void TestCliNm17x::thirdPartyMasterByteExact()
{
    const QString python = QStringLiteral("/usr/bin/python3");
    if (db::test::runProgram(python, { QStringLiteral("-c"), QStringLiteral("import can") }, 10000)
            .exitCode
        != 0)
        QSKIP("python3-can is not installed");
    QProcess sim;
    const QString banner = db::test::startAndReadBanner(
        sim, QStringLiteral(DRIVEBENCH_SIM),
        { QStringLiteral("nm17x"), QStringLiteral("--slcan-port"), QStringLiteral("0"),
          QStringLiteral("--devices"), QStringLiteral("nm172@127") },
        1);
    const quint16 port = db::test::listeningPort(banner, QStringLiteral("SLCAN"));
    QVERIFY2(port, qPrintable(banner));
    const CliRun r = db::test::runProgram(
        python,
        { QStringLiteral(DRIVEBENCH_SOURCE_DIR "/tests/app/nm17x_thirdparty.py"),
          QString::number(port) },
        30000);
    sim.terminate();
    QVERIFY(sim.waitForFinished(5000));
    QVERIFY2(r.exitCode == 0, qPrintable(r.out + r.err));
    QVERIFY(r.out.contains(QLatin1String("SDO-5 out of range: 5A5 80 00 20 05 30 00 09 06")));
    QVERIFY(r.out.trimmed().endsWith(QLatin1String("ok")));
}

QTEST_GUILESS_MAIN(TestCliNm17x)
#include "tst_cli_nm17x.moc"
