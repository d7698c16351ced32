// Level 3: how drivebench-cli connects: the connect timeout reaches the transport, and a
// connection that cannot be made names its real cause.
#include "clirun.h"

#include <QTcpServer>
#include <QTcpSocket>
#include <QTest>

#include <memory>
#include <vector>

using namespace db::test;

namespace {

const QString kCli = QStringLiteral(DRIVEBENCH_CLI);

// A loopback port whose listener never accepts and whose accept queue is full: the kernel drops
// further connection attempts, so a client's connect neither succeeds nor fails until its own
// timeout, like a host that does not answer.
class StalledListener
{
public:
    bool start()
    {
        m_server.setListenBacklogSize(0);
        if (!m_server.listen(QHostAddress::LocalHost))
            return false;
        m_server.pauseAccepting();
        for (int i = 0; i < 3; ++i) {
            auto socket = std::make_unique<QTcpSocket>();
            socket->connectToHost(QHostAddress::LocalHost, m_server.serverPort());
            m_fillers.push_back(std::move(socket));
        }
        // One more attempt must now hang: that is what the tests rely on.
        QTcpSocket probe;
        probe.connectToHost(QHostAddress::LocalHost, m_server.serverPort());
        return !probe.waitForConnected(300);
    }
    quint16 port() const { return m_server.serverPort(); }

private:
    QTcpServer m_server;
    std::vector<std::unique_ptr<QTcpSocket>> m_fillers;
};

} // namespace

class TestCliConnect : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void connectTimeoutReachesTheTransport_data();
    void connectTimeoutReachesTheTransport();
    void unknownCanPluginIsNamed();
    void missingInterfaceIsNamed();
    void missingVirtualInterfaceIsNamed();
    void badBitrateIsNamed();
    void unreadableDescriptionIsNamed();
};

void TestCliConnect::connectTimeoutReachesTheTransport_data()
{
    QTest::addColumn<QString>("scheme");
    QTest::addColumn<QString>("query");
    QTest::newRow("refgo") << QStringLiteral("refgo") << QString();
    QTest::newRow("slcan") << QStringLiteral("canopen+slcan") << QStringLiteral("?node=1");
}

void TestCliConnect::connectTimeoutReachesTheTransport()
{
    QFETCH(QString, scheme);
    QFETCH(QString, query);
    StalledListener stalled;
    if (!stalled.start())
        QSKIP("this kernel completes connections beyond a full accept queue");
    const QString uri =
        QStringLiteral("%1://127.0.0.1:%2%3").arg(scheme).arg(stalled.port()).arg(query);
    // Longer than the transport's 3 s default: the option must reach it.
    const CliRun r = runProgram(kCli,
                                { QStringLiteral("read"), uri, QStringLiteral("6041:0"),
                                  QStringLiteral("--connect-timeout"), QStringLiteral("8000") },
                                30000);
    QCOMPARE(r.exitCode, 4);
    QVERIFY2(r.ms >= 7800, qPrintable(QStringLiteral("gave up after %1 ms").arg(r.ms)));
    QVERIFY2(r.err.contains(QStringLiteral("8000 ms")), qPrintable(r.err));
    QVERIFY2(r.err.contains(QStringLiteral("127.0.0.1:%1").arg(stalled.port())), qPrintable(r.err));
}

void TestCliConnect::unknownCanPluginIsNamed()
{
    const CliRun r =
        runProgram(kCli,
                   { QStringLiteral("read"), QStringLiteral("canopen+nosuchplugin://can0?node=1"),
                     QStringLiteral("1000:0") },
                   10000);
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.err.contains(QStringLiteral("nosuchplugin")), qPrintable(r.err));
    QVERIFY2(r.err.contains(QStringLiteral("virtualcan")), qPrintable(r.err)); // what there is
    QVERIFY2(!r.err.contains(QStringLiteral("cannot make")), qPrintable(r.err));
}

void TestCliConnect::missingInterfaceIsNamed()
{
    // socketcan fails inside its open call when the interface does not exist (or names the
    // missing plugin where it is not installed): the message says which interface, no crash.
    const CliRun r =
        runProgram(kCli,
                   { QStringLiteral("read"), QStringLiteral("canopen+socketcan://nosuchif7?node=1"),
                     QStringLiteral("1000:0") },
                   10000);
    QVERIFY2(r.exitCode > 0 && r.exitCode < 128, qPrintable(QString::number(r.exitCode)));
    QVERIFY2(r.err.contains(QStringLiteral("nosuchif7")), qPrintable(r.err));
    QVERIFY2(!r.err.contains(QStringLiteral("closed unexpectedly")), qPrintable(r.err));
}

void TestCliConnect::missingVirtualInterfaceIsNamed()
{
    // Qt's virtualcan takes an unknown name with a log line only and opens can0: the request
    // would end in an SDO timeout. The cause is named before anything is opened.
    const CliRun r =
        runProgram(kCli,
                   { QStringLiteral("read"), QStringLiteral("canopen+virtualcan://nosuchif?node=5"),
                     QStringLiteral("1000:0") },
                   10000);
    QCOMPARE(r.exitCode, 3); // as for a refused connection
    QVERIFY2(r.err.contains(QStringLiteral("CAN interface 'nosuchif' does not exist for plugin "
                                           "virtualcan (available: can0")),
             qPrintable(r.err));
    QVERIFY2(!r.err.contains(QStringLiteral("did not answer")), qPrintable(r.err));
}

void TestCliConnect::badBitrateIsNamed()
{
    const CliRun r = runProgram(kCli,
                                { QStringLiteral("read"),
                                  QStringLiteral("canopen+virtualcan://can0?node=1&bitrate=fast"),
                                  QStringLiteral("1000:0") },
                                10000);
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.err.contains(QStringLiteral("bitrate")), qPrintable(r.err));
}

void TestCliConnect::unreadableDescriptionIsNamed()
{
    const CliRun r =
        runProgram(kCli,
                   { QStringLiteral("read"),
                     QStringLiteral("canopen+virtualcan://can0?node=1&eds=/nonexistent/x.eds"),
                     QStringLiteral("1000:0") },
                   10000);
    QVERIFY(r.exitCode != 0);
    QVERIFY2(r.err.contains(QStringLiteral("/nonexistent/x.eds")), qPrintable(r.err));
}

QTEST_GUILESS_MAIN(TestCliConnect)
#include "tst_cli_connect.moc"
