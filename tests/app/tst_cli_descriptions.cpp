// drivebench-cli eds-check: a summary and the warnings for every shared description file, one
// error line and a non-zero exit for files that are not descriptions.
#include "clirun.h"

#include <QDir>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

class TestCliDescriptions : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void summarizesSharedFiles_data();
    void summarizesSharedFiles();
    void brokenFilesFailWithOneLine_data();
    void brokenFilesFailWithOneLine();

private:
    using Run = db::test::CliRun;
    static Run cli(const QStringList &args);
};

namespace {

QString sharedFile(const QString &relative)
{
    QString dir = qEnvironmentVariable("DRIVEBENCH_SHARED_DIR");
    if (dir.isEmpty())
        dir = QStringLiteral(DRIVEBENCH_SOURCE_DIR "/../shared");
    return QDir(dir).filePath(relative);
}

} // namespace

TestCliDescriptions::Run TestCliDescriptions::cli(const QStringList &args)
{
    return db::test::runProgram(QStringLiteral(DRIVEBENCH_CLI), args, 15000);
}

void TestCliDescriptions::summarizesSharedFiles_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<QStringList>("expected");
    QTest::newRow("sample.eds") << QStringLiteral("fixtures/eds/sample.eds")
                                << QStringList { QStringLiteral("format:       EDS"),
                                                 QStringLiteral("vendor:       Vendor Name"),
                                                 QStringLiteral("commissioning: node id 16"),
                                                 QStringLiteral("warning: [1018]: SubNumber=5") };
    QTest::newRow("datatypes.eds")
        << QStringLiteral("fixtures/eds/datatypes.eds")
        << QStringList { QStringLiteral("objects:      24 (28 sub-objects)"),
                         QStringLiteral("INTEGER56 1"), QStringLiteral("warnings:     0") };
    QTest::newRow("NM170.eds") << QStringLiteral("specs/NM170.eds")
                               << QStringList { QStringLiteral("Baumer (0x000000ec)"),
                                                QStringLiteral("NM170 Standard (0x00000070)"),
                                                QStringLiteral("(symbolic, no node id)") };
    for (const char *xdd : { "MC349_ETH", "MC6xx_ETH", "MCFLAT_ETH", "MCN23_ETH" })
        QTest::newRow(xdd) << QStringLiteral("fixtures/xdd/%1.xdd").arg(QLatin1String(xdd))
                           << QStringList { QStringLiteral("format:       XDD"),
                                            QStringLiteral("Fullmo GmbH (0x0000053b)"),
                                            QStringLiteral("PDO-mappable: ") };
}

void TestCliDescriptions::summarizesSharedFiles()
{
    QFETCH(QString, file);
    QFETCH(QStringList, expected);
    const QString path = sharedFile(file);
    if (!QFile::exists(path))
        QSKIP("shared description file not present");
    const Run r = cli({ QStringLiteral("eds-check"), path });
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QVERIFY(r.err.isEmpty());
    for (const QString &line : expected)
        QVERIFY2(r.out.contains(line), qPrintable(line + QLatin1String(" not in:\n") + r.out));
}

void TestCliDescriptions::brokenFilesFailWithOneLine_data()
{
    QTest::addColumn<QByteArray>("content");
    QTest::addColumn<QString>("cause");
    QTest::newRow("garbage") << QByteArray("\x00\x01\x02\xFF\xFE garbage", 12)
                             << QStringLiteral("binary data");
    QTest::newRow("ini without objects")
        << QByteArray("[General]\nkey=value\n") << QStringLiteral("no object sections");
    QTest::newRow("not xdd") << QByteArray("<?xml version=\"1.0\"?><project/>")
                             << QStringLiteral("not an XDD");
}

void TestCliDescriptions::brokenFilesFailWithOneLine()
{
    QFETCH(QByteArray, content);
    QFETCH(QString, cause);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("device.eds"));
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(content);
    f.close();
    const Run r = cli({ QStringLiteral("eds-check"), path });
    QVERIFY(r.exitCode != 0);
    QCOMPARE(r.err.count(QLatin1Char('\n')), 1);
    QVERIFY2(r.err.contains(path) && r.err.contains(cause), qPrintable(r.err));
    const Run missing =
        cli({ QStringLiteral("eds-check"), dir.filePath(QStringLiteral("no.eds")) });
    QVERIFY(missing.exitCode != 0);
    QVERIFY2(missing.err.contains(QStringLiteral("no.eds")), qPrintable(missing.err));
}

QTEST_GUILESS_MAIN(TestCliDescriptions)
#include "tst_cli_descriptions.moc"
