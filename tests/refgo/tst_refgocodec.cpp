// Level 1: the RefGo command table, formatting and tolerant parsing (movingcap.md 3.2-3.6,
// errata 14-16, Appendix C).

#include "refgo/refgocodec.h"

#include <QtTest>

using namespace db;
using namespace db::refgo;

Q_DECLARE_METATYPE(db::refgo::Command)

class TstRefgoCodec : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void tableHasAllCommandsInEnumOrder();
    void formatsEveryCommand_data();
    void formatsEveryCommand();
    void formatRead_data();
    void formatRead();
    void formatWrite_data();
    void formatWrite();
    void parsesRequest_data();
    void parsesRequest();
    void refusesBadRequest_data();
    void refusesBadRequest();
    void formattedRequestsParseBack();
    void parseNumber_data();
    void parseNumber();
    void refusesNonNumber_data();
    void refusesNonNumber();
    void parsesObjectRead_data();
    void parsesObjectRead();
    void refusesObjectReadWithoutValue_data();
    void refusesObjectReadWithoutValue();
    void parsesTpsr_data();
    void parsesTpsr();
    void refusesTpsrNotEightHexDigits_data();
    void refusesTpsrNotEightHexDigits();
    void formatsTpsrLowerCase();
    void parsesTs_data();
    void parsesTs();
    void refusesUnknownTs();
};

void TstRefgoCodec::tableHasAllCommandsInEnumOrder()
{
    QCOMPARE(commands().size(), 26);
    for (int i = 0; i < commands().size(); ++i) {
        QCOMPARE(int(commands().at(i).command), i);
        QCOMPARE(int(info(Command(i)).command), i);
        QVERIFY(qstrlen(info(Command(i)).title) > 0);
    }
}

void TstRefgoCodec::formatsEveryCommand_data()
{
    QTest::addColumn<Command>("command");
    QTest::addColumn<bool>("hasArgument");
    QTest::addColumn<qlonglong>("argument");
    QTest::addColumn<QString>("expected");
    const struct
    {
        Command c;
        bool has;
        qlonglong arg;
        const char *text;
    } rows[] = {
        { Command::G, true, 10000, "G10000" },
        { Command::G, false, 0, "G" },
        { Command::GW, true, -5000, "GW-5000" },
        { Command::GW, false, 0, "GW" },
        { Command::PO, true, 10000, "PO10000" },
        { Command::WA, true, -5000, "WA-5000" },
        { Command::SM, false, 0, "SM" },
        { Command::PWC, false, 0, "PWC" },
        { Command::CM, false, 0, "CM" },
        { Command::REF, true, 35, "REF35" },
        { Command::REF, true, -18, "REF-18" },
        { Command::PQ, false, 0, "PQ" },
        { Command::TPSR, false, 0, "TPSR" },
        { Command::TS, false, 0, "TS" },
        { Command::TP, false, 0, "TP" },
        { Command::SP, true, 720, "SP720" },
        { Command::AC, true, 5000, "AC5000" },
        { Command::DE, true, 1000, "DE1000" },
        { Command::ACV, true, 100000, "ACV100000" },
        { Command::JP, false, 0, "JP" },
        { Command::JP, true, 500, "JP500" },
        { Command::JN, true, 1000, "JN1000" },
        { Command::RR, true, -10000, "RR-10000" },
        { Command::RR, false, 0, "RR" },
        { Command::RW, true, 2000, "RW2000" },
        { Command::WT, true, 5000, "WT5000" },
        { Command::SO, true, 2, "SO2" },
        { Command::CO, true, 2, "CO2" },
        { Command::TI, true, 3, "TI3" },
    };
    for (const auto &r : rows)
        QTest::newRow(r.text) << r.c << r.has << r.arg << QString::fromLatin1(r.text);
}

void TstRefgoCodec::formatsEveryCommand()
{
    QFETCH(Command, command);
    QFETCH(bool, hasArgument);
    QFETCH(qlonglong, argument);
    QFETCH(QString, expected);
    QCOMPARE(format(command, hasArgument ? std::optional<qint64>(argument) : std::nullopt),
             expected);
}

void TstRefgoCodec::formatRead_data()
{
    QTest::addColumn<int>("index");
    QTest::addColumn<int>("sub");
    QTest::addColumn<bool>("hex");
    QTest::addColumn<QString>("expected");
    QTest::newRow("3511.8") << 0x3511 << 8 << false << "OR3511,8";
    QTest::newRow("3401.1A upper-case") << 0x3401 << 0x1A << false << "OR3401,1A";
    QTest::newRow("60FD upper-case") << 0x60FD << 0 << false << "OR60FD,0";
    QTest::newRow("6041 hex output") << 0x6041 << 0 << true << "OR6041,0,h";
    QTest::newRow("index padded") << 0x0100 << 1 << false << "OR0100,1";
}

void TstRefgoCodec::formatRead()
{
    QFETCH(int, index);
    QFETCH(int, sub);
    QFETCH(bool, hex);
    QFETCH(QString, expected);
    QCOMPARE(refgo::formatRead(ObjectAddress(quint16(index), quint8(sub)), hex), expected);
}

void TstRefgoCodec::formatWrite_data()
{
    QTest::addColumn<int>("index");
    QTest::addColumn<int>("sub");
    QTest::addColumn<QVariant>("value");
    QTest::addColumn<QString>("expected");
    QTest::newRow("docklight") << 0x3511 << 8 << QVariant(qlonglong(120)) << "OW3511,8,120";
    QTest::newRow("unsigned") << 0x6040 << 0 << QVariant(qulonglong(0x80)) << "OW6040,0,128";
    QTest::newRow("negative") << 0x607A << 0 << QVariant(qlonglong(-30000)) << "OW607A,0,-30000";
    QTest::newRow("bool") << 0x2000 << 1 << QVariant(true) << "OW2000,1,1";
    QTest::newRow("int") << 0x3401 << 0x1A << QVariant(15) << "OW3401,1A,15";
    QTest::newRow("store") << 0x1010 << 1 << QVariant(qulonglong(1702257011))
                           << "OW1010,1,1702257011";
}

void TstRefgoCodec::formatWrite()
{
    QFETCH(int, index);
    QFETCH(int, sub);
    QFETCH(QVariant, value);
    QFETCH(QString, expected);
    QCOMPARE(refgo::formatWrite(ObjectAddress(quint16(index), quint8(sub)), value), expected);
}

void TstRefgoCodec::parsesRequest_data()
{
    QTest::addColumn<QString>("line");
    QTest::addColumn<Command>("command");
    QTest::addColumn<QVariant>("argument"); // invalid = none
    QTest::addColumn<int>("index");
    QTest::addColumn<int>("sub");
    QTest::addColumn<bool>("hex");
    QTest::addColumn<QVariant>("value");
    const QVariant none;
    auto simple = [&](const char *line, Command c, QVariant arg = {}) {
        QTest::newRow(line) << QString::fromLatin1(line) << c << arg << 0 << 0 << false << none;
    };
    auto object = [&](const char *tag, const char *line, Command c, int index, int sub, bool hex,
                      QVariant value = {}) {
        QTest::newRow(tag) << QString::fromLatin1(line) << c << none << index << sub << hex
                           << value;
    };
    // Every command of 3.3 with the manual's examples.
    simple("G10000", Command::G, qlonglong(10000));
    simple("G", Command::G);
    simple("GW-5000", Command::GW, qlonglong(-5000));
    simple("GW", Command::GW);
    simple("PO10000", Command::PO, qlonglong(10000));
    simple("WA-5000", Command::WA, qlonglong(-5000));
    simple("SM", Command::SM);
    simple("PWC", Command::PWC);
    simple("CM", Command::CM);
    simple("REF35", Command::REF, qlonglong(35));
    simple("REF-18", Command::REF, qlonglong(-18));
    simple("REF", Command::REF);
    simple("PQ", Command::PQ);
    object("OW6067,0,100", "OW6067,0,100", Command::OW, 0x6067, 0, false, qlonglong(100));
    object("OR6067,0", "OR6067,0", Command::OR, 0x6067, 0, false);
    simple("TPSR", Command::TPSR);
    simple("TS", Command::TS);
    simple("TP", Command::TP);
    simple("SP500", Command::SP, qlonglong(500));
    simple("AC2000", Command::AC, qlonglong(2000));
    simple("DE2000", Command::DE, qlonglong(2000));
    simple("ACV100000", Command::ACV, qlonglong(100000));
    simple("JP", Command::JP);
    simple("JP500", Command::JP, qlonglong(500));
    simple("JN1000", Command::JN, qlonglong(1000));
    simple("RR-10000", Command::RR, qlonglong(-10000));
    simple("RR", Command::RR);
    simple("RW2000", Command::RW, qlonglong(2000));
    simple("WT5000", Command::WT, qlonglong(5000));
    simple("SO2", Command::SO, qlonglong(2));
    simple("CO2", Command::CO, qlonglong(2));
    simple("TI3", Command::TI, qlonglong(3));
    // Tolerance (3.2, 3.6, errata 15/16, Appendix C).
    simple("tp", Command::TP);
    simple(" TP ", Command::TP);
    simple("sp 720", Command::SP, qlonglong(720));
    object("sub-index in hex", "OR3401,A", Command::OR, 0x3401, 0xA, false);
    object("two-digit hex sub", "OW3401,1A,15", Command::OW, 0x3401, 0x1A, false, qlonglong(15));
    object("hex flag", "OR6041,0,h", Command::OR, 0x6041, 0, true);
    object("erratum 15 sub h is hex flag", "OR6041,0h", Command::OR, 0x6041, 0, true);
    object("erratum 16 space", "OR 60FD,0", Command::OR, 0x60FD, 0, false);
    object("erratum 16 space and h", "OW 3510h,1,131072", Command::OW, 0x3510, 1, false,
           qlonglong(131072));
    object("space OW", "OW 60FE,1,393216", Command::OW, 0x60FE, 1, false, qlonglong(393216));
    object("0x value", "OW6040,0,0x80", Command::OW, 0x6040, 0, false, qulonglong(0x80));
    object("negative value", "OW607A,0,-30000", Command::OW, 0x607A, 0, false, qlonglong(-30000));
    object("appendix C index and sub h", "OR3410h,1h", Command::OR, 0x3410, 1, false);
    object("appendix C upper-case H", "OR3410H,1H", Command::OR, 0x3410, 1, false);
    object("lower-case", "or6041,0,h", Command::OR, 0x6041, 0, true);
    object("index starting with a letter", "ORA000,0", Command::OR, 0xA000, 0, false);
    object("spaces around fields", "OW6067, 0 , 100", Command::OW, 0x6067, 0, false,
           qlonglong(100));
}

void TstRefgoCodec::parsesRequest()
{
    QFETCH(QString, line);
    QFETCH(Command, command);
    QFETCH(QVariant, argument);
    QFETCH(int, index);
    QFETCH(int, sub);
    QFETCH(bool, hex);
    QFETCH(QVariant, value);
    const auto r = parseRequest(line);
    QVERIFY2(r.ok(), qPrintable(r.error().toString()));
    QCOMPARE(r->command, command);
    QCOMPARE(r->text, line);
    QCOMPARE(r->argument.has_value(), argument.isValid());
    if (argument.isValid())
        QCOMPARE(qlonglong(*r->argument), argument.toLongLong());
    if (command == Command::OR || command == Command::OW) {
        QCOMPARE(r->address, ObjectAddress(quint16(index), quint8(sub)));
        QCOMPARE(r->hexOutput, hex);
    }
    if (value.isValid()) {
        QCOMPARE(r->value.typeId(), value.typeId());
        QCOMPARE(r->value, value);
    }
}

void TstRefgoCodec::refusesBadRequest_data()
{
    QTest::addColumn<QString>("line");
    QTest::addColumn<QString>("mentions");
    QTest::newRow("empty") << ""
                           << "empty";
    QTest::newRow("unknown command") << "XYZ"
                                     << "XYZ";
    QTest::newRow("no mnemonic") << "123"
                                 << "123";
    QTest::newRow("parameter on SM") << "SM5"
                                     << "SM";
    QTest::newRow("SP without value") << "SP"
                                      << "SP";
    QTest::newRow("G not a number") << "G12ab"
                                    << "12ab";
    QTest::newRow("OR without sub") << "OR6041"
                                    << "OR";
    QTest::newRow("OR bad flag") << "OR6041,0,x"
                                 << "'x'";
    QTest::newRow("OW without value") << "OW6040,0"
                                      << "OW";
    QTest::newRow("OW bad value") << "OW6040,0,abc"
                                  << "abc";
    QTest::newRow("index too large") << "OR10000,0"
                                     << "index";
    QTest::newRow("sub too large") << "OR6041,100"
                                   << "sub-index";
    QTest::newRow("index not hex") << "OWzz,0,1"
                                   << "OW";
    QTest::newRow("empty sub") << "OR6041,,h"
                               << "sub-index";
}

void TstRefgoCodec::refusesBadRequest()
{
    QFETCH(QString, line);
    QFETCH(QString, mentions);
    const auto r = parseRequest(line);
    QVERIFY(!r.ok());
    QCOMPARE(r.error().kind(), Error::Kind::InvalidArgument);
    QVERIFY2(r.error().message().contains(mentions), qPrintable(r.error().message()));
}

void TstRefgoCodec::formattedRequestsParseBack()
{
    for (const CommandInfo &c : commands()) {
        if (c.parameter == Parameter::Object)
            continue;
        const std::optional<qint64> arg =
            c.parameter == Parameter::None ? std::nullopt : std::optional<qint64>(-42);
        const auto r = parseRequest(format(c.command, arg));
        QVERIFY2(r.ok(), c.mnemonic);
        QCOMPARE(r->command, c.command);
        QCOMPARE(r->argument, arg);
    }
    const auto read = parseRequest(refgo::formatRead({ 0x6041, 0 }, true));
    QVERIFY(read.ok() && read->hexOutput && read->address == ObjectAddress(0x6041, 0));
    const auto write = parseRequest(refgo::formatWrite({ 0x3401, 0x1A }, qlonglong(-7)));
    QVERIFY(write.ok());
    QCOMPARE(write->value, QVariant(qlonglong(-7)));
}

void TstRefgoCodec::parseNumber_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<qlonglong>("expected");
    QTest::newRow("negative decimal") << "-3658" << qlonglong(-3658);
    QTest::newRow("h suffix") << "427h" << qlonglong(0x427);
    QTest::newRow("H suffix") << "3221H" << qlonglong(0x3221);
    QTest::newRow("0x prefix") << "0x80" << qlonglong(128);
    QTest::newRow("hex is unsigned") << "FFFFFFFFh" << qlonglong(4294967295LL);
    QTest::newRow("plus") << "+5" << qlonglong(5);
    QTest::newRow("spaces") << " 12 " << qlonglong(12);
    QTest::newRow("zero") << "0" << qlonglong(0);
}

void TstRefgoCodec::parseNumber()
{
    QFETCH(QString, text);
    QFETCH(qlonglong, expected);
    const auto n = refgo::parseNumber(text);
    QVERIFY2(n.ok(), qPrintable(n.error().toString()));
    QCOMPARE(qlonglong(n.value()), expected);
}

void TstRefgoCodec::refusesNonNumber_data()
{
    QTest::addColumn<QString>("text");
    QTest::newRow("empty") << "";
    QTest::newRow("just h") << "h";
    QTest::newRow("trailing garbage") << "12x";
    QTest::newRow("bare 0x") << "0x";
    QTest::newRow("double sign") << "--1";
    QTest::newRow("hex letters without marker") << "ab";
    QTest::newRow("too large") << "99999999999999999999";
}

void TstRefgoCodec::refusesNonNumber()
{
    QFETCH(QString, text);
    const auto n = refgo::parseNumber(text);
    QVERIFY(!n.ok());
    QCOMPARE(n.error().kind(), Error::Kind::InvalidArgument);
}

void TstRefgoCodec::parsesObjectRead_data()
{
    QTest::addColumn<QString>("line");
    QTest::addColumn<int>("index");
    QTest::addColumn<int>("sub");
    QTest::addColumn<qlonglong>("value");
    QTest::addColumn<bool>("hex");
    QTest::newRow("docklight") << "OR3511,8,110" << 0x3511 << 8 << qlonglong(110) << false;
    QTest::newRow("6067") << "OR6067,0,100" << 0x6067 << 0 << qlonglong(100) << false;
    QTest::newRow("space") << "OR 60FD,0,131072" << 0x60FD << 0 << qlonglong(131072) << false;
    QTest::newRow("hex output") << "OR6041,0,427h" << 0x6041 << 0 << qlonglong(0x427) << true;
    QTest::newRow("hex inputs") << "OR60FD,0,50000h" << 0x60FD << 0 << qlonglong(0x50000) << true;
    QTest::newRow("erratum 14 hex without flag")
        << "OR1003,1,3221h" << 0x1003 << 1 << qlonglong(0x3221) << true;
    QTest::newRow("appendix C upper-case")
        << "OR3410H,1H,4242" << 0x3410 << 1 << qlonglong(4242) << false;
    QTest::newRow("negative") << "OR6078,0,-103" << 0x6078 << 0 << qlonglong(-103) << false;
    QTest::newRow("hex sub") << "OR3401,A,61" << 0x3401 << 0xA << qlonglong(61) << false;
    QTest::newRow("fault") << "OR6041,0,8h" << 0x6041 << 0 << qlonglong(8) << true;
}

void TstRefgoCodec::parsesObjectRead()
{
    QFETCH(QString, line);
    QFETCH(int, index);
    QFETCH(int, sub);
    QFETCH(qlonglong, value);
    QFETCH(bool, hex);
    const auto r = refgo::parseObjectRead(line);
    QVERIFY2(r.ok(), qPrintable(r.error().toString()));
    QCOMPARE(r->address, ObjectAddress(quint16(index), quint8(sub)));
    QCOMPARE(qlonglong(r->value), value);
    QCOMPARE(r->hex, hex);
}

void TstRefgoCodec::refusesObjectReadWithoutValue_data()
{
    QTest::addColumn<QString>("line");
    QTest::newRow("two fields") << "OR6067,0";
    QTest::newRow("empty value") << "OR6067,0,";
    QTest::newRow("not numeric") << "OR6067,0,abc";
    QTest::newRow("OW acknowledgement") << "OW6067,0,100,OK";
    QTest::newRow("bare number") << "100";
    QTest::newRow("four fields") << "OR6067,0,1,2";
}

void TstRefgoCodec::refusesObjectReadWithoutValue()
{
    QFETCH(QString, line);
    const auto r = refgo::parseObjectRead(line);
    QVERIFY(!r.ok());
    QCOMPARE(r.error().kind(), Error::Kind::InvalidArgument);
}

void TstRefgoCodec::parsesTpsr_data()
{
    QTest::addColumn<QString>("line");
    QTest::addColumn<uint>("raw");
    QTest::addColumn<bool>("error");
    QTest::addColumn<bool>("reference");
    QTest::addColumn<bool>("inMotion");
    QTest::addColumn<bool>("inPosition");
    QTest::addColumn<bool>("voltage");
    QTest::newRow("table example")
        << "00000106" << 0x106u << false << true << true << false << true;
    QTest::newRow("docklight moving")
        << "00000006" << 0x6u << false << true << true << false << false;
    QTest::newRow("docklight in position")
        << "0000000a" << 0xAu << false << true << false << true << false;
    QTest::newRow("upper-case tolerated")
        << "0000000A" << 0xAu << false << true << false << true << false;
    QTest::newRow("error") << "00000003" << 0x3u << true << true << false << false << false;
}

void TstRefgoCodec::parsesTpsr()
{
    QFETCH(QString, line);
    QFETCH(uint, raw);
    QFETCH(bool, error);
    QFETCH(bool, reference);
    QFETCH(bool, inMotion);
    QFETCH(bool, inPosition);
    QFETCH(bool, voltage);
    const auto s = refgo::parseTpsr(line);
    QVERIFY2(s.ok(), qPrintable(s.error().toString()));
    QCOMPARE(s->raw, raw);
    QCOMPARE(s->error(), error);
    QCOMPARE(s->reference(), reference);
    QCOMPARE(s->inMotion(), inMotion);
    QCOMPARE(s->inPosition(), inPosition);
    QCOMPARE(s->inverterVoltage(), voltage);
}

void TstRefgoCodec::refusesTpsrNotEightHexDigits_data()
{
    QTest::addColumn<QString>("line");
    QTest::newRow("short") << "106";
    QTest::newRow("long") << "000000106";
    QTest::newRow("not hex") << "0000000g";
    QTest::newRow("sign") << "+0000006";
    QTest::newRow("empty") << "";
}

void TstRefgoCodec::refusesTpsrNotEightHexDigits()
{
    QFETCH(QString, line);
    QVERIFY(!refgo::parseTpsr(line).ok());
}

void TstRefgoCodec::formatsTpsrLowerCase()
{
    QCOMPARE(formatTpsr(0xA), QStringLiteral("0000000a"));
    QCOMPARE(formatTpsr(0x106), QStringLiteral("00000106"));
    QCOMPARE(formatTpsr(0xFFFFFFFF), QStringLiteral("ffffffff"));
}

void TstRefgoCodec::parsesTs_data()
{
    QTest::addColumn<QString>("line");
    QTest::addColumn<int>("status");
    QTest::addColumn<QString>("name");
    QTest::newRow("0") << "0" << 0 << "Power Off";
    QTest::newRow("1") << "1" << 1 << "Power On";
    QTest::newRow("2") << "2" << 2 << "Moving";
    QTest::newRow("9") << "9" << 9 << "Error";
}

void TstRefgoCodec::parsesTs()
{
    QFETCH(QString, line);
    QFETCH(int, status);
    QFETCH(QString, name);
    const auto s = refgo::parseTs(line);
    QVERIFY(s.ok());
    QCOMPARE(int(s.value()), status);
    QCOMPARE(simpleStatusName(s.value()), name);
}

void TstRefgoCodec::refusesUnknownTs()
{
    QVERIFY(!refgo::parseTs(QStringLiteral("3")).ok());
    QVERIFY(!refgo::parseTs(QStringLiteral("x")).ok());
    QVERIFY(!refgo::parseTs(QString()).ok());
}

QTEST_GUILESS_MAIN(TstRefgoCodec)
#include "tst_refgocodec.moc"
