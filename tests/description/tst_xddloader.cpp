// CiA 311 XDD/XDC loader: the MovingCap XDDs in ../shared (read in place, skipped when absent)
// and hand-written profiles for uniqueIDRef lookups, $NODEID, XDC values and broken files.
#include "description/devicedescription.h"
#include "description/xddloader.h"

#include "descriptiontestutil.h"

#include <QDir>
#include <QTest>

using namespace db;
using db::test::hasWarning;
using db::test::sharedFile;

// Declared before the raw-string XML snippets: moc stops at them.
class TestXddLoader : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void movingCapXddsLoad_data();
    void movingCapXddsLoad();
    void mc349Objects();
    void parameterReferencesFillGaps();
    void nodeIdDefaults();
    void xdcValuesAndCommissioning();
    void sloppyObjectsGiveWarnings();
    void brokenFilesGiveClearErrors_data();
    void brokenFilesGiveClearErrors();
};

namespace {

// A two-profile container as CiA 311 lays it out; `parameters` go into the ApplicationProcess,
// `objects` into the CANopenObjectList.
QByteArray xdd(const QByteArray &parameters, const QByteArray &objects,
               const QByteArray &commissioning = QByteArray())
{
    return R"(<?xml version="1.0" encoding="UTF-8"?>
<ISO15745ProfileContainer xmlns="http://www.canopen.org/xml/1.0">
 <ISO15745Profile><ProfileHeader/>
  <ProfileBody fileVersion="3">
   <DeviceIdentity><vendorName>ACME</vendorName><vendorID>0x1234</vendorID>
    <productName>Widget</productName><productID>77</productID>
    <version versionType="FW">1.2</version></DeviceIdentity>
   <ApplicationProcess><parameterList>)"
        + parameters + R"(</parameterList></ApplicationProcess>
  </ProfileBody></ISO15745Profile>
 <ISO15745Profile><ProfileHeader/><ProfileBody>
  <ApplicationLayers><identity><vendorID>0x1234</vendorID></identity>
   <CANopenObjectList>)"
        + objects + R"(</CANopenObjectList></ApplicationLayers>
  <NetworkManagement>)"
        + commissioning + R"(</NetworkManagement>
 </ProfileBody></ISO15745Profile>
</ISO15745ProfileContainer>
)";
}

DescriptionLoad parsed(const QByteArray &data, const QString &origin = QStringLiteral("t.xdd"))
{
    auto r = parseXdd(data, origin);
    if (!r)
        qWarning("%s", qPrintable(r.error().toString()));
    return r.valueOr(DescriptionLoad());
}

} // namespace

void TestXddLoader::movingCapXddsLoad_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("product");
    QTest::addColumn<int>("objects");
    QTest::newRow("MC349") << QStringLiteral("MC349_ETH.xdd")
                           << QStringLiteral("MovingCap turnTRACK MC 349") << 117;
    QTest::newRow("MC6xx") << QStringLiteral("MC6xx_ETH.xdd") << QString() << 111;
    QTest::newRow("MCFLAT") << QStringLiteral("MCFLAT_ETH.xdd") << QString() << 117;
    QTest::newRow("MCN23") << QStringLiteral("MCN23_ETH.xdd") << QString() << 120;
}

void TestXddLoader::movingCapXddsLoad()
{
    QFETCH(QString, file);
    QFETCH(QString, product);
    QFETCH(int, objects);
    const QString path = sharedFile(QStringLiteral("fixtures/xdd/") + file);
    if (!QFile::exists(path))
        QSKIP("shared MovingCap XDD not present");
    const auto r = loadDeviceDescription(path);
    QVERIFY2(r.ok(), qPrintable(r.error().toString()));
    QCOMPARE(r->format, DescriptionLoad::Format::Xdd);
    const ObjectDictionary &d = r->dictionary;
    QCOMPARE(d.identity.vendorName, QStringLiteral("Fullmo GmbH"));
    QCOMPARE(d.identity.vendorId, 0x053Bu);
    if (!product.isEmpty())
        QCOMPARE(d.identity.productName, product);
    QSet<quint16> indices;
    for (const ObjectDef &def : d.objects())
        indices.insert(def.address.index);
    QCOMPARE(int(indices.size()), objects);
    // every MovingCap drive: CiA 402 controlword/statusword, PDO-mappable, from the parameters
    QCOMPARE(d.find({ 0x6040, 0 })->type, DataType::Unsigned16);
    QCOMPARE(d.find({ 0x6040, 0 })->access, Access::ReadWrite); // readWriteInput
    QVERIFY(d.find({ 0x6040, 0 })->pdoMappable);
    QCOMPARE(d.find({ 0x6041, 0 })->access, Access::ReadOnly); // read
    QCOMPARE(d.find({ 0x1018, 0 })->defaultValue.toULongLong(), 4ull);
    // COB-ID EMCY $NODEID+0x80000080 stays symbolic (deviceCommissioning nodeID="0")
    QCOMPARE(r->nodeIdDefaults.value({ 0x1014, 0 }), 0x80000080LL);
    QVERIFY(!r->nodeId);
}

void TestXddLoader::mc349Objects()
{
    const QString path = sharedFile(QStringLiteral("fixtures/xdd/MC349_ETH.xdd"));
    if (!QFile::exists(path))
        QSKIP("shared MC349_ETH.xdd not present");
    auto r = loadDeviceDescription(path);
    QVERIFY2(r.ok(), qPrintable(r.error().toString()));
    const ObjectDictionary &d = r->dictionary;
    QCOMPARE(d.identity.productCode, 50u);
    QCOMPARE(d.identity.descriptionVersion, QStringLiteral("8"));
    QCOMPARE(d.find({ 0x1008, 0 })->type, DataType::VisibleString);
    QCOMPARE(d.find({ 0x1008, 0 })->access, Access::Const);
    QCOMPARE(d.find({ 0x1008, 0 })->defaultValue.toString(), QStringLiteral("CANopen Slave"));
    QCOMPARE(d.find({ 0x100A, 0 })->defaultValue.toString(), QStringLiteral("V5.18"));
    // 607Ah: DINT parameter with range -2147483647 .. 2147483647
    const ObjectDef *target = d.find({ 0x607A, 0 });
    QCOMPARE(target->type, DataType::Integer32);
    QCOMPARE(target->minimum.toLongLong(), -2147483647LL);
    QCOMPARE(target->maximum.toLongLong(), 2147483647LL);
    QCOMPARE(target->defaultValue.toLongLong(), 0LL);
    QCOMPARE(d.find({ 0x6060, 0 })->type, DataType::Integer8);
    QCOMPARE(d.find({ 0x6007, 0 })->defaultValue.toLongLong(), 1LL);
    QCOMPARE(d.find({ 0x1003, 2 })->objectName, QStringLiteral("Pre-defined Error Field"));
    // the file states subNumber="9" for PDO mappings with 1 or 2 entries
    QVERIFY(hasWarning(*r, QStringLiteral("CANopenObject 1600")));
    DescriptionLoad load = r.value();
    QVERIFY(load.resolveNodeId(50));
    QCOMPARE(load.dictionary.find({ 0x1014, 0 })->defaultValue.toULongLong(), 0x80000080ull + 50);
}

void TestXddLoader::parameterReferencesFillGaps()
{
    const auto load = parsed(xdd(R"(
      <parameter uniqueID="P1" access="readWriteOutput"><label lang="de">Modus</label>
        <label lang="en">Mode</label><SINT/><description lang="en">the mode</description>
        <defaultValue value="-1"/>
        <allowedValues><value value="1"><label lang="en">Position</label></value>
          <value value="3"><label lang="en">Velocity</label></value>
          <range><minValue value="-3"/><maxValue value="10"/></range></allowedValues>
      </parameter>
      <parameter uniqueID="P2" access="const"><label lang="en">Name</label><STRING/>
        <defaultValue value="abc"/></parameter>)",
                                 R"(
      <CANopenObject index="2000" objectType="7" dataType="0002" uniqueIDRef="P1"/>
      <CANopenObject index="2001" name="Explicit" objectType="7" uniqueIDRef="P2"/>)"));
    const ObjectDef *mode = load.dictionary.find({ 0x2000, 0 });
    QVERIFY(mode);
    QCOMPARE(mode->name, QStringLiteral("Mode"));
    QCOMPARE(mode->access, Access::ReadWrite);
    QCOMPARE(mode->defaultValue.toLongLong(), -1LL);
    QCOMPARE(mode->minimum.toLongLong(), -3LL);
    QCOMPARE(mode->maximum.toLongLong(), 10LL);
    QCOMPARE(mode->enumeration.value(3), QStringLiteral("Velocity"));
    QCOMPARE(mode->description, QStringLiteral("the mode"));
    const ObjectDef *name = load.dictionary.find({ 0x2001, 0 });
    QCOMPARE(name->name, QStringLiteral("Explicit"));
    QCOMPARE(name->type, DataType::VisibleString); // from the <STRING/> element
    QCOMPARE(name->access, Access::Const);
    QCOMPARE(load.dictionary.identity.vendorId, 0x1234u);
    QCOMPARE(load.dictionary.identity.productCode, 77u);
    QCOMPARE(load.dictionary.identity.revision, QStringLiteral("1.2"));
    QVERIFY2(load.warnings.isEmpty(), qPrintable(load.warnings.join(u'\n')));
}

void TestXddLoader::nodeIdDefaults()
{
    const QByteArray data = xdd({}, R"(
      <CANopenObject index="1800" name="TPDO1" objectType="9" subNumber="2">
        <CANopenSubObject subIndex="00" name="n" objectType="7" dataType="0005" accessType="ro"
          defaultValue="1"/>
        <CANopenSubObject subIndex="01" name="COB-ID" objectType="7" dataType="0007"
          accessType="rw" defaultValue="0x180+$NODEID"/>
      </CANopenObject>)");
    const auto symbolic = parsed(data);
    QVERIFY(!symbolic.dictionary.find({ 0x1800, 1 })->defaultValue.isValid());
    QCOMPARE(symbolic.nodeIdDefaults.value({ 0x1800, 1 }), 0x180);
    const auto resolved = parseXdd(data, QStringLiteral("t.xdd"), DescriptionOptions { quint8(4) });
    QVERIFY(resolved.ok());
    QCOMPARE(resolved->dictionary.find({ 0x1800, 1 })->defaultValue.toULongLong(), 0x184ull);
    QCOMPARE(resolved->dictionary.find({ 0x1800, 1 })->objectName, QStringLiteral("TPDO1"));
}

void TestXddLoader::xdcValuesAndCommissioning()
{
    const auto load =
        parsed(xdd({},
                   R"(<CANopenObject index="2000" name="speed" objectType="7" dataType="0006"
                  accessType="rw" defaultValue="100" actualValue="0x200" PDOmapping="optional"/>
               <CANopenObject index="1014" name="EMCY" objectType="7" dataType="0007"
                  accessType="rw" defaultValue="$NODEID+0x80"/>)",
                   R"(<deviceCommissioning nodeID="12" actualBaudRate="250" nodeName="n"/>)"),
               QStringLiteral("drive.xdc"));
    QCOMPARE(load.format, DescriptionLoad::Format::Xdc);
    QCOMPARE(load.nodeId, std::optional<quint8>(12));
    QCOMPARE(load.bitrateKbit, std::optional<quint32>(250));
    QCOMPARE(load.values.value({ 0x2000, 0 }).toULongLong(), 0x200ull);
    QVERIFY(load.dictionary.find({ 0x2000, 0 })->pdoMappable);
    QCOMPARE(load.dictionary.find({ 0x1014, 0 })->defaultValue.toULongLong(), 0x80ull + 12);
}

void TestXddLoader::sloppyObjectsGiveWarnings()
{
    const auto load = parsed(xdd({}, R"(
      <CANopenObject index="zz" name="bad" objectType="7" dataType="0007"/>
      <CANopenObject index="2000" objectType="7" dataType="0040" accessType="rw"/>
      <CANopenObject index="2001" name="ref" objectType="7" dataType="0007" uniqueIDRef="NOPE"/>
      <CANopenObject index="2002" name="rec" objectType="9" subNumber="3">
        <CANopenSubObject subIndex="01" name="a" objectType="7" dataType="0005" accessType="xx"
          defaultValue="999"/>
      </CANopenObject>)"));
    QVERIFY(hasWarning(load, QStringLiteral("index 'zz'")));
    QCOMPARE(load.dictionary.find({ 0x2000, 0 })->type, DataType::Domain);
    QCOMPARE(load.dictionary.find({ 0x2000, 0 })->name, QStringLiteral("Object 2000:0"));
    QVERIFY(hasWarning(load, QStringLiteral("dataType 0040")));
    QVERIFY(hasWarning(load, QStringLiteral("uniqueIDRef 'NOPE'")));
    QVERIFY(hasWarning(load, QStringLiteral("subNumber=3 but 1")));
    QVERIFY(hasWarning(load, QStringLiteral("no sub-index 0")));
    QVERIFY(hasWarning(load, QStringLiteral("accessType 'xx'")));
    QVERIFY(hasWarning(load, QStringLiteral("defaultValue ignored")));
    QVERIFY(load.dictionary.contains({ 0x2002, 1 }));
}

void TestXddLoader::brokenFilesGiveClearErrors_data()
{
    QTest::addColumn<QByteArray>("data");
    QTest::addColumn<QString>("cause");
    const QByteArray good = xdd({}, R"(<CANopenObject index="2000" name="x" objectType="7"
        dataType="0007" accessType="rw"/>)");
    QTest::newRow("truncated") << good.left(good.size() / 2) << QStringLiteral("XML error");
    QTest::newRow("foreign xml") << QByteArray("<?xml version=\"1.0\"?><html><body/></html>")
                                 << QStringLiteral("root element is <html>");
    QTest::newRow("no object list")
        << QByteArray("<ISO15745ProfileContainer><ISO15745Profile/></ISO15745ProfileContainer>")
        << QStringLiteral("no CANopenObjectList");
    QTest::newRow("empty object list") << xdd({}, {}) << QStringLiteral("no usable object");
    QTest::newRow("binary") << QByteArray("<\x01\x02\x03\x04\x05\x06\x07\x08\x0e\x0f", 11)
                            << QStringLiteral("binary data");
}

void TestXddLoader::brokenFilesGiveClearErrors()
{
    QFETCH(QByteArray, data);
    QFETCH(QString, cause);
    const auto r = parseDeviceDescription(data, QStringLiteral("/x/broken.xdd"));
    QVERIFY(!r.ok());
    QVERIFY2(r.error().message().contains(QStringLiteral("/x/broken.xdd")),
             qPrintable(r.error().message()));
    QVERIFY2(r.error().message().contains(cause), qPrintable(r.error().message()));
}

QTEST_GUILESS_MAIN(TestXddLoader)
#include "tst_xddloader.moc"
