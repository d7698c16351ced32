// Level 3: several node connections on one CAN network. Nodes 1, 2 and 5 of one simulated bus
// behind an SlcanServer on loopback TCP share one socket, one NMT master and one node monitor;
// broadcast frames go out once; the bus closes with the last connection.
#include "canopen/cannetwork.h"
#include "canopen/cannetworkpool.h"
#include "canopen/canopenconnection.h"
#include "canopen/device/simulatednode.h"
#include "canopen/nmtmaster.h"
#include "resources/builtindescriptions.h"
#include "transport/canbus.h"
#include "transport/device/slcanserver.h"

#include <QSignalSpy>
#include <QTest>

#include <memory>
#include <vector>

using namespace db;
using namespace db::canopen;

class TestCanNetwork : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void init();
    void cleanup();
    void poolKeysIgnoreNodeAndOptions();
    void poolRefusesAnotherBitrate();
    void threeNodesShareOneSocket();
    void broadcastsGoOutOnce();
    void busClosesWithTheLastConnection();
    void subscriptionsDispatchByCobId();

private:
    std::unique_ptr<CanopenConnection> connectNode(NodeId node);
    QString uri(NodeId node) const;

    std::unique_ptr<SlcanServer> m_server;
    std::vector<std::unique_ptr<SimulatedNode>> m_nodes;
    CanNetworkPool m_pool;
};

void TestCanNetwork::init()
{
    m_server = std::make_unique<SlcanServer>();
    QVERIFY(m_server->listen(0));
    const auto dict = resources::builtinDescription(QStringLiteral("drivebench_testnode"));
    QVERIFY(dict);
    for (const NodeId id : { NodeId(1), NodeId(2), NodeId(5) }) {
        auto node = std::make_unique<SimulatedNode>(dict.value(), id);
        node->store()->set({ 0x1018, 4 }, quint32(0x1000 + id));
        connect(m_server.get(), &SlcanServer::frameReceived, node.get(), &SimulatedNode::receive);
        connect(node.get(), &SimulatedNode::transmit, m_server.get(), &SlcanServer::send);
        node->start();
        m_nodes.push_back(std::move(node));
    }
}

void TestCanNetwork::cleanup()
{
    m_nodes.clear();
    m_server.reset();
}

QString TestCanNetwork::uri(NodeId node) const
{
    return QStringLiteral("canopen+slcan://127.0.0.1:%1?node=%2").arg(m_server->port()).arg(node);
}

std::unique_ptr<CanopenConnection> TestCanNetwork::connectNode(NodeId node)
{
    const auto parsed = ConnectionUri::parse(uri(node));
    if (!parsed)
        return nullptr;
    auto network = m_pool.networkFor(*parsed);
    if (!network)
        return nullptr;
    auto connection = std::make_unique<CanopenConnection>(*parsed, network.value());
    if (!connection->openAndWait(3000))
        return nullptr;
    return connection;
}

void TestCanNetwork::poolKeysIgnoreNodeAndOptions()
{
    const auto a = ConnectionUri::parse(QStringLiteral("canopen+slcan://10.0.0.1?node=1"));
    const auto b =
        ConnectionUri::parse(QStringLiteral("canopen+slcan://10.0.0.1:15001?node=5&block=1"));
    const auto c = ConnectionUri::parse(QStringLiteral("canopen+slcan://10.0.0.1:15002?node=5"));
    const auto d = ConnectionUri::parse(QStringLiteral("canopen+virtualcan://can0?node=5"));
    QVERIFY(a && b && c && d);
    QCOMPARE(CanNetworkPool::busKey(*a), CanNetworkPool::busKey(*b));
    QVERIFY(CanNetworkPool::busKey(*a) != CanNetworkPool::busKey(*c));
    QCOMPARE(CanNetworkPool::busKey(*d), QStringLiteral("virtualcan://can0"));
    // Networks are made without opening anything.
    auto na = m_pool.networkFor(*a);
    auto nb = m_pool.networkFor(*b);
    auto nc = m_pool.networkFor(*c);
    QVERIFY(na && nb && nc);
    QCOMPARE(na->get(), nb->get());
    QVERIFY(na->get() != nc->get());
    QCOMPARE(m_pool.size(), 2);
    na = Error();
    nb = Error();
    QCOMPARE(m_pool.size(), 1); // held weakly
}

void TestCanNetwork::poolRefusesAnotherBitrate()
{
    const auto a = ConnectionUri::parse(QStringLiteral("canopen+virtualcan://can7?bitrate=125000"));
    const auto b = ConnectionUri::parse(QStringLiteral("canopen+virtualcan://can7?bitrate=250000"));
    const auto bad = ConnectionUri::parse(QStringLiteral("canopen+virtualcan://can7?bitrate=x"));
    QVERIFY(a && b && bad);
    auto na = m_pool.networkFor(*a);
    QVERIFY(na);
    const auto nb = m_pool.networkFor(*b);
    QVERIFY(!nb);
    QVERIFY2(nb.error().message().contains(QStringLiteral("125000")),
             qPrintable(nb.error().message()));
    const auto nbad = m_pool.networkFor(*bad);
    QVERIFY(!nbad);
    QVERIFY2(nbad.error().message().contains(QStringLiteral("bitrate")),
             qPrintable(nbad.error().message()));
}

void TestCanNetwork::threeNodesShareOneSocket()
{
    QSignalSpy clients(m_server.get(), &SlcanServer::clientConnected);
    auto c1 = connectNode(1);
    auto c2 = connectNode(2);
    auto c5 = connectNode(5);
    QVERIFY(c1 && c2 && c5);
    QCOMPARE(c1->network(), c2->network());
    QCOMPARE(c1->network(), c5->network());
    for (CanopenConnection *c : { c1.get(), c2.get(), c5.get() }) {
        const auto serial = Reply::wait(c->read({ 0x1018, 4 }));
        QVERIFY2(serial, qPrintable(serial.error().message()));
        QCOMPARE(serial->toUInt(), 0x1000u + c->node());
    }
    QCOMPARE(clients.size(), 1);
    QCOMPARE(m_server->clientCount(), 1);
    QCOMPARE(m_pool.size(), 1);
}

void TestCanNetwork::broadcastsGoOutOnce()
{
    auto c1 = connectNode(1);
    auto c2 = connectNode(2);
    auto c5 = connectNode(5);
    QVERIFY(c1 && c2 && c5);
    QList<QCanBusFrame> received;
    connect(m_server.get(), &SlcanServer::frameReceived, this, [&](const QCanBusFrame &f) {
        if (f.frameId() == 0 || f.frameId() == 0x201)
            received.append(f);
    });
    CanNetwork *net = c1->network();
    QVERIFY(net->nmt()->send(NmtCommand::Start, NmtMaster::kAllNodes));
    QVERIFY(net->send(QCanBusFrame(0x201, QByteArray::fromHex("0102"))));
    QTRY_COMPARE(received.size(), 2);
    // A round trip on each node later nothing more has arrived: each frame went out once, not
    // once per connection.
    for (CanopenConnection *c : { c1.get(), c2.get(), c5.get() })
        QVERIFY(Reply::wait(c->read({ 0x1018, 4 })));
    QCOMPARE(received.size(), 2);
    QCOMPARE(received.at(0).frameId(), 0u);
    QCOMPARE(received.at(0).payload(), QByteArray::fromHex("0100"));
    QCOMPARE(received.at(1).frameId(), 0x201u);
    // Every node heard the one NMT broadcast: their heartbeats say operational.
    for (const auto &node : m_nodes)
        QTRY_COMPARE(node->nmtState(), NmtState::Operational);
}

void TestCanNetwork::busClosesWithTheLastConnection()
{
    auto c1 = connectNode(1);
    auto c2 = connectNode(2);
    QVERIFY(c1 && c2);
    CanBus *bus = c1->bus();
    QCOMPARE(c1->network()->users(), 2);
    c1->close();
    QTRY_COMPARE(c1->state(), DeviceConnection::State::Disconnected);
    QVERIFY(!c1->lastError().isError());
    QVERIFY(bus->isOpen());
    // The other node goes on.
    QVERIFY(Reply::wait(c2->read({ 0x1018, 4 })));
    // Reopened on the network that is still open.
    QVERIFY(c1->openAndWait(1000));
    QCOMPARE(c1->network()->users(), 2);
    c1.reset();
    QVERIFY(bus->isOpen());
    c2->close();
    QTRY_COMPARE(c2->state(), DeviceConnection::State::Disconnected);
    QCOMPARE(bus->state(), CanBus::State::Closed);
    QTRY_COMPARE(m_server->clientCount(), 0);
}

void TestCanNetwork::subscriptionsDispatchByCobId()
{
    auto c5 = connectNode(5);
    QVERIFY(c5);
    CanNetwork *net = c5->network();
    int heartbeats = 0;
    int others = 0;
    {
        QObject context;
        net->subscribe(0x705, &context, [&](const QCanBusFrame &) { ++heartbeats; });
        net->subscribe(0x181, &context, [&](const QCanBusFrame &) { ++others; });
        m_server->send(QCanBusFrame(0x705, QByteArray::fromHex("05")));
        m_server->send(QCanBusFrame(0x185, QByteArray::fromHex("00")));
        QTRY_COMPARE(heartbeats, 1);
        QCOMPARE(others, 0);
    }
    // The context is gone: its handlers are dropped.
    m_server->send(QCanBusFrame(0x705, QByteArray::fromHex("05")));
    QVERIFY(Reply::wait(c5->read({ 0x1018, 4 }))); // a round trip later
    QCOMPARE(heartbeats, 1);
}

QTEST_MAIN(TestCanNetwork)
#include "tst_cannetwork.moc"
