// Level 2: SimulatedNode (CiA 301 device side): boot-up, NMT, heartbeat, EMCY, TPDO/RPDO and
// the SDO failure modes, frame by frame.
#include "canopen/device/simulatednode.h"
#include "canopen/sdoabort.h"

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTest>

using namespace db;
using namespace db::canopen;

namespace {

constexpr NodeId kNode = 5;

void add(ObjectDictionary &dict, quint16 index, quint8 sub, DataType type, Access access,
         QVariant value = {})
{
    ObjectDef d;
    d.address = { index, sub };
    d.name = d.address.toString();
    d.type = type;
    d.access = access;
    d.defaultValue = value;
    dict.insert(d);
}

ObjectDictionary nodeDictionary()
{
    using T = DataType;
    const auto ro = Access::ReadOnly;
    const auto rw = Access::ReadWrite;
    ObjectDictionary d;
    add(d, 0x1000, 0, T::Unsigned32, ro, 0x191u);
    add(d, 0x1001, 0, T::Unsigned8, ro, 0u);
    add(d, 0x1003, 0, T::Unsigned8, rw, 0u);
    for (quint8 s = 1; s <= 4; ++s)
        add(d, 0x1003, s, T::Unsigned32, ro, 0u);
    add(d, 0x1005, 0, T::Unsigned32, rw, 0x80u);
    add(d, 0x1014, 0, T::Unsigned32, rw, 0x85u);
    add(d, 0x100C, 0, T::Unsigned16, rw, 0u);
    add(d, 0x100D, 0, T::Unsigned8, rw, 0u);
    add(d, 0x1016, 0, T::Unsigned8, ro, 1u);
    add(d, 0x1016, 1, T::Unsigned32, rw, 0u);
    add(d, 0x1017, 0, T::Unsigned16, rw, 0u);
    add(d, 0x1029, 1, T::Unsigned8, rw, 0u);
    add(d, 0x1400, 1, T::Unsigned32, rw, 0x205u);
    add(d, 0x1600, 0, T::Unsigned8, rw, 1u);
    add(d, 0x1600, 1, T::Unsigned32, rw, 0x60400010u);
    add(d, 0x1800, 1, T::Unsigned32, rw, 0x185u);
    add(d, 0x1800, 2, T::Unsigned8, rw, 1u);
    add(d, 0x1800, 5, T::Unsigned16, rw, 0u);
    add(d, 0x1A00, 0, T::Unsigned8, rw, 2u);
    add(d, 0x1A00, 1, T::Unsigned32, rw, 0x60410010u);
    add(d, 0x1A00, 2, T::Unsigned32, rw, 0x20010020u);
    add(d, 0x1F80, 0, T::Unsigned32, rw, 0u);
    add(d, 0x2001, 0, T::Integer32, rw, 0);
    add(d, 0x6040, 0, T::Unsigned16, rw, 0u);
    add(d, 0x6041, 0, T::Unsigned16, ro, 0x0237u);
    return d;
}

QByteArray hex(const char *text)
{
    return QByteArray::fromHex(QByteArray(text).replace(' ', ""));
}

QCanBusFrame frame(quint32 id, const char *data)
{
    return QCanBusFrame(id, hex(data));
}

} // namespace

class TestSimulatedNode : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void init();
    void cleanup();
    void bootUpOnStart();
    void bootUpOperationalWith1F80();
    void nothingBeforeStart();
    void nmtCommands();
    void nmtResets();
    void heartbeatFrom1017();
    void emergencyBytesAndHistory();
    void tpdoOnSync();
    void tpdoOnEventTimer();
    void rpdoWritesMappedObject();
    void failureNoReply();
    void failureAbortForObject();
    void failureSlowReply();
    void failureDropAfterN();
    void failureGarbage();
    void lifeGuardingAnswersWithToggle();
    void lifeGuardingEventAfterLifeTime();
    void heartbeatConsumerEvent();

private:
    QList<QCanBusFrame> feed(const QCanBusFrame &f);

    SimulatedNode *m_node = nullptr;
    QSignalSpy *m_tx = nullptr;
};

void TestSimulatedNode::init()
{
    m_node = new SimulatedNode(nodeDictionary(), kNode);
    m_tx = new QSignalSpy(m_node, &SimulatedNode::transmit);
}

void TestSimulatedNode::cleanup()
{
    delete m_tx;
    delete m_node;
}

QList<QCanBusFrame> TestSimulatedNode::feed(const QCanBusFrame &f)
{
    m_tx->clear();
    m_node->receive(f);
    QList<QCanBusFrame> out;
    for (const auto &args : std::as_const(*m_tx))
        out.append(args.at(0).value<QCanBusFrame>());
    return out;
}

void TestSimulatedNode::bootUpOnStart()
{
    QSignalSpy states(m_node, &SimulatedNode::nmtStateChanged);
    m_node->start();
    QCOMPARE(m_tx->size(), 1);
    const auto bootUp = m_tx->at(0).at(0).value<QCanBusFrame>();
    QCOMPARE(bootUp.frameId(), 0x705u);
    QCOMPARE(bootUp.payload(), hex("00"));
    QCOMPARE(m_node->nmtState(), NmtState::PreOperational);
    QCOMPARE(states.size(), 1);
}

void TestSimulatedNode::bootUpOperationalWith1F80()
{
    m_node->store()->set({ 0x1F80, 0 }, 8u);
    m_node->start();
    QCOMPARE(m_node->nmtState(), NmtState::Operational);
}

void TestSimulatedNode::nothingBeforeStart()
{
    QVERIFY(feed(frame(0x605, "40 00 10 00 00000000")).isEmpty());
}

void TestSimulatedNode::nmtCommands()
{
    m_node->start();
    feed(frame(0x000, "01 05"));
    QCOMPARE(m_node->nmtState(), NmtState::Operational);
    feed(frame(0x000, "02 06")); // another node
    QCOMPARE(m_node->nmtState(), NmtState::Operational);
    feed(frame(0x000, "02 00")); // all nodes
    QCOMPARE(m_node->nmtState(), NmtState::Stopped);
    QVERIFY(feed(frame(0x605, "40 00 10 00 00000000")).isEmpty()); // no SDO in Stopped
    feed(frame(0x000, "80 05"));
    QCOMPARE(m_node->nmtState(), NmtState::PreOperational);
    const auto answer = feed(frame(0x605, "40 00 10 00 00000000"));
    QCOMPARE(answer.size(), 1);
    QCOMPARE(answer.at(0).frameId(), 0x585u);
    QCOMPARE(answer.at(0).payload(), hex("43 00 10 00 91010000"));
}

void TestSimulatedNode::nmtResets()
{
    m_node->start();
    feed(frame(0x605, "23 01 20 00 2A000000")); // 2001h = 42
    feed(frame(0x605, "2B 17 10 00 E8030000")); // 1017h = 1000
    feed(frame(0x000, "01 05"));
    auto out = feed(frame(0x000, "82 05")); // reset communication: 1017h back, 2001h kept
    QCOMPARE(out.size(), 1);
    QCOMPARE(out.at(0).payload(), hex("00"));
    QCOMPARE(m_node->nmtState(), NmtState::PreOperational);
    QCOMPARE(m_node->store()->value({ 0x1017, 0 }).toUInt(), 0u);
    QCOMPARE(m_node->store()->value({ 0x2001, 0 }).toInt(), 42);
    out = feed(frame(0x000, "81 00")); // reset node: everything back
    QCOMPARE(out.size(), 1);
    QCOMPARE(m_node->store()->value({ 0x2001, 0 }).toInt(), 0);
}

void TestSimulatedNode::heartbeatFrom1017()
{
    m_node->start();
    QCOMPARE(feed(frame(0x605, "2B 17 10 00 14000000")).at(0).payload(),
             hex("60 17 10 00 00000000"));
    QVERIFY(m_tx->wait(1000));
    const auto beat = m_tx->last().at(0).value<QCanBusFrame>();
    QCOMPARE(beat.frameId(), 0x705u);
    QCOMPARE(beat.payload(), hex("7F"));
    feed(frame(0x000, "01 05"));
    QTRY_VERIFY(!m_tx->isEmpty()
                && m_tx->last().at(0).value<QCanBusFrame>().payload() == hex("05"));
    feed(frame(0x605, "2B 17 10 00 00000000"));
    m_tx->clear();
    QVERIFY(!m_tx->wait(100)); // off again
}

void TestSimulatedNode::emergencyBytesAndHistory()
{
    m_node->start();
    m_tx->clear();
    m_node->raiseEmergency(0x3221, 0x05);
    QCOMPARE(m_tx->size(), 1);
    auto emcy = m_tx->at(0).at(0).value<QCanBusFrame>();
    QCOMPARE(emcy.frameId(), 0x085u);
    QCOMPARE(emcy.payload(), hex("21 32 05 00 00 00 00 00"));
    m_node->raiseEmergency(0x8130, 0x11, hex("01 02 03 04 05"));
    emcy = m_tx->at(1).at(0).value<QCanBusFrame>();
    QCOMPARE(emcy.payload(), hex("30 81 11 01 02 03 04 05"));
    QCOMPARE(m_node->store()->value({ 0x1001, 0 }).toUInt(), 0x11u);
    QCOMPARE(m_node->store()->value({ 0x1003, 0 }).toUInt(), 2u);
    QCOMPARE(m_node->store()->value({ 0x1003, 1 }).toUInt(), 0x8130u);
    QCOMPARE(m_node->store()->value({ 0x1003, 2 }).toUInt(), 0x3221u);
    feed(frame(0x000, "02 05"));
    m_tx->clear();
    m_node->raiseEmergency(0x3221, 0x05);
    QCOMPARE(m_tx->size(), 0); // not in Stopped
}

void TestSimulatedNode::tpdoOnSync()
{
    m_node->start();
    m_node->store()->set({ 0x2001, 0 }, -2);
    QVERIFY(feed(frame(0x080, "")).isEmpty()); // Pre-operational: no PDO
    feed(frame(0x000, "01 05"));
    auto out = feed(frame(0x080, ""));
    QCOMPARE(out.size(), 1);
    QCOMPARE(out.at(0).frameId(), 0x185u);
    QCOMPARE(out.at(0).payload(), hex("37 02 FE FF FF FF"));
    feed(frame(0x605, "2F 00 18 02 02000000")); // every 2nd SYNC
    QVERIFY(feed(frame(0x080, "00")).isEmpty());
    QCOMPARE(feed(frame(0x080, "00")).size(), 1);
    feed(frame(0x605, "23 00 18 01 85010080")); // bit 31: invalid
    QVERIFY(feed(frame(0x080, "")).isEmpty());
    QVERIFY(feed(frame(0x080, "")).isEmpty());
}

void TestSimulatedNode::tpdoOnEventTimer()
{
    m_node->start();
    feed(frame(0x605, "2F 00 18 02 FE000000"));
    feed(frame(0x605, "2B 00 18 05 0A000000")); // 10 ms
    m_tx->clear();
    QVERIFY(!m_tx->wait(50)); // not before Operational
    feed(frame(0x000, "01 05"));
    QTRY_VERIFY(m_tx->size() >= 3);
    QCOMPARE(m_tx->last().at(0).value<QCanBusFrame>().frameId(), 0x185u);
}

void TestSimulatedNode::rpdoWritesMappedObject()
{
    m_node->start();
    QSignalSpy written(m_node, &SimulatedNode::objectWritten);
    feed(frame(0x205, "0F 00"));
    QCOMPARE(m_node->store()->value({ 0x6040, 0 }).toUInt(), 0u); // Pre-operational
    feed(frame(0x000, "01 05"));
    feed(frame(0x205, "0F 00"));
    QCOMPARE(m_node->store()->value({ 0x6040, 0 }).toUInt(), 0x0Fu);
    QCOMPARE(written.size(), 1);
    feed(frame(0x205, "1F")); // too short: ignored
    QCOMPARE(m_node->store()->value({ 0x6040, 0 }).toUInt(), 0x0Fu);
}

void TestSimulatedNode::failureNoReply()
{
    m_node->start();
    m_node->setSdoNoReply(true);
    QVERIFY(feed(frame(0x605, "40 00 10 00 00000000")).isEmpty());
    m_node->setSdoNoReply(false);
    QCOMPARE(feed(frame(0x605, "40 00 10 00 00000000")).size(), 1);
}

void TestSimulatedNode::failureAbortForObject()
{
    m_node->start();
    m_node->setSdoAbort({ 0x6041, 0 }, abort::CannotStoreState);
    QCOMPARE(feed(frame(0x605, "40 41 60 00 00000000")).at(0).payload(),
             hex("80 41 60 00 22 00 00 08"));
    QCOMPARE(feed(frame(0x605, "40 00 10 00 00000000")).at(0).payload().at(0), char(0x43));
    m_node->clearSdoAborts();
    QCOMPARE(feed(frame(0x605, "40 41 60 00 00000000")).at(0).payload(),
             hex("4B 41 60 00 37 02 00 00"));
}

void TestSimulatedNode::failureSlowReply()
{
    m_node->start();
    m_node->setSdoReplyDelayMs(60);
    QElapsedTimer timer;
    timer.start();
    QVERIFY(feed(frame(0x605, "40 00 10 00 00000000")).isEmpty());
    QVERIFY(m_tx->wait(2000));
    QVERIFY(timer.elapsed() >= 50);
    QCOMPARE(m_tx->at(0).at(0).value<QCanBusFrame>().payload(), hex("43 00 10 00 91010000"));
}

void TestSimulatedNode::failureDropAfterN()
{
    m_node->start();
    m_node->setSdoDropAfter(2);
    QCOMPARE(feed(frame(0x605, "40 00 10 00 00000000")).size(), 1);
    QCOMPARE(feed(frame(0x605, "40 00 10 00 00000000")).size(), 1);
    QVERIFY(feed(frame(0x605, "40 00 10 00 00000000")).isEmpty());
    QVERIFY(feed(frame(0x605, "40 00 10 00 00000000")).isEmpty());
    QCOMPARE(m_node->sdoRequestCount(), 4);
    m_node->setSdoDropAfter(-1);
    QCOMPARE(feed(frame(0x605, "40 00 10 00 00000000")).size(), 1);
}

void TestSimulatedNode::failureGarbage()
{
    m_node->start();
    m_node->setSdoGarbage(true);
    const auto out = feed(frame(0x605, "40 00 10 00 00000000"));
    QCOMPARE(out.size(), 1);
    QCOMPARE(out.at(0).frameId(), 0x585u);
    QCOMPARE(out.at(0).payload(), hex("E7 DE AD BE EF 5A 5A 5A"));
}

static QCanBusFrame guardRequest(quint32 id)
{
    QCanBusFrame rtr(id, QByteArray());
    rtr.setFrameType(QCanBusFrame::RemoteRequestFrame);
    return rtr;
}

void TestSimulatedNode::lifeGuardingAnswersWithToggle()
{
    m_node->start();
    auto out = feed(guardRequest(0x705));
    QCOMPARE(out.size(), 1);
    QCOMPARE(out.at(0).frameId(), 0x705u);
    QCOMPARE(out.at(0).payload(), hex("7F")); // pre-operational, toggle 0
    out = feed(guardRequest(0x705));
    QCOMPARE(out.at(0).payload(), hex("FF")); // toggle 1
    QVERIFY(feed(guardRequest(0x706)).isEmpty()); // another node's
}

void TestSimulatedNode::lifeGuardingEventAfterLifeTime()
{
    m_node->start();
    feed(frame(0x000, "01 05"));
    feed(frame(0x605, "2B 0C 10 00 32000000")); // 100Ch guard time 50 ms
    feed(frame(0x605, "2F 0D 10 00 03000000")); // 100Dh factor 3: life time 150 ms
    QSignalSpy lost(m_node, &SimulatedNode::communicationLost);
    m_tx->clear();
    QVERIFY(!lost.wait(300)); // not guarded yet: no event (CiA 301: starts with the first RTR)
    feed(guardRequest(0x705));
    QVERIFY(lost.wait(1000));
    QVERIFY2(lost.at(0).at(0).toString().contains(QLatin1String("life guarding")),
             qPrintable(lost.at(0).at(0).toString()));
    QCOMPARE(m_node->nmtState(), NmtState::PreOperational); // 1029h:01 = 0
    const auto emcy = m_tx->last().at(0).value<QCanBusFrame>();
    QCOMPARE(emcy.frameId(), 0x85u);
    QCOMPARE(emcy.payload().left(3), hex("30 81 11")); // 8130h life guard / heartbeat error
}

void TestSimulatedNode::heartbeatConsumerEvent()
{
    m_node->start();
    feed(frame(0x000, "01 05"));
    feed(frame(0x605, "2F 29 10 01 02000000")); // 1029h:01 = 2: to Stopped
    feed(frame(0x605, "23 16 10 01 C8007F00")); // 1016h:01 = node 127, 200 ms
    QSignalSpy lost(m_node, &SimulatedNode::communicationLost);
    feed(frame(0x77F, "05")); // the first heartbeat starts the watch
    QVERIFY(lost.wait(1000));
    QVERIFY2(lost.at(0).at(0).toString().contains(QLatin1String("heartbeat of node 127")),
             qPrintable(lost.at(0).at(0).toString()));
    QCOMPARE(m_node->nmtState(), NmtState::Stopped);
}

QTEST_GUILESS_MAIN(TestSimulatedNode)
#include "tst_simulatednode.moc"
