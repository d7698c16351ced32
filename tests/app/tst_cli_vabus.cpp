// Level 3: drivebench-cli over VABus/TCP end to end: against drivebench-sim acu (values with
// their units and decimals, physical writes, refusals with their VABus codes, failure modes,
// a refused connection) and against a scripted VABus peer that is not ours.

#include "clirun.h"

#include <QProcess>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTemporaryDir>
#include <QtTest>

using db::test::CliRun;

namespace {

constexpr int kRunMs = 30000;

CliRun cli(const QStringList &args)
{
    return db::test::runProgram(QStringLiteral(DRIVEBENCH_CLI), args, kRunMs);
}

// A VABus peer written from the protocol's examples alone: it answers the requests it knows
// with fixed telegrams, one byte per TCP write.
class ExamplePeer : public QObject
{
public:
    explicit ExamplePeer(QHash<QByteArray, QByteArray> answers)
        : m_answers(std::move(answers))
    {
        connect(&m_server, &QTcpServer::newConnection, this, [this] {
            while (QTcpSocket *s = m_server.nextPendingConnection()) {
                s->setParent(this);
                s->setSocketOption(QAbstractSocket::LowDelayOption, 1);
                connect(s, &QTcpSocket::readyRead, s, [this, s] {
                    m_buffer += s->readAll();
                    while (m_buffer.size() >= 2 && m_buffer.size() >= m_buffer.at(1) + 2) {
                        const QByteArray request = m_buffer.left(m_buffer.at(1) + 2);
                        m_buffer.remove(0, request.size());
                        for (const char c : m_answers.value(request.toHex(' ').toUpper())) {
                            s->write(&c, 1);
                            s->flush();
                        }
                    }
                });
            }
        });
    }
    bool listen() { return m_server.listen(QHostAddress::LocalHost, 0); }
    quint16 port() const { return m_server.serverPort(); }

private:
    QTcpServer m_server;
    QHash<QByteArray, QByteArray> m_answers;
    QByteArray m_buffer;
};

QByteArray bytes(const char *hex)
{
    return QByteArray::fromHex(hex);
}

} // namespace

class TstCliVabus : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase()
    {
        m_uri = startSim(m_sim, {});
        QVERIFY(!m_uri.isEmpty());
    }
    void cleanupTestCase()
    {
        for (QProcess *p : { &m_sim, &m_silent, &m_garbage }) {
            if (p->state() != QProcess::NotRunning) {
                p->terminate();
                if (!p->waitForFinished(3000))
                    p->kill();
            }
        }
    }

    void readsWithUnitAndDecimals_data()
    {
        QTest::addColumn<QString>("address");
        QTest::addColumn<QString>("expected");
        QTest::newRow("372:2") << "372:2"
                               << "1390 rpm";
        QTest::newRow("481:1") << "481:1"
                               << "10.00 Hz";
        QTest::newRow("12") << "12"
                            << "5.3.2 STO";
        QTest::newRow("388") << "388"
                             << "1 (fault)";
    }
    void readsWithUnitAndDecimals()
    {
        QFETCH(QString, address);
        QFETCH(QString, expected);
        const CliRun r = cli({ QStringLiteral("read"), m_uri, address });
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QCOMPARE(r.out, expected + QLatin1Char('\n'));
    }

    void writesPhysicalValues()
    {
        CliRun r =
            cli({ QStringLiteral("write"), m_uri, QStringLiteral("376:4"), QStringLiteral("1.5") });
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        r = cli({ QStringLiteral("read"), m_uri, QStringLiteral("376:4") });
        QCOMPARE(r.out, QStringLiteral("1.5 kW\n"));
        r = cli(
            { QStringLiteral("write"), m_uri, QStringLiteral("481:1"), QStringLiteral("10.5") });
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        r = cli({ QStringLiteral("read"), m_uri, QStringLiteral("481:1") });
        QCOMPARE(r.out, QStringLiteral("10.50 Hz\n"));
        // More decimals than the parameter has: refused before anything is sent.
        r = cli(
            { QStringLiteral("write"), m_uri, QStringLiteral("481:1"), QStringLiteral("10.555") });
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(QLatin1String("decimal")), qPrintable(r.err));
    }

    // An empty string is written as a select telegram without data, and reads back empty.
    void emptyStringWrites()
    {
        CliRun r =
            cli({ QStringLiteral("write"), m_uri, QStringLiteral("29"), QStringLiteral("Line 3") });
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        r = cli({ QStringLiteral("read"), m_uri, QStringLiteral("29") });
        QCOMPARE(r.out, QStringLiteral("Line 3\n"));
        r = cli({ QStringLiteral("write"), m_uri, QStringLiteral("29"), QString() });
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        r = cli({ QStringLiteral("read"), m_uri, QStringLiteral("29") });
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QCOMPARE(r.out, QStringLiteral("\n"));
    }

    // backup, change two data sets, diff names them, restore writes them back, diff is clean.
    void backupDiffRestoreRoundTrip()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString file = dir.filePath(QStringLiteral("acu.set"));
        CliRun r = cli({ QStringLiteral("backup"), m_uri, QStringLiteral("-o"), file });
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        for (const auto &[address, value] :
             { std::pair { "481:3", "33.33" }, std::pair { "372:4", "1400" } }) {
            r = cli(
                { QStringLiteral("write"), m_uri, QLatin1String(address), QLatin1String(value) });
            QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        }
        r = cli({ QStringLiteral("diff"), m_uri, file });
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.out.contains(QLatin1String("481:3")) && r.out.contains(QLatin1String("372:4"))
                     && r.out.contains(QLatin1String("2 changed")),
                 qPrintable(r.out));
        // Physical values with their decimals and unit, as the editor shows them.
        QVERIFY2(r.out.contains(QLatin1String(": 33.33 Hz | 20.00 Hz\n")), qPrintable(r.out));
        QVERIFY2(r.out.contains(QLatin1String(": 1400 rpm | 1390 rpm\n")), qPrintable(r.out));
        r = cli({ QStringLiteral("restore"), m_uri, file });
        QVERIFY2(r.exitCode == 0, qPrintable(r.out + r.err));
        r = cli({ QStringLiteral("diff"), m_uri, file });
        QVERIFY2(r.exitCode == 0, qPrintable(r.out + r.err));
        r = cli({ QStringLiteral("read"), m_uri, QStringLiteral("481:3") });
        QCOMPARE(r.out, QStringLiteral("20.00 Hz\n"));
    }

    // --ram writes the RAM copy (DS + 5): the value reads back, the EEPROM counter stays put.
    void ramWritesSpareTheEeprom()
    {
        QProcess sim;
        const QString uri = startSim(sim, {});
        QVERIFY(!uri.isEmpty());
        CliRun r = cli({ QStringLiteral("write"), uri, QStringLiteral("481:2"),
                         QStringLiteral("12.34"), QStringLiteral("--ram") });
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        r = cli({ QStringLiteral("read"), uri, QStringLiteral("481:2") });
        QCOMPARE(r.out, QStringLiteral("12.34 Hz\n"));
        r = cli({ QStringLiteral("write"), QStringLiteral("refgo://127.0.0.1:1"),
                  QStringLiteral("6041:0"), QStringLiteral("1"), QStringLiteral("--ram") });
        QCOMPARE(r.exitCode, 2);
        QVERIFY(r.err.contains(QLatin1String("--ram needs a vabus:// URI")));
        // The same write without --ram is the one EEPROM write the simulator counts.
        r = cli({ QStringLiteral("write"), uri, QStringLiteral("481:2"), QStringLiteral("12.34") });
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        sim.terminate();
        QVERIFY(sim.waitForFinished(5000));
        const QString out = QString::fromUtf8(sim.readAllStandardOutput());
        QVERIFY2(out.contains(QLatin1String("acu: 1 EEPROM writes")), qPrintable(out));
    }

    void refusalsNameTheirCode()
    {
        CliRun r =
            cli({ QStringLiteral("write"), m_uri, QStringLiteral("376:4"), QStringLiteral("0") });
        QCOMPARE(r.exitCode, 6);
        QVERIFY2(r.err.contains(QLatin1String("invalid parameter value"))
                     && r.err.contains(QLatin1String("error 1,")),
                 qPrintable(r.err));
        r = cli({ QStringLiteral("read"), m_uri, QStringLiteral("1599") });
        QCOMPARE(r.exitCode, 6);
        QVERIFY2(r.err.contains(QLatin1String("unknown parameter"))
                     && r.err.contains(QLatin1String("error 11")),
                 qPrintable(r.err));
        r = cli({ QStringLiteral("read"), m_uri, QStringLiteral("481") });
        QCOMPARE(r.exitCode, 6);
        QVERIFY2(r.err.contains(QLatin1String("error 9")), qPrintable(r.err));
    }

    void hexAddressIsRefused()
    {
        CliRun r = cli({ QStringLiteral("read"), m_uri, QStringLiteral("0x6041:0") });
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(QLatin1String("372:2")), qPrintable(r.err));
        r = cli({ QStringLiteral("read"), m_uri, QStringLiteral("6041:0") });
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(QLatin1String("1599")), qPrintable(r.err));
    }

    void silenceExits4()
    {
        const QString uri =
            startSim(m_silent, { QStringLiteral("--fail"), QStringLiteral("silent") });
        QVERIFY(!uri.isEmpty());
        const CliRun r = cli({ QStringLiteral("read"), uri, QStringLiteral("372:2"),
                               QStringLiteral("-t"), QStringLiteral("200") });
        QCOMPARE(r.exitCode, 4);
        QVERIFY2(r.err.contains(QLatin1String("372:2")), qPrintable(r.err));
    }

    void garbageExits5()
    {
        const QString uri =
            startSim(m_garbage, { QStringLiteral("--fail"), QStringLiteral("garbage") });
        QVERIFY(!uri.isEmpty());
        const CliRun r = cli({ QStringLiteral("read"), uri, QStringLiteral("372:2") });
        QCOMPARE(r.exitCode, 5);
        QVERIFY2(r.err.contains(QLatin1String("no VABus header")), qPrintable(r.err));
    }

    void refusedConnectionExits3()
    {
        QTcpServer probe;
        QVERIFY(probe.listen(QHostAddress::LocalHost, 0));
        const quint16 port = probe.serverPort();
        probe.close();
        const CliRun r =
            cli({ QStringLiteral("read"), QStringLiteral("vabus://127.0.0.1:%1").arg(port),
                  QStringLiteral("372:2") });
        QCOMPARE(r.exitCode, 3);
        QVERIFY2(r.err.contains(QString::number(port)), qPrintable(r.err));
    }

    void peerThatIsNotOurs()
    {
        ExamplePeer peer({
            { "00 04 00 02 74 01", bytes("0006000274016E05") },
            { "00 04 00 01 E1 01", bytes("00080001E101E8030000") },
            { "00 04 00 00 0C 00", bytes("000D00000C00352E332E322053544F") },
            { "80 06 00 04 78 01 0F 00", bytes("8006000478010F00") },
            { "80 06 00 04 78 01 00 00", bytes("C006000478010100") },
        });
        QVERIFY(peer.listen());
        const QString uri = QStringLiteral("vabus://127.0.0.1:%1").arg(peer.port());
        const auto run = [](const QStringList &args) {
            return db::test::runServing(QStringLiteral(DRIVEBENCH_CLI), args, kRunMs);
        };
        CliRun r = run({ QStringLiteral("read"), uri, QStringLiteral("372:2") });
        QCOMPARE(r.out, QStringLiteral("1390 rpm\n"));
        r = run({ QStringLiteral("read"), uri, QStringLiteral("481:1") });
        QCOMPARE(r.out, QStringLiteral("10.00 Hz\n"));
        r = run({ QStringLiteral("read"), uri, QStringLiteral("12") });
        QCOMPARE(r.out, QStringLiteral("5.3.2 STO\n"));
        r = run({ QStringLiteral("write"), uri, QStringLiteral("376:4"), QStringLiteral("1.5") });
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        r = run({ QStringLiteral("write"), uri, QStringLiteral("376:4"), QStringLiteral("0") });
        QCOMPARE(r.exitCode, 6);
        QVERIFY(r.err.contains(QLatin1String("invalid parameter value")));
    }

private:
    static QString startSim(QProcess &process, const QStringList &extra)
    {
        const QString banner = db::test::startAndReadBanner(
            process, QStringLiteral(DRIVEBENCH_SIM),
            QStringList { QStringLiteral("acu"), QStringLiteral("--vabus-port"),
                          QStringLiteral("0") }
                + extra,
            1);
        const quint16 port = db::test::listeningPort(banner, QStringLiteral("VABus/TCP"));
        return port ? QStringLiteral("vabus://127.0.0.1:%1").arg(port) : QString();
    }

    QProcess m_sim;
    QProcess m_silent;
    QProcess m_garbage;
    QString m_uri;
};

QTEST_GUILESS_MAIN(TstCliVabus)
#include "tst_cli_vabus.moc"
