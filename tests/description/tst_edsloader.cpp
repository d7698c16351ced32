// CiA 306 EDS/DCF loader: the real files in ../shared (read in place, skipped when absent) and
// hand-written snippets for the edge cases real-world files have.
#include "description/devicedescription.h"
#include "description/edsloader.h"

#include "descriptiontestutil.h"

#include <QDir>
#include <QTemporaryDir>
#include <QTest>

using namespace db;
using db::test::hasWarning;
using db::test::sharedFile;

namespace {

// A minimal valid EDS around the given object sections.
QByteArray eds(const QByteArray &objects)
{
    return "[FileInfo]\nFileVersion=1\n[DeviceInfo]\nVendorName=Test\nVendorNumber=0x42\n"
           "ProductName=Snippet\n"
        + objects;
}

DescriptionLoad parsed(const QByteArray &data, std::optional<quint8> nodeId = std::nullopt)
{
    auto r = parseEds(data, QStringLiteral("snippet.eds"), DescriptionOptions { nodeId });
    if (!r)
        qWarning("%s", qPrintable(r.error().toString()));
    return r.valueOr(DescriptionLoad());
}

} // namespace

class TestEdsLoader : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void sampleDcfLoads();
    void datatypesCatalogLoads();
    void nm170Loads();
    void nodeIdExpressions_data();
    void nodeIdExpressions();
    void symbolicNodeIdResolvesLater();
    void numberFormats();
    void missingFieldsGetDefaultsWithWarnings();
    void compactSubObjExpands();
    void objectTypesAndSubIndexCount();
    void accessTypes_data();
    void accessTypes();
    void oddBitWidths();
    void crlfBomAndLatin1();
    void duplicatesAndUnknownSections();
    void brokenFilesGiveClearErrors_data();
    void brokenFilesGiveClearErrors();
    void dispatcherChoosesByContent();
};

void TestEdsLoader::sampleDcfLoads()
{
    const QString path = sharedFile(QStringLiteral("fixtures/eds/sample.eds"));
    if (!QFile::exists(path))
        QSKIP("shared fixture sample.eds not present");
    const auto r = loadDeviceDescription(path);
    QVERIFY2(r.ok(), qPrintable(r.error().toString()));
    const ObjectDictionary &d = r->dictionary;
    QCOMPARE(d.identity.vendorName, QStringLiteral("Vendor Name"));
    QCOMPARE(d.identity.vendorId, 1u);
    QCOMPARE(r->format, DescriptionLoad::Format::Eds);
    // [DeviceComissioning] NodeID=0x10, Baudrate=500
    QCOMPARE(r->nodeId, std::optional<quint8>(0x10));
    QCOMPARE(r->bitrateKbit, std::optional<quint32>(500));
    // DefaultValue=$NODEID+512 and 1280+$NODEID, resolved with the DCF's own node id
    QCOMPARE(d.find({ 0x1400, 1 })->defaultValue.toULongLong(), 0x10ull + 512);
    QCOMPARE(d.find({ 0x1403, 1 })->defaultValue.toULongLong(), 0x10ull + 1280);
    QCOMPARE(r->nodeIdDefaults.value({ 0x1400, 1 }), 512);
    QCOMPARE(d.find({ 0x1018, 0 })->access, Access::Const);
    QCOMPARE(d.find({ 0x1008, 0 })->defaultValue.toString(), QStringLiteral("TEST DEVICE"));
    QVERIFY(d.find({ 0x1001, 0 })->pdoMappable);
    // 1018sub3 and 1003sub2/6/8 are left out in the file
    QVERIFY(!d.contains({ 0x1018, 3 }));
    QCOMPARE(d.subObjects(0x1003).size(), 6);
    QVERIFY(hasWarning(*r, QStringLiteral("[1018]: SubNumber=5 but 4")));
    // CompactSubObj=3 with [3004Name], CompactSubObj=24 without
    QCOMPARE(d.subObjects(0x3004).size(), 4);
    QCOMPARE(d.find({ 0x3004, 2 })->name, QStringLiteral("Sensor Status 2"));
    QCOMPARE(d.find({ 0x3004, 2 })->type, DataType::Unsigned16);
    QCOMPARE(d.find({ 0x3004, 2 })->defaultValue.toULongLong(), 3ull);
    QCOMPARE(d.find({ 0x3004, 0 })->defaultValue.toULongLong(), 3ull);
    QCOMPARE(d.find({ 0x3006, 24 })->name, QStringLiteral("Valve 1 % Open24"));
    QCOMPARE(d.find({ 0x3006, 24 })->type, DataType::Real32);
    // hex limits are bit patterns of the type
    QCOMPARE(d.find({ 0x3030, 0 })->maximum.toLongLong(), -1LL);
    QCOMPARE(d.find({ 0x3030, 0 })->minimum.toLongLong(), qlonglong(INT32_MIN));
    QCOMPARE(d.find({ 0x3040, 0 })->minimum.toLongLong(), -10LL);
    QCOMPARE(d.find({ 0x3040, 0 })->maximum.toLongLong(), 10LL);
    QCOMPARE(d.find({ 0x3010, 0 })->type, DataType::Real32);
    QCOMPARE(d.find({ 0x3050, 1 })->unit, QStringLiteral("mV"));
    QCOMPARE(d.find({ 0x3050, 1 })->factor, 0.1);
    QVERIFY(hasWarning(*r, QStringLiteral("Factor 'ERROR'")));
    QVERIFY(hasWarning(*r, QStringLiteral("[2020]: DataType 0x40")));
    QCOMPARE(d.find({ 0x2020, 0 })->type, DataType::Domain);
    QVERIFY(hasWarning(*r, QStringLiteral("[3003]: ARRAY/RECORD without")));
    QVERIFY(!d.contains({ 0x3003, 0 }));
    // ParameterValue: 1018sub1=1, 3002=5.200000
    QCOMPARE(r->values.value({ 0x1018, 1 }).toULongLong(), 1ull);
    QCOMPARE(r->values.value({ 0x3002, 0 }).toDouble(), double(5.2f));
}

void TestEdsLoader::datatypesCatalogLoads()
{
    const QString path = sharedFile(QStringLiteral("fixtures/eds/datatypes.eds"));
    if (!QFile::exists(path))
        QSKIP("shared fixture datatypes.eds not present");
    const auto r = loadDeviceDescription(path);
    QVERIFY2(r.ok(), qPrintable(r.error().toString()));
    const ObjectDictionary &d = r->dictionary;
    QCOMPARE(d.identity.productName, QStringLiteral("Alltypes"));
    QCOMPARE(d.size(), 28); // 1018 with 5 sub-indices + 23 typed objects
    QVERIFY(r->warnings.isEmpty());
    QCOMPARE(d.find({ 0x2010, 0 })->type, DataType::Integer24);
    QCOMPARE(d.find({ 0x2010, 0 })->defaultValue.toLongLong(), -1LL);
    QCOMPARE(d.find({ 0x2014, 0 })->type, DataType::Integer56);
    QCOMPARE(d.find({ 0x2014, 0 })->defaultValue.toLongLong(), -56LL);
    QCOMPARE(d.find({ 0x201A, 0 })->type, DataType::Unsigned56);
    QCOMPARE(d.find({ 0x2006, 0 })->defaultValue.toULongLong(), 8198ull);
    QCOMPARE(d.find({ 0x2011, 0 })->defaultValue.toDouble(), 1.6);
    QCOMPARE(d.find({ 0x200B, 0 })->defaultValue.toString(), QString::fromUtf8("abc\u2713"));
    QCOMPARE(d.find({ 0x200A, 0 })->defaultValue.toByteArray(), QByteArray("\xAB\xCD"));
    QVERIFY(d.find({ 0x2001, 0 })->pdoMappable);
}

void TestEdsLoader::nm170Loads()
{
    const QString path = sharedFile(QStringLiteral("specs/NM170.eds"));
    if (!QFile::exists(path))
        QSKIP("shared NM170.eds not present");
    const auto r = loadDeviceDescription(path);
    QVERIFY2(r.ok(), qPrintable(r.error().toString()));
    const ObjectDictionary &d = r->dictionary;
    QCOMPARE(d.identity.vendorName, QStringLiteral("Baumer"));
    QCOMPARE(d.identity.vendorId, 0xECu);
    QCOMPARE(d.identity.productCode, 0x70u);
    QCOMPARE(d.identity.revision, QStringLiteral("0x00010001"));
    QCOMPARE(d.find({ 0x1000, 0 })->defaultValue.toULongLong(), 0x00020196ull);
    // 1014 DefaultValue=$NODEID+0x80 stays symbolic: an EDS has no node id
    QVERIFY(!r->nodeId);
    QVERIFY(!d.find({ 0x1014, 0 })->defaultValue.isValid());
    QCOMPARE(r->nodeIdDefaults.value({ 0x1014, 0 }), 0x80);
    QCOMPARE(d.find({ 0x1014, 0 })->minimum.toULongLong(), 0x81ull);
    // 204Dh: sub 0 says 2 although sub 3 (Start jog) is documented (the file's Comments Line5)
    QVERIFY(d.contains({ 0x204D, 3 }));
    QVERIFY(hasWarning(*r, QStringLiteral("[204Dsub0]")));
    QCOMPARE(d.find({ 0x204E, 1 })->access, Access::ReadOnly);
    QVERIFY(d.find({ 0x204E, 1 })->pdoMappable);
}

void TestEdsLoader::nodeIdExpressions_data()
{
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<qulonglong>("expected");
    QTest::newRow("node+hex") << QByteArray("$NODEID+0x180") << 0x185ull;
    QTest::newRow("hex+node") << QByteArray("0x180+$NODEID") << 0x185ull;
    QTest::newRow("spaces") << QByteArray("$NODEID + 384") << 0x185ull;
    QTest::newRow("octal") << QByteArray("$NODEID+0600") << 0x185ull;
    QTest::newRow("lower case") << QByteArray("$nodeid+0x180") << 0x185ull;
    QTest::newRow("alone") << QByteArray("$NODEID") << 5ull;
}

void TestEdsLoader::nodeIdExpressions()
{
    QFETCH(QByteArray, text);
    QFETCH(qulonglong, expected);
    const auto load = parsed(eds("[1800]\nObjectType=9\nParameterName=TPDO\n"
                                 "[1800sub0]\nParameterName=n\nDataType=5\nAccessType=ro\n"
                                 "DefaultValue=1\n[1800sub1]\nParameterName=COB-ID\nDataType=7\n"
                                 "AccessType=rw\nDefaultValue="
                                 + text + "\n"),
                             5);
    QCOMPARE(load.dictionary.find({ 0x1800, 1 })->defaultValue.toULongLong(), expected);
}

void TestEdsLoader::symbolicNodeIdResolvesLater()
{
    auto load = parsed(eds("[1014]\nParameterName=COB-ID EMCY\nDataType=7\nAccessType=rw\n"
                           "DefaultValue=$NODEID+0x80\n[1015]\nParameterName=broken\n"
                           "DataType=7\nAccessType=rw\nDefaultValue=$NODEID*2\n"));
    QVERIFY(!load.dictionary.find({ 0x1014, 0 })->defaultValue.isValid());
    QCOMPARE(load.nodeIdDefaults.value({ 0x1014, 0 }), 0x80);
    QVERIFY(hasWarning(load, QStringLiteral("cannot evaluate '$NODEID*2'")));
    QVERIFY(load.resolveNodeId(3));
    QCOMPARE(load.dictionary.find({ 0x1014, 0 })->defaultValue.toULongLong(), 0x83ull);
}

void TestEdsLoader::numberFormats()
{
    const auto load = parsed(eds("[2000]\nParameterName=octal\nDataType=6\nAccessType=rw\n"
                                 "DefaultValue=010\nLowLimit=0x4\nHighLimit=0777\n"
                                 "[2001]\nParameterName=dec\nDataType=0x0003\nAccessType=rw\n"
                                 "DefaultValue=-10\nLowLimit=-0x10\n"
                                 "[2002]\nParameterName=zero\nDataType=05\nAccessType=rw\n"
                                 "DefaultValue=0\n"));
    QCOMPARE(load.dictionary.find({ 0x2000, 0 })->defaultValue.toULongLong(), 8ull);
    QCOMPARE(load.dictionary.find({ 0x2000, 0 })->minimum.toULongLong(), 4ull);
    QCOMPARE(load.dictionary.find({ 0x2000, 0 })->maximum.toULongLong(), 511ull);
    QCOMPARE(load.dictionary.find({ 0x2001, 0 })->defaultValue.toLongLong(), -10LL);
    QCOMPARE(load.dictionary.find({ 0x2001, 0 })->minimum.toLongLong(), -16LL);
    QCOMPARE(load.dictionary.find({ 0x2002, 0 })->type, DataType::Unsigned8);
    QVERIFY2(!hasWarning(load, QStringLiteral("[200")), qPrintable(load.warnings.join(u'\n')));
}

void TestEdsLoader::missingFieldsGetDefaultsWithWarnings()
{
    const auto load = parsed(eds("[2000]\nParameterName=no type\nAccessType=ro\n"
                                 "[2001]\nDataType=7\nAccessType=rw\n"
                                 "[2002]\nParameterName=no access\nDataType=7\n"
                                 "[2003]\nParameterName=bad default\nDataType=5\nAccessType=rw\n"
                                 "DefaultValue=300\nPDOMapping=maybe\nObjFlags=x\n"));
    QCOMPARE(load.dictionary.find({ 0x2000, 0 })->type, DataType::Domain);
    QVERIFY(hasWarning(load, QStringLiteral("[2000]: no DataType")));
    QCOMPARE(load.dictionary.find({ 0x2001, 0 })->name, QStringLiteral("Object 2001:0"));
    QVERIFY(hasWarning(load, QStringLiteral("[2001]: no ParameterName")));
    QCOMPARE(load.dictionary.find({ 0x2002, 0 })->access, Access::ReadWrite);
    QVERIFY(hasWarning(load, QStringLiteral("[2002]: no AccessType")));
    QVERIFY(!load.dictionary.find({ 0x2003, 0 })->defaultValue.isValid());
    QVERIFY(hasWarning(load, QStringLiteral("[2003]: defaultvalue ignored")));
    QVERIFY(hasWarning(load, QStringLiteral("PDOMapping 'maybe'")));
    QVERIFY(hasWarning(load, QStringLiteral("ObjFlags 'x'")));
}

void TestEdsLoader::compactSubObjExpands()
{
    const auto load = parsed(eds("[4000]\nParameterName=Gain\nObjectType=0x8\nCompactSubObj=3\n"
                                 "DataType=0x0004\nAccessType=rw\nDefaultValue=-7\nPDOMapping=1\n"
                                 "[4000Name]\nNrOfEntries=1\n2=Second gain\n"
                                 "[4000Value]\nNrOfEntries=1\n3=0x10\n"));
    const ObjectDictionary &d = load.dictionary;
    QCOMPARE(d.subObjects(0x4000).size(), 4);
    QCOMPARE(d.find({ 0x4000, 0 })->type, DataType::Unsigned8);
    QCOMPARE(d.find({ 0x4000, 0 })->access, Access::ReadOnly);
    QCOMPARE(d.find({ 0x4000, 0 })->defaultValue.toULongLong(), 3ull);
    QCOMPARE(d.find({ 0x4000, 1 })->name, QStringLiteral("Gain1"));
    QCOMPARE(d.find({ 0x4000, 2 })->name, QStringLiteral("Second gain"));
    QCOMPARE(d.find({ 0x4000, 3 })->objectName, QStringLiteral("Gain"));
    QCOMPARE(d.find({ 0x4000, 3 })->defaultValue.toLongLong(), -7LL);
    QVERIFY(d.find({ 0x4000, 3 })->pdoMappable);
    QCOMPARE(load.values.value({ 0x4000, 3 }).toLongLong(), 16LL);
}

void TestEdsLoader::objectTypesAndSubIndexCount()
{
    const auto load = parsed(eds("[0007]\nObjectType=5\nParameterName=UNSIGNED32\nDataType=7\n"
                                 "[0040]\nObjectType=6\nParameterName=my struct\nSubNumber=0\n"
                                 "[2100]\nObjectType=2\nParameterName=firmware\nAccessType=wo\n"
                                 "[2200]\nObjectType=9\nParameterName=rec\nSubNumber=2\n"
                                 "[2200sub2]\nParameterName=b\nDataType=6\nAccessType=rw\n"
                                 "[2300]\nObjectType=0x0D\nParameterName=weird\nDataType=5\n"
                                 "AccessType=ro\n"));
    QCOMPARE(load.typeDefinitions, 2);
    QVERIFY(!load.dictionary.contains({ 0x0007, 0 }));
    QCOMPARE(load.dictionary.find({ 0x2100, 0 })->type, DataType::Domain);
    QVERIFY(!hasWarning(load, QStringLiteral("[2100]")));
    // RECORD without sub 0: one is made, counting up to the highest sub-index
    QCOMPARE(load.dictionary.find({ 0x2200, 0 })->defaultValue.toULongLong(), 2ull);
    QCOMPARE(load.dictionary.find({ 0x2200, 2 })->objectName, QStringLiteral("rec"));
    QVERIFY(hasWarning(load, QStringLiteral("[2200]: no sub-index 0")));
    QVERIFY(hasWarning(load, QStringLiteral("[2200]: SubNumber=2 but 1")));
    QVERIFY(hasWarning(load, QStringLiteral("[2300]: unknown ObjectType")));
    QVERIFY(load.dictionary.contains({ 0x2300, 0 }));
}

void TestEdsLoader::accessTypes_data()
{
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<Access>("access");
    QTest::addColumn<bool>("warns");
    QTest::newRow("ro") << QByteArray("ro") << Access::ReadOnly << false;
    QTest::newRow("wo") << QByteArray("wo") << Access::WriteOnly << false;
    QTest::newRow("rw") << QByteArray("rw") << Access::ReadWrite << false;
    QTest::newRow("rwr") << QByteArray("rwr") << Access::ReadWrite << false;
    QTest::newRow("rww") << QByteArray("rww") << Access::ReadWrite << false;
    QTest::newRow("const") << QByteArray("const") << Access::Const << false;
    QTest::newRow("upper case") << QByteArray("RO") << Access::ReadOnly << false;
    QTest::newRow("unknown") << QByteArray("sometimes") << Access::ReadWrite << true;
}

void TestEdsLoader::accessTypes()
{
    QFETCH(QByteArray, text);
    QFETCH(Access, access);
    QFETCH(bool, warns);
    const auto load = parsed(eds("[2000]\nParameterName=x\nDataType=7\nAccessType=" + text + "\n"));
    QCOMPARE(load.dictionary.find({ 0x2000, 0 })->access, access);
    QCOMPARE(hasWarning(load, QStringLiteral("AccessType")), warns);
}

void TestEdsLoader::oddBitWidths()
{
    const auto load = parsed(eds("[2000]\nParameterName=i24\nDataType=0x10\nAccessType=rw\n"
                                 "DefaultValue=0xFFFFFF\n"
                                 "[2001]\nParameterName=u40\nDataType=0x18\nAccessType=rw\n"
                                 "DefaultValue=0xFFFFFFFFFF\n"
                                 "[2002]\nParameterName=i48\nDataType=0x13\nAccessType=rw\n"
                                 "DefaultValue=-140737488355328\n"
                                 "[2003]\nParameterName=u56\nDataType=0x1A\nAccessType=rw\n"
                                 "DefaultValue=0x100000000000000\n"));
    QCOMPARE(load.dictionary.find({ 0x2000, 0 })->defaultValue.toLongLong(), -1LL);
    QCOMPARE(load.dictionary.find({ 0x2001, 0 })->defaultValue.toULongLong(), 0xFFFFFFFFFFull);
    QCOMPARE(load.dictionary.find({ 0x2002, 0 })->defaultValue.toLongLong(), -140737488355328LL);
    // 2^56 does not fit UNSIGNED56
    QVERIFY(!load.dictionary.find({ 0x2003, 0 })->defaultValue.isValid());
    QVERIFY(hasWarning(load, QStringLiteral("[2003]")));
}

void TestEdsLoader::crlfBomAndLatin1()
{
    QByteArray data = "\xEF\xBB\xBF"
        + eds("[2000]\r\nParameterName=Temperatur \xB0"
              "C\r\nDataType=7\r\nAccessType=ro\r\n"
              "DefaultValue=0x10\r\n");
    const auto load = parsed(data);
    QCOMPARE(load.dictionary.find({ 0x2000, 0 })->name, QString::fromUtf8("Temperatur \u00B0C"));
    QCOMPARE(load.dictionary.find({ 0x2000, 0 })->defaultValue.toULongLong(), 16ull);
    QCOMPARE(load.dictionary.identity.vendorId, 0x42u);
}

void TestEdsLoader::duplicatesAndUnknownSections()
{
    const auto load = parsed(eds("[Comments]\nLines=1\nLine1=hello\n[Tools]\nItems=0\n"
                                 "[2000]\nParameterName=first\nParameterName=second\nDataType=7\n"
                                 "AccessType=rw\n[60FFsubX]\nDataType=7\n[12345]\nDataType=7\n"
                                 "[2000]\nDefaultValue=4\n"));
    QCOMPARE(load.dictionary.find({ 0x2000, 0 })->name, QStringLiteral("second"));
    QCOMPARE(load.dictionary.find({ 0x2000, 0 })->defaultValue.toULongLong(), 4ull);
    QVERIFY(hasWarning(load, QStringLiteral("ParameterName given twice")));
    QVERIFY(hasWarning(load, QStringLiteral("section [2000] appears again")));
    QVERIFY(hasWarning(load, QStringLiteral("[60FFsubX]: looks like an object")));
    QVERIFY(hasWarning(load, QStringLiteral("[12345]: looks like an object")));
    QVERIFY(!hasWarning(load, QStringLiteral("Tools")));
    QVERIFY(!hasWarning(load, QStringLiteral("Comments")));
}

void TestEdsLoader::brokenFilesGiveClearErrors_data()
{
    QTest::addColumn<QByteArray>("data");
    QTest::addColumn<QString>("cause");
    QTest::newRow("binary") << QByteArray("\x7F"
                                          "ELF\x02\x01\x01\0\0\0\0\0\0\0\0\0",
                                          16)
                            << QStringLiteral("binary data");
    QTest::newRow("no objects") << QByteArray("[FileInfo]\nFileVersion=1\n[DeviceInfo]\nX=1\n")
                                << QStringLiteral("no object sections");
    QTest::newRow("plain text") << QByteArray("hello world\nthis is not an ini\n")
                                << QStringLiteral("no [sections]");
    QTest::newRow("empty") << QByteArray("  \n") << QStringLiteral("is empty");
    QTest::newRow("foreign xml") << QByteArray("<?xml version=\"1.0\"?><svg><g/></svg>")
                                 << QStringLiteral("root element is <svg>");
    QTest::newRow("only unusable objects")
        << QByteArray("[DeviceInfo]\n[3003]\nObjectType=8\nParameterName=x\n")
        << QStringLiteral("none of its object sections");
}

void TestEdsLoader::brokenFilesGiveClearErrors()
{
    QFETCH(QByteArray, data);
    QFETCH(QString, cause);
    const auto r = parseDeviceDescription(data, QStringLiteral("/tmp/broken.eds"));
    QVERIFY(!r.ok());
    QVERIFY2(r.error().message().contains(QStringLiteral("/tmp/broken.eds")),
             qPrintable(r.error().message()));
    QVERIFY2(r.error().message().contains(cause), qPrintable(r.error().message()));
}

void TestEdsLoader::dispatcherChoosesByContent()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("device.dcf"));
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(eds("[DeviceComissioning]\nNodeID=7\nBaudrate=250\n[2000]\nParameterName=x\n"
                "DataType=7\nAccessType=rw\nDefaultValue=$NODEID+0x100\nParameterValue=42\n"));
    f.close();
    const auto r = loadDeviceDescription(path);
    QVERIFY2(r.ok(), qPrintable(r.error().toString()));
    QCOMPARE(r->format, DescriptionLoad::Format::Dcf);
    QCOMPARE(r->dictionary.find({ 0x2000, 0 })->defaultValue.toULongLong(), 0x107ull);
    QCOMPARE(r->values.value({ 0x2000, 0 }).toULongLong(), 42ull);
    // a node id given to the loader wins over the file's
    const auto other = loadDeviceDescription(path, DescriptionOptions { quint8(9) });
    QCOMPARE(other->dictionary.find({ 0x2000, 0 })->defaultValue.toULongLong(), 0x109ull);
    const auto missing = loadDeviceDescription(dir.filePath(QStringLiteral("nope.eds")));
    QVERIFY(!missing.ok());
    QVERIFY(missing.error().message().contains(QStringLiteral("nope.eds")));
}

QTEST_GUILESS_MAIN(TestEdsLoader)
#include "tst_edsloader.moc"
