// drivebench-cli backup/dump/restore when reads fail: hostile peers served by the test itself
// (a RefGo drive that answers one behind, with ERROR, a NUL byte, a value too big, another
// object; a CANopen node behind SLCAN that aborts every SDO) and drivebench-sim for the good
// side. A backup must never replace a file with less than a complete set.
#include "clirun.h"
#include "peers.h"

#include <QFile>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

using db::test::HostileRefgoPeer;
using Fault = db::test::HostileRefgoPeer::Fault;

class TestCliParamsFailures : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void cleanupTestCase();

    void backupKeepsTheGoodFileWhenEveryReadFails_data();
    void backupKeepsTheGoodFileWhenEveryReadFails();
    void backupAbortedByEverySdoKeepsTheGoodFile();
    void partialBackupListsEveryFailedRow();
    void unreadIdentityIsUnknownAndRestoreRefusesIt();
    void anotherUnitIsRefusedUnlessIgnored();
    void dumpWithFailedRowsPrintsTheRestAndFails();
    void dumpWithNothingReadFails();
    void restoreRefusesAnEmptySet();

private:
    using Run = db::test::CliRun;
    // The tool, with the test's event loop running (the hostile peers live in this process).
    Run cli(const QStringList &args)
    {
        return db::test::runServing(QStringLiteral(DRIVEBENCH_CLI), args, 30000);
    }
    QString file(const QString &name) const { return m_dir.filePath(name); }
    static QByteArray contents(const QString &path)
    {
        QFile f(path);
        return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
    }
    // A fresh good backup of the simulator at path; its bytes.
    QByteArray goodBackup(const QString &path);

    QTemporaryDir m_dir;
    QProcess m_sim;
    QString m_refgo;
};

void TestCliParamsFailures::initTestCase()
{
    QVERIFY(m_dir.isValid());
    const QString banner = db::test::startAndReadBanner(
        m_sim, QStringLiteral(DRIVEBENCH_SIM),
        { QStringLiteral("movingcap"), QStringLiteral("--refgo-port"), QStringLiteral("0") }, 1);
    const quint16 port = db::test::listeningPort(banner, QStringLiteral("RefGo"));
    QVERIFY2(port != 0, qPrintable(banner));
    m_refgo = QStringLiteral("refgo://127.0.0.1:%1").arg(port);
}

void TestCliParamsFailures::cleanupTestCase()
{
    if (m_sim.state() != QProcess::NotRunning) {
        m_sim.terminate();
        if (!m_sim.waitForFinished(3000))
            m_sim.kill();
    }
}

QByteArray TestCliParamsFailures::goodBackup(const QString &path)
{
    const Run r = cli({ QStringLiteral("backup"), m_refgo, QStringLiteral("-o"), path });
    if (r.exitCode != 0)
        qWarning("good backup failed: %s", qPrintable(r.err));
    QFile::remove(path + QStringLiteral(".partial"));
    return contents(path);
}

void TestCliParamsFailures::backupKeepsTheGoodFileWhenEveryReadFails_data()
{
    QTest::addColumn<int>("fault");
    QTest::addColumn<int>("exitCode");
    QTest::addColumn<QString>("cause");
    QTest::addColumn<int>("failed");
    // 201 objects, 1018h.4, .3 and .2; 1018h.1 too where its answer is bad (not the first one
    // behind).
    QTest::newRow("answer to the previous request")
        << int(Fault::PreviousAnswer) << 5 << QStringLiteral("does not belong to") << 204;
    QTest::newRow("ERROR to everything")
        << int(Fault::Error) << 6 << QStringLiteral("ERROR") << 205;
    QTest::newRow("NUL byte in the value")
        << int(Fault::NulByte) << 5 << QStringLiteral("\\x00") << 205;
    QTest::newRow("value beyond 64 bits")
        << int(Fault::HugeValue) << 5 << QStringLiteral("too large") << 205;
    QTest::newRow("value outside the type") << int(Fault::OutOfRange) << 5 << QString() << 205;
    QTest::newRow("answer for another object") << int(Fault::OtherObject) << 5 << QString() << 205;
}

void TestCliParamsFailures::backupKeepsTheGoodFileWhenEveryReadFails()
{
    QFETCH(int, fault);
    QFETCH(int, exitCode);
    QFETCH(QString, cause);
    QFETCH(int, failed);
    const QString path = file(QStringLiteral("every-%1.dbp").arg(fault));
    const QByteArray good = goodBackup(path);
    QVERIFY(good.contains("\nentries 201\n"));

    HostileRefgoPeer peer { Fault(fault) };
    QVERIFY(peer.isListening());
    const Run r = cli({ QStringLiteral("backup"), peer.uri(), QStringLiteral("-o"), path });
    QVERIFY2(r.exitCode == exitCode,
             qPrintable(QStringLiteral("exit %1: %2").arg(r.exitCode).arg(r.out + r.err)));
    QVERIFY2(!r.out.contains(QLatin1String("backed up")), qPrintable(r.out));
    QCOMPARE(contents(path), good);
    const QString last = r.err.trimmed().section(QLatin1Char('\n'), -1);
    QVERIFY2(last.contains(QStringLiteral("%1 not written").arg(path)), qPrintable(last));
    QVERIFY2(last.contains(QLatin1String("no object could be read")), qPrintable(last));

    // The partial file lists every object with its cause and still loads.
    const QByteArray partial = contents(path + QStringLiteral(".partial"));
    QVERIFY(partial.contains("\nentries 0\n"));
    QCOMPARE(int(partial.count("\n# failed ")), failed);
    QVERIFY(partial.contains("\n# failed 6083:0 Profile acceleration: "));
    QVERIFY2(cause.isEmpty() || partial.contains(cause.toUtf8()), partial.left(1500).constData());
    QVERIFY(!partial.contains('\0'));
    QVERIFY(partial.contains("\nproduct unknown "));
    QVERIFY(!partial.contains("product 0x00000000"));
    const QString partialPath = path + QStringLiteral(".partial");
    QCOMPARE(cli({ QStringLiteral("diff"), partialPath, partialPath }).exitCode, 0);
}

void TestCliParamsFailures::backupAbortedByEverySdoKeepsTheGoodFile()
{
    const QString path = file(QStringLiteral("aborted.dbp"));
    const QByteArray good = goodBackup(path);
    QVERIFY(!good.isEmpty());
    db::test::AbortingSlcanPeer peer(50);
    QVERIFY(peer.isListening());
    const Run r = cli({ QStringLiteral("backup"), peer.uri(), QStringLiteral("-o"), path });
    QVERIFY2(r.exitCode == 6, qPrintable(QStringLiteral("exit %1: %2").arg(r.exitCode).arg(r.err)));
    QVERIFY(peer.aborts() > 200);
    QCOMPARE(contents(path), good);
    const QByteArray partial = contents(path + QStringLiteral(".partial"));
    QCOMPARE(int(partial.count("\n# failed ")), 205); // 201 objects, 1018h.1-.4
    QVERIFY2(partial.contains("06020000"), partial.left(900).constData());
    QVERIFY(partial.contains("\nvendor unknown "));
}

void TestCliParamsFailures::partialBackupListsEveryFailedRow()
{
    const QString path = file(QStringLiteral("partial.dbp"));
    const QByteArray good = goodBackup(path);
    HostileRefgoPeer peer(Fault::Error, { QStringLiteral("6084,0"), QStringLiteral("3300,4") });
    const Run r = cli({ QStringLiteral("backup"), peer.uri(), QStringLiteral("-o"), path });
    QCOMPARE(r.exitCode, 6);
    QCOMPARE(contents(path), good);
    QVERIFY2(r.err.contains(QLatin1String("2 of 205 objects could not be read")),
             qPrintable(r.err));
    QVERIFY(r.err.contains(QLatin1String("warning: 6084:0 Profile deceleration: device error: ")));
    const QByteArray partial = contents(path + QStringLiteral(".partial"));
    QVERIFY(partial.contains("\nentries 199\n"));
    QCOMPARE(int(partial.count("\n# failed ")), 2);
    QVERIFY(partial.contains("\n# failed 3300:4 "));
    QVERIFY(partial.contains("\n# failed 6084:0 Profile deceleration: device error: "));
    QVERIFY(!partial.contains("\n6084:0 "));
    QVERIFY(partial.contains("\n6083:0 \"Profile acceleration\" UNSIGNED32 0 "));
}

void TestCliParamsFailures::unreadIdentityIsUnknownAndRestoreRefusesIt()
{
    const QString path = file(QStringLiteral("identity.dbp"));
    HostileRefgoPeer peer(Fault::Error, { QStringLiteral("1018,2") });
    const Run r = cli({ QStringLiteral("backup"), peer.uri(), QStringLiteral("-o"), path });
    QCOMPARE(r.exitCode, 6);
    QVERIFY(!QFile::exists(path));
    const QString partial = path + QStringLiteral(".partial");
    const QByteArray text = contents(partial);
    QVERIFY(text.contains("\nentries 201\n"));
    QVERIFY(text.contains("\nproduct unknown \"MovingCap ETH\"\n"));
    QVERIFY(text.contains("\n# failed 1018:2 "));

    const Run refused = cli({ QStringLiteral("restore"), m_refgo, partial, QStringLiteral("--only"),
                              QStringLiteral("3300:4") });
    QCOMPARE(refused.exitCode, 2);
    QVERIFY2(refused.err.contains(QLatin1String("does not record the product code")),
             qPrintable(refused.err));
    QVERIFY(refused.out.isEmpty());
    // 3300:4 holds 0 in the simulator and in the set: the override writes the same value.
    const Run forced = cli({ QStringLiteral("restore"), m_refgo, partial, QStringLiteral("--only"),
                             QStringLiteral("3300:4"), QStringLiteral("--ignore-identity") });
    QVERIFY2(forced.exitCode == 0, qPrintable(forced.out + forced.err));
    QVERIFY(forced.out.startsWith(QLatin1String("restore: 1 verified")));
    QVERIFY(forced.err.contains(QLatin1String("--ignore-identity")));
}

void TestCliParamsFailures::anotherUnitIsRefusedUnlessIgnored()
{
    // A set of the same product read from another unit (its serial number changed).
    const QString path = file(QStringLiteral("unit.dbp"));
    const Run backup = cli({ QStringLiteral("backup"), m_refgo, QStringLiteral("-o"), path });
    QVERIFY2(backup.exitCode == 0, qPrintable(backup.err));
    QByteArray text = contents(path);
    const qsizetype at = text.indexOf("\nserial \"");
    QVERIFY2(at >= 0, text.left(400).constData());
    const qsizetype end = text.indexOf('\n', at + 1);
    text.replace(at, end - at, "\nserial \"0x7FFFFFFE\"");
    {
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
        f.write(text);
    }
    const Run refused = cli({ QStringLiteral("restore"), m_refgo, path, QStringLiteral("--only"),
                              QStringLiteral("3300:4") });
    QCOMPARE(refused.exitCode, 2);
    QVERIFY2(refused.err.contains(QLatin1String("another unit (serial number 0x7FFFFFFE)")),
             qPrintable(refused.err));
    const Run forced = cli({ QStringLiteral("restore"), m_refgo, path, QStringLiteral("--only"),
                             QStringLiteral("3300:4"), QStringLiteral("--ignore-identity") });
    QVERIFY2(forced.exitCode == 0, qPrintable(forced.out + forced.err));
}

void TestCliParamsFailures::dumpWithFailedRowsPrintsTheRestAndFails()
{
    HostileRefgoPeer peer(Fault::NulByte, { QStringLiteral("6084,0") });
    const Run r = cli({ QStringLiteral("dump"), peer.uri() });
    QCOMPARE(r.exitCode, 5);
    QVERIFY(r.out.contains(QLatin1String("6083:0")));
    QVERIFY(!r.out.contains(QLatin1String("6084:0")));
    QVERIFY2(r.err.contains(QLatin1String("warning: 6084:0 Profile deceleration: malformed")),
             qPrintable(r.err));
    QVERIFY(r.err.trimmed().section(QLatin1Char('\n'), -1).contains(QLatin1String("1 of ")));
}

void TestCliParamsFailures::dumpWithNothingReadFails()
{
    HostileRefgoPeer peer(Fault::OtherObject);
    const Run r = cli({ QStringLiteral("dump"), peer.uri() });
    QCOMPARE(r.exitCode, 5);
    QVERIFY(r.out.isEmpty());
    QVERIFY2(r.err.contains(QLatin1String("no object could be read")), qPrintable(r.err));
}

void TestCliParamsFailures::restoreRefusesAnEmptySet()
{
    const QString path = file(QStringLiteral("empty-source.dbp"));
    QByteArray text = goodBackup(path);
    const qsizetype at = text.indexOf("\nentries ");
    QVERIFY(at > 0);
    text.truncate(at + 1);
    text += "entries 0\nend\n";
    const QString empty = file(QStringLiteral("empty.dbp"));
    QFile out(empty);
    QVERIFY(out.open(QIODevice::WriteOnly));
    out.write(text);
    out.close();
    const Run r = cli({ QStringLiteral("restore"), m_refgo, empty, QStringLiteral("--store") });
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.err.contains(QLatin1String("holds no object")), qPrintable(r.err));
    QVERIFY(!r.out.contains(QLatin1String("stored")));
}

QTEST_GUILESS_MAIN(TestCliParamsFailures)
#include "tst_cli_params_failures.moc"
