// Scope channels of a device whose addresses are decimal NUMBER:DATASET: named "372:2", written
// to the CSV with their format and read back as the same object, found by triggers and by
// Recording::indexOf in any spelling of that format.
#include "fakeconnection.h"
#include "scope/csv.h"
#include "scope/pollingsource.h"
#include "scope/recording.h"
#include "scope/trigger.h"
#include "textlanguage.h"

#include <QTest>

using namespace db;
using namespace db::scope;

namespace {

constexpr ObjectAddress kAcceleration { 372, 2 };

ObjectDictionary inverterDictionary()
{
    ObjectDictionary dict;
    dict.setAddressFormat(AddressFormat::parameter());
    ObjectDef def;
    def.address = kAcceleration;
    def.name = QStringLiteral("Acceleration");
    def.localNames.insert(QStringLiteral("de"), QStringLiteral("Beschleunigung"));
    def.type = DataType::Unsigned16;
    def.access = Access::ReadWrite;
    dict.insert(def);
    return dict;
}

Recording recordingOf(const ChannelInfo &info)
{
    Recording rec;
    rec.device = info.device;
    RecordedChannel c;
    c.info = info;
    c.buffer.append(0.0, 1);
    c.buffer.append(0.5, 2);
    rec.channels.append(c);
    return rec;
}

} // namespace

class TestScopeAddresses : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void channelsAreNamedInTheFormat();
    void pollingSourceTakesTheConnectionFormat();
    void csvRoundTripKeepsTheFormat();
    void canopenCsvIsUnchanged();
    void unknownFormatInACsvIsRefused();
    void triggersFindDecimalChannels();
    void namesFollowTheLanguageFilesDoNot();
};

void TestScopeAddresses::channelsAreNamedInTheFormat()
{
    const ChannelInfo fromDictionary =
        ChannelInfo::forObject(kAcceleration, inverterDictionary(), QStringLiteral("fake://x"));
    QCOMPARE(fromDictionary.id, QStringLiteral("372:2"));
    QCOMPARE(fromDictionary.label(), QStringLiteral("372:2 Acceleration"));
    QCOMPARE(fromDictionary.addressFormat, &AddressFormat::parameter());
    const ChannelInfo hex =
        ChannelInfo::forObject(kAcceleration, ObjectDictionary(), QStringLiteral("fake://x"));
    QCOMPARE(hex.id, QStringLiteral("0174:2"));
}

void TestScopeAddresses::pollingSourceTakesTheConnectionFormat()
{
    // The connection says "parameter" although its dictionary does not.
    test::FakeConnection fake;
    fake.setAddressFormat(AddressFormat::parameter());
    PollingSource source(&fake);
    const auto added = source.addChannel(kAcceleration, 10);
    QVERIFY2(added, qPrintable(added.error().toString()));
    QCOMPARE(source.channels().at(*added).id, QStringLiteral("372:2"));
}

void TestScopeAddresses::csvRoundTripKeepsTheFormat()
{
    const Recording rec = recordingOf(
        ChannelInfo::forObject(kAcceleration, inverterDictionary(), QStringLiteral("fake://x")));
    const QByteArray text = csv::toCsv(rec);
    QVERIFY2(text.contains("# channel: 372:2; name: Acceleration;"), text.constData());
    QVERIFY2(text.contains("; addresses: parameter"), text.constData());
    QVERIFY2(text.contains(",372:2 Acceleration"), text.constData());
    const auto back = csv::fromCsv(text);
    QVERIFY2(back, qPrintable(back.error().toString()));
    QCOMPARE(back->channels.size(), 1);
    QCOMPARE(back->channels.first().info.address, kAcceleration);
    QCOMPARE(back->channels.first().info.addressFormat, &AddressFormat::parameter());
    QCOMPARE(back->channels.first().info.id, QStringLiteral("372:2"));
    QCOMPARE(back->channels.first().info.decimals, rec.channels.first().info.decimals);
    QCOMPARE(back->indexOf(QStringLiteral("372:2")), 0);
    QCOMPARE(back->indexOf(QStringLiteral("0372.2")), 0);
    QCOMPARE(back->indexOf(QStringLiteral("0174:2")), -1);
}

void TestScopeAddresses::canopenCsvIsUnchanged()
{
    const Recording rec = recordingOf(
        ChannelInfo::forObject({ 0x6064, 0 }, ObjectDictionary(), QStringLiteral("fake://x")));
    const QByteArray text = csv::toCsv(rec);
    QVERIFY(!text.contains("addresses"));
    const auto back = csv::fromCsv(text);
    QVERIFY2(back, qPrintable(back.error().toString()));
    QCOMPARE(back->channels.first().info.address, ObjectAddress(0x6064, 0));
    QCOMPARE(back->channels.first().info.addressFormat, &AddressFormat::canopen());
}

void TestScopeAddresses::unknownFormatInACsvIsRefused()
{
    const Recording rec = recordingOf(
        ChannelInfo::forObject(kAcceleration, inverterDictionary(), QStringLiteral("fake://x")));
    QByteArray text = csv::toCsv(rec);
    text.replace("addresses: parameter", "addresses: octal");
    const auto back = csv::fromCsv(text);
    QVERIFY(!back);
    QVERIFY2(back.error().message().contains(QLatin1String("unknown address format 'octal'")),
             qPrintable(back.error().message()));
}

void TestScopeAddresses::triggersFindDecimalChannels()
{
    const QStringList ids { QStringLiteral("12:0"), QStringLiteral("372:2") };
    const auto exact = Trigger::parse(QStringLiteral("372:2,rising,100"), ids, Trigger(),
                                      AddressFormat::parameter());
    QVERIFY2(exact, qPrintable(exact.error().toString()));
    QCOMPARE(exact->channel, 1);
    const auto spelled = Trigger::parse(QStringLiteral("0372.2,rising,100"), ids, Trigger(),
                                        AddressFormat::parameter());
    QVERIFY2(spelled, qPrintable(spelled.error().toString()));
    QCOMPARE(spelled->channel, 1);
    // 372 written in hex is parameter 174 here: not recorded.
    const auto other = Trigger::parse(QStringLiteral("0174:2,rising,100"), ids, Trigger(),
                                      AddressFormat::parameter());
    QVERIFY(!other);
    QVERIFY2(other.error().message().contains(QLatin1String("not one of the recorded channels")),
             qPrintable(other.error().message()));
    const auto hex = Trigger::parse(QStringLiteral("0x174:2,rising,100"), ids, Trigger(),
                                    AddressFormat::parameter());
    QVERIFY(!hex);
    QVERIFY2(hex.error().message().contains(QLatin1String("NUMBER:DATASET")),
             qPrintable(hex.error().message()));
}

// The scope's legend and lists show a channel's name in the program's language; the CSV keeps the
// English name, so that a recording reads the same in every language.
void TestScopeAddresses::namesFollowTheLanguageFilesDoNot()
{
    const ChannelInfo info =
        ChannelInfo::forObject(kAcceleration, inverterDictionary(), QStringLiteral("fake://x"));
    QCOMPARE(info.displayLabel(), QStringLiteral("372:2 Acceleration"));
    const test::TextLanguage german(QStringLiteral("de"));
    QCOMPARE(info.displayLabel(), QStringLiteral("372:2 Beschleunigung"));
    QCOMPARE(info.label(), QStringLiteral("372:2 Acceleration"));
    const QByteArray text = csv::toCsv(recordingOf(info));
    QVERIFY2(text.contains("# channel: 372:2; name: Acceleration;"), text.constData());
    QVERIFY2(!text.contains("Beschleunigung"), text.constData());
}

QTEST_GUILESS_MAIN(TestScopeAddresses)
#include "tst_scopeaddresses.moc"
