// A dictionary knows how its addresses are written (our JSON description says so with
// "addresses"), a connection takes its dictionary's format unless it knows better, and the
// errors a dictionary or connection gives name objects in that format.
#include "core/objectdictionary.h"
#include "fakeconnection.h"

#include <QSignalSpy>
#include <QTest>

using namespace db;

namespace {

QByteArray description(const QByteArray &extra)
{
    return R"({ "format": "drivebench-device-description", "version": 1,
                "device": { "vendor": "v", "product": "inverter" }, )"
        + extra + R"(
                "objects": [ { "index": 372, "sub": 2, "name": "Acceleration",
                               "type": "UNSIGNED16", "access": "rw", "max": 1000 } ] })";
}

} // namespace

class TestDictionaryAddresses : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void dictionariesAreCanopenByDefault();
    void descriptionSaysParameter();
    void descriptionWithAnUnknownFormatIsRefused();
    void connectionTakesTheDictionaryFormat();
    void valueErrorsNameTheAddressInTheFormat();
    void accessErrorsNameTheAddressInTheFormat();
};

void TestDictionaryAddresses::dictionariesAreCanopenByDefault()
{
    const ObjectDictionary empty;
    QCOMPARE(&empty.addressFormat(), &AddressFormat::canopen());
    const auto dict = ObjectDictionary::parseDescription(description({}), QStringLiteral("d.json"));
    QVERIFY2(dict, qPrintable(dict.error().toString()));
    QCOMPARE(&dict->addressFormat(), &AddressFormat::canopen());
}

void TestDictionaryAddresses::descriptionSaysParameter()
{
    const auto dict = ObjectDictionary::parseDescription(
        description(R"("addresses": "parameter",)"), QStringLiteral("d.json"));
    QVERIFY2(dict, qPrintable(dict.error().toString()));
    QCOMPARE(&dict->addressFormat(), &AddressFormat::parameter());
    QVERIFY(dict->contains({ 372, 2 }));
    // A copy keeps it.
    const ObjectDictionary copy = *dict;
    QCOMPARE(&copy.addressFormat(), &AddressFormat::parameter());
}

void TestDictionaryAddresses::descriptionWithAnUnknownFormatIsRefused()
{
    const auto dict = ObjectDictionary::parseDescription(description(R"("addresses": "octal",)"),
                                                         QStringLiteral("d.json"));
    QVERIFY(!dict);
    QCOMPARE(dict.error().kind(), Error::Kind::Malformed);
    QVERIFY2(dict.error().message().contains(QLatin1String("d.json")),
             qPrintable(dict.error().message()));
    QVERIFY2(dict.error().message().contains(QLatin1String("'octal' (canopen or parameter)")),
             qPrintable(dict.error().message()));
}

void TestDictionaryAddresses::connectionTakesTheDictionaryFormat()
{
    // FakeConnection overrides addressFormat(); the base class default is what is tested here.
    class Plain : public DeviceConnection
    {
    public:
        Plain()
            : DeviceConnection(ConnectionUri::parse(QStringLiteral("plain://x")).value())
        { }
        QString protocolKey() const override { return QStringLiteral("plain"); }

    protected:
        void doOpen() override { }
        void doClose() override { }
        void doRead(Reply *, const ObjectDef *) override { }
        void doWrite(Reply *, const QVariant &, const ObjectDef *) override { }
    };
    Plain connection;
    QCOMPARE(&connection.addressFormat(), &AddressFormat::canopen());
    const auto dict = ObjectDictionary::parseDescription(
        description(R"("addresses": "parameter",)"), QStringLiteral("d.json"));
    QVERIFY(dict);
    connection.setDictionary(*dict);
    QCOMPARE(&connection.addressFormat(), &AddressFormat::parameter());
}

void TestDictionaryAddresses::valueErrorsNameTheAddressInTheFormat()
{
    const auto dict = ObjectDictionary::parseDescription(
        description(R"("addresses": "parameter",)"), QStringLiteral("d.json"));
    QVERIFY(dict);
    const ObjectDef *def = dict->find({ 372, 2 });
    QVERIFY(def);
    const auto tooBig = def->parseText(QStringLiteral("5000"), dict->addressFormat());
    QVERIFY(!tooBig);
    QVERIFY2(tooBig.error().message().startsWith(QLatin1String("372:2")),
             qPrintable(tooBig.error().message()));
    // Without a format: CANopen's, as before.
    QVERIFY(def->validate(5000u).error().message().startsWith(QLatin1String("0174:2")));
}

void TestDictionaryAddresses::accessErrorsNameTheAddressInTheFormat()
{
    test::FakeConnection device;
    device.setAddressFormat(AddressFormat::parameter());
    ObjectDictionary dict;
    ObjectDef def;
    def.address = { 372, 2 };
    def.name = QStringLiteral("Acceleration");
    def.type = DataType::Unsigned16;
    def.access = Access::ReadOnly;
    def.maximum = 1000u;
    dict.insert(def);
    device.setDictionary(dict);
    device.open();
    QTRY_VERIFY(device.isConnected());
    const auto written = Reply::wait(device.write({ 372, 2 }, 5u));
    QVERIFY(!written);
    QCOMPARE(written.error().message(), QStringLiteral("372:2 Acceleration is read-only"));
    const auto missing = Reply::wait(device.read({ 373, 0 }));
    QVERIFY(!missing);
    QVERIFY2(missing.error().message().contains(QLatin1String("373:0")),
             qPrintable(missing.error().message()));
}

QTEST_GUILESS_MAIN(TestDictionaryAddresses)
#include "tst_dictionaryaddresses.moc"
