// Node discovery: the pipelined SDO probe of 1000h on ids 1..127 (all requests out before the
// first answer), identity and name of each node, passive nodes (heartbeat only), silent and
// garbage-answering nodes, against SimulatedNodes on a loopback bus.
#include "canopen/nodemonitor.h"
#include "canopen/nodescanner.h"
#include "canopen/sdoclient.h"
#include "simloopback.h"

#include <QSignalSpy>
#include <QTest>

using namespace db;
using namespace db::canopen;

class TestNodeScanner : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void findsNodesWithIdentityAndName();
    void probesArePipelined();
    void windowLimitsRequestsInFlight();
    void silentNodeIsNotListedButHeardNodeIs();
    void garbageAnsweringNodeCountsAsPresent();
    void emptyBusFinishesWithNothing();
    void lineFormat();

private:
    static void runScan(NodeScanner &scanner)
    {
        QSignalSpy done(&scanner, &NodeScanner::finished);
        QVERIFY(scanner.start());
        QVERIFY(!scanner.start()); // one scan at a time
        QVERIFY(done.wait(10000));
        QCOMPARE(done.size(), 1);
    }
};

void TestNodeScanner::findsNodesWithIdentityAndName()
{
    test::SimLoopback sim;
    for (NodeId id : { 1, 2, 5 })
        sim.addNode(id);
    SdoClient sdo(&sim.bus);
    sdo.setTimeoutMs(100);
    NodeMonitor monitor(&sim.bus);
    NodeScanner scanner(&sdo, &monitor);
    runScan(scanner);
    const auto nodes = scanner.nodes();
    QCOMPARE(nodes.size(), 3);
    QCOMPARE(nodes.at(0).id, NodeId(1));
    QCOMPARE(nodes.at(2).id, NodeId(5));
    for (const NodeInfo &n : nodes) {
        QVERIFY(n.answersSdo);
        QVERIFY(n.hasIdentity);
        QCOMPARE(n.vendorId, 0x0DB0u);
        QCOMPARE(n.productCode, 1u);
        QCOMPARE(n.serial, 0x1000u + n.id);
        QCOMPARE(n.deviceType, 0x191u);
        QCOMPARE(n.name, QStringLiteral("drivebench test node"));
        QCOMPARE(n.state, NmtState::PreOperational); // from the boot-up seen by the monitor
        QVERIFY(n.problems.isEmpty());
    }
}

void TestNodeScanner::probesArePipelined()
{
    test::SimLoopback sim;
    sim.addNode(7);
    SdoClient sdo(&sim.bus);
    sdo.setTimeoutMs(100);
    NodeScanner scanner(&sdo, nullptr);
    (void)sim.bus.takeSent();
    QSignalSpy done(&scanner, &NodeScanner::finished);
    scanner.start();
    // Every probe is on the bus before any answer was delivered (answers come from the loop).
    const auto sent = sim.bus.takeSent();
    QCOMPARE(sent.size(), 127);
    for (int i = 0; i < 127; ++i) {
        QCOMPARE(sent.at(i).frameId(), 0x600u + i + 1);
        QCOMPARE(sent.at(i).payload().left(4), QByteArray::fromHex("40001000"));
    }
    QVERIFY(done.wait(5000));
    QCOMPARE(scanner.nodes().size(), 1);
}

void TestNodeScanner::windowLimitsRequestsInFlight()
{
    test::SimLoopback sim;
    sim.addNode(3);
    SdoClient sdo(&sim.bus);
    sdo.setTimeoutMs(30);
    NodeScanner scanner(&sdo, nullptr);
    scanner.setRange(1, 20);
    scanner.setWindow(8);
    (void)sim.bus.takeSent();
    QSignalSpy done(&scanner, &NodeScanner::finished);
    scanner.start();
    QCOMPARE(sim.bus.takeSent().size(), 8);
    QVERIFY(done.wait(5000));
    QCOMPARE(scanner.nodes().size(), 1);
    QCOMPARE(scanner.nodes().first().id, NodeId(3));
}

void TestNodeScanner::silentNodeIsNotListedButHeardNodeIs()
{
    test::SimLoopback sim;
    sim.addNode(1);
    sim.addNode(4)->setSdoNoReply(true); // boot-up heard, SDO silent
    SdoClient sdo(&sim.bus);
    sdo.setTimeoutMs(50);
    NodeMonitor monitor(&sim.bus);
    QTRY_COMPARE(monitor.nodes().size(), 2);
    NodeScanner scanner(&sdo, &monitor);
    runScan(scanner);
    const auto nodes = scanner.nodes();
    QCOMPARE(nodes.size(), 2);
    QCOMPARE(nodes.at(1).id, NodeId(4));
    QVERIFY(!nodes.at(1).answersSdo);
    QVERIFY(!nodes.at(1).hasIdentity);
    QVERIFY(nodes.at(1).toString().contains(QLatin1String("no SDO answer")));
}

void TestNodeScanner::garbageAnsweringNodeCountsAsPresent()
{
    test::SimLoopback sim;
    sim.addNode(2)->setSdoGarbage(true);
    SdoClient sdo(&sim.bus);
    sdo.setTimeoutMs(50);
    NodeScanner scanner(&sdo, nullptr);
    runScan(scanner);
    // A malformed answer is not an answer: the node is not listed, the scan still ends.
    QVERIFY(scanner.nodes().isEmpty());
}

void TestNodeScanner::emptyBusFinishesWithNothing()
{
    test::SimLoopback sim;
    SdoClient sdo(&sim.bus);
    sdo.setTimeoutMs(30);
    NodeScanner scanner(&sdo, nullptr);
    runScan(scanner);
    QVERIFY(scanner.nodes().isEmpty());
    runScan(scanner); // reusable
}

void TestNodeScanner::lineFormat()
{
    NodeInfo n;
    n.id = 5;
    n.state = NmtState::Operational;
    n.answersSdo = n.hasIdentity = true;
    n.vendorId = 0xEC;
    n.productCode = 0x71;
    n.revision = 0x10001;
    n.serial = 0x4D52F567;
    n.name = QStringLiteral("NM172");
    QCOMPARE(n.toString(),
             QStringLiteral("  5  operational      vendor 0x000000EC product "
                            "0x00000071 rev 0x00010001 serial 0x4D52F567  \"NM172\""));
}

QTEST_GUILESS_MAIN(TestNodeScanner)
#include "tst_nodescanner.moc"
