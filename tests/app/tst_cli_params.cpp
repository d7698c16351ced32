// drivebench-cli backup/restore/diff/dump end to end against drivebench-sim on OS-chosen
// loopback ports, over RefGo and over CANopen (SLCAN over TCP), plus the failure cases: a
// simulator that rejects a write, and corrupt or foreign files that must change nothing.
#include "clirun.h"

#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

class TestCliParams : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void cleanupTestCase();

    void backupChangeDiffRestore_data();
    void backupChangeDiffRestore();
    void diffOfTwoFiles();
    void restoreReportsRejectedWrites();
    void badFileChangesNothing_data();
    void badFileChangesNothing();
    void usageErrors_data();
    void usageErrors();

private:
    using Run = db::test::CliRun;
    Run cli(const QStringList &args);
    // Starts drivebench-sim movingcap with extra arguments; returns the RefGo and SLCAN URIs.
    bool startSim(QProcess &sim, const QStringList &extra, QString *refgo, QString *slcan);
    QString file(const QString &name) const { return m_dir.filePath(name); }

    QTemporaryDir m_dir;
    QProcess m_sim;
    QProcess m_rejecting;
    QString m_refgo;
    QString m_slcan;
};

TestCliParams::Run TestCliParams::cli(const QStringList &args)
{
    return db::test::runProgram(QStringLiteral(DRIVEBENCH_CLI), args, 20000);
}

bool TestCliParams::startSim(QProcess &sim, const QStringList &extra, QString *refgo,
                             QString *slcan)
{
    sim.start(QStringLiteral(DRIVEBENCH_SIM),
              QStringList { QStringLiteral("movingcap"), QStringLiteral("--refgo-port"),
                            QStringLiteral("0"), QStringLiteral("--slcan-port"),
                            QStringLiteral("0") }
                  + extra);
    if (!sim.waitForStarted())
        return false;
    QString banner;
    const QRegularExpression re(
        QStringLiteral("\\((refgo://[^)]+)\\)[\\s\\S]*\\((canopen\\+slcan://[^)]+)\\)"));
    QRegularExpressionMatch m;
    for (int i = 0; i < 100 && !(m = re.match(banner)).hasMatch(); ++i) {
        sim.waitForReadyRead(100);
        banner += QString::fromUtf8(sim.readAllStandardOutput());
    }
    if (!m.hasMatch())
        return false;
    *refgo = m.captured(1);
    *slcan = m.captured(2);
    return true;
}

void TestCliParams::initTestCase()
{
    QVERIFY(m_dir.isValid());
    QVERIFY(startSim(m_sim, {}, &m_refgo, &m_slcan));
}

void TestCliParams::cleanupTestCase()
{
    for (QProcess *p : { &m_sim, &m_rejecting }) {
        if (p->state() != QProcess::NotRunning) {
            p->terminate();
            if (!p->waitForFinished(3000))
                p->kill();
        }
    }
}

void TestCliParams::backupChangeDiffRestore_data()
{
    QTest::addColumn<bool>("canopen");
    QTest::newRow("refgo") << false;
    QTest::newRow("canopen+slcan") << true;
}

void TestCliParams::backupChangeDiffRestore()
{
    QFETCH(bool, canopen);
    const QString uri = canopen ? m_slcan : m_refgo;
    const QString set = file(QStringLiteral("backup-%1.dbp").arg(canopen));

    const Run before = cli({ QStringLiteral("dump"), uri });
    QCOMPARE(before.exitCode, 0);
    QVERIFY(before.out.contains(QLatin1String("6083:0")));
    QVERIFY(before.out.contains(QLatin1String("Statusword")));

    const Run backup = cli({ QStringLiteral("backup"), uri, QStringLiteral("-o"), set });
    QVERIFY2(backup.exitCode == 0, qPrintable(backup.err));
    QVERIFY2(backup.out.startsWith(QLatin1String("backed up 201 objects from ")),
             qPrintable(backup.out));

    const QString original =
        cli({ QStringLiteral("read"), uri, QStringLiteral("6083:0") }).out.trimmed();
    QCOMPARE(cli({ QStringLiteral("write"), uri, QStringLiteral("6083:0"), QStringLiteral("2345") })
                 .exitCode,
             0);
    QCOMPARE(cli({ QStringLiteral("write"), uri, QStringLiteral("3511:7"), QStringLiteral("4321") })
                 .exitCode,
             0);

    const Run changed = cli({ QStringLiteral("diff"), uri, set });
    QCOMPARE(changed.exitCode, 1);
    QVERIFY2(changed.out.contains(
                 QStringLiteral("changed 6083:0  Profile acceleration: 2345 | %1").arg(original)),
             qPrintable(changed.out));
    QVERIFY(changed.out.contains(QLatin1String("3511:7  IN1 Profile acceleration: 4321 | ")));
    QVERIFY2(changed.out.contains(
                 QLatin1String("201 objects: 199 unchanged, 2 changed, 0 missing, 0 unknown")),
             qPrintable(changed.out));

    const Run restore = cli({ QStringLiteral("restore"), uri, set });
    QVERIFY2(restore.exitCode == 0, qPrintable(restore.out + restore.err));
    QVERIFY2(restore.out.startsWith(QLatin1String(
                 "restore: 201 verified, 0 written, 0 failed, 0 mismatch, 0 skipped")),
             qPrintable(restore.out));

    const Run same = cli({ QStringLiteral("diff"), set, uri });
    QCOMPARE(same.exitCode, 0);
    QVERIFY(same.out.contains(QLatin1String("201 unchanged, 0 changed")));
    const Run after = cli({ QStringLiteral("dump"), uri });
    QCOMPARE(after.exitCode, 0);
    QCOMPARE(after.out, before.out);
}

void TestCliParams::diffOfTwoFiles()
{
    const QString a = file(QStringLiteral("a.dbp"));
    QCOMPARE(cli({ QStringLiteral("backup"), m_refgo, QStringLiteral("-o"), a }).exitCode, 0);
    QFile in(a);
    QVERIFY(in.open(QIODevice::ReadOnly));
    QByteArray text = in.readAll();
    // A hand-edited copy: hex for a decimal value (equal) and one real change.
    text.replace("\"Homing method\" INTEGER8 35", "\"Homing method\" INTEGER8 0x23");
    const qsizetype at = text.indexOf("6084:0 \"Profile deceleration\" UNSIGNED32 ");
    QVERIFY(at > 0);
    text.insert(text.indexOf('\n', at) - 3, "9"); // 1000 -> 10900 (before the unit)
    const QString b = file(QStringLiteral("b.dbp"));
    QFile out(b);
    QVERIFY(out.open(QIODevice::WriteOnly));
    out.write(text);
    out.close();
    const Run d = cli({ QStringLiteral("diff"), a, b });
    QCOMPARE(d.exitCode, 1);
    QVERIFY2(d.out.contains(QLatin1String("changed 6084:0  Profile deceleration:")),
             qPrintable(d.out));
    QVERIFY(!d.out.contains(QLatin1String("6098:0")));
    QVERIFY(d.out.contains(QLatin1String("200 unchanged, 1 changed")));
    QCOMPARE(cli({ QStringLiteral("diff"), a, a }).exitCode, 0);
}

void TestCliParams::restoreReportsRejectedWrites()
{
    QString refgo;
    QString slcan;
    QVERIFY(startSim(m_rejecting, { QStringLiteral("--reject-write"), QStringLiteral("6084:0") },
                     &refgo, &slcan));
    const QString set = file(QStringLiteral("reject.dbp"));
    QCOMPARE(cli({ QStringLiteral("backup"), refgo, QStringLiteral("-o"), set }).exitCode, 0);
    QCOMPARE(
        cli({ QStringLiteral("write"), refgo, QStringLiteral("6083:0"), QStringLiteral("777") })
            .exitCode,
        0);
    const Run r = cli({ QStringLiteral("restore"), slcan, set, QStringLiteral("--only"),
                        QStringLiteral("6083:0,6084:0"), QStringLiteral("--store") });
    QCOMPARE(r.exitCode, 1);
    const QStringList lines = r.out.trimmed().split(QLatin1Char('\n'));
    QCOMPARE(lines.size(), 4);
    QCOMPARE(lines.at(0),
             QStringLiteral("restore: 1 verified, 0 written, 1 failed, 0 mismatch, 0 skipped"));
    QCOMPARE(lines.at(1), QStringLiteral("  verified  6083:0 Profile acceleration"));
    QVERIFY2(lines.at(2).startsWith(QLatin1String("  failed    6084:0 Profile deceleration: ")),
             qPrintable(lines.at(2)));
    QVERIFY(lines.at(2).contains(QLatin1String("present device state")));
    QCOMPARE(lines.at(3), QStringLiteral("not stored: 1 row(s) did not succeed"));
    QCOMPARE(cli({ QStringLiteral("read"), refgo, QStringLiteral("6083:0") }).out.trimmed(),
             cli({ QStringLiteral("read"), slcan, QStringLiteral("6083:0") }).out.trimmed());
    QVERIFY(cli({ QStringLiteral("read"), refgo, QStringLiteral("6083:0") }).out.trimmed()
            != QLatin1String("777"));
}

void TestCliParams::badFileChangesNothing_data()
{
    QTest::addColumn<QString>("kind");
    QTest::addColumn<QString>("message");
    QTest::newRow("truncated") << QStringLiteral("truncated")
                               << QStringLiteral(":212: truncated: no 'end' line");
    QTest::newRow("corrupt") << QStringLiteral("corrupt")
                             << QStringLiteral(":15: expected an object line");
    QTest::newRow("foreign") << QStringLiteral("foreign")
                             << QStringLiteral(":1: not a drivebench parameter set");
}

void TestCliParams::badFileChangesNothing()
{
    QFETCH(QString, kind);
    QFETCH(QString, message);
    const QString good = file(QStringLiteral("good-%1.dbp").arg(kind));
    QCOMPARE(cli({ QStringLiteral("backup"), m_refgo, QStringLiteral("-o"), good }).exitCode, 0);
    QFile in(good);
    QVERIFY(in.open(QIODevice::ReadOnly));
    QByteArray text = in.readAll();
    // Every variant carries a changed first object, which a careless reader would write.
    text.replace("3300:4 \"motor_imbalance_amplitude\" UNSIGNED16 0 ",
                 "3300:4 \"motor_imbalance_amplitude\" UNSIGNED16 55 ");
    if (kind == QLatin1String("truncated"))
        text.chop(4); // "end\n"
    else if (kind == QLatin1String("corrupt"))
        text.replace("3301:4 \"mass_payload\"", "3301:4 mass_payload");
    else
        text = "[FileInfo]\nFileName=movingcap.eds\n" + text;
    const QString bad = file(QStringLiteral("bad-%1.dbp").arg(kind));
    QFile out(bad);
    QVERIFY(out.open(QIODevice::WriteOnly));
    out.write(text);
    out.close();

    const Run dumpBefore = cli({ QStringLiteral("dump"), m_refgo });
    const Run r = cli({ QStringLiteral("restore"), m_refgo, bad });
    QCOMPARE(r.exitCode, 5); // malformed
    QVERIFY2(r.err.startsWith(QStringLiteral("drivebench-cli: ") + bad + message),
             qPrintable(r.err));
    QVERIFY(r.out.isEmpty());
    QCOMPARE(cli({ QStringLiteral("read"), m_refgo, QStringLiteral("3300:4") }).out.trimmed(),
             QStringLiteral("0"));
    QCOMPARE(cli({ QStringLiteral("dump"), m_refgo }).out, dumpBefore.out);
    QCOMPARE(cli({ QStringLiteral("diff"), bad, good }).exitCode, 5);
}

void TestCliParams::usageErrors_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("message");
    QTest::newRow("backup without -o")
        << QStringList { QStringLiteral("backup"), QStringLiteral("refgo://127.0.0.1:1") }
        << QStringLiteral("-o FILE");
    QTest::newRow("only not in set")
        << QStringList { QStringLiteral("restore"), QStringLiteral("refgo://127.0.0.1:1"),
                         QStringLiteral("@SET@"), QStringLiteral("--only"),
                         QStringLiteral("6041:0") }
        << QStringLiteral("6041:0 is not in");
    QTest::newRow("only garbage") << QStringList {
        QStringLiteral("restore"), QStringLiteral("refgo://127.0.0.1:1"), QStringLiteral("@SET@"),
        QStringLiteral("--only"), QStringLiteral("zz")
    } << QStringLiteral("--only:");
    QTest::newRow("other product")
        << QStringList { QStringLiteral("restore"), QStringLiteral("@URI@"),
                         QStringLiteral("@OTHER@") }
        << QStringLiteral("is a set for product code 0x00000999, but the device reports 0x");
}

void TestCliParams::usageErrors()
{
    QFETCH(QStringList, args);
    QFETCH(QString, message);
    const QString set = file(QStringLiteral("usage.dbp"));
    if (!QFile::exists(set))
        QCOMPARE(cli({ QStringLiteral("backup"), m_refgo, QStringLiteral("-o"), set }).exitCode, 0);
    const QString other = file(QStringLiteral("other-product.dbp"));
    if (!QFile::exists(other)) {
        QFile in(set);
        QVERIFY(in.open(QIODevice::ReadOnly));
        QByteArray text = in.readAll();
        const qsizetype at = text.indexOf("product 0x");
        QVERIFY(at >= 0);
        text.replace(at + 8, 10, "0x00000999");
        QFile out(other);
        QVERIFY(out.open(QIODevice::WriteOnly));
        out.write(text);
    }
    args.replaceInStrings(QStringLiteral("@SET@"), set);
    args.replaceInStrings(QStringLiteral("@OTHER@"), other);
    args.replaceInStrings(QStringLiteral("@URI@"), m_refgo);
    const Run r = cli(args);
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.err.contains(message), qPrintable(r.err));
}

QTEST_GUILESS_MAIN(TestCliParams)
#include "tst_cli_params.moc"
