// The simulated NM17x displays against the byte sequences of the device (SDO, LSS selective and
// broadcast addressing, RxPDO checks, EMCY) and the spindle model (loop, limits, jog).
#include "devices/nm17x/device/nm17xsim.h"
#include "devices/nm17x/device/simulatednm17x.h"
#include "devices/nm17x/nm17xcodes.h"
#include "nm17xtestline.h"

#include <QSignalSpy>
#include <QTest>

using namespace db;
using namespace db::nm17x;
using db::test::Frame;
using db::test::Line;

class TstSimulatedNm17x : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void bootUp();
    void sdoVectors();
    void sdoDeviceRules();
    void lssSelectiveSequence();
    void lssBroadcastAddressing();
    void forbiddenControlWordRaisesEmcy();
    void broadcastOnlyAllowedObjects();
    void positioningWithLoop();
    void setpointBeyondEndLimitIsRefused();
    void jogUntilStopAndUntilLimit();
    void oscillationBetweenD1AndD2();
    void inputsTakten();
    void inputsExternPosiAsInTheManual();
    void inputsStandardOscillateAndTravel();
    void heldKeyRunsAtTheKeyModeSpeed();
    void txPdo2OnChange();
    void cycleRestsWhileNothingChanges();
    void faultsShowTheirErrors();
    void heartbeatLossStopsAndReports();
    void storeAndRestoreCommunicationObjects();
    void lowerNmtStateStopsPositioning();
    void simParsesDevices();
    void controlCommands();
};

void TstSimulatedNm17x::bootUp()
{
    Line line({ Variant::Nm172 });
    const QList<Frame> f = line.take();
    QCOMPARE(f.size(), 1);
    QCOMPARE(f.at(0).id, 0x77Fu);
    QCOMPARE(f.at(0).data, QByteArray(1, '\0'));
    QCOMPARE(line.devices.at(0)->nmtState(), canopen::NmtState::PreOperational);
}

void TstSimulatedNm17x::sdoVectors()
{
    Line line({ Variant::Nm172 });
    line.take();
    line.devices.at(0)->spindle().setPosition(500000);
    line.send(0x67F, "4004600000000000"); // SDO-1
    QCOMPARE(line.take().at(0).data, QByteArray::fromHex("4304600020A10700"));
    line.send(0x67F, "2303200040010000"); // SDO-2
    QCOMPARE(line.take().at(0).data, QByteArray::fromHex("6003200000000000"));
    line.send(0x67F, "4001210000000000"); // SDO-3
    QCOMPARE(line.take().at(0).data, QByteArray::fromHex("4F0121007F000000"));
    line.send(0x67F, "2300200501000000"); // SDO-4
    QCOMPARE(line.take().at(0).data, QByteArray::fromHex("6000200500000000"));
    line.send(0x67F, "2300200502000000"); // SDO-5: out of range
    QCOMPARE(line.take().at(0).data, QByteArray::fromHex("8000200530000906"));
}

void TstSimulatedNm17x::sdoDeviceRules()
{
    Line line({ Variant::Nm170 });
    line.take();
    line.send(0x67F, "2380 1F00 03000000"); // 1F80h only 0 or 8
    QCOMPARE(line.take().at(0).data, QByteArray::fromHex("80801F0030000906"));
    line.send(0x67F, "2310100173617600"); // wrong "save" signature
    QCOMPARE(line.take().at(0).data, QByteArray::fromHex("8010100120000008"));
    line.send(0x67F, "4008200000000000"); // 2008h is write-only
    QCOMPARE(line.take().at(0).data, QByteArray::fromHex("8008200001000106"));
    line.send(0x67F, "404E200100000000"); // NM170 has no 204Eh
    QCOMPARE(line.take().at(0).data, QByteArray::fromHex("804E200100000206"));
    line.send(0x000, "027F"); // no SDO in Stopped
    line.send(0x67F, "4001210000000000");
    QVERIFY(line.takeId(0x5FF).isEmpty());
}

void TstSimulatedNm17x::lssSelectiveSequence()
{
    Line line({ Variant::Nm172 });
    line.take();
    line.send(0x000, "0200");
    line.send(0x7E5, "0401");
    line.send(0x7E5, "40EC000000000000");
    line.send(0x7E5, "4171000000000000");
    line.send(0x7E5, "4201000100000000");
    QVERIFY(line.takeId(0x7E4).isEmpty());
    line.send(0x7E5, "4367F5524D000000");
    QCOMPARE(line.takeId(0x7E4).at(0).data, QByteArray::fromHex("4400000000000000"));
    line.send(0x7E5, "1125");
    QCOMPARE(line.takeId(0x7E4).at(0).data, QByteArray::fromHex("1100000000000000"));
    line.send(0x7E5, "1700");
    QCOMPARE(line.takeId(0x7E4).at(0).data, QByteArray::fromHex("1700000000000000"));
    line.send(0x000, "8100");
    QCOMPARE(line.devices.at(0)->nodeId(), canopen::NodeId(0x25));
    const QList<Frame> boot = line.takeId(0x725);
    QCOMPARE(boot.size(), 1);
    QCOMPARE(boot.at(0).data, QByteArray(1, '\0'));
}

void TstSimulatedNm17x::lssBroadcastAddressing()
{
    Line line({ Variant::Nm172, Variant::Nm172, Variant::Nm174 });
    line.take();
    line.send(0x000, "0200");
    line.send(0x7E5, "0401");
    line.send(0x7E5, "40EC000000000000");
    line.send(0x7E5, "41FFFFFFFF000000");
    line.send(0x7E5, "42FFFFFFFF000000");
    line.send(0x7E5, "43FFFFFFFF000000");
    QVERIFY(line.takeId(0x7E4).isEmpty()); // no 44h answer
    for (SimulatedNm17x *d : line.devices)
        QVERIFY(d->inAddressingMode());
    // Node 2 goes to the third display, 3 to the first, 4 to the second.
    const int order[] = { 2, 0, 1 };
    for (int step = 0; step < 3; ++step) {
        const QByteArray offer = QByteArray::fromHex("1100000000000000");
        QByteArray frame = offer;
        frame[1] = char(2 + step);
        for (SimulatedNm17x *d : line.devices)
            d->receive(QCanBusFrame(0x7E5, frame));
        QVERIFY(line.takeId(0x7E4).isEmpty()); // nobody answers before the operator acts
        line.devices.at(order[step])->turnShaft(10);
        const QList<Frame> answers = line.takeId(0x7E4);
        QCOMPARE(answers.size(), 1);
        QCOMPARE(answers.at(0).data, QByteArray::fromHex("1100000000000000"));
        line.devices.at(order[step])->turnShaft(10); // a second turn answers nothing more
        QVERIFY(line.takeId(0x7E4).isEmpty());
    }
    line.send(0x000, "8100");
    QCOMPARE(line.devices.at(2)->nodeId(), canopen::NodeId(2));
    QCOMPARE(line.devices.at(0)->nodeId(), canopen::NodeId(3));
    QCOMPARE(line.devices.at(1)->nodeId(), canopen::NodeId(4));
    // COB-IDs followed the node id; the broadcast RxPDO1 did not.
    line.take();
    line.send(0x603, "4001180100000000");
    QCOMPARE(line.takeId(0x583).at(0).data, QByteArray::fromHex("4301180183020040"));
}

void TstSimulatedNm17x::forbiddenControlWordRaisesEmcy()
{
    Line line({ Variant::Nm172 });
    line.send(0x000, "017F");
    line.take();
    line.send(0x37F, "E803000000000500"); // 0005h: no loop without release
    const QList<Frame> emcy = line.takeId(0x0FF);
    QCOMPARE(emcy.size(), 1);
    QCOMPARE(emcy.at(0).data, QByteArray::fromHex("3082010000000001"));
    QCOMPARE(emcyText(0x8230, quint8(emcy.at(0).data.at(7))),
             QStringLiteral("RxPDO2: invalid value in the control word"));
    line.send(0x67F, "4003100100000000"); // 1003h:01 keeps it
    QCOMPARE(line.takeId(0x5FF).at(0).data, QByteArray::fromHex("4303100130820100"));
}

void TstSimulatedNm17x::broadcastOnlyAllowedObjects()
{
    Line line({ Variant::Nm172, Variant::Nm170 });
    line.send(0x000, "0100");
    line.take();
    line.send(0x201, "0001200001000000"); // inch on both
    QVERIFY(line.takeId(0x0FF).isEmpty());
    line.send(0x67F, "4001200000000000");
    QCOMPARE(line.takeId(0x5FF).size(), 2); // two displays at node 127 answer
    line.send(0x201, "0020200101000000"); // 2020h is no broadcast object
    QCOMPARE(line.takeId(0x0FF).size(), 2);
    line.send(0x201, "0003600050C30000"); // preset all to 500.00 mm
    for (SimulatedNm17x *d : line.devices)
        QCOMPARE(d->position(), 50000);
}

void TstSimulatedNm17x::positioningWithLoop()
{
    Line line({ Variant::Nm172 });
    SimulatedNm17x *d = line.devices.at(0);
    d->spindle().setPosition(2000); // 20.00 mm, loop 1.00 mm by default, approach Up
    line.send(0x000, "017F");
    line.take();
    line.send(0x37F, "E803000000000300"); // setpoint 10.00 mm with release
    // The position is sampled at every frame the display sends and every check of the wait.
    double lowest = 1e9;
    const auto sample = [&] {
        lowest = qMin(lowest, double(d->position()));
    };
    const auto sampling = connect(d, &SimulatedNm17x::transmit, this, sample);
    const bool inPosition = QTest::qWaitFor(
        [&] {
            sample();
            return bool(d->statusWord() & status::InPosition);
        },
        10000);
    disconnect(sampling);
    QVERIFY(inPosition && (d->statusWord() & status::InPosition));
    QCOMPARE(lowest, 900.0); // loop point 10.00 - 1.00 mm, then up to the target
    QCOMPARE(d->position(), 1000);
    QTRY_VERIFY(!(d->statusWord() & status::Moving));
}

void TstSimulatedNm17x::setpointBeyondEndLimitIsRefused()
{
    Line line({ Variant::Nm172 });
    SimulatedNm17x *d = line.devices.at(0);
    line.send(0x000, "017F");
    line.send(0x67F, "2343200210270000"); // end limit MAX 100.00 mm
    QTRY_COMPARE(d->read({ 0x2043, 2 }).value().toInt(), 10000);
    line.send(0x37F, "11270000 0000 0300"); // 100.01 mm with release
    QTRY_VERIFY(d->errorWord() & (1u << 8));
    QVERIFY(d->statusWord() & status::Error);
    QVERIFY(!d->spindle().isMoving());
    QCOMPARE(activeErrors(d->errorWord()).at(0).code, QStringLiteral("Er 8"));
}

void TstSimulatedNm17x::jogUntilStopAndUntilLimit()
{
    Line line({ Variant::Nm174 });
    SimulatedNm17x *d = line.devices.at(0);
    line.send(0x000, "017F");
    line.send(0x37F, "0000000000009900"); // Tippen right fast
    QTRY_VERIFY(d->position() > 500);
    line.send(0x37F, "0000000000000040"); // stop
    QTRY_VERIFY(!d->spindle().isMoving());
    const qint32 stopped = d->position();
    QTest::qWait(50);
    QCOMPARE(d->position(), stopped);
    line.send(0x67F, "2343200288130000"); // end limit MAX 50.00 mm
    QTRY_COMPARE(d->read({ 0x2043, 2 }).value().toInt(), 5000);
    line.send(0x37F, "0000000000009100"); // right medium: runs into the limit and stops
    QTRY_VERIFY_WITH_TIMEOUT(!d->spindle().isMoving() && d->position() == 5000, 10000);
    QCOMPARE(d->errorWord(), quint16(0));
}

// 204Dh:02 = 1: D1 <-> D2 without loop, status bit 2; = 0: back to the setpoint 2020h:01.
void TstSimulatedNm17x::oscillationBetweenD1AndD2()
{
    Line line({ Variant::Nm172 });
    SimulatedNm17x *d = line.devices.at(0);
    line.send(0x000, "017F");
    line.send(0x67F, "2345200164000000"); // D1 = 1.00 mm
    line.send(0x67F, "234520022C010000"); // D2 = 3.00 mm
    QTRY_COMPARE(d->read({ 0x2045, 2 }).value().toInt(), 300);
    line.send(0x67F, "2F4D200201000000"); // start oscillating
    QTRY_VERIFY(d->statusWord() & status::Oscillating);
    QTRY_VERIFY_WITH_TIMEOUT(d->position() >= 295, 10000);
    QTRY_VERIFY_WITH_TIMEOUT(d->position() <= 105, 10000);
    QTRY_VERIFY_WITH_TIMEOUT(d->position() >= 295, 10000);
    QVERIFY(d->position() <= 305); // reversal points are approached directly, no loop beyond
    QVERIFY(d->isOscillating());
    line.send(0x67F, "2F4D200200000000"); // stop: back to the setpoint (10.00 mm by default)
    QTRY_VERIFY(!(d->statusWord() & status::Oscillating));
    QTRY_VERIFY_WITH_TIMEOUT(d->statusWord() & status::InPosition, 10000);
    QVERIFY(qAbs(d->position() - 1000) <= 5);

    // Not in input mode Takten (2041h:03 = 1): the external switch owns the axis.
    line.send(0x67F, "2341200301000000");
    QTRY_COMPARE(d->read({ 0x2041, 3 }).value().toUInt(), 1u);
    line.send(0x67F, "2F4D200201000000");
    QTRY_COMPARE(d->read({ 0x204D, 2 }).value().toUInt(), 1u);
    QVERIFY(!d->isOscillating());
}

// Mode 1: a rising edge of F positions to D1, of G to D2; with one input active the axis
// belongs to the inputs (status bit 3; CAN setpoints ignored).
void TstSimulatedNm17x::inputsTakten()
{
    Line line({ Variant::Nm172 });
    SimulatedNm17x *d = line.devices.at(0);
    line.send(0x000, "017F");
    line.send(0x67F, "2341200301000000"); // 2041h:03 = 1 Takten
    line.send(0x67F, "23452001C8000000"); // D1 = 2.00 mm
    line.send(0x67F, "2345200290010000"); // D2 = 4.00 mm
    QTRY_COMPARE(d->read({ 0x2041, 3 }).value().toUInt(), 1u);
    d->setInputs(true, false);
    QVERIFY(d->statusWord() & status::Takten);
    QTRY_VERIFY_WITH_TIMEOUT(d->statusWord() & status::InPosition, 10000);
    QVERIFY(qAbs(d->position() - 200) <= 5);
    line.send(0x67F, "23202002E8030000"); // 2020h:02 = 10.00 mm with release: ignored
    QTRY_COMPARE(d->read({ 0x2020, 2 }).value().toInt(), 1000);
    d->setInputs(false, false);
    QVERIFY(!(d->statusWord() & status::Takten));
    d->setInputs(false, true);
    QTRY_VERIFY_WITH_TIMEOUT(qAbs(d->position() - 400) <= 5 && !d->spindle().isMoving(), 10000);
    QVERIFY(d->statusWord() & status::InPosition);
}

// Mode 2, the manual's example (spec 6.10): D3 = 20.00 mm, F on: positioning starts; F off:
// stop, release revoked; D3 cannot be written while F is active; D3 written again: reached.
void TstSimulatedNm17x::inputsExternPosiAsInTheManual()
{
    Line line({ Variant::Nm174 });
    SimulatedNm17x *d = line.devices.at(0);
    line.send(0x000, "017F");
    line.send(0x67F, "2341200302000000"); // 2041h:03 = 2 ExternPosi
    QTRY_COMPARE(d->read({ 0x2041, 3 }).value().toUInt(), 2u);
    d->setInputs(true, false); // D3 is locked after power-on: nothing moves
    QVERIFY(d->statusWord() & status::ExternPosi);
    QVERIFY(!d->spindle().isMoving());
    d->setInputs(false, false);
    line.take();
    line.send(0x67F, "23452003D0070000"); // D3 = 20.00 mm
    QTRY_COMPARE(d->read({ 0x2045, 3 }).value().toInt(), 2000);
    d->setInputs(true, false);
    QTRY_VERIFY(d->position() > 100);
    line.take();
    line.send(0x67F, "2345200390010000"); // D3 = 4.00 mm while F is active: refused
    const QList<Frame> answer = line.takeId(0x5FF);
    QCOMPARE(answer.size(), 1);
    QCOMPARE(quint8(answer.at(0).data.at(0)), quint8(0x80));
    d->setInputs(false, false); // released before the target: stop
    QTRY_VERIFY(!d->spindle().isMoving());
    const qint32 stopped = d->position();
    QVERIFY(stopped < 2000);
    d->setInputs(true, false); // release revoked: F alone does not restart
    QVERIFY(!d->spindle().isMoving());
    d->setInputs(false, false);
    line.send(0x67F, "23452003D0070000"); // D3 = 20.00 mm again
    QTRY_VERIFY(d->read({ 0x2045, 3 }).value().toInt() == 2000);
    d->setInputs(true, false);
    QTRY_VERIFY_WITH_TIMEOUT(d->statusWord() & status::InPosition, 10000);
    QVERIFY(qAbs(d->position() - 2000) <= 5);
}

// Mode 0: both inputs oscillate (and CAN cannot stop it), one input travels until released.
void TstSimulatedNm17x::inputsStandardOscillateAndTravel()
{
    Line line({ Variant::Nm172 });
    SimulatedNm17x *d = line.devices.at(0);
    line.send(0x000, "017F");
    line.send(0x67F, "2345200164000000"); // D1 = 1.00 mm
    line.send(0x67F, "234520022C010000"); // D2 = 3.00 mm
    QTRY_COMPARE(d->read({ 0x2045, 2 }).value().toInt(), 300);
    d->setInputs(true, true);
    QVERIFY(d->isOscillating());
    line.send(0x67F, "2F4D200200000000"); // CAN stop: the switch has priority
    QTRY_COMPARE(d->read({ 0x204D, 2 }).value().toUInt(), 0u);
    QVERIFY(d->isOscillating());
    d->setInputs(false, false);
    QVERIFY(!d->isOscillating());
    QTRY_VERIFY_WITH_TIMEOUT(d->statusWord() & status::InPosition, 10000);
    const qint32 start = d->position();
    d->setInputs(true, false); // F alone: travel counting up
    QTRY_VERIFY(d->position() > start + 50);
    d->setInputs(false, false);
    QTRY_VERIFY(!d->spindle().isMoving());
}

// A key held longer than 400 ms runs the motor until it is let go (status bit 6 meanwhile), at
// the speed of 2041h:04: fast travels farther than slow in the same time.
void TstSimulatedNm17x::heldKeyRunsAtTheKeyModeSpeed()
{
    Line line({ Variant::Nm172, Variant::Nm172 });
    SimulatedNm17x *slow = line.devices.at(0);
    SimulatedNm17x *fast = line.devices.at(1);
    line.send(0x000, "017F");
    line.send(0x67F, "2341200403000000"); // both: 2041h:04 = 3 fast ...
    QTRY_COMPARE(fast->read({ 0x2041, 4 }).value().toUInt(), 3u);
    QVERIFY(slow->write({ 0x2041, 4 }, 1u).ok()); // ... then the first one slow
    QTRY_COMPARE(slow->read({ 0x2041, 4 }).value().toUInt(), 1u);
    const qint32 slowStart = slow->position();
    const qint32 fastStart = fast->position();
    slow->pressKey(1, 600);
    fast->pressKey(1, 600);
    QVERIFY(slow->statusWord() & status::RightKey);
    QTRY_VERIFY(slow->spindle().isMoving() && fast->spindle().isMoving());
    QTRY_VERIFY_WITH_TIMEOUT(!slow->spindle().isMoving() && !fast->spindle().isMoving(), 5000);
    QVERIFY(!(slow->statusWord() & status::RightKey));
    QVERIFY(slow->position() > slowStart);
    QVERIFY2(fast->position() - fastStart > 2 * (slow->position() - slowStart),
             qPrintable(QStringLiteral("slow %1, fast %2")
                            .arg(slow->position() - slowStart)
                            .arg(fast->position() - fastStart)));
}

void TstSimulatedNm17x::txPdo2OnChange()
{
    Line line({ Variant::Nm172 });
    SimulatedNm17x *d = line.devices.at(0);
    line.take();
    line.send(0x000, "017F");
    QTRY_VERIFY(!line.frames.isEmpty());
    QCOMPARE(line.takeId(0x2FF).size(), 1); // the first one on entering Operational
    QTest::qWait(100);
    QVERIFY(line.takeId(0x2FF).isEmpty()); // nothing changed: nothing sent
    d->turnShaft(250);
    QTRY_VERIFY(!line.frames.isEmpty());
    const QList<Frame> f = line.takeId(0x2FF);
    QCOMPARE(f.size(), 1);
    QCOMPARE(decodeTpdo2(f.at(0).data)->position, 250);
    QVERIFY(line.takeId(0x1FF).isEmpty()); // TxPDO1 is off at delivery
}

void TstSimulatedNm17x::cycleRestsWhileNothingChanges()
{
    Line line({ Variant::Nm172 });
    SimulatedNm17x *d = line.devices.at(0);
    line.take();
    line.send(0x67F, "2B011803E8030000"); // TxPDO2 inhibit time 1000 ms
    QCOMPARE(line.takeId(0x5FF).size(), 1);
    line.send(0x000, "017F");
    QTRY_VERIFY(!line.frames.isEmpty());
    QCOMPARE(line.takeId(0x2FF).size(), 1); // on entering Operational
    // Nothing changes: the 10 ms cycle stops, and another node's traffic does not start it.
    QTRY_VERIFY(!d->cycling());
    line.send(0x605, "4000100000000000");
    QVERIFY(!d->cycling());
    QTest::qWait(1100);
    // The rest counts for the inhibit time: a change after it goes out with the next cycle
    // (with the rest not counted it would wait almost the whole second).
    d->turnShaft(250);
    QVERIFY(d->cycling());
    QTRY_VERIFY_WITH_TIMEOUT(!line.frames.isEmpty(), 600);
    const QList<Frame> sent = line.takeId(0x2FF);
    QCOMPARE(sent.size(), 1);
    QCOMPARE(decodeTpdo2(sent.at(0).data)->position, 250);
    QTRY_VERIFY(!d->cycling());
}

void TstSimulatedNm17x::faultsShowTheirErrors()
{
    Line line({ Variant::Nm174 });
    SimulatedNm17x *d = line.devices.at(0);
    line.send(0x000, "017F");
    d->spindle().setMotorFault(true);
    line.send(0x37F, "0000000000009900"); // jog: refused, Er 4
    QTRY_VERIFY(d->errorWord() & (1u << 3));
    QVERIFY(!d->spindle().isMoving());
    QCOMPARE(activeErrors(d->errorWord()).at(0).code, QStringLiteral("Er 4"));
    d->spindle().setMotorFault(false);
    QTRY_VERIFY_WITH_TIMEOUT(!(d->errorWord() & (1u << 3)), 8000); // shown for about 5 s
    line.send(0x37F, "0000000000009900");
    QTRY_VERIFY(d->spindle().isMoving());
    d->spindle().setSensorFault(true); // Er C: the motor stops and stays off
    QTRY_VERIFY(!d->spindle().isMoving());
    QCOMPARE(activeErrors(d->errorWord()).at(0).code, QStringLiteral("Er C"));
    line.take();
    line.send(0x67F, "4001100000000000"); // error register: manufacturer bit with a display error
    QCOMPARE(quint8(line.takeId(0x5FF).at(0).data.at(4)) & 0x80, 0x80);
}

void TstSimulatedNm17x::heartbeatLossStopsAndReports()
{
    Line line({ Variant::Nm172 });
    SimulatedNm17x *d = line.devices.at(0);
    line.send(0x000, "017F");
    line.send(0x67F, "2316100164000100"); // watch node 1, 100 ms
    line.send(0x37F, "0000000000009900"); // jog right fast
    QTRY_VERIFY(d->spindle().isMoving());
    line.send(0x701, "05"); // the master's first heartbeat arms the watch
    line.take();
    QTRY_VERIFY(!line.frames.isEmpty() && !d->spindle().isMoving());
    const QList<Frame> emcy = line.takeId(0x0FF);
    QCOMPARE(emcy.size(), 1);
    QCOMPARE(emcy.at(0).data.left(2), QByteArray::fromHex("3081"));
    QCOMPARE(d->nmtState(), canopen::NmtState::PreOperational); // 1029h:01 = 0
}

void TstSimulatedNm17x::storeAndRestoreCommunicationObjects()
{
    Line line({ Variant::Nm172 });
    SimulatedNm17x *d = line.devices.at(0);
    line.send(0x67F, "2B171000F4010000"); // heartbeat 500 ms, not saved
    line.send(0x000, "817F");
    QCOMPARE(d->read({ 0x1017, 0 }).value().toUInt(), 0u); // lost at reset
    line.send(0x67F, "2B171000F4010000");
    line.send(0x67F, "2310100173617665"); // save
    line.send(0x000, "817F");
    QCOMPARE(d->read({ 0x1017, 0 }).value().toUInt(), 500u);
    line.send(0x67F, "2F01210005000000"); // node id 5 by SDO: active after Reset Node
    QCOMPARE(d->nodeId(), canopen::NodeId(127));
    line.send(0x000, "817F");
    QCOMPARE(d->nodeId(), canopen::NodeId(5));
    line.send(0x605, "231110016C6F6164"); // load: defaults (and node 127) after the next reset
    line.send(0x000, "8105");
    QCOMPARE(d->nodeId(), canopen::NodeId(127));
    QCOMPARE(d->read({ 0x1017, 0 }).value().toUInt(), 0u);
    QCOMPARE(d->read({ 0x1801, 1 }).value().toUInt(), 0x400002FFu);
}

void TstSimulatedNm17x::lowerNmtStateStopsPositioning()
{
    Line line({ Variant::Nm172 });
    SimulatedNm17x *d = line.devices.at(0);
    line.send(0x67F, "2320200210270000"); // SDO setpoint with release works in Pre-operational
    QTRY_VERIFY(d->spindle().isMoving());
    line.send(0x000, "017F"); // Pre-operational -> Operational does not stop it
    QVERIFY(d->spindle().isMoving());
    line.send(0x000, "807F"); // Operational -> Pre-operational does
    QTRY_VERIFY(!d->spindle().isMoving());
}

void TstSimulatedNm17x::simParsesDevices()
{
    const auto specs = Nm17xSim::parseDevices(QStringLiteral("nm172@127,NM172@127, nm174@5"));
    QVERIFY(specs);
    QCOMPARE(specs->size(), 3);
    QCOMPARE(specs->at(2).variant, Variant::Nm174);
    QCOMPARE(specs->at(2).node, canopen::NodeId(5));
    QVERIFY(!Nm17xSim::parseDevices(QStringLiteral("nm173@5")));
    QVERIFY(!Nm17xSim::parseDevices(QStringLiteral("nm172@128")));
    QVERIFY(Nm17xSim::parseDevices(QStringLiteral("nm172@x"))
                .error()
                .message()
                .contains(QLatin1String("nm172@x")));
}

void TstSimulatedNm17x::controlCommands()
{
    Nm17xSim sim;
    sim.create(Nm17xSim::parseDevices(QStringLiteral("nm172@127,nm170@9")).value());
    QVERIFY(sim.startSlcan(0));
    QCOMPARE(sim.execute(QStringLiteral("turn 2 150")), QStringLiteral("ok"));
    QCOMPARE(sim.devices().at(1)->position(), 150);
    QVERIFY(sim.execute(QStringLiteral("list"))
                .contains(QLatin1String("2 NM170 serial 0x4d52f568 node 9 position 150")));
    QVERIFY(sim.execute(QStringLiteral("turn 3 1")).startsWith(QLatin1String("error: ")));
    QVERIFY(sim.execute(QStringLiteral("key 1 up")).startsWith(QLatin1String("error: ")));
    QVERIFY(sim.execute(QStringLiteral("fly")).startsWith(QLatin1String("error: ")));
    QCOMPARE(sim.execute(QStringLiteral("fault 1 motor")), QStringLiteral("ok"));
    QVERIFY(sim.execute(QStringLiteral("fault 2 sensor")).startsWith(QLatin1String("error: ")));
}

QTEST_GUILESS_MAIN(TstSimulatedNm17x)
#include "tst_simulatednm17x.moc"
