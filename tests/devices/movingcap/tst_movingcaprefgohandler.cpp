#include "devices/movingcap/movingcapdrive.h"
#include "devices/movingcap/movingcaprefgohandler.h"
#include "resources/builtindescriptions.h"

#include <QTest>

using namespace db;
using namespace db::refgo;
using namespace db::sim;

namespace {
struct Fixture
{
    explicit Fixture(const MovingCapOptions &options = {})
        : drive(resources::movingCapDictionary(), options)
        , handler(&drive)
    { }
    QStringList ask(const QString &line)
    {
        const auto request = parseRequest(line);
        if (!request)
            return { QStringLiteral("PARSE ") + request.error().message() };
        return handler.handle(request.value());
    }
    MovingCapDrive drive;
    MovingCapRefgoHandler handler;
};
} // namespace

class TestMovingCapRefgoHandler : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void docklightTranscriptRows1To14();
    void objectReadFormats_data();
    void objectReadFormats();
    void objectWriteEchoesRequestWithOk();
    void errorLines_data();
    void errorLines();
    void tellInputAndOutputs();
    void powerContinueTellStatusAndPowerQuit();
    void errorHistoryIsPrintedInHex();
};

void TestMovingCapRefgoHandler::docklightTranscriptRows1To14()
{
    // Spec 3.8, timed by the drive's reply timestamps. The 2021 firmware of that log did not
    // set TPSR BIT8 and 3511h.8 held 110 from an earlier session: fixture settings.
    MovingCapOptions options;
    options.tpsrInverterVoltageBit = false;
    options.initialValues.insert({ 0x3511, 8 }, 110);
    Fixture f(options);
    const QStringList none;
    struct Row
    {
        double replyAt; // seconds since 13:24:52.908
        const char *request;
        QStringList result;
    };
    const QList<Row> rows {
        { 0.000, "REF35", none },
        { 2.638, "SP720", none },
        { 3.490, "AC5000", none },
        { 4.460, "DE1000", none },
        { 6.523, "G360", none },
        { 16.693, "G-7200", none },
        { 18.804, "TPSR", { QStringLiteral("00000006") } },
        { 22.299, "TP", { QStringLiteral("-3658") } },
        { 28.101, "TPSR", { QStringLiteral("0000000a") } },
        { 29.958, "TP", { QStringLiteral("-7200") } },
        { 33.302, "PQ", none },
        { 1693.142, "OR3511,8", { QStringLiteral("OR3511,8,110") } },
        { 1784.103, "OW3511,8,120", { QStringLiteral("OW3511,8,120,OK") } },
        { 1822.099, "OR3511,8", { QStringLiteral("OR3511,8,120") } },
    };
    double now = 0.0;
    int number = 1;
    for (const Row &row : rows) {
        f.drive.advance(row.replyAt - now);
        now = row.replyAt;
        const QStringList got = f.ask(QLatin1String(row.request));
        QVERIFY2(got == row.result,
                 qPrintable(QStringLiteral("row %1 (%2): got '%3'")
                                .arg(number)
                                .arg(QLatin1String(row.request), got.join(QLatin1Char('|')))));
        ++number;
    }
    QCOMPARE(f.drive.ts(), 0);
}

void TestMovingCapRefgoHandler::objectReadFormats_data()
{
    QTest::addColumn<QString>("request");
    QTest::addColumn<QString>("result");
    QTest::newRow("decimal") << "OR6067,0"
                             << "OR6067,0,5000";
    QTest::newRow("hex flag") << "OR6041,0,h"
                              << "OR6041,0,427h";
    QTest::newRow("hex glued to sub") << "OR6041,0h"
                                      << "OR6041,0,427h";
    QTest::newRow("space form") << "OR 60FD,0"
                                << "OR 60FD,0,131072";
    QTest::newRow("hex inputs") << "OR60FD,0,h"
                                << "OR60FD,0,20000h";
    QTest::newRow("sub in hex") << "OR3401,A"
                                << "OR3401,A,35";
    QTest::newRow("negative") << "OR607D,1"
                              << "OR607D,1,-2147483647";
    QTest::newRow("negative hex") << "OR607D,1,h"
                                  << "OR607D,1,80000001h";
}

void TestMovingCapRefgoHandler::objectReadFormats()
{
    QFETCH(QString, request);
    QFETCH(QString, result);
    Fixture f;
    f.drive.powerContinue();
    f.drive.setPhysicalInput(2, true);
    f.drive.advance(0.2);
    QCOMPARE(f.ask(request), QStringList { result });
}

void TestMovingCapRefgoHandler::objectWriteEchoesRequestWithOk()
{
    Fixture f;
    QCOMPARE(f.ask(QStringLiteral("OW6067,0,100")), QStringList { "OW6067,0,100,OK" });
    QCOMPARE(f.ask(QStringLiteral("OR6067,0")), QStringList { "OR6067,0,100" });
    QCOMPARE(f.ask(QStringLiteral("OW 60FE,1,393216")), QStringList { "OW 60FE,1,393216,OK" });
    QCOMPARE(f.ask(QStringLiteral("OW 3510h,1,131072")), QStringList { "OW 3510h,1,131072,OK" });
    QCOMPARE(f.ask(QStringLiteral("OR 60FD,0")), QStringList { "OR 60FD,0,131072" });
    QCOMPARE(f.ask(QStringLiteral("OW6040,0,0x80")), QStringList { "OW6040,0,0x80,OK" });
}

void TestMovingCapRefgoHandler::errorLines_data()
{
    QTest::addColumn<QString>("request");
    QTest::addColumn<QString>("result");
    QTest::newRow("unknown object") << "OR1234,0"
                                    << "ERROR object 1234:0 does not exist";
    QTest::newRow("read-only") << "OW6041,0,1"
                               << "ERROR 6041:0 is read-only";
    QTest::newRow("fault state") << "G100"
                                 << "ERROR drive in fault state";
    QTest::newRow("jog in fault") << "JP"
                                  << "ERROR drive in fault state";
    QTest::newRow("bad output") << "SO7"
                                << "ERROR output 7 does not exist (1..4)";
}

void TestMovingCapRefgoHandler::errorLines()
{
    QFETCH(QString, request);
    QFETCH(QString, result);
    Fixture f;
    f.drive.injectFault(0x3221);
    QCOMPARE(f.ask(request), QStringList { result });
}

void TestMovingCapRefgoHandler::tellInputAndOutputs()
{
    Fixture f;
    f.drive.setPhysicalInput(3, true);
    QCOMPARE(f.ask(QStringLiteral("TI3")), QStringList { "1" });
    QCOMPARE(f.ask(QStringLiteral("TI1")), QStringList { "0" });
    QCOMPARE(f.ask(QStringLiteral("SO2")), QStringList {});
    QCOMPARE(f.ask(QStringLiteral("OR60FE,1,h")), QStringList { "OR60FE,1,20000h" });
    QCOMPARE(f.ask(QStringLiteral("CO2")), QStringList {});
    QCOMPARE(f.ask(QStringLiteral("OR60FE,1")), QStringList { "OR60FE,1,0" });
}

void TestMovingCapRefgoHandler::powerContinueTellStatusAndPowerQuit()
{
    Fixture f;
    QCOMPARE(f.ask(QStringLiteral("TS")), QStringList { "0" });
    QCOMPARE(f.ask(QStringLiteral("PWC")), QStringList {});
    f.drive.advance(0.2);
    QCOMPARE(f.ask(QStringLiteral("TS")), QStringList { "1" });
    QCOMPARE(f.ask(QStringLiteral("TPSR")), QStringList { "0000010a" });
    QCOMPARE(f.ask(QStringLiteral("G720")), QStringList {});
    f.drive.advance(0.2);
    QCOMPARE(f.ask(QStringLiteral("TPSR")), QStringList { "00000106" });
    QCOMPARE(f.ask(QStringLiteral("TS")), QStringList { "2" });
    QCOMPARE(f.ask(QStringLiteral("OR6041,0,h")), QStringList { "OR6041,0,127h" });
    QCOMPARE(f.ask(QStringLiteral("PQ")), QStringList {});
    QCOMPARE(f.ask(QStringLiteral("TS")), QStringList { "0" });
    QCOMPARE(f.ask(QStringLiteral("REF")), QStringList {});
    QCOMPARE(f.ask(QStringLiteral("TS")), QStringList { "0" });
}

void TestMovingCapRefgoHandler::errorHistoryIsPrintedInHex()
{
    Fixture f;
    f.drive.injectFault(0x3221);
    QCOMPARE(f.ask(QStringLiteral("OR603F,0,h")), QStringList { "OR603F,0,3221h" });
    QCOMPARE(f.ask(QStringLiteral("OR1003,1")), QStringList { "OR1003,1,3221h" });
    QCOMPARE(f.ask(QStringLiteral("OR6041,0h")), QStringList { "OR6041,0,8h" });
    QCOMPARE(f.ask(QStringLiteral("OW6040,0,0x80")), QStringList { "OW6040,0,0x80,OK" });
    QCOMPARE(f.ask(QStringLiteral("TS")), QStringList { "0" });
}

QTEST_GUILESS_MAIN(TestMovingCapRefgoHandler)
#include "tst_movingcaprefgohandler.moc"
