// The master's NM17x services against simulated displays on a scripted bus: broadcast
// addressing by shaft turns, reading a display, positioning and broadcast commands, and the
// refusal of forbidden commands before anything is sent.
#include "devices/nm17x/device/simulatednm17x.h"
#include "devices/nm17x/nm17xaddressing.h"
#include "devices/nm17x/nm17xcodes.h"
#include "devices/nm17x/nm17xline.h"
#include "scriptedcanbus.h"

#include "canopen/device/simulatednode.h"
#include "canopen/nmtmaster.h"
#include "canopen/nodemonitor.h"
#include "canopen/sdoclient.h"

#include <QSignalSpy>
#include <QTest>

using namespace db;
using namespace db::nm17x;

namespace {

struct Bench
{
    explicit Bench(const QList<Variant> &variants, const QList<canopen::NodeId> &nodes = {})
        : bus(new test::ScriptedCanBus)
        , network(bus)
    {
        network.acquire();
        quint32 serial = 0x1000;
        for (const Variant v : variants) {
            const auto node = nodes.value(displays.size(), canopen::NodeId(127));
            auto *d = new SimulatedNm17x(v, serial++, node);
            QObject::connect(bus, &test::ScriptedCanBus::frameWritten, d, &SimulatedNm17x::receive);
            QObject::connect(d, &SimulatedNm17x::transmit, bus,
                             [this](const QCanBusFrame &f) { bus->feedLater(f); });
            d->start();
            displays.append(d);
        }
    }
    ~Bench() { qDeleteAll(displays); }
    int framesSentTo(quint32 id)
    {
        int n = 0;
        for (const QCanBusFrame &f : bus->sent())
            n += f.frameId() == id ? 1 : 0;
        return n;
    }

    test::ScriptedCanBus *bus; // owned by the network
    canopen::CanNetwork network;
    QList<SimulatedNm17x *> displays;
};

} // namespace

class TstNm17xLine : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void broadcastAddressingByShaftTurns();
    void addressingTimesOutWithoutOperator();
    void addressingEndsAtFirstSilentStepWithoutCount();
    void readStateAndPosition();
    void findDisplaysSkipsOtherDevices();
    void forbiddenCommandsNeverLeave();
    void jogStopAndPresetAll();
    void emergencyWithText();
    void segmentedStringsAndNodeIdBySdo();
    void millimetres();
};

void TstNm17xLine::broadcastAddressingByShaftTurns()
{
    Bench b({ Variant::Nm172, Variant::Nm172, Variant::Nm174 });
    BroadcastAddressing addressing(&b.network);
    const int order[] = { 2, 0, 1 }; // the operator's choice for ids 2, 3, 4
    connect(&addressing, &BroadcastAddressing::offering, this, [&](canopen::NodeId node) {
        QTimer::singleShot(20, this, [&, node] { b.displays.at(order[node - 2])->turnShaft(5); });
    });
    QSignalSpy finished(&addressing, &BroadcastAddressing::finished);
    QVERIFY(addressing.start(2, 3));
    QVERIFY(finished.wait(5000));
    QCOMPARE(finished.at(0).at(0).toBool(), true);
    QCOMPARE(addressing.assignedIds(), (QList<canopen::NodeId> { 2, 3, 4 }));
    QCOMPARE(b.displays.at(2)->nodeId(), canopen::NodeId(2));
    QCOMPARE(b.displays.at(0)->nodeId(), canopen::NodeId(3));
    QCOMPARE(b.displays.at(1)->nodeId(), canopen::NodeId(4));
    // The frames of the procedure, as the displays expect them.
    const QList<QCanBusFrame> sent = b.bus->sent();
    QCOMPARE(sent.at(0).payload(), QByteArray::fromHex("0200"));
    QCOMPARE(sent.at(1).payload(), QByteArray::fromHex("0401"));
    QCOMPARE(sent.at(2).payload(), QByteArray::fromHex("40EC000000000000"));
    QCOMPARE(sent.at(5).payload(), QByteArray::fromHex("43FFFFFFFF000000"));
    QCOMPARE(sent.at(6).payload(), QByteArray::fromHex("1102000000000000"));
    QCOMPARE(sent.last().payload(), QByteArray::fromHex("8100"));
}

void TstNm17xLine::addressingTimesOutWithoutOperator()
{
    Bench b({ Variant::Nm172 });
    BroadcastAddressing addressing(&b.network);
    addressing.setStepTimeoutMs(100);
    QSignalSpy finished(&addressing, &BroadcastAddressing::finished);
    QVERIFY(addressing.start(5, 1));
    QVERIFY(finished.wait(2000));
    QCOMPARE(finished.at(0).at(0).toBool(), false);
    QCOMPARE(addressing.error().kind(), Error::Kind::Timeout);
    QVERIFY(addressing.error().message().contains(QLatin1String("node id 5")));
    QVERIFY(!addressing.start(0, 1));
    QVERIFY(!addressing.start(127, 2));
}

void TstNm17xLine::addressingEndsAtFirstSilentStepWithoutCount()
{
    Bench b({ Variant::Nm170, Variant::Nm172 });
    BroadcastAddressing addressing(&b.network);
    addressing.setStepTimeoutMs(300);
    connect(&addressing, &BroadcastAddressing::offering, this, [&](canopen::NodeId node) {
        if (node == 10)
            QTimer::singleShot(20, this, [&] { b.displays.at(1)->pressKey(1); });
    });
    QSignalSpy finished(&addressing, &BroadcastAddressing::finished);
    QVERIFY(addressing.start(10));
    QVERIFY(finished.wait(3000));
    QCOMPARE(finished.at(0).at(0).toBool(), true);
    QCOMPARE(addressing.assignedIds(), QList<canopen::NodeId> { 10 });
    QCOMPARE(b.displays.at(1)->nodeId(), canopen::NodeId(10));
    QCOMPARE(b.displays.at(0)->nodeId(), canopen::NodeId(127));
}

void TstNm17xLine::readStateAndPosition()
{
    Bench b({ Variant::Nm174 });
    b.displays.at(0)->spindle().setPosition(12345);
    Nm17xLine line(&b.network);
    const auto state = Reply::wait(line.readState(127));
    QVERIFY2(state, qPrintable(state ? QString() : state.error().toString()));
    const auto s = state->value<DisplayState>();
    QCOMPARE(s.variant, Variant::Nm174);
    QCOMPARE(s.serial, 0x1000u);
    QCOMPARE(s.position, 12345);
    QVERIFY(s.toString().contains(QLatin1String("NM174  serial 0x00001000  position 123.45 mm")));
    QCOMPARE(formatPosition(2540, true), QStringLiteral("1.0000 in"));
}

void TstNm17xLine::findDisplaysSkipsOtherDevices()
{
    Bench b({ Variant::Nm170, Variant::Nm174 }, { 5, 2 });
    b.network.sdo()->setTimeoutMs(200);
    // A node of another vendor at 9 with a look-alike product code.
    canopen::SimulatedNode foreign(dictionary(Variant::Nm172), 9);
    foreign.store()->set({ 0x1018, 1 }, 0x53Bu);
    connect(b.bus, &test::ScriptedCanBus::frameWritten, &foreign, &canopen::SimulatedNode::receive);
    connect(&foreign, &canopen::SimulatedNode::transmit, b.bus,
            [&b](const QCanBusFrame &f) { b.bus->feedLater(f); });
    foreign.start();
    Nm17xLine line(&b.network);
    const auto found = Reply::wait(line.findDisplays());
    QVERIFY(found);
    const auto displays = found->value<QList<DisplayState>>();
    QCOMPARE(displays.size(), 2);
    QCOMPARE(displays.at(0).node, canopen::NodeId(2));
    QCOMPARE(displays.at(0).variant, Variant::Nm174);
    QCOMPARE(displays.at(1).node, canopen::NodeId(5));
    QCOMPARE(displays.at(1).variant, Variant::Nm170);
    QVERIFY(line.problems().isEmpty());
}

void TstNm17xLine::forbiddenCommandsNeverLeave()
{
    Bench b({ Variant::Nm172 });
    Nm17xLine line(&b.network);
    const int before = b.bus->sent().size();
    const auto refused = line.send(127, { 1000, 0, 0x0005 });
    QVERIFY(!refused);
    QVERIFY(refused.error().message().contains(QLatin1String("not an allowed combination")));
    QVERIFY(!line.setpoint(127, 1000, SetpointKind::Plunge)); // plunge cut needs a speed
    QVERIFY(!line.setpoint(127, 1000000, SetpointKind::Release)); // beyond 9999.99 mm
    QVERIFY(!line.broadcast({ 0, 0x2020, 1, 5 })); // not a broadcast object
    QVERIFY(!line.startGroup(9));
    QCOMPARE(b.bus->sent().size(), before);
    QVERIFY(line.setpoint(127, 1000, SetpointKind::Release));
    QCOMPARE(b.framesSentTo(0x37F), 1);
}

void TstNm17xLine::jogStopAndPresetAll()
{
    Bench b({ Variant::Nm172, Variant::Nm172 });
    Nm17xLine line(&b.network);
    b.network.nmt()->send(canopen::NmtCommand::Start, 0);
    QVERIFY(line.jog(127, 1, Speed::Fast)); // both displays share node 127 here
    QTRY_VERIFY(b.displays.at(0)->position() > 300);
    QVERIFY(line.stop(127));
    QTRY_VERIFY(!b.displays.at(0)->spindle().isMoving());
    QVERIFY(line.presetAll(-500));
    QTRY_COMPARE(b.displays.at(0)->position(), -500);
    QCOMPARE(b.displays.at(1)->position(), -500);
    QSignalSpy tpdo(&line, &Nm17xLine::tpdo2);
    b.displays.at(1)->turnShaft(100);
    // Both displays answer on node 127: a TxPDO2 of display 0 (still -500) may come first.
    const auto sawTurnedDisplay = [&tpdo] {
        for (const QList<QVariant> &args : tpdo)
            if (args.at(1).value<Tpdo2>().position == -400)
                return true;
        return false;
    };
    QTRY_VERIFY_WITH_TIMEOUT(sawTurnedDisplay(), 2000);
}

void TstNm17xLine::emergencyWithText()
{
    Bench b({ Variant::Nm172 });
    Nm17xLine line(&b.network);
    b.network.nmt()->send(canopen::NmtCommand::Start, 127);
    QSignalSpy emcy(&line, &Nm17xLine::emergency);
    b.network.send(QCanBusFrame(0x37F, QByteArray::fromHex("0000000000008100"))); // jog, no speed
    QVERIFY(emcy.wait(2000));
    QCOMPARE(emcy.at(0).at(1).toUInt(), 0x8230u);
    QCOMPARE(emcy.at(0).at(2).toUInt(), 1u);
    QCOMPARE(emcy.at(0).at(3).toString(),
             QStringLiteral("RxPDO2: invalid value in the control word"));
}

void TstNm17xLine::segmentedStringsAndNodeIdBySdo()
{
    Bench b({ Variant::Nm172 });
    canopen::SdoClient *sdo = b.network.sdo();
    QCOMPARE(Reply::wait(sdo->upload(127, { 0x1008, 0 }))->toByteArray(),
             QByteArray("NM172 Standard"));
    QVERIFY(Reply::wait(sdo->download(127, { 0x2007, 0 }, "HELLO-WORLD_")));
    const auto shortText = Reply::wait(sdo->download(127, { 0x2007, 0 }, "HELLO"));
    QVERIFY(!shortText);
    QCOMPARE(shortText.error().deviceCode(), 0x06090030u);
    QVERIFY(Reply::wait(sdo->download(127, { 0x2101, 0 }, QByteArray(1, char(9)))));
    QSignalSpy boot(b.network.monitor(), &canopen::NodeMonitor::bootUp);
    b.network.nmt()->send(canopen::NmtCommand::ResetNode, 127);
    QVERIFY(boot.wait(2000));
    QCOMPARE(boot.at(0).at(0).value<canopen::NodeId>(), canopen::NodeId(9));
    QCOMPARE(Reply::wait(sdo->upload(9, { 0x2101, 0 }))->toByteArray(), QByteArray(1, char(9)));
}

void TstNm17xLine::millimetres()
{
    QCOMPARE(parseMillimetres(QStringLiteral("10")).value(), 1000);
    QCOMPARE(parseMillimetres(QStringLiteral("-2.5")).value(), -250);
    QCOMPARE(parseMillimetres(QStringLiteral("9999.99")).value(), 999999);
    QVERIFY(!parseMillimetres(QStringLiteral("10000")));
    QVERIFY(!parseMillimetres(QStringLiteral("ten")));
}

QTEST_GUILESS_MAIN(TstNm17xLine)
#include "tst_nm17xline.moc"
