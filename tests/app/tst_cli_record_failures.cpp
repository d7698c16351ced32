// drivebench-cli record under failure: a peer that floods SLCAN frames, silent and garbage peers
// (RefGo and SLCAN), reads of one object failing while another records, and SIGINT / SIGTERM
// during a recording against drivebench-sim. A recording without samples is a failure that
// names why and writes nothing; failed reads give the exit code `read` gives for the same peer;
// an interrupted recording keeps what was recorded.
#include "clirun.h"
#include "peers.h"

#include "scope/csv.h"

#include <QDir>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <signal.h>

using namespace db;
using db::test::RawPeer;

class TestCliRecordFailures : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void cleanupTestCase();

    void floodingPeerIsNoRecording_data();
    void floodingPeerIsNoRecording();
    void failingReadsNameTheirCause_data();
    void failingReadsNameTheirCause();
    void partlyFailingReadsKeepTheData();
    void interruptionWritesWhatWasRecorded_data();
    void interruptionWritesWhatWasRecorded();

private:
    using Run = db::test::CliRun;
    // Runs drivebench-cli while this test's peers keep serving.
    static Run cli(const QStringList &args)
    {
        return db::test::runServing(QStringLiteral(DRIVEBENCH_CLI), args, 30000);
    }
    static QString peerUri(bool slcan, quint16 port)
    {
        return slcan ? QStringLiteral("canopen+slcan://127.0.0.1:%1?node=1").arg(port)
                     : QStringLiteral("refgo://127.0.0.1:%1").arg(port);
    }
    QString simUri() const { return QStringLiteral("refgo://127.0.0.1:%1").arg(m_port); }
    QString file(const QString &name) const { return m_dir.filePath(name); }

    QProcess m_sim;
    quint16 m_port = 0;
    QTemporaryDir m_dir;
};

void TestCliRecordFailures::initTestCase()
{
    QVERIFY(m_dir.isValid());
    const QString banner = db::test::startAndReadBanner(
        m_sim, QStringLiteral(DRIVEBENCH_SIM),
        { QStringLiteral("movingcap"), QStringLiteral("--refgo-port"), QStringLiteral("0") }, 1);
    m_port = db::test::listeningPort(banner);
    QVERIFY2(m_port != 0, qPrintable(banner));
}

void TestCliRecordFailures::cleanupTestCase()
{
    m_sim.terminate();
    QVERIFY(m_sim.waitForFinished(5000));
}

void TestCliRecordFailures::floodingPeerIsNoRecording_data()
{
    QTest::addColumn<QString>("timeoutMs");
    QTest::addColumn<QString>("duration");
    // The one read is still unanswered when the recording ends.
    QTest::newRow("read unanswered") << QStringLiteral("1000") << QStringLiteral("0.5");
    // Every read times out within the recording.
    QTest::newRow("reads time out") << QStringLiteral("150") << QStringLiteral("1");
}

void TestCliRecordFailures::floodingPeerIsNoRecording()
{
    QFETCH(QString, timeoutMs);
    QFETCH(QString, duration);
    RawPeer flood(RawPeer::Behaviour::Flood);
    QVERIFY(flood.isListening());
    const QString uri = peerUri(true, flood.port());
    const Run read = cli({ QStringLiteral("read"), QStringLiteral("--timeout"), timeoutMs, uri,
                           QStringLiteral("6064:0") });
    QVERIFY2(read.exitCode > 0, qPrintable(read.err));

    const QString csvFile = file(QStringLiteral("flood.csv"));
    const Run r = cli({ QStringLiteral("record"), QStringLiteral("--timeout"), timeoutMs, uri,
                        QStringLiteral("--obj"), QStringLiteral("6064:0"),
                        QStringLiteral("--duration"), duration, QStringLiteral("-o"), csvFile });
    QVERIFY(flood.framesSent() > 0);
    QCOMPARE(r.exitCode, read.exitCode);
    QVERIFY2(r.err.startsWith(QLatin1String("drivebench-cli: no sample recorded")),
             qPrintable(r.err));
    QVERIFY2(r.err.contains(QLatin1String("6064:0")), qPrintable(r.err));
    QVERIFY2(r.err.contains(QLatin1String("nothing written")), qPrintable(r.err));
    QCOMPARE(r.err.count(QLatin1Char('\n')), 1);
    QVERIFY2(!r.out.contains(QLatin1String("recorded")), qPrintable(r.out));
    QVERIFY(!QFile::exists(csvFile));
}

void TestCliRecordFailures::failingReadsNameTheirCause_data()
{
    QTest::addColumn<bool>("slcan");
    QTest::addColumn<int>("behaviour");
    QTest::addColumn<QByteArray>("answer");
    QTest::addColumn<QString>("cause");
    const auto silent = int(RawPeer::Behaviour::Silent);
    const auto garbage = int(RawPeer::Behaviour::Garbage);
    QTest::newRow("refgo silent") << false << silent << QByteArray() << "timeout";
    QTest::newRow("refgo garbage")
        << false << garbage << QByteArray("HELLO WORLD\r\n12\r\n>") << "malformed";
    QTest::newRow("slcan silent") << true << silent << QByteArray() << "timeout";
    static constexpr char slcanGarbage[] = "\x07zz\rt5818\xff\xfe\rT12\r\x00\x01garbage\r";
    QTest::newRow("slcan garbage")
        << true << garbage << QByteArray(slcanGarbage, sizeof slcanGarbage - 1) << "timeout";
}

void TestCliRecordFailures::failingReadsNameTheirCause()
{
    QFETCH(bool, slcan);
    QFETCH(int, behaviour);
    QFETCH(QByteArray, answer);
    QFETCH(QString, cause);
    RawPeer peer(RawPeer::Behaviour(behaviour), answer);
    QVERIFY(peer.isListening());
    const QString uri = peerUri(slcan, peer.port());
    const Run read = cli({ QStringLiteral("read"), QStringLiteral("--timeout"),
                           QStringLiteral("200"), uri, QStringLiteral("6064:0") });
    QVERIFY2(read.exitCode > 1, qPrintable(read.err));
    QVERIFY2(read.err.contains(cause, Qt::CaseInsensitive), qPrintable(read.err));

    const QString csvFile = file(QStringLiteral("failing.csv"));
    const Run r =
        cli({ QStringLiteral("record"), QStringLiteral("--timeout"), QStringLiteral("200"), uri,
              QStringLiteral("--obj"), QStringLiteral("6064:0"), QStringLiteral("--rate-ms"),
              QStringLiteral("10"), QStringLiteral("--duration"), QStringLiteral("1"),
              QStringLiteral("-o"), csvFile });
    QCOMPARE(r.exitCode, read.exitCode);
    QVERIFY2(r.err.contains(cause, Qt::CaseInsensitive), qPrintable(r.err));
    QVERIFY2(r.err.contains(QLatin1String("reads failed")), qPrintable(r.err));
    QVERIFY2(!r.err.contains(QLatin1String("slower")), qPrintable(r.err));
    QVERIFY2(r.err.contains(QLatin1String("nothing written")), qPrintable(r.err));
    QCOMPARE(r.err.count(QLatin1Char('\n')), 1);
    QVERIFY(!QFile::exists(csvFile));
}

void TestCliRecordFailures::partlyFailingReadsKeepTheData()
{
    // 2FFF:0 does not exist on the drive: every read of it is refused, 6064:0 records.
    const Run read = cli({ QStringLiteral("read"), simUri(), QStringLiteral("2FFF:0") });
    QVERIFY2(read.exitCode > 1, qPrintable(read.err));
    const QString csvFile = file(QStringLiteral("partly.csv"));
    const Run r =
        cli({ QStringLiteral("record"), simUri(), QStringLiteral("--obj"),
              QStringLiteral("6064:0,2FFF:0"), QStringLiteral("--rate-ms"), QStringLiteral("20"),
              QStringLiteral("--duration"), QStringLiteral("0.5"), QStringLiteral("-o"), csvFile });
    QCOMPARE(r.exitCode, read.exitCode);
    QVERIFY2(r.out.startsWith(QLatin1String("recorded ")), qPrintable(r.out));
    QVERIFY2(r.err.contains(QLatin1String("reads failed")), qPrintable(r.err));
    QVERIFY2(r.err.contains(QLatin1String("2FFF:0")), qPrintable(r.err));
    QVERIFY2(!r.err.contains(QLatin1String("slower")), qPrintable(r.err));
    QVERIFY2(r.err.contains(csvFile), qPrintable(r.err));
    const auto rec = scope::csv::load(csvFile);
    QVERIFY2(rec.ok(), qPrintable(rec.error().toString()));
    QCOMPARE(rec->channels.size(), 2);
    QVERIFY(rec->channels[0].buffer.size() >= 5);
    QCOMPARE(rec->channels[1].buffer.size(), 0);
    QVERIFY(rec->channels[1].buffer.lostAtSource() >= 5);
}

void TestCliRecordFailures::interruptionWritesWhatWasRecorded_data()
{
    QTest::addColumn<int>("signo");
    QTest::addColumn<QString>("name");
    QTest::newRow("SIGINT") << int(SIGINT) << QStringLiteral("SIGINT");
    QTest::newRow("SIGTERM") << int(SIGTERM) << QStringLiteral("SIGTERM");
}

void TestCliRecordFailures::interruptionWritesWhatWasRecorded()
{
    QFETCH(int, signo);
    QFETCH(QString, name);
    QDir dir(m_dir.filePath(name));
    QVERIFY(dir.mkpath(QStringLiteral(".")));
    const QString csvFile = dir.filePath(QStringLiteral("interrupted.csv"));
    QProcess record;
    // As a shell starts a foreground job: SIGINT as by default, even when this test runs where it
    // is ignored (a background job).
    record.setChildProcessModifier([] { ::signal(SIGINT, SIG_DFL); });
    record.start(QStringLiteral(DRIVEBENCH_CLI),
                 { QStringLiteral("record"), simUri(), QStringLiteral("--obj"),
                   QStringLiteral("6064:0,6041:0"), QStringLiteral("--rate-ms"),
                   QStringLiteral("10"), QStringLiteral("--duration"), QStringLiteral("60"),
                   QStringLiteral("-o"), csvFile });
    // The line that says samples arrive, then a while more of them.
    QString err;
    QTRY_VERIFY_WITH_TIMEOUT((err += QString::fromUtf8(record.readAllStandardError()),
                              err.contains(QLatin1String("recording: samples arriving"))),
                             10000);
    QElapsedTimer flowing;
    flowing.start();
    QTRY_VERIFY(flowing.elapsed() >= 300);
    if (signo == SIGTERM)
        record.terminate();
    else
        QCOMPARE(::kill(pid_t(record.processId()), signo), 0);
    QVERIFY(record.waitForFinished(10000));
    const QString out = QString::fromUtf8(record.readAllStandardOutput());
    err += QString::fromUtf8(record.readAllStandardError());
    QCOMPARE(record.exitStatus(), QProcess::NormalExit);
    QCOMPARE(record.exitCode(), 128 + signo);
    QVERIFY2(out.contains(QLatin1String("recorded ")), qPrintable(out));
    QVERIFY2(out.contains(csvFile), qPrintable(out));
    QVERIFY2(err.contains(QLatin1String("interrupted by ") + name), qPrintable(err));
    QVERIFY2(err.contains(csvFile + QLatin1String(" written")), qPrintable(err));
    const auto rec = scope::csv::load(csvFile);
    QVERIFY2(rec.ok(), qPrintable(rec.error().toString()));
    QCOMPARE(rec->channels.size(), 2);
    QVERIFY(rec->channels[0].buffer.size() >= 10);
    // Written atomically: the file and nothing beside it.
    QCOMPARE(dir.entryList(QDir::Files), QStringList { QStringLiteral("interrupted.csv") });
}

QTEST_GUILESS_MAIN(TestCliRecordFailures)
#include "tst_cli_record_failures.moc"
