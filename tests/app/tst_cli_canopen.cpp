// drivebench-cli over CANopen end to end, against `drivebench-sim canopen`
// (nodes 1, 2, 5 answering, node 9 silent) over SLCAN-over-TCP on an OS-chosen loopback port and
// over Qt's virtualcan (LOCK virtualcan): 1008h, a 1 kB string and a 100 kB domain written and
// read back by segmented and by block SDO, scan, nmt, lss, pdo, dcf, and the failures (abort,
// timeout, garbage, refused, bad arguments) with clear errors and non-zero exits, never a hang.
#include "clirun.h"
#include "peers.h"

#include <QElapsedTimer>
#include <QProcess>
#include <QRandomGenerator>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

class TestCliCanopen : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void cleanupTestCase();

    void readsTheDeviceName_data();
    void readsTheDeviceName();
    void writesAndReadsBackStringAndDomain_data();
    void writesAndReadsBackStringAndDomain();
    void scanListsTheSimulatedNodes();
    void nmtStartsANode();
    void lssSelectsAndInquires();
    void pdoPrintsTheConfiguration();
    void dcfExportsCurrentValues();
    void typeGivesTheSizeOfAnUnknownObject();
    void abortExitsWithSix();
    void silentNodeTimesOutWithFour();
    void garbageOnTheLinkFailsQuickly();
    void refusedConnectionExitsWithThree();
    void usageErrorsExitWithTwo_data();
    void usageErrorsExitWithTwo();
    void simRefusesBadNodeLists();

private:
    using Run = db::test::CliRun;
    Run cli(const QStringList &args, int timeoutMs = 30000);
    QString slcan(const QString &query = {}) const
    {
        return QStringLiteral("canopen+slcan://127.0.0.1:%1%2").arg(m_port).arg(query);
    }
    QString uriFor(const QString &transport, const QString &query) const
    {
        return transport == u"slcan" ? slcan(query)
                                     : QStringLiteral("canopen+virtualcan://can0") + query;
    }
    QString eds() const
    {
        return QStringLiteral(DRIVEBENCH_SOURCE_DIR "/resources/devices/drivebench_testnode.json");
    }

    QProcess m_sim;
    quint16 m_port = 0;
    QTemporaryDir m_dir;
};

TestCliCanopen::Run TestCliCanopen::cli(const QStringList &args, int timeoutMs)
{
    return db::test::runProgram(QStringLiteral(DRIVEBENCH_CLI), args, timeoutMs);
}

void TestCliCanopen::initTestCase()
{
    QVERIFY(m_dir.isValid());
    const QString banner = db::test::startAndReadBanner(
        m_sim, QStringLiteral(DRIVEBENCH_SIM),
        { QStringLiteral("canopen"), QStringLiteral("--slcan-port"), QStringLiteral("0"),
          QStringLiteral("--virtualcan"), QStringLiteral("can0"), QStringLiteral("--nodes"),
          QStringLiteral("1,2,5,9"), QStringLiteral("--no-reply-node"), QStringLiteral("9") },
        2);
    const auto m = QRegularExpression(QStringLiteral("SLCAN listening on 127\\.0\\.0\\.1:(\\d+)"))
                       .match(banner);
    QVERIFY2(m.hasMatch(), qPrintable(banner));
    QVERIFY2(banner.contains(QLatin1String("virtualcan listening on can0")), qPrintable(banner));
    m_port = quint16(m.captured(1).toUInt());
}

void TestCliCanopen::cleanupTestCase()
{
    m_sim.terminate();
    QVERIFY(m_sim.waitForFinished(5000));
    QCOMPARE(m_sim.exitCode(), 0);
}

void TestCliCanopen::readsTheDeviceName_data()
{
    QTest::addColumn<QString>("transport");
    QTest::newRow("slcan") << QStringLiteral("slcan");
    QTest::newRow("virtualcan") << QStringLiteral("virtualcan");
}

void TestCliCanopen::readsTheDeviceName()
{
    QFETCH(QString, transport);
    const Run r = cli({ QStringLiteral("read"), uriFor(transport, QStringLiteral("?node=1")),
                        QStringLiteral("1008:0") });
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QCOMPARE(r.out.trimmed(), QStringLiteral("drivebench test node"));
}

void TestCliCanopen::writesAndReadsBackStringAndDomain_data()
{
    QTest::addColumn<QString>("transport");
    QTest::addColumn<QString>("mode");
    for (const char *t : { "slcan", "virtualcan" }) {
        for (const char *m : { "segmented", "block" })
            QTest::addRow("%s-%s", t, m) << QString::fromLatin1(t) << QString::fromLatin1(m);
    }
}

void TestCliCanopen::writesAndReadsBackStringAndDomain()
{
    QFETCH(QString, transport);
    QFETCH(QString, mode);
    const QString uri = uriFor(transport, QStringLiteral("?node=2&eds=") + eds());
    QByteArray text;
    for (int i = 0; text.size() < 1024; ++i)
        text += QByteArray::number(i) + ' ';
    text.truncate(1024);
    QByteArray domain(100 * 1024, '\0');
    for (char &b : domain)
        b = char(QRandomGenerator::global()->bounded(256));
    const struct
    {
        const char *address;
        QByteArray data;
    } cases[] = { { "2000:0", text }, { "2001:0", domain } };
    for (const auto &c : cases) {
        const QString in = m_dir.filePath(QStringLiteral("in-%1").arg(mode));
        const QString out = m_dir.filePath(QStringLiteral("out-%1").arg(mode));
        QFile f(in);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(c.data);
        f.close();
        Run r = cli({ QStringLiteral("write"), uri, QString::fromLatin1(c.address),
                      QStringLiteral("--file"), in, QStringLiteral("--sdo"), mode });
        QVERIFY2(r.exitCode == 0, qPrintable(c.address + QStringLiteral(": ") + r.err));
        r = cli({ QStringLiteral("read"), uri, QString::fromLatin1(c.address),
                  QStringLiteral("--file"), out, QStringLiteral("--sdo"), mode });
        QVERIFY2(r.exitCode == 0, qPrintable(c.address + QStringLiteral(": ") + r.err));
        QFile back(out);
        QVERIFY(back.open(QIODevice::ReadOnly));
        QCOMPARE(back.readAll(), c.data);
    }
    const Run r = cli({ QStringLiteral("read"), uri, QStringLiteral("2000:0") });
    QCOMPARE(r.out.trimmed(), QString::fromLatin1(text).trimmed());
}

void TestCliCanopen::scanListsTheSimulatedNodes()
{
    const Run r = cli({ QStringLiteral("scan"), slcan() });
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    const QStringList lines = r.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    for (const char *id : { "1", "2", "5" }) {
        const auto line = lines.filter(QRegularExpression(QStringLiteral("^\\s*%1\\s").arg(id)));
        QVERIFY2(line.size() == 1, qPrintable(r.out));
        QVERIFY2(line.first().contains(QLatin1String("vendor 0x00000DB0")), qPrintable(r.out));
        QVERIFY2(line.first().contains(QLatin1String("\"drivebench test node\"")),
                 qPrintable(r.out));
    }
    QVERIFY(!r.out.contains(QLatin1String("vendor 0x00000DB0 product 0x00000001 rev 0x00010000 "
                                          "serial 0x00000009")));
}

void TestCliCanopen::nmtStartsANode()
{
    Run r =
        cli({ QStringLiteral("nmt"), slcan(QStringLiteral("?node=5")), QStringLiteral("start") });
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QCOMPARE(r.out.trimmed(), QStringLiteral("node 5: operational"));
    r = cli({ QStringLiteral("nmt"), slcan(), QStringLiteral("preop"), QStringLiteral("--all") });
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    r = cli({ QStringLiteral("nmt"), slcan(), QStringLiteral("start") });
    QCOMPARE(r.exitCode, 2); // no node and no --all
}

void TestCliCanopen::lssSelectsAndInquires()
{
    Run r = cli({ QStringLiteral("lss"), slcan(), QStringLiteral("switch-selective"),
                  QStringLiteral("0xDB0,1,0x10000,2") });
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    r = cli({ QStringLiteral("lss"), slcan(), QStringLiteral("inquire") });
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QVERIFY2(r.out.contains(QLatin1String("serial 0x00000002")), qPrintable(r.out));
    QVERIFY2(r.out.contains(QLatin1String("node-id 2")), qPrintable(r.out));
    r = cli({ QStringLiteral("lss"), slcan(), QStringLiteral("switch-global"),
              QStringLiteral("waiting") });
    QCOMPARE(r.exitCode, 0);
    r = cli({ QStringLiteral("lss"), QStringLiteral("--timeout"), QStringLiteral("200"), slcan(),
              QStringLiteral("inquire") });
    QCOMPARE(r.exitCode, 4); // nobody in configuration mode any more
    QVERIFY2(r.err.contains(QLatin1String("configuration mode")), qPrintable(r.err));
}

void TestCliCanopen::pdoPrintsTheConfiguration()
{
    const Run r = cli({ QStringLiteral("pdo"), slcan(QStringLiteral("?node=1&eds=") + eds()) });
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QVERIFY2(r.out.contains(QLatin1String("TPDO1 cob 0x181 enabled type 0xff")), qPrintable(r.out));
    QVERIFY2(r.out.contains(QLatin1String("6064:0 32 bits  Position actual value")),
             qPrintable(r.out));
    QVERIFY2(r.out.contains(QLatin1String("RPDO2 cob 0x301")), qPrintable(r.out));
}

void TestCliCanopen::dcfExportsCurrentValues()
{
    const QString file = m_dir.filePath(QStringLiteral("node1.dcf"));
    Run r = cli({ QStringLiteral("write"), slcan(QStringLiteral("?node=1&eds=") + eds()),
                  QStringLiteral("2102:0"), QStringLiteral("0xCAFE") });
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    r = cli({ QStringLiteral("dcf"), slcan(QStringLiteral("?node=1&eds=") + eds()),
              QStringLiteral("-o"), file });
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QFile f(file);
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QString dcf = QString::fromUtf8(f.readAll());
    QVERIFY(dcf.contains(QLatin1String("[DeviceComissioning]")));
    QVERIFY2(dcf.contains(
                 QRegularExpression(QStringLiteral("\\[2102\\][^\\[]*ParameterValue=0x0000CAFE"),
                                    QRegularExpression::CaseInsensitiveOption)),
             qPrintable(dcf.left(3000)));
    r = cli(
        { QStringLiteral("dcf"), slcan(QStringLiteral("?node=1")), QStringLiteral("-o"), file });
    QCOMPARE(r.exitCode, 2); // no description: nothing to export
}

void TestCliCanopen::typeGivesTheSizeOfAnUnknownObject()
{
    // Without ?eds= the client knows nothing of 1800h.5 (UNSIGNED16 on the node): --type u16
    // makes it a 2-byte download, which the node accepts; without it the size is a guess.
    const QString bare = slcan(QStringLiteral("?node=2"));
    const Run w = cli({ QStringLiteral("write"), bare, QStringLiteral("1800:5"),
                        QStringLiteral("37"), QStringLiteral("--type"), QStringLiteral("u16") });
    QVERIFY2(w.exitCode == 0, qPrintable(w.err));
    const Run r = cli({ QStringLiteral("read"), slcan(QStringLiteral("?node=2&eds=") + eds()),
                        QStringLiteral("1800:5") });
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QCOMPARE(r.out.trimmed(), QStringLiteral("37"));
    const Run back = cli({ QStringLiteral("write"), bare, QStringLiteral("1800:5"),
                           QStringLiteral("0"), QStringLiteral("--type"), QStringLiteral("u16") });
    QVERIFY2(back.exitCode == 0, qPrintable(back.err));
}

void TestCliCanopen::abortExitsWithSix()
{
    const Run r =
        cli({ QStringLiteral("read"), slcan(QStringLiteral("?node=1")), QStringLiteral("3000:0") });
    QCOMPARE(r.exitCode, 6);
    QVERIFY2(r.err.contains(QLatin1String("06020000")) || r.err.contains(QLatin1String("exist")),
             qPrintable(r.err));
    QCOMPARE(r.err.count(QLatin1Char('\n')), 1);
}

void TestCliCanopen::silentNodeTimesOutWithFour()
{
    for (const QString &transport : { QStringLiteral("slcan"), QStringLiteral("virtualcan") }) {
        const Run r =
            cli({ QStringLiteral("read"), QStringLiteral("--timeout"), QStringLiteral("300"),
                  uriFor(transport, QStringLiteral("?node=9")), QStringLiteral("1008:0") });
        QCOMPARE(r.exitCode, 4);
        QVERIFY2(r.err.contains(QLatin1String("timeout")), qPrintable(r.err));
    }
}

void TestCliCanopen::garbageOnTheLinkFailsQuickly()
{
    // Bytes up to the NUL: a BEL, an unknown command, a short frame and a truncated one.
    db::test::RawPeer server(db::test::RawPeer::Behaviour::Garbage,
                             "\x07zz\rt5818\xff\xfe\rT12\r\x00\x01garbage\r");
    QVERIFY(server.isListening());
    QProcess p;
    p.start(QStringLiteral(DRIVEBENCH_CLI),
            { QStringLiteral("read"), QStringLiteral("--timeout"), QStringLiteral("300"),
              QStringLiteral("canopen+slcan://127.0.0.1:%1?node=1").arg(server.serverPort()),
              QStringLiteral("1008:0") });
    QTRY_VERIFY_WITH_TIMEOUT(p.state() == QProcess::NotRunning, 15000);
    QVERIFY(p.exitCode() != 0);
    const QString err = QString::fromUtf8(p.readAllStandardError());
    QVERIFY2(err.startsWith(QLatin1String("drivebench-cli: ")), qPrintable(err));
}

void TestCliCanopen::refusedConnectionExitsWithThree()
{
    const Run r = cli({ QStringLiteral("scan"), QStringLiteral("canopen+slcan://127.0.0.1:1") });
    QCOMPARE(r.exitCode, 3);
    QVERIFY2(!r.err.isEmpty(), "no error line");
}

void TestCliCanopen::usageErrorsExitWithTwo_data()
{
    QTest::addColumn<QStringList>("args");
    const QString node1 = QStringLiteral("canopen+slcan://127.0.0.1:1?node=1");
    QTest::newRow("bad sdo mode") << QStringList { "read", "--sdo", "fast", node1, "1008:0" };
    QTest::newRow("nmt verb") << QStringList { "nmt", node1, "jump" };
    QTest::newRow("lss verb") << QStringList { "lss", node1, "dance" };
    QTest::newRow("lss bitrate") << QStringList { "lss", node1, "set-bitrate", "333k" };
    QTest::newRow("dcf no -o") << QStringList { "dcf", node1 };
    QTest::newRow("write both") << QStringList { "write", node1, "2000:0", "x", "--file", "/x" };
    QTest::newRow("write neither") << QStringList { "write", node1, "2000:0" };
}

void TestCliCanopen::usageErrorsExitWithTwo()
{
    QFETCH(QStringList, args);
    const Run r = cli(args);
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.err.startsWith(QLatin1String("drivebench-cli: ")), qPrintable(r.err));
}

void TestCliCanopen::simRefusesBadNodeLists()
{
    for (const char *nodes : { "0", "1,x", "128" }) {
        QProcess p;
        p.start(QStringLiteral(DRIVEBENCH_SIM),
                { QStringLiteral("canopen"), QStringLiteral("--slcan-port"), QStringLiteral("0"),
                  QStringLiteral("--nodes"), QString::fromLatin1(nodes) });
        QVERIFY(p.waitForFinished(5000));
        QCOMPARE(p.exitCode(), 2);
    }
}

QTEST_GUILESS_MAIN(TestCliCanopen)
#include "tst_cli_canopen.moc"
