#include "core/objectaddress.h"

#include <QTest>

using namespace db;

class TestObjectAddress : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void parsesTheUsualSpellings_data();
    void parsesTheUsualSpellings();
    void refusesGarbage_data();
    void refusesGarbage();
    void formatsForTheCli();
    void ordersByIndexThenSub();
};

void TestObjectAddress::parsesTheUsualSpellings_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<int>("index");
    QTest::addColumn<int>("sub");
    QTest::newRow("cli") << "6041:0" << 0x6041 << 0;
    QTest::newRow("padded sub") << "3401:1A" << 0x3401 << 0x1A;
    QTest::newRow("0x prefixes") << "0x6040:0x00" << 0x6040 << 0;
    QTest::newRow("manual h notation") << "3511h.08h" << 0x3511 << 8;
    QTest::newRow("dot") << "6092.1" << 0x6092 << 1;
    QTest::newRow("comma like RefGo") << "3511,8" << 0x3511 << 8;
    QTest::newRow("sub keyword") << "1018sub4" << 0x1018 << 4;
    QTest::newRow("index only") << "6041" << 0x6041 << 0;
    QTest::newRow("lower case and spaces") << " 60fd : a " << 0x60FD << 0x0A;
}

void TestObjectAddress::parsesTheUsualSpellings()
{
    QFETCH(QString, text);
    QFETCH(int, index);
    QFETCH(int, sub);
    const auto a = ObjectAddress::parse(text);
    QVERIFY2(a.ok(), qPrintable(a.error().toString()));
    QCOMPARE(int(a->index), index);
    QCOMPARE(int(a->sub), sub);
}

void TestObjectAddress::refusesGarbage_data()
{
    QTest::addColumn<QString>("text");
    QTest::newRow("empty") << "";
    QTest::newRow("five digit index") << "16041:0";
    QTest::newRow("three digit sub") << "6041:100";
    QTest::newRow("words") << "statusword";
    QTest::newRow("missing sub") << "6041:";
}

void TestObjectAddress::refusesGarbage()
{
    QFETCH(QString, text);
    const auto a = ObjectAddress::parse(text);
    QVERIFY(!a.ok());
    QCOMPARE(a.error().kind(), Error::Kind::InvalidArgument);
    QVERIFY(a.error().message().contains(QLatin1String("6041:0"))); // tells how to write it
}

void TestObjectAddress::formatsForTheCli()
{
    QCOMPARE(ObjectAddress(0x6041, 0).toString(), QStringLiteral("6041:0"));
    QCOMPARE(ObjectAddress(0x3401, 0x1A).toString(), QStringLiteral("3401:1A"));
    QCOMPARE(ObjectAddress(0x1A, 0).toString(), QStringLiteral("001A:0"));
}

void TestObjectAddress::ordersByIndexThenSub()
{
    QVERIFY(ObjectAddress(0x1000, 5) < ObjectAddress(0x1001, 0));
    QVERIFY(ObjectAddress(0x6092, 1) < ObjectAddress(0x6092, 2));
    QCOMPARE(ObjectAddress(0x6092, 1), ObjectAddress::parse(QStringLiteral("6092:1")).value());
}

QTEST_GUILESS_MAIN(TestObjectAddress)
#include "tst_objectaddress.moc"
