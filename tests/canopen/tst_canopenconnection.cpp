// Level 2: CanopenConnection over a scripted CAN bus: reads/writes with the dictionary's types,
// unknown objects, strings, store, the optional 1000h probe and a lost bus.

#include "canopen/canbusfactory.h"
#include "canopen/canopenconnection.h"
#include "canopen/heartbeatproducer.h"
#include "canopen/sdoclient.h"
#include "objectdefs.h"
#include "parameters/parameterrunner.h"
#include "scriptedcanbus.h"
#include "transport/qtcanbus.h"

#include <QtTest>

using namespace db;
using namespace db::canopen;
using db::test::ScriptedCanBus;

namespace {
constexpr int kWaitMs = 5000;

ScriptedCanBus::Line tx(const char *hex)
{
    return ScriptedCanBus::tx(0x632, hex);
}
ScriptedCanBus::Line rx(const char *hex)
{
    return ScriptedCanBus::rx(0x5B2, hex);
}
ConnectionUri uri(const QString &text)
{
    return ConnectionUri::parse(text).value();
}
} // namespace

class TstCanopenConnection : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void init();
    void cleanup();

    void missingNodeFailsOpenWithClearError();
    void connectedWhenBusOpens();
    void toolNodeIsTheHeartbeatNode_data();
    void toolNodeIsTheHeartbeatNode();
    void readTypedStatusword();
    void readUnknownObjectGivesIntegerByLength();
    void readVisibleStringSegmented();
    void writeTypedControlword();
    void writeUnknownIntegerAsFourBytes();
    void storeParametersWritesSave();
    void abortReachesTheReply();
    void probeWithoutAnswerSaysNodeDoesNotAnswer();
    void probeAnsweredByAbortStillConnects();
    void lostBusFailsPendingAndDisconnects();
    void unknownValueConversions();
    void factoryMakesBusesAndRefusesOtherSchemes();

private:
    void open(const QString &text);
    void checkScript()
    {
        QVERIFY2(m_bus->scriptErrors().isEmpty(),
                 qPrintable(m_bus->scriptErrors().join(QLatin1Char('\n'))));
        QVERIFY(m_bus->scriptDone());
    }

    ScriptedCanBus *m_bus = nullptr;
    CanopenConnection *m_conn = nullptr;
};

void TstCanopenConnection::init()
{
    m_bus = new ScriptedCanBus;
}

void TstCanopenConnection::cleanup()
{
    if (m_conn)
        delete m_conn; // owns the bus
    else
        delete m_bus; // the test made no connection
    m_conn = nullptr;
    m_bus = nullptr;
}

void TstCanopenConnection::open(const QString &text)
{
    m_conn = new CanopenConnection(uri(text), m_bus);
    ObjectDictionary dict;
    dict.insert(test::objectDef(0x6041, 0, DataType::Unsigned16, Access::ReadOnly));
    dict.insert(test::objectDef(0x6040, 0, DataType::Unsigned16, Access::ReadWrite));
    dict.insert(test::objectDef(0x1008, 0, DataType::VisibleString, Access::Const));
    dict.insert(test::objectDef(0x1010, 1, DataType::Unsigned32, Access::ReadWrite));
    m_conn->setDictionary(dict);
    m_conn->setRequestTimeoutMs(50);
    m_conn->open();
}

void TstCanopenConnection::missingNodeFailsOpenWithClearError()
{
    open(QStringLiteral("canopen+virtualcan://can0"));
    QCOMPARE(m_conn->state(), DeviceConnection::State::Disconnected);
    QCOMPARE(m_conn->lastError().kind(), Error::Kind::InvalidArgument);
    QVERIFY2(m_conn->lastError().message().contains(QLatin1String("node=")),
             qPrintable(m_conn->lastError().message()));
}

void TstCanopenConnection::connectedWhenBusOpens()
{
    open(QStringLiteral("canopen+slcan://127.0.0.1?node=50"));
    QCOMPARE(m_conn->state(), DeviceConnection::State::Connected);
    QCOMPARE(m_conn->node(), NodeId(50));
    QCOMPARE(m_conn->protocolKey(), QStringLiteral("canopen"));
    QVERIFY(m_conn->capabilities() & DeviceConnection::Capability::StoreNonVolatile);
    QVERIFY(m_bus->sent().isEmpty());
}

void TstCanopenConnection::toolNodeIsTheHeartbeatNode_data()
{
    QTest::addColumn<QString>("query");
    QTest::addColumn<int>("tool"); // 0: refused
    QTest::addColumn<QString>("why");
    QTest::newRow("default") << QString() << 127 << QString();
    QTest::newRow("given") << QStringLiteral("&toolnode=100") << 100 << QString();
    QTest::newRow("hex") << QStringLiteral("&toolnode=0x70") << 0x70 << QString();
    QTest::newRow("clash") << QStringLiteral("&toolnode=50") << 0
                           << QStringLiteral("?toolnode=50 is the drive's own node id");
    QTest::newRow("zero") << QStringLiteral("&toolnode=0") << 0 << QStringLiteral("toolnode=0 in");
    QTest::newRow("too big") << QStringLiteral("&toolnode=128") << 0
                             << QStringLiteral("from 1 to 127");
}

// The tool's own heartbeat (what drives with 1016h watch) uses ?toolnode=, 127 by default, never
// the drive's id.
void TstCanopenConnection::toolNodeIsTheHeartbeatNode()
{
    QFETCH(QString, query);
    QFETCH(int, tool);
    QFETCH(QString, why);
    open(QStringLiteral("canopen+slcan://127.0.0.1?node=50") + query);
    if (tool == 0) {
        QCOMPARE(m_conn->state(), DeviceConnection::State::Disconnected);
        QCOMPARE(m_conn->lastError().kind(), Error::Kind::InvalidArgument);
        QVERIFY2(m_conn->lastError().message().contains(why),
                 qPrintable(m_conn->lastError().message()));
        return;
    }
    QCOMPARE(m_conn->state(), DeviceConnection::State::Connected);
    QCOMPARE(int(m_conn->network()->heartbeat()->nodeId()), tool);
}

void TstCanopenConnection::readTypedStatusword()
{
    open(QStringLiteral("canopen+slcan://127.0.0.1?node=50"));
    m_bus->play({ tx("40 41 60 00 00 00 00 00"), rx("4B 41 60 00 27 04 00 00") });
    const auto r = Reply::wait(m_conn->read({ 0x6041, 0 }), kWaitMs);
    QVERIFY2(r.ok(), qPrintable(r.error().toString()));
    QCOMPARE(r->toULongLong(), 0x0427ull);
    checkScript();
}

void TstCanopenConnection::readUnknownObjectGivesIntegerByLength()
{
    open(QStringLiteral("canopen+slcan://127.0.0.1?node=50&block=1"));
    // Unknown objects go by normal upload even with block enabled.
    m_bus->play({ tx("40 00 35 02 00 00 00 00"), rx("43 00 35 02 FE FF FF FF") });
    const auto r = Reply::wait(m_conn->read({ 0x3500, 2 }), kWaitMs);
    QVERIFY2(r.ok(), qPrintable(r.error().toString()));
    QCOMPARE(r->toLongLong(), 0xFFFFFFFEll);
    checkScript();
}

void TstCanopenConnection::readVisibleStringSegmented()
{
    open(QStringLiteral("canopen+slcan://127.0.0.1?node=50"));
    m_bus->play({
        tx("40 08 10 00 00 00 00 00"),
        rx("41 08 10 00 09 00 00 00"),
        tx("60 00 00 00 00 00 00 00"),
        rx("00 4D 6F 76 69 6E 67 43"),
        tx("70 00 00 00 00 00 00 00"),
        rx("1B 61 70 00 00 00 00 00"),
    });
    const auto r = Reply::wait(m_conn->read({ 0x1008, 0 }), kWaitMs);
    QVERIFY2(r.ok(), qPrintable(r.error().toString()));
    QCOMPARE(r->toString(), QStringLiteral("MovingCap"));
    checkScript();
}

void TstCanopenConnection::writeTypedControlword()
{
    open(QStringLiteral("canopen+slcan://127.0.0.1?node=50"));
    m_bus->play({ tx("2B 40 60 00 0F 00 00 00"), rx("60 40 60 00 00 00 00 00") });
    const auto r = Reply::wait(m_conn->write({ 0x6040, 0 }, 15), kWaitMs);
    QVERIFY2(r.ok(), qPrintable(r.error().toString()));
    checkScript();
}

void TstCanopenConnection::writeUnknownIntegerAsFourBytes()
{
    open(QStringLiteral("canopen+slcan://127.0.0.1?node=50"));
    m_bus->play({ tx("23 03 20 00 40 01 00 00"), rx("60 03 20 00 00 00 00 00") });
    QVERIFY(Reply::wait(m_conn->write({ 0x2003, 0 }, QVariant::fromValue<qlonglong>(320)), kWaitMs)
                .ok());
    checkScript();
}

void TstCanopenConnection::storeParametersWritesSave()
{
    open(QStringLiteral("canopen+slcan://127.0.0.1?node=50"));
    // movingcap.md 4.3: t63282310100173617665
    m_bus->play({ tx("23 10 10 01 73 61 76 65"), rx("60 10 10 01 00 00 00 00") });
    QVERIFY(Reply::wait(m_conn->storeNonVolatile(), kWaitMs).ok());
    checkScript();
}

void TstCanopenConnection::abortReachesTheReply()
{
    open(QStringLiteral("canopen+slcan://127.0.0.1?node=50"));
    m_bus->play({ tx("2B 40 60 00 0F 00 00 00"), rx("80 40 60 00 22 00 00 08") });
    const auto r = Reply::wait(m_conn->write({ 0x6040, 0 }, 15), kWaitMs);
    QCOMPARE(r.error().kind(), Error::Kind::DeviceError);
    QCOMPARE(r.error().deviceCode(), 0x08000022u);
    QVERIFY(r.error().message().contains(QLatin1String("present device state")));
}

void TstCanopenConnection::probeWithoutAnswerSaysNodeDoesNotAnswer()
{
    open(QStringLiteral("canopen+slcan://127.0.0.1?node=50&probe=1"));
    QSignalSpy states(m_conn, &DeviceConnection::stateChanged);
    QTRY_COMPARE_WITH_TIMEOUT(m_conn->state(), DeviceConnection::State::Disconnected, kWaitMs);
    QCOMPARE(m_conn->lastError().kind(), Error::Kind::Timeout);
    QVERIFY2(m_conn->lastError().message().contains(QLatin1String("node 50 does not answer")),
             qPrintable(m_conn->lastError().message()));
    QVERIFY(!m_bus->isOpen());
    QCOMPARE(m_bus->sent().at(0).payload(), QByteArray::fromHex("4000100000000000"));
}

void TstCanopenConnection::probeAnsweredByAbortStillConnects()
{
    m_bus->play({ tx("40 00 10 00 00 00 00 00"), rx("80 00 10 00 00 00 02 06") });
    open(QStringLiteral("canopen+slcan://127.0.0.1?node=50&probe=1"));
    QCOMPARE(m_conn->state(), DeviceConnection::State::Connecting);
    QTRY_COMPARE_WITH_TIMEOUT(m_conn->state(), DeviceConnection::State::Connected, kWaitMs);
}

void TstCanopenConnection::lostBusFailsPendingAndDisconnects()
{
    open(QStringLiteral("canopen+slcan://127.0.0.1?node=50"));
    Reply *pending = m_conn->read({ 0x6041, 0 });
    QSignalSpy errors(m_conn, &DeviceConnection::errorOccurred);
    m_bus->drop(Error(Error::Kind::Disconnected, QStringLiteral("peer closed the connection")));
    QCOMPARE(m_conn->state(), DeviceConnection::State::Disconnected);
    QCOMPARE(errors.size(), 1);
    const auto r = Reply::wait(pending, kWaitMs);
    QCOMPARE(r.error().kind(), Error::Kind::Disconnected);
}

void TstCanopenConnection::unknownValueConversions()
{
    QCOMPARE(CanopenConnection::valueFromUnknownBytes(QByteArray::fromHex("2704")).toLongLong(),
             0x0427ll);
    QCOMPARE(CanopenConnection::valueFromUnknownBytes("hello").toByteArray(), QByteArray("hello"));
    QCOMPARE(*CanopenConnection::bytesFromUnknownValue(QVariant::fromValue<quint8>(7)),
             QByteArray::fromHex("07"));
    QCOMPARE(*CanopenConnection::bytesFromUnknownValue(QVariant::fromValue<qlonglong>(-1)),
             QByteArray::fromHex("ffffffff"));
    QCOMPARE(*CanopenConnection::bytesFromUnknownValue(QVariant::fromValue<qlonglong>(1ll << 40)),
             QByteArray::fromHex("0000000000010000"));
    QCOMPARE(*CanopenConnection::bytesFromUnknownValue(QStringLiteral("abc")), QByteArray("abc"));
    QVERIFY(!CanopenConnection::bytesFromUnknownValue(QVariant(1.5)).ok());
}

void TstCanopenConnection::factoryMakesBusesAndRefusesOtherSchemes()
{
    auto bus = CanBusFactory::makeBus(uri(QStringLiteral("canopen+virtualcan://can0?node=5")));
    QVERIFY(bus.ok());
    QCOMPARE(bus.value()->name(), QStringLiteral("virtualcan can0"));
    delete bus.value();
    auto sock = CanBusFactory::makeBus(
        uri(QStringLiteral("canopen+socketcan://can1?node=5&bitrate=500000")));
    QVERIFY(sock.ok());
    QCOMPARE(qobject_cast<QtCanBus *>(sock.value())->bitrate(), 500000);
    delete sock.value();
    QVERIFY(!CanBusFactory::makeBus(uri(QStringLiteral("refgo://127.0.0.1"))).ok());
    QVERIFY(
        !CanBusFactory::makeBus(uri(QStringLiteral("canopen+socketcan://can0?bitrate=x"))).ok());
    auto slcan = CanBusFactory::makeBus(uri(QStringLiteral("canopen+slcan://127.0.0.1?node=50")));
    if (slcan.ok()) {
        QVERIFY2(slcan.value()->name().contains(QLatin1String("15001")),
                 qPrintable(slcan.value()->name()));
        delete slcan.value();
    } else {
        QCOMPARE(slcan.error().kind(), Error::Kind::NotSupported);
    }
}

QTEST_GUILESS_MAIN(TstCanopenConnection)
#include "tst_canopenconnection.moc"
