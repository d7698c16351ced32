// Level 2: NMT master frames, heartbeat/boot-up consumer (state tracking, loss, resume), EMCY
// decoding of the MovingCap codes (movingcap.md 7.1, byte for byte) and the SYNC producer.

#include "canopen/emcyconsumer.h"
#include "canopen/nmtmaster.h"
#include "canopen/nodemonitor.h"
#include "canopen/syncproducer.h"
#include "scriptedcanbus.h"

#include <QtTest>

using namespace db;
using namespace db::canopen;
using db::test::ScriptedCanBus;

namespace {
constexpr int kConsumerMs = 60;
constexpr int kWaitMs = 5000;

QByteArray h(const char *hex)
{
    return QByteArray::fromHex(QByteArray(hex).replace(' ', ""));
}
} // namespace

class TstCanopenServices : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void init();
    void cleanup();

    void nmtFrames_data();
    void nmtFrames();
    void nmtRefusedOnClosedBusOrBadNode();
    void bootUpAndStateTracking();
    void heartbeatLostAfterConsumerTimeAndResumed();
    void noLossReportedWithoutConsumerTime();
    void unconfiguredNodeWatchedWithLearnedTime();
    void nodeGuardToggleBitIsIgnored();
    void emcyMovingCapCodes_data();
    void emcyMovingCapCodes();
    void emcyUsesDeviceTextFromDictionary();
    void emcyManufacturerBytesAndReset();
    void emcyTooShortIsReportedMalformed();
    void syncWithoutCounter();
    void syncCounterWrapsAtOverflow();

private:
    ScriptedCanBus *m_bus = nullptr;
};

void TstCanopenServices::init()
{
    m_bus = new ScriptedCanBus;
    m_bus->open();
}

void TstCanopenServices::cleanup()
{
    delete m_bus;
}

void TstCanopenServices::nmtFrames_data()
{
    QTest::addColumn<int>("command");
    QTest::addColumn<int>("node");
    QTest::addColumn<QByteArray>("payload");
    // movingcap.md 4.3: start node 50 = t00020132.
    QTest::newRow("start 50") << int(NmtCommand::Start) << 50 << h("01 32");
    QTest::newRow("stop 5") << int(NmtCommand::Stop) << 5 << h("02 05");
    QTest::newRow("preop all") << int(NmtCommand::EnterPreOperational) << 0 << h("80 00");
    QTest::newRow("reset node 127") << int(NmtCommand::ResetNode) << 127 << h("81 7F");
    QTest::newRow("reset comm all") << int(NmtCommand::ResetCommunication) << 0 << h("82 00");
}

void TstCanopenServices::nmtFrames()
{
    QFETCH(int, command);
    QFETCH(int, node);
    QFETCH(QByteArray, payload);
    NmtMaster nmt(m_bus);
    QSignalSpy sent(&nmt, &NmtMaster::commandSent);
    QVERIFY(nmt.send(NmtCommand(command), NodeId(node)));
    QCOMPARE(m_bus->sent().size(), 1);
    QCOMPARE(m_bus->sent().at(0).frameId(), 0u);
    QCOMPARE(m_bus->sent().at(0).payload(), payload);
    QCOMPARE(sent.size(), 1);
}

void TstCanopenServices::nmtRefusedOnClosedBusOrBadNode()
{
    NmtMaster nmt(m_bus);
    QVERIFY(!nmt.start(128));
    m_bus->close();
    QVERIFY(!nmt.resetNode(5));
    QVERIFY(m_bus->sent().isEmpty());
}

void TstCanopenServices::bootUpAndStateTracking()
{
    NodeMonitor monitor(m_bus);
    QSignalSpy seen(&monitor, &NodeMonitor::nodeSeen);
    QSignalSpy boot(&monitor, &NodeMonitor::bootUp);
    QSignalSpy changed(&monitor, &NodeMonitor::stateChanged);
    QCOMPARE(monitor.state(50), NmtState::Unknown);
    m_bus->feed(0x732, "00");
    QCOMPARE(boot.size(), 1);
    QCOMPARE(seen.size(), 1);
    QCOMPARE(monitor.state(50), NmtState::BootUp);
    m_bus->feed(0x732, "7F");
    m_bus->feed(0x732, "7F");
    QCOMPARE(monitor.state(50), NmtState::PreOperational);
    m_bus->feed(0x732, "05"); // movingcap.md 4.3: t732105
    QCOMPARE(monitor.state(50), NmtState::Operational);
    m_bus->feed(0x705, "04");
    QCOMPARE(monitor.state(5), NmtState::Stopped);
    QCOMPARE(changed.size(), 4); // boot-up, pre-op, operational, stopped(5)
    QCOMPARE(monitor.nodes(), (QList<NodeId> { 5, 50 }));
    QVERIFY(monitor.isAlive(50));
    m_bus->feed(0x632, "40 41 60 00 00 00 00 00"); // not a heartbeat
    QCOMPARE(monitor.nodes().size(), 2);
}

void TstCanopenServices::heartbeatLostAfterConsumerTimeAndResumed()
{
    NodeMonitor monitor(m_bus);
    monitor.setConsumerTime(50, kConsumerMs);
    QSignalSpy lost(&monitor, &NodeMonitor::heartbeatLost);
    QSignalSpy resumed(&monitor, &NodeMonitor::heartbeatResumed);
    QElapsedTimer clock;
    clock.start();
    m_bus->feed(0x732, "05");
    QVERIFY(lost.wait(kWaitMs));
    QVERIFY(clock.elapsed() >= kConsumerMs - 5);
    QCOMPARE(lost.at(0).at(0).value<NodeId>(), NodeId(50));
    QVERIFY(!monitor.isAlive(50));
    QCOMPARE(monitor.state(50), NmtState::Operational); // last known state is kept
    m_bus->feed(0x732, "05");
    QCOMPARE(resumed.size(), 1);
    QVERIFY(monitor.isAlive(50));
    QVERIFY(lost.wait(kWaitMs)); // and watched again
    QCOMPARE(lost.size(), 2);
}

void TstCanopenServices::noLossReportedWithoutConsumerTime()
{
    NodeMonitor monitor(m_bus);
    monitor.setConsumerTime(7, kConsumerMs);
    QSignalSpy lost(&monitor, &NodeMonitor::heartbeatLost);
    m_bus->feed(0x732, "05"); // node 50 has no consumer time
    QVERIFY(!lost.wait(3 * kConsumerMs));
    QVERIFY(monitor.isAlive(50));
}

// A node nobody configured (found by a scan, or only heard) beating every 200 ms is watched with
// three times that once two intervals were seen; its silence while lost is not learned. A node
// beating fast is watched with at least kLearnedMinMs.
void TstCanopenServices::unconfiguredNodeWatchedWithLearnedTime()
{
    NodeMonitor monitor(m_bus);
    QSignalSpy lost(&monitor, &NodeMonitor::heartbeatLost);
    QSignalSpy resumed(&monitor, &NodeMonitor::heartbeatResumed);
    QTimer beat;
    beat.setInterval(200);
    connect(&beat, &QTimer::timeout, this, [this] { m_bus->feed(0x70A, "05"); });
    m_bus->feed(0x70A, "05");
    beat.start();
    QTRY_VERIFY_WITH_TIMEOUT(monitor.consumerTime(10) > 0, kWaitMs);
    // (coarse timers may fire up to 5 % early)
    QVERIFY2(monitor.consumerTime(10) >= 3 * 190 && monitor.consumerTime(10) < 3 * 200 * 3,
             qPrintable(QString::number(monitor.consumerTime(10))));
    QVERIFY(!lost.wait(3 * 200)); // beating: not lost
    beat.stop();
    const int learned = monitor.consumerTime(10);
    QElapsedTimer clock;
    clock.start();
    QVERIFY(lost.wait(kWaitMs));
    QVERIFY(clock.elapsed() >= learned - 205);
    QCOMPARE(lost.at(0).at(0).value<NodeId>(), NodeId(10));
    m_bus->feed(0x70A, "05");
    QCOMPARE(resumed.size(), 1);
    QCOMPARE(monitor.consumerTime(10), learned); // the silence was not learned

    for (int i = 0; i < 3; ++i) // a burst: three frames at once
        m_bus->feed(0x70B, "05");
    QCOMPARE(monitor.consumerTime(11), NodeMonitor::kLearnedMinMs);
}

void TstCanopenServices::nodeGuardToggleBitIsIgnored()
{
    NodeMonitor monitor(m_bus);
    m_bus->feed(0x705, "85");
    QCOMPARE(monitor.state(5), NmtState::Operational);
}

void TstCanopenServices::emcyMovingCapCodes_data()
{
    QTest::addColumn<QByteArray>("payload");
    QTest::addColumn<int>("code");
    QTest::addColumn<int>("reg");
    QTest::addColumn<QString>("errorClass");
    QTest::addColumn<QStringList>("bits");
    const QStringList gv { "generic", "voltage" };
    const QStringList gt { "generic", "temperature" };
    const QStringList comm { "communication" };
    QTest::newRow("2220h over-current")
        << h("20 22 05 00 00 00 00 00") << 0x2220 << 0x05 << "current inside the device" << gv;
    QTest::newRow("3211h over-voltage")
        << h("11 32 05 00 00 00 00 00") << 0x3211 << 0x05 << "voltage inside the device" << gv;
    QTest::newRow("3221h under-voltage")
        << h("21 32 05 00 00 00 00 00") << 0x3221 << 0x05 << "voltage inside the device" << gv;
    QTest::newRow("4210h over-temp")
        << h("10 42 09 00 00 00 00 00") << 0x4210 << 0x09 << cia301ErrorClassText(0x4210) << gt;
    QTest::newRow("7121h stroke") << h("21 71 10 00 00 00 00 00") << 0x7121 << 0x10
                                  << cia301ErrorClassText(0x7121) << comm;
    QTest::newRow("FFF1h sensor") << h("F1 FF 10 00 00 00 00 00") << 0xFFF1 << 0x10
                                  << cia301ErrorClassText(0xFFF1) << comm;
}

void TstCanopenServices::emcyMovingCapCodes()
{
    QFETCH(QByteArray, payload);
    QFETCH(int, code);
    QFETCH(int, reg);
    QFETCH(QString, errorClass);
    QFETCH(QStringList, bits);
    EmcyConsumer consumer(m_bus);
    QSignalSpy spy(&consumer, &EmcyConsumer::emergency);
    m_bus->feed(QCanBusFrame(0x0B2, payload)); // node 50 (movingcap.md 4.3)
    QCOMPARE(spy.size(), 1);
    const auto e = spy.at(0).at(0).value<Emergency>();
    QCOMPARE(e.node, NodeId(50));
    QCOMPARE(int(e.code), code);
    QCOMPARE(int(e.errorRegister), reg);
    QCOMPARE(e.errorClass, errorClass);
    QCOMPARE(emcy::errorRegisterBits(e.errorRegister), bits);
    QCOMPARE(e.manufacturer, QByteArray(5, '\0'));
    QVERIFY(e.time.isValid());
    QVERIFY(!e.isReset());
}

void TstCanopenServices::emcyUsesDeviceTextFromDictionary()
{
    ObjectDictionary dict;
    dict.insertErrorCode({ 0x3221, QStringLiteral("ERROR_UNDER_VOLT"),
                           QStringLiteral("Under-voltage on UZK, the motor power supply") });
    EmcyConsumer consumer(m_bus);
    consumer.setDictionary(50, dict);
    QSignalSpy spy(&consumer, &EmcyConsumer::emergency);
    m_bus->feed(0x0B2, "21 32 05 00 00 00 00 00"); // t0B282132050000000000
    m_bus->feed(0x0B3, "21 32 05 00 00 00 00 00"); // another node: CiA 301 class only
    QCOMPARE(spy.size(), 2);
    const auto mine = spy.at(0).at(0).value<Emergency>();
    QCOMPARE(mine.text, QStringLiteral("Under-voltage on UZK, the motor power supply"));
    QVERIFY2(mine.toString().contains(QLatin1String("3221h")), qPrintable(mine.toString()));
    QVERIFY2(mine.toString().contains(QLatin1String("generic, voltage")),
             qPrintable(mine.toString()));
    QCOMPARE(spy.at(1).at(0).value<Emergency>().text, QStringLiteral("voltage inside the device"));
}

void TstCanopenServices::emcyManufacturerBytesAndReset()
{
    const auto e = emcy::decode(5, h("00 81 11 01 02 03 04 05"));
    QVERIFY(e.ok());
    QCOMPARE(int(e->code), 0x8100);
    QCOMPARE(e->manufacturer, h("01 02 03 04 05"));
    QVERIFY(e->toString().contains(QLatin1String("01 02 03 04 05")));
    const auto reset = emcy::decode(5, h("00 00 00"));
    QVERIFY(reset->isReset());
    QCOMPARE(reset->manufacturer, QByteArray(5, '\0'));
}

void TstCanopenServices::emcyTooShortIsReportedMalformed()
{
    EmcyConsumer consumer(m_bus);
    QSignalSpy bad(&consumer, &EmcyConsumer::malformed);
    QSignalSpy good(&consumer, &EmcyConsumer::emergency);
    m_bus->feed(0x085, "21 32");
    m_bus->feed(0x080, ""); // SYNC, not an EMCY
    QCOMPARE(bad.size(), 1);
    QCOMPARE(good.size(), 0);
    QCOMPARE(emcy::decode(5, h("21")).error().kind(), Error::Kind::Malformed);
}

void TstCanopenServices::syncWithoutCounter()
{
    SyncProducer sync(m_bus);
    QSignalSpy spy(&sync, &SyncProducer::syncSent);
    sync.start(5);
    QTRY_VERIFY_WITH_TIMEOUT(spy.size() >= 3, kWaitMs);
    sync.stop();
    QVERIFY(!sync.isRunning());
    for (const QCanBusFrame &f : m_bus->sent()) {
        QCOMPARE(f.frameId(), 0x080u);
        QVERIFY(f.payload().isEmpty());
    }
}

void TstCanopenServices::syncCounterWrapsAtOverflow()
{
    SyncProducer sync(m_bus);
    sync.start(1000, 3);
    QList<int> counters;
    for (int i = 0; i < 7; ++i) {
        QVERIFY(sync.sendOnce());
        counters.append(quint8(m_bus->sent().last().payload().at(0)));
    }
    QCOMPARE(counters, (QList<int> { 1, 2, 3, 1, 2, 3, 1 }));
    m_bus->close();
    QVERIFY(!sync.isRunning());
    QVERIFY(!sync.sendOnce());
}

QTEST_GUILESS_MAIN(TstCanopenServices)
#include "tst_canopenservices.moc"
