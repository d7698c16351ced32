// The simulators' servers under abuse: hundreds of connections that send random bytes, close at
// once, or connect and then neither read nor close (half-open), and one endless line without a
// terminator. Afterwards each simulator still runs, listens on 127.0.0.1 only, and a well-behaved
// client (drivebench-cli read) gets its answer.
#include "clirun.h"

#include <QFile>
#include <QProcess>
#include <QRandomGenerator>
#include <QScopeGuard>
#include <QTcpSocket>
#include <QTemporaryDir>
#include <QTest>

#include <memory>
#include <vector>

namespace {

constexpr int kConnections = 300;

// Listening TCP sockets on `port` from /proc/net/tcp and /proc/net/tcp6: their local addresses
// as the kernel writes them ("0100007F" is 127.0.0.1).
QStringList listeningAddresses(quint16 port)
{
    QStringList out;
    for (const char *table : { "/proc/net/tcp", "/proc/net/tcp6" }) {
        QFile f(QString::fromLatin1(table));
        if (!f.open(QIODevice::ReadOnly))
            continue;
        const QList<QByteArray> lines = f.readAll().split('\n');
        for (const QByteArray &line : lines) {
            const QList<QByteArray> cols = line.simplified().split(' ');
            if (cols.size() < 4 || cols.at(3) != "0A") // 0A: LISTEN
                continue;
            const QList<QByteArray> local = cols.at(1).split(':');
            if (local.size() == 2 && local.at(1).toUInt(nullptr, 16) == port)
                out << QString::fromLatin1(local.at(0));
        }
    }
    return out;
}

QString simLog(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? QString::fromUtf8(f.readAll().right(3000)) : QString();
}

} // namespace

class TestSimHardening : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void survivesAbuse_data();
    void survivesAbuse();
};

void TestSimHardening::survivesAbuse_data()
{
    QTest::addColumn<QStringList>("simArgs");
    QTest::addColumn<QString>("what"); // the banner's name of the door under test
    QTest::addColumn<QString>("uri"); // %1 = port
    QTest::addColumn<QString>("address");
    QTest::addColumn<QString>("expected");
    QTest::addColumn<bool>("oneClient"); // the device takes one client at a time

    QTest::newRow("movingcap RefGo") << QStringList { "movingcap", "--refgo-port", "0" } << "RefGo"
                                     << "refgo://127.0.0.1:%1"
                                     << "1000:0"
                                     << "" << false;
    QTest::newRow("movingcap SLCAN") << QStringList { "movingcap", "--slcan-port", "0" } << "SLCAN"
                                     << "canopen+slcan://127.0.0.1:%1?node=50"
                                     << "1000:0"
                                     << "" << false;
    QTest::newRow("ACU VABus/TCP") << QStringList { "acu", "--vabus-port", "0" } << "VABus/TCP"
                                   << "vabus://127.0.0.1:%1"
                                   << "372:2"
                                   << "1390" << true;
    QTest::newRow("NM17x SLCAN") << QStringList { "nm17x", "--slcan-port", "0", "--devices",
                                                  "nm172@5" }
                                 << "SLCAN"
                                 << "canopen+slcan://127.0.0.1:%1?node=5"
                                 << "1000:0"
                                 << "" << false;
}

void TestSimHardening::survivesAbuse()
{
    QFETCH(QStringList, simArgs);
    QFETCH(QString, what);
    QFETCH(QString, uri);
    QFETCH(QString, address);
    QFETCH(QString, expected);
    QFETCH(bool, oneClient);

    // The simulator logs every refused line and connection: into a file, since nobody reads
    // a pipe here while the abuse runs (a full pipe would stall the simulator, not the server).
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString log = dir.filePath(QStringLiteral("sim.log"));
    QProcess sim;
    sim.setStandardErrorFile(log);
    const auto stopSim = qScopeGuard([&sim] {
        sim.kill();
        sim.waitForFinished(5000);
    });
    const QString banner =
        db::test::startAndReadBanner(sim, QStringLiteral(DRIVEBENCH_SIM), simArgs, 1);
    const quint16 port = db::test::listeningPort(banner, what);
    QVERIFY2(port != 0, qPrintable(banner + QString::fromUtf8(sim.readAllStandardError())));

    // Loopback only: nothing listens on this port on another address.
    QCOMPARE(listeningAddresses(port), QStringList { QStringLiteral("0100007F") });

    QRandomGenerator random(4711);
    std::vector<std::unique_ptr<QTcpSocket>> open;
    for (int i = 0; i < kConnections; ++i) {
        auto s = std::make_unique<QTcpSocket>();
        s->connectToHost(QStringLiteral("127.0.0.1"), port);
        QVERIFY2(s->waitForConnected(5000),
                 qPrintable(QStringLiteral("connection %1: %2").arg(i).arg(s->errorString())));
        switch (i % 3) {
        case 0: { // random bytes, then stays connected
            QByteArray junk(256, '\0');
            for (char &c : junk)
                c = char(random.bounded(256));
            s->write(junk);
            s->waitForBytesWritten(1000);
            open.push_back(std::move(s));
            break;
        }
        case 1: // gone at once (reset)
            s->abort();
            break;
        default: // half-open: never reads, never closes
            open.push_back(std::move(s));
            break;
        }
    }
    // One endless line: 1 MB without a terminator.
    {
        auto s = std::make_unique<QTcpSocket>();
        s->connectToHost(QStringLiteral("127.0.0.1"), port);
        QVERIFY(s->waitForConnected(5000));
        s->write(QByteArray(1024 * 1024, 'A'));
        s->waitForBytesWritten(2000);
        open.push_back(std::move(s));
    }
    QCOMPARE(sim.state(), QProcess::Running);

    if (oneClient) // the device serves one client: the abusers go first
        open.clear();

    const QStringList args { QStringLiteral("read"), uri.arg(port), address };
    db::test::CliRun run;
    QElapsedTimer clock;
    clock.start();
    do { // a one-client device may still be closing the abusers' connections
        run = db::test::runProgram(QStringLiteral(DRIVEBENCH_CLI), args, 15000);
    } while (run.exitCode != 0 && oneClient && clock.elapsed() < 15000);
    QVERIFY2(run.exitCode == 0,
             qPrintable(QStringLiteral("exit %1: %2%3\nsimulator: %4")
                            .arg(run.exitCode)
                            .arg(run.out, run.err, simLog(log))));
    QVERIFY2(run.out.contains(expected), qPrintable(run.out));
    QCOMPARE(sim.state(), QProcess::Running);
}

QTEST_GUILESS_MAIN(TestSimHardening)
#include "tst_sim_hardening.moc"
