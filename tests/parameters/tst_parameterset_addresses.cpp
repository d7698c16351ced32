// Parameter sets know how their addresses are written: a set of inverter parameters is saved
// and read back in decimal NUMBER:DATASET, files without the "addresses" line stay CANopen, and
// sets (or a set and a device) of different formats are never compared or restored across.
#include "fakeconnection.h"
#include "parameters/parameterrunner.h"
#include "parameters/parameterset.h"

#include <QSignalSpy>
#include <QTest>

using namespace db;

namespace {

ParameterEntry entry(ObjectAddress a, const char *name, quint32 value)
{
    return { a, QString::fromLatin1(name), DataType::Unsigned16,
             codec::normalize(DataType::Unsigned16, value).value(), QString() };
}

ParameterSet decimalSet()
{
    ParameterSet set;
    set.addressFormat = &AddressFormat::parameter();
    set.source = QStringLiteral("fake://inverter");
    set.insert(entry({ 372, 2 }, "Acceleration", 1200));
    set.insert(entry({ 12, 0 }, "Language", 1));
    set.insert(entry({ 65535, 255 }, "Last", 7));
    return set;
}

ObjectDictionary parameterDictionary()
{
    ObjectDictionary dict;
    dict.setAddressFormat(AddressFormat::parameter());
    for (const ObjectAddress a : { ObjectAddress(372, 2), ObjectAddress(12, 0) }) {
        ObjectDef def;
        def.address = a;
        def.name = QStringLiteral("P%1").arg(a.index);
        def.type = DataType::Unsigned16;
        def.access = Access::ReadWrite;
        def.storable = true;
        def.defaultValue = 5u;
        dict.insert(def);
    }
    return dict;
}

} // namespace

class TestParameterSetAddresses : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void decimalRoundTrip();
    void filesWithoutTheLineAreCanopen();
    void canopenSetsAreWrittenAsBefore();
    void badAddressNamesTheFormat();
    void unknownFormatIsRefused();
    void defaultsTakeTheDictionaryFormat();
    void comparisonRefusesMixedFormats();
    void backupRecordsTheDeviceFormat();
    void backupFailuresNameDecimalAddresses();
    void restoreRefusesASetOfAnotherFormat();
};

void TestParameterSetAddresses::decimalRoundTrip()
{
    const ParameterSet set = decimalSet();
    const QByteArray text = set.serialize();
    QVERIFY2(text.contains("\naddresses parameter\n"), text.constData());
    QVERIFY2(text.contains("\n372:2 \"Acceleration\" UNSIGNED16 1200 \"\"\n"), text.constData());
    QVERIFY2(text.contains("\n12:0 \"Language\""), text.constData());
    QVERIFY2(text.contains("\n65535:255 \"Last\""), text.constData());
    QVERIFY2(!text.contains("0174:2"), text.constData()); // 372 in hex
    const auto back = ParameterSet::parse(text, QStringLiteral("mem"));
    QVERIFY2(back, qPrintable(back.error().toString()));
    QCOMPARE(back->addressFormat, &AddressFormat::parameter());
    QCOMPARE(back->entries(), set.entries());
    QVERIFY(back->contains({ 372, 2 }));
    QVERIFY(!back->contains({ 0x372, 2 }));
    QCOMPARE(back->serialize(), text);
}

void TestParameterSetAddresses::filesWithoutTheLineAreCanopen()
{
    // As written before sets recorded their address format.
    const QByteArray old = "# drivebench parameter set\nformat 1\nvendor 0x1 \"v\"\n"
                           "entries 1\n0372:2 \"Old\" UNSIGNED16 3 \"\"\nend\n";
    const auto set = ParameterSet::parse(old, QStringLiteral("old.dbp"));
    QVERIFY2(set, qPrintable(set.error().toString()));
    QCOMPARE(set->addressFormat, &AddressFormat::canopen());
    QVERIFY(set->contains({ 0x372, 2 }));
    // Saying so explicitly reads the same.
    QByteArray explicitly = old;
    explicitly.replace("format 1\n", "format 1\naddresses canopen\n");
    const auto same = ParameterSet::parse(explicitly, QStringLiteral("new.dbp"));
    QVERIFY2(same, qPrintable(same.error().toString()));
    QCOMPARE(same->addressFormat, &AddressFormat::canopen());
    QCOMPARE(same->entries(), set->entries());
}

void TestParameterSetAddresses::canopenSetsAreWrittenAsBefore()
{
    // No "addresses" line: older drivebench versions read them as they always did.
    ParameterSet set;
    set.insert(entry({ 0x6083, 0 }, "Profile acceleration", 5));
    const QByteArray text = set.serialize();
    QVERIFY2(text.startsWith("# drivebench parameter set\nformat 1\nvendor "), text.constData());
    QVERIFY(!text.contains("addresses"));
    QVERIFY(text.contains("\n6083:0 \"Profile acceleration\""));
}

void TestParameterSetAddresses::badAddressNamesTheFormat()
{
    const QByteArray text = "# drivebench parameter set\nformat 1\naddresses parameter\n"
                            "entries 1\n6083:0A \"A\" UNSIGNED16 1 \"\"\nend\n";
    const auto set = ParameterSet::parse(text, QStringLiteral("f.dbp"));
    QVERIFY(!set);
    QCOMPARE(set.error().kind(), Error::Kind::Malformed);
    QVERIFY2(set.error().message().startsWith(QLatin1String("f.dbp:5: bad address '6083:0A'")),
             qPrintable(set.error().message()));
    QVERIFY2(set.error().message().contains(QLatin1String("372:2")),
             qPrintable(set.error().message()));
    const QByteArray twice = "# drivebench parameter set\nformat 1\naddresses parameter\n"
                             "entries 2\n372:2 \"A\" UNSIGNED16 1 \"\"\n0372.2 \"A\" UNSIGNED16 2 "
                             "\"\"\nend\n";
    const auto dup = ParameterSet::parse(twice, QStringLiteral("f.dbp"));
    QVERIFY(!dup);
    QVERIFY2(dup.error().message().contains(QLatin1String("f.dbp:6: 372:2 appears twice")),
             qPrintable(dup.error().message()));
}

void TestParameterSetAddresses::unknownFormatIsRefused()
{
    const auto set = ParameterSet::parse(
        "# drivebench parameter set\nformat 1\naddresses octal\nentries 0\nend\n",
        QStringLiteral("f.dbp"));
    QVERIFY(!set);
    QCOMPARE(set.error().kind(), Error::Kind::Malformed);
    QVERIFY2(set.error().message().contains(QLatin1String("f.dbp:3: unknown address format "
                                                          "'octal' (canopen or parameter)")),
             qPrintable(set.error().message()));
}

void TestParameterSetAddresses::defaultsTakeTheDictionaryFormat()
{
    const ParameterSet set = ParameterSet::defaults(parameterDictionary());
    QCOMPARE(set.addressFormat, &AddressFormat::parameter());
    QVERIFY(set.serialize().contains("\n372:2 \"P372\" UNSIGNED16 5 \"\"\n"));
}

void TestParameterSetAddresses::comparisonRefusesMixedFormats()
{
    ParameterSet hex;
    hex.insert(entry({ 0x372, 2 }, "Hex", 1));
    const ParameterSet decimal = decimalSet();
    const auto mixed = checkSameAddressFormat({ decimal, hex }, { "inverter.dbp", "drive.dbp" });
    QVERIFY(!mixed);
    QCOMPARE(mixed.error().kind(), Error::Kind::InvalidArgument);
    QVERIFY2(mixed.error().message().contains(QLatin1String("inverter.dbp has parameter")),
             qPrintable(mixed.error().message()));
    QVERIFY2(mixed.error().message().contains(QLatin1String("drive.dbp has canopen")),
             qPrintable(mixed.error().message()));
    QVERIFY(checkSameAddressFormat({ decimal, decimal }, { "a", "b" }));
    const ParameterComparison c = compareParameterSets({ decimal, decimal }, { "a", "b" });
    QCOMPARE(c.addressFormat, &AddressFormat::parameter());
}

void TestParameterSetAddresses::backupRecordsTheDeviceFormat()
{
    test::FakeConnection device;
    device.setAddressFormat(AddressFormat::parameter());
    device.setDictionary(parameterDictionary());
    device.setValue({ 372, 2 }, 1200u);
    device.setValue({ 12, 0 }, 1u);
    device.open();
    QTRY_VERIFY(device.isConnected());
    ParameterBackup backup(&device);
    QSignalSpy finished(&backup, &ParameterBackup::finished);
    backup.start();
    QVERIFY(finished.wait(5000));
    const auto set = backup.result();
    QVERIFY2(set, qPrintable(set.error().toString()));
    QCOMPARE(set->addressFormat, &AddressFormat::parameter());
    QVERIFY2(set->serialize().contains("\n372:2 \"P372\" UNSIGNED16 1200"),
             set->serialize().constData());
}

void TestParameterSetAddresses::backupFailuresNameDecimalAddresses()
{
    test::FakeConnection device;
    device.setAddressFormat(AddressFormat::parameter());
    device.setDictionary(parameterDictionary());
    device.setValue({ 12, 0 }, 1u);
    device.setFailure({ 372, 2 }, Error(Error::Kind::DeviceError, QStringLiteral("no access")));
    device.open();
    QTRY_VERIFY(device.isConnected());
    ParameterBackup backup(&device);
    QSignalSpy finished(&backup, &ParameterBackup::finished);
    backup.start();
    QVERIFY(finished.wait(5000));
    QCOMPARE(backup.warnings().size(), 1);
    QVERIFY2(backup.warnings().first().startsWith(QLatin1String("372:2 P372: ")),
             qPrintable(backup.warnings().first()));
}

void TestParameterSetAddresses::restoreRefusesASetOfAnotherFormat()
{
    test::FakeConnection device;
    device.setAddressFormat(AddressFormat::parameter());
    device.setDictionary(parameterDictionary());
    device.open();
    QTRY_VERIFY(device.isConnected());
    ParameterSet hex;
    hex.insert(entry({ 0x0C, 0 }, "Hex twelve", 9)); // "000C:0": parameter 12 by number only
    ParameterRestore restore(&device);
    restore.setParameterSet(hex);
    QSignalSpy finished(&restore, &ParameterRestore::finished);
    restore.start();
    QVERIFY(finished.wait(5000));
    QVERIFY(!restore.report().succeeded());
    QCOMPARE(restore.report().error.kind(), Error::Kind::InvalidArgument);
    QVERIFY2(restore.report().error.message().contains(QLatin1String("not a set for this device")),
             qPrintable(restore.report().error.message()));
    QVERIFY(device.writes.isEmpty());

    // The same set in the device's format is written, and reported in decimal.
    ParameterSet decimal;
    decimal.addressFormat = &AddressFormat::parameter();
    decimal.insert(entry({ 12, 0 }, "Language", 9));
    restore.setParameterSet(decimal);
    restore.start();
    QVERIFY(finished.wait(5000));
    QVERIFY2(restore.report().succeeded(), qPrintable(restore.report().summary()));
    QCOMPARE(device.writes.size(), 1);
    QCOMPARE(device.writes.first().first, ObjectAddress(12, 0));
    QVERIFY2(restore.report().summary().contains(QLatin1String("12:0 P12")),
             qPrintable(restore.report().summary()));
}

QTEST_GUILESS_MAIN(TestParameterSetAddresses)
#include "tst_parameterset_addresses.moc"
