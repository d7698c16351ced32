// The two ways object addresses are written: CANopen's hex INDEX:SUB and the decimal
// NUMBER:DATASET of inverter parameter lists. The same text means different objects in each.
#include "core/addressformat.h"

#include <QTest>

using namespace db;

class TestAddressFormat : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void canopenParsesHex_data();
    void canopenParsesHex();
    void parameterParsesDecimal_data();
    void parameterParsesDecimal();
    void parameterRefusesWithTheExpectedForm_data();
    void parameterRefusesWithTheExpectedForm();
    void canopenRefusesWithTheExpectedForm();
    void sameTextDifferentObject();
    void formatsCanonically();
    void roundTrips_data();
    void roundTrips();
    void limits();
    void findsFormatsByKey();
    void describesItself();
};

void TestAddressFormat::canopenParsesHex_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<int>("index");
    QTest::addColumn<int>("sub");
    QTest::newRow("cli") << "6041:0" << 0x6041 << 0;
    QTest::newRow("hex sub") << "3401:1A" << 0x3401 << 0x1A;
    QTest::newRow("0x") << "0x6040:0x00" << 0x6040 << 0;
    QTest::newRow("h notation") << "3511h.08h" << 0x3511 << 8;
    QTest::newRow("index only") << "6041" << 0x6041 << 0;
    QTest::newRow("digits only are still hex") << "372:2" << 0x372 << 2;
}

void TestAddressFormat::canopenParsesHex()
{
    QFETCH(QString, text);
    QFETCH(int, index);
    QFETCH(int, sub);
    const auto a = AddressFormat::canopen().parse(text);
    QVERIFY2(a.ok(), qPrintable(a.error().toString()));
    QCOMPARE(int(a->index), index);
    QCOMPARE(int(a->sub), sub);
}

void TestAddressFormat::parameterParsesDecimal_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<int>("index");
    QTest::addColumn<int>("sub");
    QTest::newRow("number:dataset") << "372:2" << 372 << 2;
    QTest::newRow("number alone is data set 0") << "12" << 12 << 0;
    QTest::newRow("dot") << "1100.5" << 1100 << 5;
    QTest::newRow("comma") << "1100,9" << 1100 << 9;
    QTest::newRow("spaces") << "  372 : 2 " << 372 << 2;
    QTest::newRow("leading zeros are decimal") << "0372:02" << 372 << 2;
    QTest::newRow("zero") << "0:0" << 0 << 0;
    QTest::newRow("largest") << "65535:255" << 65535 << 255;
}

void TestAddressFormat::parameterParsesDecimal()
{
    QFETCH(QString, text);
    QFETCH(int, index);
    QFETCH(int, sub);
    const auto a = AddressFormat::parameter().parse(text);
    QVERIFY2(a.ok(), qPrintable(a.error().toString()));
    QCOMPARE(int(a->index), index);
    QCOMPARE(int(a->sub), sub);
}

void TestAddressFormat::parameterRefusesWithTheExpectedForm_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<int>("kind");
    const int invalid = int(Error::Kind::InvalidArgument);
    const int range = int(Error::Kind::OutOfRange);
    QTest::newRow("empty") << "" << invalid;
    QTest::newRow("hex digits") << "6041:0A" << invalid;
    QTest::newRow("hex index") << "60FD:0" << invalid;
    QTest::newRow("0x prefix") << "0x174:0" << invalid;
    QTest::newRow("h suffix") << "372h" << invalid;
    QTest::newRow("negative") << "-1:0" << invalid;
    QTest::newRow("missing data set") << "372:" << invalid;
    QTest::newRow("words") << "speed" << invalid;
    QTest::newRow("three parts") << "372:2:1" << invalid;
    QTest::newRow("six digit number") << "100000:0" << invalid;
    QTest::newRow("number too large") << "65536:0" << range;
    QTest::newRow("data set too large") << "372:256" << range;
}

void TestAddressFormat::parameterRefusesWithTheExpectedForm()
{
    QFETCH(QString, text);
    QFETCH(int, kind);
    const auto a = AddressFormat::parameter().parse(text);
    QVERIFY(!a.ok());
    QCOMPARE(int(a.error().kind()), kind);
    const QString message = a.error().message();
    QVERIFY2(message.contains(QLatin1String("NUMBER:DATASET")), qPrintable(message));
    QVERIFY2(message.contains(QLatin1String("372:2")), qPrintable(message));
    if (!text.isEmpty())
        QVERIFY2(message.contains(text), qPrintable(message));
}

void TestAddressFormat::canopenRefusesWithTheExpectedForm()
{
    for (const QString &text : { QStringLiteral("statusword"), QStringLiteral("16041:0"),
                                 QStringLiteral("6041:100"), QStringLiteral("6041:") }) {
        const auto a = AddressFormat::canopen().parse(text);
        QVERIFY2(!a.ok(), qPrintable(text));
        QCOMPARE(a.error().kind(), Error::Kind::InvalidArgument);
        QVERIFY2(a.error().message().contains(QLatin1String("INDEX:SUB")),
                 qPrintable(a.error().message()));
        QVERIFY2(a.error().message().contains(QLatin1String("6041:0")),
                 qPrintable(a.error().message()));
    }
}

void TestAddressFormat::sameTextDifferentObject()
{
    const auto hex = AddressFormat::canopen().parse(QStringLiteral("372:2"));
    const auto decimal = AddressFormat::parameter().parse(QStringLiteral("372:2"));
    QVERIFY(hex.ok() && decimal.ok());
    QCOMPARE(*hex, ObjectAddress(0x372, 2));
    QCOMPARE(*decimal, ObjectAddress(372, 2));
    QVERIFY(*hex != *decimal);
}

void TestAddressFormat::formatsCanonically()
{
    QCOMPARE(AddressFormat::canopen().format({ 0x6041, 0 }), QStringLiteral("6041:0"));
    QCOMPARE(AddressFormat::canopen().format({ 0x3401, 0x1A }), QStringLiteral("3401:1A"));
    QCOMPARE(AddressFormat::canopen().format({ 0x1A, 0 }), QStringLiteral("001A:0"));
    QCOMPARE(AddressFormat::parameter().format({ 372, 2 }), QStringLiteral("372:2"));
    QCOMPARE(AddressFormat::parameter().format({ 12, 0 }), QStringLiteral("12:0"));
    QCOMPARE(AddressFormat::parameter().format({ 65535, 255 }), QStringLiteral("65535:255"));
    QCOMPARE(AddressFormat::parameter().format({ 0x6041, 0 }), QStringLiteral("24641:0"));
}

void TestAddressFormat::roundTrips_data()
{
    QTest::addColumn<QString>("key");
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("canonical");
    QTest::newRow("canopen") << "canopen"
                             << "6041:0"
                             << "6041:0";
    QTest::newRow("canopen spelled otherwise") << "canopen"
                                               << "0x3511h.08h"
                                               << "3511:8";
    QTest::newRow("canopen index only") << "canopen"
                                        << "1a"
                                        << "001A:0";
    QTest::newRow("parameter") << "parameter"
                               << "372:2"
                               << "372:2";
    QTest::newRow("parameter number alone") << "parameter"
                                            << "12"
                                            << "12:0";
    QTest::newRow("parameter dot, zeros") << "parameter"
                                          << "0372.05"
                                          << "372:5";
}

void TestAddressFormat::roundTrips()
{
    QFETCH(QString, key);
    QFETCH(QString, text);
    QFETCH(QString, canonical);
    const AddressFormat *format = AddressFormat::byKey(key);
    QVERIFY(format);
    const auto parsed = format->parse(text);
    QVERIFY2(parsed.ok(), qPrintable(parsed.error().toString()));
    QCOMPARE(format->format(*parsed), canonical);
    const auto again = format->parse(canonical);
    QVERIFY(again.ok());
    QCOMPARE(*again, *parsed);
}

void TestAddressFormat::limits()
{
    // Every corner of the address space survives format() then parse() in both formats.
    for (const AddressFormat *format : { &AddressFormat::canopen(), &AddressFormat::parameter() }) {
        for (const quint16 index : { quint16(0), quint16(1), quint16(0x174), quint16(0xFFFF) }) {
            for (const quint8 sub : { quint8(0), quint8(9), quint8(0x10), quint8(0xFF) }) {
                const ObjectAddress a(index, sub);
                const auto back = format->parse(format->format(a));
                QVERIFY2(back.ok(), qPrintable(format->format(a)));
                QCOMPARE(*back, a);
            }
        }
    }
}

void TestAddressFormat::findsFormatsByKey()
{
    QCOMPARE(AddressFormat::byKey(QStringLiteral("canopen")), &AddressFormat::canopen());
    QCOMPARE(AddressFormat::byKey(QStringLiteral("parameter")), &AddressFormat::parameter());
    QCOMPARE(AddressFormat::byKey(QStringLiteral("hex")), nullptr);
    QCOMPARE(AddressFormat::byKey(QString()), nullptr);
    QCOMPARE(AddressFormat::canopen().key(), QStringLiteral("canopen"));
    QCOMPARE(AddressFormat::parameter().key(), QStringLiteral("parameter"));
}

void TestAddressFormat::describesItself()
{
    // The example is what the format prints for it, so help texts show a form that parses.
    for (const AddressFormat *format : { &AddressFormat::canopen(), &AddressFormat::parameter() }) {
        const auto example = format->parse(format->example());
        QVERIFY(example.ok());
        QCOMPARE(format->format(*example), format->example());
    }
    QCOMPARE(AddressFormat::parameter().indexName(), QStringLiteral("parameter"));
    QCOMPARE(AddressFormat::parameter().subName(), QStringLiteral("data set"));
    QCOMPARE(AddressFormat::canopen().indexName(), QStringLiteral("index"));
    QCOMPARE(AddressFormat::canopen().subName(), QStringLiteral("sub-index"));
}

QTEST_GUILESS_MAIN(TestAddressFormat)
#include "tst_addressformat.moc"
