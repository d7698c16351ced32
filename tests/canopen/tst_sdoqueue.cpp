// Level 2: the SDO client's queue: one transfer in flight per node, FIFO order, nodes in
// parallel, deleted replies skipped, everything failed when the bus goes away.

#include "canopen/sdoclient.h"
#include "scriptedcanbus.h"

#include <QtTest>

using namespace db;
using namespace db::canopen;
using db::test::ScriptedCanBus;

namespace {
constexpr int kWaitMs = 5000;
constexpr NodeId kNode = 50;

QByteArray h(const char *hex)
{
    return QByteArray::fromHex(QByteArray(hex).replace(' ', ""));
}
} // namespace

class TstSdoQueue : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void init();
    void cleanup();

    void concurrentRequestsToOneNodeAreQueued();
    void differentNodesRunInParallel();
    void busClosedFailsPendingAndQueued();
    void requestOnClosedBusFailsAtOnce();
    void replyDeletedWhileQueuedIsSkipped();

private:
    Result<QVariant> run(Reply *reply) { return Reply::wait(reply, kWaitMs); }

    ScriptedCanBus *m_bus = nullptr;
    SdoClient *m_sdo = nullptr;
};

void TstSdoQueue::init()
{
    m_bus = new ScriptedCanBus;
    m_bus->open();
    m_sdo = new SdoClient(m_bus);
}

void TstSdoQueue::cleanup()
{
    delete m_sdo;
    delete m_bus;
}

void TstSdoQueue::concurrentRequestsToOneNodeAreQueued()
{
    Reply *a = m_sdo->upload(kNode, { 0x6041, 0 });
    Reply *b = m_sdo->upload(kNode, { 0x6064, 0 });
    Reply *c = m_sdo->download(kNode, { 0x6040, 0 }, h("0F 00"));
    QCOMPARE(m_bus->takeSent().size(), 1);
    QCOMPARE(m_sdo->pending(kNode), 3);
    m_bus->feed(0x5B2, "4B 41 60 00 27 04 00 00");
    auto sent = m_bus->takeSent();
    QCOMPARE(sent.size(), 1);
    QCOMPARE(sent.at(0).payload(), h("40 64 60 00 00 00 00 00"));
    m_bus->feed(0x5B2, "43 64 60 00 10 00 00 00");
    sent = m_bus->takeSent();
    QCOMPARE(sent.size(), 1);
    QCOMPARE(sent.at(0).payload(), h("2B 40 60 00 0F 00 00 00"));
    m_bus->feed(0x5B2, "60 40 60 00 00 00 00 00");
    QCOMPARE(run(a)->toByteArray(), h("27 04"));
    QCOMPARE(run(b)->toByteArray(), h("10 00 00 00"));
    QVERIFY(run(c).ok());
    QCOMPARE(m_sdo->pending(kNode), 0);
}

void TstSdoQueue::differentNodesRunInParallel()
{
    Reply *a = m_sdo->upload(5, { 0x1000, 0 });
    Reply *b = m_sdo->upload(6, { 0x1000, 0 });
    const auto sent = m_bus->takeSent();
    QCOMPARE(sent.size(), 2);
    QCOMPARE(sent.at(0).frameId(), 0x605u);
    QCOMPARE(sent.at(1).frameId(), 0x606u);
    m_bus->feed(0x586, "43 00 10 00 92 01 02 00");
    m_bus->feed(0x585, "43 00 10 00 91 01 02 00");
    QCOMPARE(run(a)->toByteArray(), h("91 01 02 00"));
    QCOMPARE(run(b)->toByteArray(), h("92 01 02 00"));
}

void TstSdoQueue::busClosedFailsPendingAndQueued()
{
    Reply *a = m_sdo->upload(kNode, { 0x6041, 0 });
    Reply *b = m_sdo->upload(kNode, { 0x6064, 0 });
    m_bus->drop(Error(Error::Kind::Disconnected, QStringLiteral("link lost")));
    QCOMPARE(run(a).error().kind(), Error::Kind::Disconnected);
    QCOMPARE(run(b).error().message(), QStringLiteral("link lost"));
}

void TstSdoQueue::requestOnClosedBusFailsAtOnce()
{
    m_bus->close();
    const auto r = run(m_sdo->upload(kNode, { 0x6041, 0 }));
    QCOMPARE(r.error().kind(), Error::Kind::Disconnected);
}

void TstSdoQueue::replyDeletedWhileQueuedIsSkipped()
{
    Reply *a = m_sdo->upload(kNode, { 0x6041, 0 });
    delete m_sdo->upload(kNode, { 0x6064, 0 });
    Reply *c = m_sdo->upload(kNode, { 0x6061, 0 });
    m_bus->takeSent();
    m_bus->feed(0x5B2, "4B 41 60 00 27 04 00 00");
    const auto sent = m_bus->takeSent();
    QCOMPARE(sent.size(), 1);
    QCOMPARE(sent.at(0).payload(), h("40 61 60 00 00 00 00 00"));
    m_bus->feed(0x5B2, "4F 61 60 00 01 00 00 00");
    QVERIFY(run(a).ok());
    QCOMPARE(run(c)->toByteArray(), h("01"));
}

QTEST_GUILESS_MAIN(TstSdoQueue)
#include "tst_sdoqueue.moc"
