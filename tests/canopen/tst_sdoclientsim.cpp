// Level 3: SdoClient end to end against the simulated node, over SLCAN-over-TCP on loopback and
// over Qt's virtualcan (LOCK virtualcan): expedited, a 1 kB string segmented, a 100 kB domain by
// segmented and by block transfer, and an abort from the node.

#include "canopen/device/simulatednode.h"
#include "canopen/sdoabort.h"
#include "canopen/sdoclient.h"
#include "objectdefs.h"
#include "transport/device/slcanserver.h"
#include "transport/qtcanbus.h"
#include "transport/slcanbus.h"
#include "transport/tcpstream.h"

#include <QtTest>

using namespace db;
using namespace db::canopen;

namespace {
constexpr NodeId kNode = 50;
constexpr int kWaitMs = 20000;

ObjectDictionary dictionary()
{
    ObjectDictionary dict;
    ObjectDef value = test::objectDef(0x2000, 0, DataType::Unsigned32, Access::ReadWrite);
    value.defaultValue = QVariant::fromValue<qulonglong>(0x12345678);
    dict.insert(value);
    dict.insert(test::objectDef(0x2001, 0, DataType::VisibleString, Access::ReadWrite));
    dict.insert(test::objectDef(0x2F00, 0, DataType::Domain, Access::ReadWrite));
    return dict;
}

QByteArray pattern(int size)
{
    QByteArray data(size, '\0');
    for (int i = 0; i < size; ++i)
        data[i] = char((i * 13 + 5) & 0xFF);
    return data;
}
} // namespace

class TstSdoClientSim : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void transfers_data();
    void transfers();

private:
    void exercise(SdoClient &sdo);
};

void TstSdoClientSim::transfers_data()
{
    QTest::addColumn<QString>("transport");
    QTest::newRow("slcan over tcp") << QStringLiteral("slcan");
    QTest::newRow("virtualcan") << QStringLiteral("virtualcan");
}

void TstSdoClientSim::transfers()
{
    QFETCH(QString, transport);
    SimulatedNode node(dictionary(), kNode);
    SlcanServer server;
    std::unique_ptr<QtCanBus> deviceBus;
    std::unique_ptr<CanBus> bus;
    if (transport == u"slcan") {
        QVERIFY(server.listen(0).ok());
        connect(&server, &SlcanServer::frameReceived, &node, &SimulatedNode::receive);
        connect(&node, &SimulatedNode::transmit, &server, &SlcanServer::send);
        bus = std::make_unique<SlcanBus>(new TcpStream(QStringLiteral("127.0.0.1"), server.port()));
    } else {
        deviceBus =
            std::make_unique<QtCanBus>(QStringLiteral("virtualcan"), QStringLiteral("can0"));
        deviceBus->open();
        QTRY_VERIFY_WITH_TIMEOUT(deviceBus->isOpen(), kWaitMs);
        node.attach(deviceBus.get());
        bus = std::make_unique<QtCanBus>(QStringLiteral("virtualcan"), QStringLiteral("can0"));
    }
    node.start();
    bus->open();
    QTRY_VERIFY_WITH_TIMEOUT(bus->isOpen(), kWaitMs);
    SdoClient sdo(bus.get());
    exercise(sdo);
}

void TstSdoClientSim::exercise(SdoClient &sdo)
{
    const auto value = Reply::wait(sdo.upload(kNode, { 0x2000, 0 }), kWaitMs);
    QVERIFY2(value.ok(), qPrintable(value.error().toString()));
    QCOMPARE(value->toByteArray(), QByteArray::fromHex("78563412"));

    const QByteArray text = QByteArray(1024, 'a') + "end";
    QVERIFY(Reply::wait(sdo.download(kNode, { 0x2001, 0 }, text), kWaitMs).ok());
    QCOMPARE(Reply::wait(sdo.upload(kNode, { 0x2001, 0 }), kWaitMs).valueOr({}).toByteArray(),
             text);

    const QByteArray domain = pattern(100 * 1024);
    for (const auto mode : { SdoClient::Mode::Segmented, SdoClient::Mode::Block }) {
        const auto w = Reply::wait(sdo.download(kNode, { 0x2F00, 0 }, domain, mode), kWaitMs);
        QVERIFY2(w.ok(), qPrintable(w.error().toString()));
        const auto r = Reply::wait(sdo.upload(kNode, { 0x2F00, 0 }, mode), kWaitMs);
        QVERIFY2(r.ok(), qPrintable(r.error().toString()));
        QVERIFY(r->toByteArray() == domain);
    }

    const auto missing = Reply::wait(sdo.upload(kNode, { 0x3333, 0 }), kWaitMs);
    QCOMPARE(missing.error().kind(), Error::Kind::DeviceError);
    QCOMPARE(missing.error().deviceCode(), abort::NoSuchObject);
}

QTEST_GUILESS_MAIN(TstSdoClientSim)
#include "tst_sdoclientsim.moc"
