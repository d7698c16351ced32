// Level 3: the simulated MovingCap's SLCAN door (movingcap.md 4.3, 7.1) over real loopback TCP:
// byte-exact slcan lines for SDO reads and writes on node 50, EMCY frames on 0x0B2.
#include "canopen/sdoabort.h"
#include "canopen/sdocodec.h"
#include "devices/movingcap/movingcapcanopen.h"
#include "devices/movingcap/movingcapdrive.h"
#include "resources/builtindescriptions.h"
#include "transport/device/slcanserver.h"
#include "transport/slcancodec.h"

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTcpSocket>
#include <QTest>
#include <QtEndian>

using namespace db;
using namespace db::canopen;

class TestMovingCapCanopen : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void init();
    void cleanup();
    void readStatuswordAsInSpec();
    void writeControlwordThenReadBack();
    void segmentedUploadOfDeviceName();
    void blockUploadOfDeviceName();
    void wrongSaveSignatureAborts();
    void readOnlyAndMissingObjects();
    void faultInjectionGivesEmcyBytes_data();
    void faultInjectionGivesEmcyBytes();
    void nmtAndHeartbeat();
    void lifeGuardingEndsInTheAbortConnectionReaction_data();
    void lifeGuardingEndsInTheAbortConnectionReaction();
    void noConsumerHeartbeatObject();
    void silencedHeartbeat();

private:
    // Sends lines and collects the answer until it ends with `until` (or 2 s pass).
    QByteArray exchange(const QByteArray &lines, const QByteArray &until);
    static QByteArray sdoLine(const char *hexPayload, quint32 id = 0x632);

    sim::MovingCapDrive *m_drive = nullptr;
    MovingCapCanopen *m_canopen = nullptr;
    SlcanServer *m_server = nullptr;
    QTcpSocket *m_client = nullptr;
};

void TestMovingCapCanopen::init()
{
    m_drive = new sim::MovingCapDrive(resources::movingCapDictionary());
    m_canopen = new MovingCapCanopen(m_drive);
    m_server = new SlcanServer;
    connect(m_server, &SlcanServer::frameReceived, m_canopen, &MovingCapCanopen::receive);
    connect(m_canopen, &MovingCapCanopen::transmit, m_server, &SlcanServer::send);
    QVERIFY(m_server->listen(0).ok());
    m_client = new QTcpSocket;
    QSignalSpy connected(m_server, &SlcanServer::clientConnected);
    m_client->connectToHost(QHostAddress::LocalHost, m_server->port());
    QVERIFY(connected.wait(2000));
    QCOMPARE(exchange("C\rS4\rO\r", "\r\r\r"), QByteArray("\r\r\r"));
}

void TestMovingCapCanopen::cleanup()
{
    delete m_client;
    delete m_server;
    delete m_canopen;
    delete m_drive;
}

QByteArray TestMovingCapCanopen::exchange(const QByteArray &lines, const QByteArray &until)
{
    m_client->write(lines);
    QByteArray answer;
    QElapsedTimer timer;
    timer.start();
    while (!answer.endsWith(until) && timer.elapsed() < 2000) {
        if (m_client->bytesAvailable() == 0)
            QSignalSpy(m_client, &QTcpSocket::readyRead).wait(200);
        answer += m_client->readAll();
    }
    return answer;
}

QByteArray TestMovingCapCanopen::sdoLine(const char *hexPayload, quint32 id)
{
    return slcan::encodeFrame(
        QCanBusFrame(id, QByteArray::fromHex(QByteArray(hexPayload).replace(' ', ""))));
}

void TestMovingCapCanopen::readStatuswordAsInSpec()
{
    QByteArray expected = sdoLine("4B 41 60 00 0000 0000", 0x5B2);
    const QByteArray sw =
        QByteArray::number(m_drive->statusword() & 0xFF, 16).rightJustified(2, '0')
        + QByteArray::number(m_drive->statusword() >> 8, 16).rightJustified(2, '0');
    expected.replace(13, 4, sw.toUpper());
    QCOMPARE(exchange("t63284041600000000000\r", expected), QByteArray("z\r") + expected);
}

void TestMovingCapCanopen::writeControlwordThenReadBack()
{
    // Spec 4.3: 6040h = 000Fh acknowledged by t5B286040600000000000.
    for (const char *cw :
         { "2B 40 60 00 0600 0000", "2B 40 60 00 0700 0000", "2B 40 60 00 0F00 0000" })
        QCOMPARE(exchange(sdoLine(cw), "t5B286040600000000000\r"),
                 QByteArray("z\rt5B286040600000000000\r"));
    m_drive->advance(0.05);
    QCOMPARE(m_drive->read({ 0x6040, 0 }).value().toUInt(), 0x0Fu);
    QCOMPARE(m_drive->state(), cia402::State::OperationEnabled);
    // Mode of operation: write 6060h = 3, read it back through SDO.
    exchange(sdoLine("2F 60 60 00 03 000000"), "t5B286060600000000000\r");
    QCOMPARE(exchange(sdoLine("40 60 60 00 00000000"), "\r").right(22),
             sdoLine("4F 60 60 00 03 000000", 0x5B2));
    QCOMPARE(m_drive->statusword() & 0x6F, 0x27); // operation enabled, seen by RefGo too
}

void TestMovingCapCanopen::segmentedUploadOfDeviceName()
{
    const QByteArray name = m_drive->read({ 0x1008, 0 }).value().toString().toLatin1();
    QCOMPARE(name, QByteArray("MovingCap ETH"));
    QVERIFY(exchange(sdoLine("40 08 10 00 00000000"), "\r")
                .endsWith(sdoLine("41 08 10 00 0D000000", 0x5B2)));
    QVERIFY(exchange(sdoLine("60 00000000000000"), "\r")
                .endsWith(slcan::encodeFrame(QCanBusFrame(0x5B2, QByteArray(1, 0) + "MovingC"))));
    QVERIFY(exchange(sdoLine("70 00000000000000"), "\r")
                .endsWith(slcan::encodeFrame(
                    QCanBusFrame(0x5B2, QByteArray(1, 0x13) + "ap ETH" + QByteArray(1, 0)))));
}

void TestMovingCapCanopen::blockUploadOfDeviceName()
{
    QVERIFY(exchange(sdoLine("A4 08 10 00 7F 00 0000"), "\r")
                .endsWith(sdoLine("C6 08 10 00 0D000000", 0x5B2)));
    const QByteArray second = slcan::encodeFrame(
        QCanBusFrame(0x5B2, QByteArray(1, char(0x82)) + "ap ETH" + QByteArray(1, 0)));
    const QByteArray segments = exchange(sdoLine("A3 00000000000000"), second);
    QVERIFY(segments.endsWith(slcan::encodeFrame(QCanBusFrame(0x5B2, QByteArray(1, 1) + "MovingC"))
                              + second));
    QByteArray end = QByteArray::fromHex("C5000000000000 00");
    qToLittleEndian(sdocodec::crc16("MovingCap ETH"), end.data() + 1);
    QVERIFY(exchange(sdoLine("A2 02 7F 0000000000"), "\r")
                .endsWith(slcan::encodeFrame(QCanBusFrame(0x5B2, end))));
}

void TestMovingCapCanopen::wrongSaveSignatureAborts()
{
    // Spec 4.3: 1010h.01 = "save" is accepted; anything else gives 08000020.
    QVERIFY(exchange("t63282310100173617665\r", "\r").endsWith("t5B286010100100000000\r"));
    QVERIFY(
        exchange("t63282310100173617666\r", "\r").endsWith(sdoLine("80 10 10 01 20000008", 0x5B2)));
}

void TestMovingCapCanopen::readOnlyAndMissingObjects()
{
    QVERIFY(exchange(sdoLine("2B 41 60 00 0000 0000"), "\r")
                .endsWith(sdoLine("80 41 60 00 02000106", 0x5B2)));
    QVERIFY(exchange(sdoLine("40 34 12 00 00000000"), "\r")
                .endsWith(sdoLine("80 34 12 00 00000206", 0x5B2)));
    QVERIFY(exchange(sdoLine("40 10 10 01 00000000"), "\r")
                .endsWith(sdoLine("80 10 10 01 01000106", 0x5B2)));
}

void TestMovingCapCanopen::faultInjectionGivesEmcyBytes_data()
{
    QTest::addColumn<quint16>("code");
    QTest::addColumn<QByteArray>("line");
    // movingcap.md 7.1, "CAN Monitor data" column, on COB-ID 0x0B2 (4.3).
    QTest::newRow("under-voltage") << quint16(0x3221) << QByteArray("t0B282132050000000000\r");
    QTest::newRow("over-temp") << quint16(0x4210) << QByteArray("t0B281042090000000000\r");
    QTest::newRow("stroke") << quint16(0x7121) << QByteArray("t0B282171100000000000\r");
    QTest::newRow("over-current") << quint16(0x2220) << QByteArray("t0B282022050000000000\r");
    QTest::newRow("needs reset") << quint16(0xFFF5) << QByteArray("t0B28F5FF100000000000\r");
}

void TestMovingCapCanopen::faultInjectionGivesEmcyBytes()
{
    QFETCH(quint16, code);
    QFETCH(QByteArray, line);
    m_drive->injectFault(code);
    QByteArray got;
    QElapsedTimer timer;
    timer.start();
    while (!got.contains(line) && timer.elapsed() < 2000) {
        QSignalSpy(m_client, &QTcpSocket::readyRead).wait(200);
        got += m_client->readAll();
    }
    QCOMPARE(got, line);
}

void TestMovingCapCanopen::nmtAndHeartbeat()
{
    QSignalSpy states(&m_canopen->node(), &SimulatedNode::nmtStateChanged);
    exchange("t00020132\r", "z\r"); // spec 4.3: start node 50
    QTRY_COMPARE(m_canopen->node().nmtState(), NmtState::Operational);
    // Reset communication: boot-up frame t732100.
    QVERIFY(exchange("t00028232\r", "t732100\r").endsWith("t732100\r"));
}

void TestMovingCapCanopen::lifeGuardingEndsInTheAbortConnectionReaction_data()
{
    QTest::addColumn<int>("option");
    QTest::addColumn<cia402::State>("after");
    QTest::newRow("0 no action") << 0 << cia402::State::OperationEnabled;
    QTest::newRow("1 fault") << 1 << cia402::State::Fault;
    QTest::newRow("2 disable voltage") << 2 << cia402::State::SwitchOnDisabled;
    QTest::newRow("3 quick stop") << 3 << cia402::State::QuickStopActive;
}

// Guarded once, then no more guard requests for guard time x life time factor: the drive reacts
// as 6007h says (CiA 402), and a fault shows as 1002h bit 5 "Abort connection".
void TestMovingCapCanopen::lifeGuardingEndsInTheAbortConnectionReaction()
{
    QFETCH(int, option);
    QFETCH(cia402::State, after);
    m_drive->startRealTime(); // the fault reaction takes its time
    QVERIFY(m_drive->write({ 0x605A, 0 }, 6).ok()); // quick stop: stay in quick stop active
    QVERIFY(m_drive->write({ 0x6007, 0 }, option).ok());
    QVERIFY(exchange(sdoLine("2B 0C 10 00 1400 0000"), "\r")
                .endsWith(sdoLine("60 0C 10 00 00000000", 0x5B2)));
    QVERIFY(exchange(sdoLine("2F 0D 10 00 02 000000"), "\r")
                .endsWith(sdoLine("60 0D 10 00 00000000", 0x5B2)));
    for (int cw : { 6, 7, 15 })
        QVERIFY(m_drive->write({ 0x6040, 0 }, cw).ok());
    QCOMPARE(m_drive->state(), cia402::State::OperationEnabled);
    // Guard request (RTR on 732h): answered with the NMT state and toggle bit 0.
    QSignalSpy lost(&m_canopen->node(), &SimulatedNode::communicationLost);
    QVERIFY(exchange("r7321\r", "t73217F\r").endsWith("t73217F\r"));
    QVERIFY(lost.wait(2000));
    QTRY_COMPARE_WITH_TIMEOUT(m_drive->state(), after, 2000);
    // One EMCY for the event (CiA 301 8130h, error register 11h), whatever the reaction.
    QByteArray got;
    QTRY_VERIFY((got += m_client->readAll()).contains("t0B28"));
    QCOMPARE(got.count("t0B28"), 1);
    QVERIFY2(got.contains("t0B2830811"), got.constData());
    const quint32 status = quint32(m_drive->read({ 0x1002, 0 }).value().toULongLong());
    QCOMPARE(bool(status & (1u << 5)), after == cia402::State::Fault);
    if (after == cia402::State::Fault)
        QCOMPARE(m_drive->read({ 0x603F, 0 }).value().toUInt(), 0x8130u);
}

// The drive's XDD has no 1016h: a master cannot make it watch a heartbeat, only guard it.
void TestMovingCapCanopen::noConsumerHeartbeatObject()
{
    QVERIFY(exchange(sdoLine("40 16 10 01 00000000"), "\r")
                .endsWith(sdoLine("80 16 10 01 00000206", 0x5B2)));
}

void TestMovingCapCanopen::silencedHeartbeat()
{
    QVERIFY(exchange(sdoLine("2B 17 10 00 1400 0000"), "\r")
                .endsWith(sdoLine("60 17 10 00 00000000", 0x5B2)));
    QByteArray got;
    QTRY_VERIFY_WITH_TIMEOUT((got += m_client->readAll()).count("t7321") >= 2, 2000);
    m_canopen->node().setHeartbeatSilenced(true);
    QSignalSpy sent(&m_canopen->node(), &SimulatedNode::transmit);
    QVERIFY(!sent.wait(100)); // five periods without a frame
    m_canopen->node().setHeartbeatSilenced(false);
    got.clear();
    QTRY_VERIFY_WITH_TIMEOUT((got += m_client->readAll()).contains("t7321"), 2000);
}

QTEST_GUILESS_MAIN(TestMovingCapCanopen)
#include "tst_movingcapcanopen.moc"
