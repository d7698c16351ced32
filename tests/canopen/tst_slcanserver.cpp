// Level 3: SlcanServer over real loopback TCP (movingcap.md 4.2 simulator recommendations), and
// SlcanBus over TcpStream against it, and both under floods: a client that never reads, a peer
// that sends frames as fast as it can.
#include "canopen/sdoclient.h"
#include "transport/device/slcanserver.h"
#include "transport/slcanbus.h"
#include "transport/tcpstream.h"

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTest>

#include <atomic>
#include <future>
#include <thread>

using namespace db;

class TestSlcanServer : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void init();
    void cleanup();
    void commandsAreAcknowledged();
    void frameGetsZAckAndReachesDevice();
    void transmitAckIsConfigurable();
    void garbageGetsBell();
    void deviceFramesGoToEveryClient();
    void timestampsAfterZ1();
    void requireOpen();
    void noDelayOnClientSockets();
    void slcanBusRoundTrip();
    void clientThatDoesNotReadIsPausedAndDropped();
    void frameFloodIsBoundedAndTimeoutsFireOnTime();

private:
    QByteArray exchange(const QByteArray &request, qsizetype expectedBytes);
    QTcpSocket *connectClient();

    SlcanServer *m_server = nullptr;
    QTcpSocket *m_client = nullptr;
};

void TestSlcanServer::init()
{
    m_server = new SlcanServer(this);
    QVERIFY(m_server->listen(0).ok());
    QVERIFY(m_server->port() != 0);
    m_client = connectClient();
    QVERIFY(m_client);
}

void TestSlcanServer::cleanup()
{
    delete m_client;
    delete m_server;
    m_client = nullptr;
    m_server = nullptr;
}

QTcpSocket *TestSlcanServer::connectClient()
{
    auto *socket = new QTcpSocket(this);
    QSignalSpy connected(m_server, &SlcanServer::clientConnected);
    socket->connectToHost(QHostAddress::LocalHost, m_server->port());
    if (!socket->waitForConnected(2000) || !connected.wait(2000))
        return nullptr;
    return socket;
}

QByteArray TestSlcanServer::exchange(const QByteArray &request, qsizetype expectedBytes)
{
    m_client->write(request);
    QByteArray answer;
    QElapsedTimer timer;
    timer.start();
    // With expectedBytes 0, one short wait shows that nothing comes.
    do {
        if (m_client->bytesAvailable() == 0)
            QSignalSpy(m_client, &QTcpSocket::readyRead).wait(expectedBytes ? 200 : 100);
        answer += m_client->readAll();
    } while (answer.size() < expectedBytes && timer.elapsed() < 2000);
    return answer;
}

void TestSlcanServer::commandsAreAcknowledged()
{
    QCOMPARE(exchange("C\rS4\rO\r", 3), QByteArray("\r\r\r"));
    QCOMPARE(exchange("s031C\rL\rZ0\r", 3), QByteArray("\r\r\r"));
    QCOMPARE(exchange("V\rN\rF\r", 15), QByteArray("V1013\rN0001\rF00\r"));
}

void TestSlcanServer::frameGetsZAckAndReachesDevice()
{
    QSignalSpy frames(m_server, &SlcanServer::frameReceived);
    QCOMPARE(exchange("t63284041600000000000\r", 2), QByteArray("z\r"));
    QTRY_COMPARE(frames.size(), 1);
    const auto frame = frames.at(0).at(0).value<QCanBusFrame>();
    QCOMPARE(frame.frameId(), 0x632u);
    QCOMPARE(frame.payload(), QByteArray::fromHex("4041600000000000"));
    QCOMPARE(exchange("T123456780\r", 2), QByteArray("Z\r"));
}

void TestSlcanServer::transmitAckIsConfigurable()
{
    m_server->setTransmitAck(SlcanServer::TransmitAck::Cr);
    QCOMPARE(exchange("t7321", 0).size(), 0);
    QCOMPARE(exchange("05\r", 1), QByteArray("\r"));
    m_server->setTransmitAck(SlcanServer::TransmitAck::None);
    QSignalSpy frames(m_server, &SlcanServer::frameReceived);
    QCOMPARE(exchange("t732105\rO\r", 1), QByteArray("\r")); // only the O is answered
    QCOMPARE(frames.size(), 1);
}

void TestSlcanServer::garbageGetsBell()
{
    QSignalSpy refused(m_server, &SlcanServer::refused);
    QCOMPARE(exchange("hello\rt8001AA\rO\r", 3), QByteArray("\a\a\r"));
    QCOMPARE(refused.size(), 2);
    QCOMPARE(refused.at(0).at(0).toByteArray(), QByteArray("hello"));
}

void TestSlcanServer::deviceFramesGoToEveryClient()
{
    QTcpSocket *second = connectClient();
    QVERIFY(second);
    QTRY_COMPARE(m_server->clientCount(), 2);
    QCOMPARE(m_server->send(QCanBusFrame(0x0B2, QByteArray::fromHex("2132050000000000"))), 2);
    QByteArray a, b;
    QTRY_COMPARE(a += m_client->readAll(), QByteArray("t0B282132050000000000\r"));
    QTRY_COMPARE(b += second->readAll(), QByteArray("t0B282132050000000000\r"));
    QSignalSpy gone(m_server, &SlcanServer::clientDisconnected);
    delete second;
    QVERIFY(gone.wait(2000));
    QCOMPARE(m_server->clientCount(), 1);
}

void TestSlcanServer::timestampsAfterZ1()
{
    QCOMPARE(exchange("Z1\r", 1), QByteArray("\r"));
    m_server->send(QCanBusFrame(0x732, QByteArray::fromHex("05")));
    QByteArray line;
    QTRY_VERIFY((line += m_client->readAll()).endsWith('\r'));
    QCOMPARE(line.size(), 12); // t732105 + 4 hex digits + CR
    QVERIFY(line.startsWith("t732105"));
}

void TestSlcanServer::requireOpen()
{
    m_server->setRequireOpen(true);
    QSignalSpy frames(m_server, &SlcanServer::frameReceived);
    QCOMPARE(exchange("t732105\r", 1), QByteArray("\a"));
    QCOMPARE(m_server->send(QCanBusFrame(0x732, QByteArray::fromHex("05"))), 0);
    QCOMPARE(exchange("O\rt732105\r", 3), QByteArray("\rz\r"));
    QTRY_COMPARE(frames.size(), 1);
    QCOMPARE(m_server->send(QCanBusFrame(0x732, QByteArray::fromHex("05"))), 1);
}

void TestSlcanServer::noDelayOnClientSockets()
{
    const auto sockets = m_server->findChildren<QTcpSocket *>();
    QCOMPARE(sockets.size(), 1);
    QCOMPARE(sockets.first()->socketOption(QAbstractSocket::LowDelayOption).toInt(), 1);
}

void TestSlcanServer::slcanBusRoundTrip()
{
    SlcanBus bus(new TcpStream(QStringLiteral("127.0.0.1"), m_server->port()));
    QSignalSpy opened(&bus, &CanBus::opened);
    QSignalSpy busFrames(&bus, &CanBus::frameReceived);
    QSignalSpy warnings(&bus, &CanBus::warning);
    QSignalSpy serverFrames(m_server, &SlcanServer::frameReceived);
    bus.open();
    QVERIFY(opened.wait(2000));
    QVERIFY(bus.send(QCanBusFrame(0x632, QByteArray::fromHex("4041600000000000"))));
    QVERIFY(serverFrames.wait(2000));
    QCOMPARE(serverFrames.at(0).at(0).value<QCanBusFrame>().frameId(), 0x632u);
    QTRY_COMPARE(m_server->clientCount(), 2);
    m_server->send(QCanBusFrame(0x5B2, QByteArray::fromHex("4B41600027040000")));
    QVERIFY(busFrames.wait(2000));
    QCOMPARE(busFrames.at(0).at(0).value<QCanBusFrame>().payload(),
             QByteArray::fromHex("4B41600027040000"));
    m_server->sendRaw("\agarbage\r");
    QTRY_COMPARE(warnings.size(), 2);
    QSignalSpy closed(&bus, &CanBus::closed);
    m_server->close();
    QVERIFY(closed.wait(2000));
}

void TestSlcanServer::clientThatDoesNotReadIsPausedAndDropped()
{
    constexpr qint64 kLimit = 16 * 1024;
    delete m_client;
    m_server->setClientLimits({ kLimit, 1500 });
    m_client = connectClient();
    QVERIFY(m_client);
    QTcpSocket *greedy = connectClient();
    QVERIFY(greedy);
    // The greedy client takes next to nothing from the kernel, whose buffers are small on both
    // ends: the answers pile up in the server's process soon.
    greedy->setReadBufferSize(16);
    greedy->setSocketOption(QAbstractSocket::ReceiveBufferSizeSocketOption, 4096);
    for (QTcpSocket *socket : m_server->findChildren<QTcpSocket *>())
        socket->setSocketOption(QAbstractSocket::SendBufferSizeSocketOption, 4096);
    QSignalSpy gone(m_server, &SlcanServer::clientDisconnected);
    greedy->write(QByteArray("t732105\r").repeated(60000)); // 120 kB of acks, never read
    QTRY_VERIFY(m_server->peakQueuedBytes() > kLimit);

    // Meanwhile the well-behaved client is served at once; device frames skip the greedy one.
    QCOMPARE(exchange("V\r", 6), QByteArray("V1013\r"));
    QCOMPARE(m_server->send(QCanBusFrame(0x732, QByteArray::fromHex("05"))), 1);
    QCOMPARE(m_server->droppedFrames(), 1);
    QByteArray line;
    QTRY_COMPARE(line += m_client->readAll(), QByteArray("t732105\r"));

    QVERIFY(gone.wait(5000));
    QCOMPARE(m_server->clientCount(), 1);
    QVERIFY2(m_server->peakQueuedBytes() <= 2 * kLimit,
             qPrintable(QString::number(m_server->peakQueuedBytes())));
    QCOMPARE(exchange("N\r", 6), QByteArray("N0001\r"));
    delete greedy;
}

namespace {
// A peer on its own thread that writes PDO frames as fast as loopback takes them.
class Flooder
{
public:
    Flooder()
    {
        std::promise<quint16> port;
        auto listening = port.get_future();
        m_thread = std::thread([this, &port] { run(port); });
        m_port = listening.get();
    }
    ~Flooder()
    {
        m_stop = true;
        m_thread.join();
    }
    quint16 port() const { return m_port; }
    qint64 framesWritten() const { return m_frames; }

private:
    void run(std::promise<quint16> &port)
    {
        QTcpServer server;
        server.listen(QHostAddress::LocalHost, 0);
        port.set_value(server.serverPort());
        if (!server.waitForNewConnection(5000))
            return;
        std::unique_ptr<QTcpSocket> socket(server.nextPendingConnection());
        constexpr int kFramesPerChunk = 1000;
        const QByteArray chunk = QByteArray("t18180102030405060708\r").repeated(kFramesPerChunk);
        while (!m_stop && socket->state() == QAbstractSocket::ConnectedState) {
            if (socket->bytesToWrite() < 4 * chunk.size()) {
                socket->write(chunk);
                m_frames += kFramesPerChunk;
            }
            socket->waitForBytesWritten(20);
        }
    }

    std::thread m_thread;
    quint16 m_port = 0;
    std::atomic<bool> m_stop = false;
    std::atomic<qint64> m_frames = 0;
};
} // namespace

void TestSlcanServer::frameFloodIsBoundedAndTimeoutsFireOnTime()
{
    Flooder flooder;
    SlcanBus bus(new TcpStream(QStringLiteral("127.0.0.1"), flooder.port()));
    QSignalSpy warnings(&bus, &CanBus::warning);
    QVERIFY(bus.openAndWait(2000).ok());
    canopen::SdoClient sdo(&bus);
    constexpr int kTimeoutMs = 1000;
    sdo.setTimeoutMs(kTimeoutMs);
    QTRY_VERIFY(flooder.framesWritten() > 100000); // the flood is on

    QElapsedTimer clock;
    clock.start();
    qint64 finishedAfter = -1;
    std::unique_ptr<Reply> reply(sdo.upload(5, { 0x1000, 0 }));
    connect(reply.get(), &Reply::finished, this, [&] { finishedAfter = clock.elapsed(); });
    QTRY_VERIFY_WITH_TIMEOUT(finishedAfter >= 0, 10000);
    qInfo("SDO timeout of %d ms fired after %lld ms; %lld of %lld frames dropped, peak backlog "
          "%lld bytes",
          kTimeoutMs, finishedAfter, bus.droppedFrames(), flooder.framesWritten(),
          qint64(bus.peakBacklogBytes()));
    QCOMPARE(reply->error().kind(), Error::Kind::Timeout);
    QVERIFY2(finishedAfter < kTimeoutMs * 3 / 2, qPrintable(QString::number(finishedAfter)));

    QVERIFY(bus.droppedFrames() > 0);
    QVERIFY2(bus.peakBacklogBytes() <= SlcanBus::kMaxBacklogBytes + slcan::kMaxLineLength + 1,
             qPrintable(QString::number(bus.peakBacklogBytes())));
    QTRY_VERIFY(!warnings.isEmpty());
    const QString warning = warnings.last().at(0).toString();
    QVERIFY2(warning.contains(QLatin1String("receive queue overflow: "))
                 && warning.contains(QLatin1String("frames dropped")),
             qPrintable(warning));
}

QTEST_GUILESS_MAIN(TestSlcanServer)
#include "tst_slcanserver.moc"
