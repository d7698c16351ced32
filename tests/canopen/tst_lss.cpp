// LSS (CiA 305): the byte-exact example of nm170_canopen.md 2.4 from both sides (master frames
// against a script, slave answers to the manual's requests), then master and the simulated
// node's slave together: inquire, configure node id, store, bit timing, fastscan, failures.
#include "canopen/device/lssslave.h"
#include "canopen/lssmaster.h"
#include "canopen/nmtmaster.h"
#include "simloopback.h"

#include <QSignalSpy>
#include <QTest>

using namespace db;
using namespace db::canopen;
using db::test::ScriptedCanBus;

namespace {
// The identity of the manual's example (nm170_canopen.md 2.4).
const LssAddress kNm172 { 0x000000EC, 0x00000071, 0x00010001, 0x4D52F567 };
} // namespace

class TestLss : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void masterSendsTheManualsFramesCompact();
    void slaveAnswersTheManualsFrames();
    void fullFramesHaveDlc8();
    void inquireAndConfigureTheSimulatedNode();
    void selectiveSwitchIgnoresOtherIdentities();
    void bitTimingOutOfRangeIsRefused();
    void fastscanFindsTheUnconfiguredSlave();
    void fastscanWithoutSlaveTimesOut();
    void silentBusTimesOut();
    void secondRequestWhileBusyFails();
    void bitTimingTable();
};

void TestLss::masterSendsTheManualsFramesCompact()
{
    ScriptedCanBus bus;
    bus.open();
    LssMaster master(&bus);
    master.setFrameLength(LssMaster::FrameLength::Compact);
    NmtMaster nmt(&bus);
    bus.play(
        { ScriptedCanBus::tx(0x000, "02 00"), ScriptedCanBus::tx(0x7E5, "04 01"),
          ScriptedCanBus::tx(0x7E5, "40 EC 00 00 00 00 00 00"),
          ScriptedCanBus::tx(0x7E5, "41 71 00 00 00 00 00 00"),
          ScriptedCanBus::tx(0x7E5, "42 01 00 01 00 00 00 00"),
          ScriptedCanBus::tx(0x7E5, "43 67 F5 52 4D 00 00 00"),
          ScriptedCanBus::rx(0x7E4, "44 00 00 00 00 00 00 00"), ScriptedCanBus::tx(0x7E5, "11 25"),
          ScriptedCanBus::rx(0x7E4, "11 00 00 00 00 00 00 00"), ScriptedCanBus::tx(0x7E5, "17 00"),
          ScriptedCanBus::rx(0x7E4, "17 00 00 00 00 00 00 00") });
    QVERIFY(nmt.stop());
    QVERIFY(master.switchModeGlobal(LssMode::Configuration));
    QVERIFY(Reply::wait(master.switchModeSelective(kNm172)));
    QVERIFY(Reply::wait(master.configureNodeId(0x25)));
    QVERIFY(Reply::wait(master.storeConfiguration()));
    QVERIFY2(bus.scriptErrors().isEmpty(), qPrintable(bus.scriptErrors().join(u'\n')));
    QVERIFY(bus.scriptDone());
}

void TestLss::slaveAnswersTheManualsFrames()
{
    LssSlave slave;
    slave.setIdentity(kNm172);
    slave.setActiveNodeId(127);
    QSignalSpy out(&slave, &LssSlave::transmit);
    const auto feed = [&](const char *hex) {
        slave.receive(ScriptedCanBus::frame(0x7E5, hex));
        QStringList answers;
        for (const auto &args : out)
            answers << test::describe(args.first().value<QCanBusFrame>());
        out.clear();
        return answers;
    };
    QCOMPARE(feed("04 01"), QStringList());
    QCOMPARE(slave.mode(), LssMode::Configuration);
    QCOMPARE(feed("40 EC 00 00 00 00 00 00"), QStringList());
    QCOMPARE(feed("41 71 00 00 00 00 00 00"), QStringList());
    QCOMPARE(feed("42 01 00 01 00 00 00 00"), QStringList());
    QCOMPARE(feed("43 67 F5 52 4D 00 00 00"), QStringList({ "7e4 [8] 44 00 00 00 00 00 00 00" }));
    QCOMPARE(feed("11 25"), QStringList({ "7e4 [8] 11 00 00 00 00 00 00 00" }));
    QCOMPARE(slave.pendingNodeId(), quint8(0x25));
    QCOMPARE(slave.activeNodeId(), quint8(127)); // until reset communication (CiA 305)
    QCOMPARE(feed("17 00"), QStringList({ "7e4 [8] 17 00 00 00 00 00 00 00" }));
    QCOMPARE(slave.storeCount(), 1);
}

void TestLss::fullFramesHaveDlc8()
{
    ScriptedCanBus bus;
    bus.open();
    LssMaster master(&bus);
    master.switchModeGlobal(LssMode::Configuration);
    delete master.configureNodeId(5);
    const auto sent = bus.takeSent();
    QCOMPARE(sent.size(), 2);
    QCOMPARE(sent.at(0).payload(), QByteArray::fromHex("0401000000000000"));
    QCOMPARE(sent.at(1).payload(), QByteArray::fromHex("1105000000000000"));
}

void TestLss::inquireAndConfigureTheSimulatedNode()
{
    test::SimLoopback sim;
    SimulatedNode *node = sim.addNode(5);
    LssMaster master(&sim.bus);
    NmtMaster nmt(&sim.bus);
    const LssAddress address { 0x0DB0, 0x0001, 0x00010000, 0x1005 };
    QVERIFY(Reply::wait(master.switchModeSelective(address)));
    QCOMPARE(node->lssSlave().mode(), LssMode::Configuration);
    QCOMPARE(Reply::wait(master.inquire(lss::InquireVendor))->toUInt(), 0x0DB0u);
    QCOMPARE(Reply::wait(master.inquire(lss::InquireSerial))->toUInt(), 0x1005u);
    QCOMPARE(Reply::wait(master.inquire(lss::InquireNodeId))->toUInt(), 5u);
    QVERIFY(Reply::wait(master.configureNodeId(9)));
    QVERIFY(Reply::wait(master.storeConfiguration()));
    QVERIFY(master.switchModeGlobal(LssMode::Waiting));
    QCOMPARE(node->nodeId(), NodeId(5));
    QSignalSpy boot(&sim.bus, &CanBus::frameReceived);
    QVERIFY(nmt.resetCommunication(5));
    QCOMPARE(node->nodeId(), NodeId(9));
    QTRY_VERIFY(std::any_of(boot.cbegin(), boot.cend(), [](const QList<QVariant> &a) {
        return a.first().value<QCanBusFrame>().frameId() == 0x709;
    }));
}

void TestLss::selectiveSwitchIgnoresOtherIdentities()
{
    test::SimLoopback sim;
    SimulatedNode *node = sim.addNode(5);
    LssMaster master(&sim.bus);
    master.setTimeoutMs(50);
    const auto r = Reply::wait(master.switchModeSelective({ 0x0DB0, 1, 0x00010000, 0x1006 }));
    QVERIFY(!r);
    QCOMPARE(r.error().kind(), Error::Kind::Timeout);
    QCOMPARE(node->lssSlave().mode(), LssMode::Waiting);
    // Inquire and configure are ignored outside configuration mode.
    QCOMPARE(Reply::wait(master.configureNodeId(9)).error().kind(), Error::Kind::Timeout);
}

void TestLss::bitTimingOutOfRangeIsRefused()
{
    test::SimLoopback sim;
    sim.addNode(5);
    LssMaster master(&sim.bus);
    master.switchModeGlobal(LssMode::Configuration);
    const auto bad = Reply::wait(master.configureBitTiming(9));
    QVERIFY(!bad);
    QCOMPARE(bad.error().kind(), Error::Kind::DeviceError);
    QCOMPARE(bad.error().deviceCode(), 1u);
    QVERIFY(Reply::wait(master.configureBitTiming(quint8(lss::bitTimingIndex(250000)))));
    QCOMPARE(sim.nodes.front()->lssSlave().bitTimingIndex(), 3);
}

void TestLss::fastscanFindsTheUnconfiguredSlave()
{
    ScriptedCanBus bus;
    bus.open();
    LssSlave unconfigured;
    unconfigured.setIdentity(kNm172);
    LssSlave configured; // has a node id: stays out of fastscan (CiA 305)
    configured.setIdentity({ 0xEC, 0x71, 0x00010001, 0x11111111 });
    configured.setActiveNodeId(3);
    for (LssSlave *s : { &unconfigured, &configured }) {
        connect(&bus, &ScriptedCanBus::frameWritten, s, &LssSlave::receive);
        connect(s, &LssSlave::transmit, &bus, [&bus](const QCanBusFrame &f) { bus.feedLater(f); });
    }
    LssMaster master(&bus);
    master.setFastscanStepMs(5);
    const auto found = Reply::wait(master.fastscan());
    QVERIFY2(found, qPrintable(found.error().toString()));
    QCOMPARE(found->value<LssAddress>(), kNm172);
    QCOMPARE(unconfigured.mode(), LssMode::Configuration);
    QCOMPARE(configured.mode(), LssMode::Waiting);
    QVERIFY(Reply::wait(master.configureNodeId(12)));
    QSignalSpy activated(&unconfigured, &LssSlave::nodeIdActivated);
    master.switchModeGlobal(LssMode::Waiting);
    QCOMPARE(activated.size(), 1);
    QCOMPARE(unconfigured.activeNodeId(), quint8(12));
}

void TestLss::fastscanWithoutSlaveTimesOut()
{
    test::SimLoopback sim;
    sim.addNode(5); // configured: does not take part
    LssMaster master(&sim.bus);
    master.setFastscanStepMs(5);
    const auto found = Reply::wait(master.fastscan());
    QVERIFY(!found);
    QCOMPARE(found.error().kind(), Error::Kind::Timeout);
    QVERIFY(found.error().message().contains(QLatin1String("unconfigured")));
}

void TestLss::silentBusTimesOut()
{
    ScriptedCanBus bus;
    bus.open();
    LssMaster master(&bus);
    master.setTimeoutMs(30);
    const auto r = Reply::wait(master.inquire(lss::InquireVendor));
    QVERIFY(!r);
    QCOMPARE(r.error().kind(), Error::Kind::Timeout);
    bus.feed(0x7E4, "5A EC 00 00 00 00 00 00"); // late: belongs to nothing
    QVERIFY(!master.isBusy());
}

void TestLss::secondRequestWhileBusyFails()
{
    ScriptedCanBus bus;
    bus.open();
    LssMaster master(&bus);
    Reply *first = master.inquire(lss::InquireVendor);
    const auto second = Reply::wait(master.storeConfiguration());
    QCOMPARE(second.error().kind(), Error::Kind::Busy);
    bus.feed(0x7E4, "5A EC 00 00 00 00 00 00");
    QCOMPARE(Reply::wait(first)->toUInt(), 0xECu);
}

void TestLss::bitTimingTable()
{
    QCOMPARE(lss::bitTimingIndex(1000000), 0);
    QCOMPARE(lss::bitTimingIndex(125000), 4);
    QCOMPARE(lss::bitTimingIndex(10000), 8);
    QCOMPARE(lss::bitTimingIndex(33333), -1);
    QCOMPARE(lss::bitrateOfIndex(3), 250000);
}

QTEST_GUILESS_MAIN(TestLss)
#include "tst_lss.moc"
