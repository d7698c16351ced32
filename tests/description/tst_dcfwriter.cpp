// DCF export: values written per CiA 306, atomically, and read back to the same values.
#include "description/dcfwriter.h"
#include "description/devicedescription.h"
#include "description/edsloader.h"
#include "objectdefs.h"

#include "descriptiontestutil.h"

#include <QDir>
#include <QTemporaryDir>
#include <QTest>

using namespace db;
using db::test::hasWarning;
using db::test::sharedFile;

namespace {

// A dictionary with every kind of value a DCF has to carry.
ObjectDictionary handMade()
{
    ObjectDictionary d;
    d.identity.vendorName = QStringLiteral("ACME");
    d.identity.vendorId = 0x1234;
    d.identity.productName = QStringLiteral("Widget");
    d.identity.productCode = 77;
    d.identity.revision = QStringLiteral("0x00010002");
    d.insert(test::namedObjectDef(0x1000, 0, DataType::Unsigned32, Access::ReadOnly,
                                  QStringLiteral("Device type")));
    d.insert(test::namedObjectDef(0x1008, 0, DataType::VisibleString, Access::Const,
                                  QStringLiteral("Name")));
    ObjectDef i16 = test::namedObjectDef(0x2000, 0, DataType::Integer16, Access::ReadWrite,
                                         QStringLiteral("Offset"));
    i16.minimum = QVariant::fromValue(-100LL);
    i16.maximum = QVariant::fromValue(100LL);
    i16.defaultValue = QVariant::fromValue(-5LL);
    i16.pdoMappable = true;
    i16.unit = QStringLiteral("mm");
    i16.factor = 0.01;
    d.insert(i16);
    d.insert(test::namedObjectDef(0x2001, 0, DataType::Real32, Access::ReadWrite,
                                  QStringLiteral("Gain")));
    d.insert(test::namedObjectDef(0x2002, 0, DataType::Domain, Access::ReadWrite,
                                  QStringLiteral("Blob")));
    d.insert(test::namedObjectDef(0x2003, 0, DataType::Integer48, Access::ReadWrite,
                                  QStringLiteral("Wide")));
    d.insert(test::namedObjectDef(0x2004, 0, DataType::Unsigned64, Access::ReadWrite,
                                  QStringLiteral("Big")));
    d.insert(test::namedObjectDef(0x3000, 0, DataType::Unsigned8, Access::ReadOnly,
                                  QStringLiteral("Count"), QStringLiteral("Table")));
    d.insert(test::namedObjectDef(0x3000, 1, DataType::Integer32, Access::ReadWrite,
                                  QStringLiteral("A"), QStringLiteral("Table")));
    d.insert(test::namedObjectDef(0x3000, 2, DataType::Integer32, Access::WriteOnly,
                                  QStringLiteral("B"), QStringLiteral("Table")));
    return d;
}

QMap<ObjectAddress, QVariant> handMadeValues()
{
    return {
        { { 0x1000, 0 }, QVariant::fromValue(0x00020192ULL) },
        { { 0x1008, 0 }, QStringLiteral("drive; no. 1 [left]") },
        { { 0x2000, 0 }, QVariant::fromValue(-42LL) },
        { { 0x2001, 0 }, QVariant(double(1.25f)) },
        { { 0x2002, 0 }, QByteArray("\x00\x01\xFF\x10", 4) },
        { { 0x2003, 0 }, QVariant::fromValue(-140737488355328LL) },
        { { 0x2004, 0 }, QVariant::fromValue(0xFFFFFFFFFFFFFFFFULL) },
        { { 0x3000, 0 }, QVariant::fromValue(2ULL) },
        { { 0x3000, 2 }, QVariant::fromValue(-7LL) },
        { { 0x7000, 0 }, QVariant::fromValue(1ULL) }, // unknown to the dictionary: left out
    };
}

} // namespace

class TestDcfWriter : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void textFollowsCia306();
    void deviceInfoComesFromTheDevice();
    void roundTripKeepsValuesAndDefinitions();
    void roundTripOfRealFiles_data();
    void roundTripOfRealFiles();
    void unwritablePathFailsCleanly();
};

void TestDcfWriter::textFollowsCia306()
{
    const QString text =
        QString::fromUtf8(dcfText(handMade(), handMadeValues(), { 5, 500, QStringLiteral("left") },
                                  QDateTime(QDate(2024, 3, 1), QTime(14, 5))));
    QVERIFY(text.contains(QStringLiteral("[DeviceComissioning]\nNodeID=5\nNodeName=left\n"
                                         "Baudrate=500\n")));
    QVERIFY(text.contains(QStringLiteral("VendorNumber=0x00001234\n")));
    QVERIFY(text.contains(QStringLiteral("CreationDate=03-01-2024\n")));
    QVERIFY(text.contains(QStringLiteral("[MandatoryObjects]\nSupportedObjects=1\n1=0x1000\n")));
    QVERIFY(text.contains(QStringLiteral("[ManufacturerObjects]\nSupportedObjects=6\n")));
    QVERIFY(text.contains(QStringLiteral("[1000]\nParameterName=Device type\nObjectType=0x7\n"
                                         "DataType=0x0007\nAccessType=ro\nPDOMapping=0\n"
                                         "ParameterValue=0x00020192\n")));
    QVERIFY(text.contains(QStringLiteral("LowLimit=-100\nHighLimit=100\nUnit=mm\nFactor=0.01\n")));
    QVERIFY(text.contains(QStringLiteral("ParameterValue=-42\n")));
    QVERIFY(text.contains(QStringLiteral("ParameterValue=0001FF10\n")));
    QVERIFY(text.contains(QStringLiteral("[3000]\nParameterName=Table\nObjectType=0x8\n"
                                         "SubNumber=3\n")));
    QVERIFY(text.contains(QStringLiteral("[3000sub2]\nParameterName=B\n")));
    QVERIFY(!text.contains(QStringLiteral("[7000]")));
}

void TestDcfWriter::deviceInfoComesFromTheDevice()
{
    ObjectDictionary d = handMade();
    d.identity.productCode = 0; // the description does not know it
    d.identity.revision = QStringLiteral("1.0 beta"); // free text, not a number
    const QString unknown = QString::fromUtf8(dcfText(d, {}, {}));
    QVERIFY2(!unknown.contains(QStringLiteral("ProductNumber=")), qPrintable(unknown));
    QVERIFY(!unknown.contains(QStringLiteral("RevisionNumber=")));
    QVERIFY(unknown.contains(QStringLiteral("VendorNumber=0x00001234\n")));

    QMap<ObjectAddress, QVariant> values;
    values.insert(ObjectAddress(0x1018, 1), QVariant::fromValue(0x2D6u));
    values.insert(ObjectAddress(0x1018, 2), QVariant::fromValue(0x1234ABCDu));
    values.insert(ObjectAddress(0x1018, 3), QVariant::fromValue(0x10002u));
    const QString text = QString::fromUtf8(dcfText(d, values, {}));
    QVERIFY2(text.contains(QStringLiteral("VendorNumber=0x000002D6\n")), qPrintable(text));
    QVERIFY(text.contains(QStringLiteral("ProductNumber=0x1234ABCD\n")));
    QVERIFY(text.contains(QStringLiteral("RevisionNumber=0x00010002\n")));

    d.identity.revision = QStringLiteral("0x00030001"); // a numeric description revision
    QVERIFY(QString::fromUtf8(dcfText(d, {}, {}))
                .contains(QStringLiteral("RevisionNumber=0x00030001\n")));
}

void TestDcfWriter::roundTripKeepsValuesAndDefinitions()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("widget.dcf"));
    const ObjectDictionary original = handMade();
    const auto values = handMadeValues();
    QVERIFY(writeDcf(path, original, values, { 5, 500, QStringLiteral("left") }).ok());
    const auto back = loadDeviceDescription(path);
    QVERIFY2(back.ok(), qPrintable(back.error().toString()));
    QVERIFY2(back->warnings.isEmpty(), qPrintable(back->warnings.join(u'\n')));
    QCOMPARE(back->format, DescriptionLoad::Format::Dcf);
    QCOMPARE(back->nodeId, std::optional<quint8>(5));
    QCOMPARE(back->bitrateKbit, std::optional<quint32>(500));
    QCOMPARE(back->dictionary.identity.vendorId, 0x1234u);
    QCOMPARE(back->dictionary.identity.productName, QStringLiteral("Widget"));
    QCOMPARE(back->dictionary.size(), original.size());
    for (const ObjectDef &d : original.objects()) {
        const ObjectDef *b = back->dictionary.find(d.address);
        QVERIFY2(b, qPrintable(d.address.toString()));
        QCOMPARE(b->name, d.name);
        QCOMPARE(b->type, d.type);
        QCOMPARE(b->access, d.access);
        QCOMPARE(b->defaultValue, d.defaultValue);
        QCOMPARE(b->minimum, d.minimum);
        QCOMPARE(b->maximum, d.maximum);
        QCOMPARE(b->pdoMappable, d.pdoMappable);
        QCOMPARE(b->unit, d.unit);
        QCOMPARE(b->factor, d.factor);
    }
    auto expected = values;
    expected.remove({ 0x7000, 0 });
    QCOMPARE(back->values.keys(), expected.keys());
    for (auto it = expected.cbegin(); it != expected.cend(); ++it)
        QCOMPARE(back->values.value(it.key()),
                 codec::normalize(original.find(it.key())->type, it.value()).value());
}

void TestDcfWriter::roundTripOfRealFiles_data()
{
    QTest::addColumn<QString>("file");
    QTest::newRow("sample.eds") << QStringLiteral("fixtures/eds/sample.eds");
    QTest::newRow("datatypes.eds") << QStringLiteral("fixtures/eds/datatypes.eds");
    QTest::newRow("NM170.eds") << QStringLiteral("specs/NM170.eds");
    QTest::newRow("MC349_ETH.xdd") << QStringLiteral("fixtures/xdd/MC349_ETH.xdd");
}

// Every object with its default as the "current value": the DCF carries them all back.
void TestDcfWriter::roundTripOfRealFiles()
{
    QFETCH(QString, file);
    const QString source = sharedFile(file);
    if (!QFile::exists(source))
        QSKIP("shared fixture not present");
    const auto loaded = loadDeviceDescription(source, DescriptionOptions { quint8(3) });
    QVERIFY2(loaded.ok(), qPrintable(loaded.error().toString()));
    QMap<ObjectAddress, QVariant> values;
    for (const ObjectDef &d : loaded->dictionary.objects()) {
        if (d.defaultValue.isValid())
            values.insert(d.address, d.defaultValue);
    }
    QVERIFY(values.size() > 20);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("out.dcf"));
    QVERIFY(writeDcf(path, loaded->dictionary, values, { 3, 250, {} }).ok());
    const auto back = loadDeviceDescription(path);
    QVERIFY2(back.ok(), qPrintable(back.error().toString()));
    QCOMPARE(back->dictionary.size(), loaded->dictionary.size());
    QCOMPARE(back->values, values);
    QCOMPARE(back->nodeId, std::optional<quint8>(3));
}

void TestDcfWriter::unwritablePathFailsCleanly()
{
    const auto r = writeDcf(QStringLiteral("/nonexistent-dir/x.dcf"), handMade(), {}, {});
    QVERIFY(!r.ok());
    QVERIFY(r.error().message().contains(QStringLiteral("/nonexistent-dir/x.dcf")));
    QVERIFY(!QFile::exists(QStringLiteral("/nonexistent-dir/x.dcf")));
}

QTEST_GUILESS_MAIN(TestDcfWriter)
#include "tst_dcfwriter.moc"
