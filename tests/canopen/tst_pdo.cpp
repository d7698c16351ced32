// PDO configuration (CiA 301 7.5.2.35-38): the value type and decoding (level 1), reading and
// configuring through SDO against SimulatedNode on a loopback bus (level 2), including the safe
// write order and the failures (missing PDO, aborts, silent node).
#include "canopen/pdoclient.h"
#include "canopen/sdoabort.h"
#include "canopen/sdoclient.h"
#include "simloopback.h"

#include <QSignalSpy>
#include <QTest>

using namespace db;
using namespace db::canopen;

class TestPdo : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void mappingEntryRoundTrip();
    void decodesByteAlignedMapping();
    void decodesBitFieldsAndDummies();
    void decodeRejectsShortFrame();
    void readsTheNodesConfiguration();
    void readAllProbesWithoutDictionary();
    void configureWritesInTheSafeOrder();
    void configuredTpdoIsSentOnSync();
    void decodesTheSentTpdo();
    void missingPdoFailsWithAbort();
    void abortDuringConfigureStopsAndNamesTheObject();
    void silentNodeTimesOut();
};

void TestPdo::mappingEntryRoundTrip()
{
    const auto e = PdoMappingEntry::fromRaw(0x60410010);
    QCOMPARE(e.address, ObjectAddress(0x6041, 0));
    QCOMPARE(e.bits, quint8(16));
    QCOMPARE(e.toRaw(), 0x60410010u);
    QVERIFY(PdoMappingEntry::fromRaw(0x00050008).isDummy());
}

namespace {
ObjectDictionary testDictionary()
{
    return resources::builtinDescription(QStringLiteral("drivebench_testnode")).valueOr({});
}
} // namespace

void TestPdo::decodesByteAlignedMapping()
{
    PdoConfig c;
    c.cobId = 0x181;
    c.entries = { PdoMappingEntry::fromRaw(0x60410010), PdoMappingEntry::fromRaw(0x60640020) };
    const auto values = decodePdo(c, QByteArray::fromHex("5002D2040000"), testDictionary());
    QVERIFY2(values, qPrintable(values.error().toString()));
    QCOMPARE(values->size(), 2);
    QCOMPARE(values->at(0).address, ObjectAddress(0x6041, 0));
    QCOMPARE(values->at(0).raw.toUInt(), 0x0250u);
    QCOMPARE(values->at(1).raw.toInt(), 1234);
}

void TestPdo::decodesBitFieldsAndDummies()
{
    PdoConfig c;
    // 4 bits of 2100h, a 4-bit dummy (0005h = UNSIGNED8 dummy), then 2101h (INTEGER16).
    c.entries = { PdoMappingEntry::fromRaw(0x21000004), PdoMappingEntry::fromRaw(0x00050004),
                  PdoMappingEntry::fromRaw(0x21010010) };
    const auto values = decodePdo(c, QByteArray::fromHex("F5D4FE"), testDictionary());
    QVERIFY2(values, qPrintable(values.error().toString()));
    QCOMPARE(values->size(), 2);
    QCOMPARE(values->at(0).raw.toUInt(), 5u);
    QCOMPARE(values->at(1).raw.toInt(), -300);
}

void TestPdo::decodeRejectsShortFrame()
{
    PdoConfig c;
    c.entries = { PdoMappingEntry::fromRaw(0x60640020) };
    const auto values = decodePdo(c, QByteArray::fromHex("0102"), testDictionary());
    QVERIFY(!values);
    QCOMPARE(values.error().kind(), Error::Kind::Malformed);
}

void TestPdo::readsTheNodesConfiguration()
{
    test::SimLoopback sim;
    sim.addNode(5);
    SdoClient sdo(&sim.bus);
    PdoClient client(&sdo);
    const auto read = Reply::wait(client.read(5, PdoDirection::Transmit, 0));
    QVERIFY2(read, qPrintable(read.error().toString()));
    const auto c = read->value<PdoConfig>();
    QCOMPARE(c.cobId, 0x40000185u);
    QVERIFY(c.isEnabled());
    QCOMPARE(c.canId(), 0x185u);
    QCOMPARE(c.transmissionType, quint8(0xFF));
    QCOMPARE(c.inhibitTime, std::optional<quint16>(0));
    QCOMPARE(c.eventTimer, std::optional<quint16>(0));
    QCOMPARE(c.entries.size(), 2);
    QCOMPARE(c.entries.at(1).toRaw(), 0x60640020u);
    const auto rx = Reply::wait(client.read(5, PdoDirection::Receive, 1));
    QVERIFY(rx);
    QVERIFY(!rx->value<PdoConfig>().inhibitTime); // RPDO comm has no sub 3 here
    QCOMPARE(rx->value<PdoConfig>().entries.size(), 2);
}

void TestPdo::readAllProbesWithoutDictionary()
{
    test::SimLoopback sim;
    sim.addNode(5);
    SdoClient sdo(&sim.bus);
    PdoClient client(&sdo);
    const auto all = Reply::wait(client.readAll(5));
    QVERIFY2(all, qPrintable(all.error().toString()));
    const auto list = all->value<QList<PdoConfig>>();
    QCOMPARE(list.size(), 4);
    QCOMPARE(list.at(0).name(), QStringLiteral("RPDO1"));
    QCOMPARE(list.at(3).name(), QStringLiteral("TPDO2"));
    const auto byDict = Reply::wait(client.readAll(5, testDictionary()));
    QVERIFY(byDict);
    QCOMPARE(byDict->value<QList<PdoConfig>>(), list);
    // One direction only (the scope's PDO discovery needs only the TPDOs).
    const auto tpdos = Reply::wait(client.readAll(5, {}, PdoDirection::Transmit));
    QVERIFY(tpdos);
    QCOMPARE(tpdos->value<QList<PdoConfig>>(), list.mid(2));
    const auto tpdosByDict =
        Reply::wait(client.readAll(5, testDictionary(), PdoDirection::Transmit));
    QVERIFY(tpdosByDict);
    QCOMPARE(tpdosByDict->value<QList<PdoConfig>>(), list.mid(2));
}

void TestPdo::configureWritesInTheSafeOrder()
{
    PdoConfig c;
    c.direction = PdoDirection::Transmit;
    c.number = 0;
    c.cobId = 0x185;
    c.transmissionType = 1;
    c.entries = { PdoMappingEntry::fromRaw(0x21030020), PdoMappingEntry::fromRaw(0x21000008) };
    const auto seq = PdoClient::configureSequence(c);
    QStringList order;
    for (const auto &w : seq)
        order << QStringLiteral("%1=%2").arg(w.address.toString(),
                                             QString::fromLatin1(w.data.toHex()));
    QCOMPARE(order,
             QStringList({ "1800:1=85010080", "1800:2=01", "1A00:0=00", "1A00:1=20000321",
                           "1A00:2=08000021", "1A00:0=02", "1800:1=85010000" }));
}

void TestPdo::configuredTpdoIsSentOnSync()
{
    test::SimLoopback sim;
    SimulatedNode *node = sim.addNode(5);
    SdoClient sdo(&sim.bus);
    PdoClient client(&sdo);
    PdoConfig c;
    c.number = 0;
    c.cobId = 0x185;
    c.transmissionType = 1;
    c.entries = { PdoMappingEntry::fromRaw(0x21030020), PdoMappingEntry::fromRaw(0x21000008) };
    const auto done = Reply::wait(client.configure(5, c));
    QVERIFY2(done, qPrintable(done.error().toString()));
    const auto back = Reply::wait(client.read(5, PdoDirection::Transmit, 0));
    QVERIFY(back);
    QCOMPARE(back->value<PdoConfig>().entries, c.entries);
    QCOMPARE(back->value<PdoConfig>().cobId, 0x185u);
    QCOMPARE(node->tpdoPayload(0), QByteArray::fromHex("6079feff07"));
}

void TestPdo::decodesTheSentTpdo()
{
    test::SimLoopback sim;
    SimulatedNode *node = sim.addNode(5);
    node->receive(QCanBusFrame(0x000, QByteArray::fromHex("0105"))); // start
    SdoClient sdo(&sim.bus);
    PdoClient client(&sdo);
    const auto read = Reply::wait(client.read(5, PdoDirection::Transmit, 1));
    QVERIFY(read);
    const auto config = read->value<PdoConfig>();
    QSignalSpy seen(&sim.bus, &CanBus::frameReceived);
    sim.bus.send(QCanBusFrame(0x080, QByteArray())); // SYNC: TPDO2 is synchronous (type 1)
    QCanBusFrame frame;
    QTRY_VERIFY(std::any_of(seen.cbegin(), seen.cend(), [&](const QList<QVariant> &args) {
        frame = args.first().value<QCanBusFrame>();
        return frame.frameId() == config.canId();
    }));
    const auto values = decodePdo(config, frame.payload(), testDictionary());
    QVERIFY(values);
    QCOMPARE(values->at(0).raw.toUInt(), 7u);
    QCOMPARE(values->at(1).raw.toUInt(), 0x12345678u);
}

void TestPdo::missingPdoFailsWithAbort()
{
    test::SimLoopback sim;
    sim.addNode(5);
    SdoClient sdo(&sim.bus);
    PdoClient client(&sdo);
    const auto read = Reply::wait(client.read(5, PdoDirection::Transmit, 7));
    QVERIFY(!read);
    QCOMPARE(read.error().kind(), Error::Kind::DeviceError);
    QCOMPARE(read.error().deviceCode(), abort::NoSuchObject);
    QVERIFY(read.error().message().contains(QLatin1String("1807:1")));
}

void TestPdo::abortDuringConfigureStopsAndNamesTheObject()
{
    test::SimLoopback sim;
    SimulatedNode *node = sim.addNode(5);
    node->setSdoAbort({ 0x1A00, 1 }, abort::NotMappable);
    SdoClient sdo(&sim.bus);
    PdoClient client(&sdo);
    PdoConfig c;
    c.cobId = 0x185;
    c.entries = { PdoMappingEntry::fromRaw(0x21030020) };
    const auto done = Reply::wait(client.configure(5, c));
    QVERIFY(!done);
    QCOMPARE(done.error().deviceCode(), abort::NotMappable);
    QVERIFY2(done.error().message().contains(QLatin1String("1A00:1")),
             qPrintable(done.error().message()));
    // The PDO stays disabled and unmapped: never half-configured.
    QCOMPARE(node->store()->value({ 0x1800, 1 }).toUInt() & PdoConfig::kInvalidBit,
             PdoConfig::kInvalidBit);
    QCOMPARE(node->store()->value({ 0x1A00, 0 }).toUInt(), 0u);
}

void TestPdo::silentNodeTimesOut()
{
    test::SimLoopback sim;
    sim.addNode(5)->setSdoNoReply(true);
    SdoClient sdo(&sim.bus);
    sdo.setTimeoutMs(50);
    PdoClient client(&sdo);
    const auto read = Reply::wait(client.readAll(5));
    QVERIFY(!read);
    QCOMPARE(read.error().kind(), Error::Kind::Timeout);
}

QTEST_GUILESS_MAIN(TestPdo)
#include "tst_pdo.moc"
