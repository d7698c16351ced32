// Level 3: the device-side RefGo server over real loopback TCP with a fake device handler:
// byte-exact framing (movingcap.md 3.1, 3.8), split requests, refused requests, several
// clients, and RefgoConnection end to end against it. Floods: a client that never reads its
// answers, and a peer whose answer never ends.

#include "refgo/device/refgoserver.h"
#include "refgo/refgoclient.h"
#include "refgo/refgoconnection.h"
#include "transport/tcpstream.h"
#include "wait.h"

#include <QElapsedTimer>
#include <QTcpServer>
#include <QTcpSocket>
#include <QtTest>

#include <memory>

using namespace db;
using namespace db::refgo;

namespace {

constexpr int kWaitMs = 5000;

// Answers like the Docklight drive: TP, TPSR, OR 3511h.08h and any OW; nothing for the rest.
class FakeDevice : public DeviceHandler
{
public:
    QStringList handle(const Request &request) override
    {
        requests.append(request.text);
        switch (request.command) {
        case Command::TP:
            return { QStringLiteral("-3658") };
        case Command::TPSR:
            return { formatTpsr(0x6) };
        case Command::OR:
            return { QStringLiteral("%1,%2").arg(request.text.trimmed()).arg(m_value) };
        case Command::OW:
            m_value = request.value.toLongLong();
            return { request.text + QStringLiteral(",OK") };
        default:
            return {};
        }
    }
    QStringList requests;

private:
    qlonglong m_value = 110;
};

// A loopback client that collects everything it receives.
class Peer
{
public:
    explicit Peer(quint16 port)
    {
        QObject::connect(&socket, &QTcpSocket::readyRead, [this] { received += socket.readAll(); });
        socket.connectToHost(QHostAddress::LocalHost, port);
    }
    bool waitConnected() { return socket.waitForConnected(kWaitMs); }
    void send(const QByteArray &bytes)
    {
        socket.write(bytes);
        socket.flush();
    }
    QTcpSocket socket;
    QByteArray received;
};

} // namespace

class TstRefgoServer : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void init();
    void cleanup();

    void listensOnChosenLoopbackPort();
    void secondListenFails();
    void answersAreByteExact_data();
    void answersAreByteExact();
    void splitRequestIsReassembled();
    void lineFeedIsIgnored();
    void emptyLinesGetNoAnswer();
    void refusedRequestGetsErrorLine();
    void severalClientsAreServedSeparately();
    void connectionReadsWritesAndCommandsOverLoopback();
    void connectionToClosedPortIsRefused();
    void clientThatDoesNotReadIsPausedAndDropped();
    void endlessAnswerIsTooLong_data();
    void endlessAnswerIsTooLong();

private:
    FakeDevice *m_device = nullptr;
    Server *m_server = nullptr;
};

void TstRefgoServer::init()
{
    m_device = new FakeDevice;
    m_server = new Server(m_device);
    const auto ok = m_server->listen();
    QVERIFY2(ok.ok(), qPrintable(ok.error().toString()));
}

void TstRefgoServer::cleanup()
{
    delete m_server;
    delete m_device;
}

void TstRefgoServer::listensOnChosenLoopbackPort()
{
    QVERIFY(m_server->port() != 0);
    QCOMPARE(m_server->clientCount(), 0);
}

void TstRefgoServer::secondListenFails()
{
    QVERIFY(!m_server->listen().ok());
}

void TstRefgoServer::answersAreByteExact_data()
{
    QTest::addColumn<QByteArray>("request");
    QTest::addColumn<QByteArray>("answer");
    // movingcap.md 3.8 (values from the fake device).
    QTest::newRow("REF35") << QByteArray("REF35\r") << QByteArray("REF35\r\n>");
    QTest::newRow("G360") << QByteArray("G360\r") << QByteArray("G360\r\n>");
    QTest::newRow("TPSR") << QByteArray("TPSR\r") << QByteArray("TPSR\r\n00000006\r\n>");
    QTest::newRow("TP") << QByteArray("TP\r") << QByteArray("TP\r\n-3658\r\n>");
    QTest::newRow("PQ") << QByteArray("PQ\r") << QByteArray("PQ\r\n>");
    QTest::newRow("OR") << QByteArray("OR3511,8\r") << QByteArray("OR3511,8\r\nOR3511,8,110\r\n>");
    QTest::newRow("OW") << QByteArray("OW3511,8,120\r")
                        << QByteArray("OW3511,8,120\r\nOW3511,8,120,OK\r\n>");
    QTest::newRow("echo keeps the space")
        << QByteArray("OR 60FD,0\r") << QByteArray("OR 60FD,0\r\nOR 60FD,0,110\r\n>");
}

void TstRefgoServer::answersAreByteExact()
{
    QFETCH(QByteArray, request);
    QFETCH(QByteArray, answer);
    Peer peer(m_server->port());
    QVERIFY(peer.waitConnected());
    QSignalSpy handled(m_server, &Server::requestHandled);
    peer.send(request);
    QTRY_COMPARE(peer.received, answer);
    QCOMPARE(handled.size(), 1);
    QCOMPARE(handled.at(0).at(0).toString(), QString::fromLatin1(request.chopped(1)));
}

void TstRefgoServer::splitRequestIsReassembled()
{
    Peer peer(m_server->port());
    QVERIFY(peer.waitConnected());
    QSignalSpy handled(m_server, &Server::requestHandled);
    peer.send("O");
    peer.send("R35");
    peer.send("11,8");
    QTRY_COMPARE(m_server->clientCount(), 1);
    QCOMPARE(handled.size(), 0);
    peer.send("\rT");
    peer.send("P\r");
    QTRY_COMPARE(peer.received, QByteArray("OR3511,8\r\nOR3511,8,110\r\n>TP\r\n-3658\r\n>"));
}

void TstRefgoServer::lineFeedIsIgnored()
{
    Peer peer(m_server->port());
    QVERIFY(peer.waitConnected());
    peer.send("TP\r\n\nTP\r");
    QTRY_COMPARE(peer.received, QByteArray("TP\r\n-3658\r\n>TP\r\n-3658\r\n>"));
}

void TstRefgoServer::emptyLinesGetNoAnswer()
{
    Peer peer(m_server->port());
    QVERIFY(peer.waitConnected());
    peer.send("\r\r\r\nTP\r");
    QTRY_COMPARE(peer.received, QByteArray("TP\r\n-3658\r\n>"));
    QCOMPARE(m_device->requests, QStringList { "TP" });
}

void TstRefgoServer::refusedRequestGetsErrorLine()
{
    Peer peer(m_server->port());
    QVERIFY(peer.waitConnected());
    peer.send("XYZ\r");
    QTRY_VERIFY(peer.received.endsWith("\r\n>"));
    QVERIFY2(peer.received.startsWith("XYZ\r\nERROR "), peer.received.constData());
    QVERIFY(peer.received.contains("unknown command"));
    QCOMPARE(peer.received.count("\r\n"), 2); // echo + exactly one ERROR line
    QVERIFY(m_device->requests.isEmpty());
}

void TstRefgoServer::severalClientsAreServedSeparately()
{
    Peer a(m_server->port());
    Peer b(m_server->port());
    QVERIFY(a.waitConnected());
    QVERIFY(b.waitConnected());
    QTRY_COMPARE(m_server->clientCount(), 2);
    a.send("TP");
    b.send("G360\r");
    QTRY_COMPARE(b.received, QByteArray("G360\r\n>"));
    a.send("\r");
    QTRY_COMPARE(a.received, QByteArray("TP\r\n-3658\r\n>"));
    a.socket.disconnectFromHost();
    QTRY_COMPARE(m_server->clientCount(), 1);
}

void TstRefgoServer::connectionReadsWritesAndCommandsOverLoopback()
{
    const auto uri =
        ConnectionUri::parse(QStringLiteral("refgo://127.0.0.1:%1").arg(m_server->port()));
    QVERIFY(uri.ok());
    RefgoConnection connection(uri.value());
    connection.open();
    QTRY_COMPARE(connection.state(), DeviceConnection::State::Connected);

    auto r = test::await(connection.read({ 0x3511, 8 }), kWaitMs);
    QVERIFY2(r.ok(), qPrintable(r.error().toString()));
    QCOMPARE(r.value(), QVariant(qlonglong(110)));
    QVERIFY(test::await(connection.write({ 0x3511, 8 }, qlonglong(120)), kWaitMs).ok());
    QCOMPARE(test::await(connection.read({ 0x3511, 8 }), kWaitMs).value(),
             QVariant(qlonglong(120)));
    QCOMPARE(test::await(connection.command(QStringLiteral("TP")), kWaitMs).value().toStringList(),
             QStringList { "-3658" });
    QCOMPARE(test::await(connection.client()->tellProcessStatus(), kWaitMs).value(),
             QVariant::fromValue<quint32>(6));
    r = test::await(connection.command(QStringLiteral("XYZ")), kWaitMs);
    QCOMPARE(r.error().kind(), Error::Kind::DeviceError);
    QVERIFY(r.error().message().contains(QLatin1String("unknown command")));

    connection.close();
    QTRY_COMPARE(connection.state(), DeviceConnection::State::Disconnected);
    QTRY_COMPARE(m_server->clientCount(), 0);
}

void TstRefgoServer::connectionToClosedPortIsRefused()
{
    // A port that was free a moment ago: nothing listens there now.
    QTcpServer probe;
    QVERIFY(probe.listen(QHostAddress::LocalHost, 0));
    const quint16 port = probe.serverPort();
    probe.close();
    RefgoConnection connection(
        ConnectionUri::parse(QStringLiteral("refgo://127.0.0.1:%1").arg(port)).value());
    QSignalSpy errors(&connection, &DeviceConnection::errorOccurred);
    connection.open();
    QTRY_COMPARE(connection.state(), DeviceConnection::State::Disconnected);
    QCOMPARE(connection.lastError().kind(), Error::Kind::ConnectionRefused);
    QVERIFY(connection.lastError().message().contains(QString::number(port)));
    QCOMPARE(errors.size(), 1);
}

void TstRefgoServer::clientThatDoesNotReadIsPausedAndDropped()
{
    constexpr qint64 kLimit = 16 * 1024;
    m_server->setClientLimits({ kLimit, 1500 });
    Peer greedy(m_server->port());
    QVERIFY(greedy.waitConnected());
    QTRY_COMPARE(m_server->clientCount(), 1);
    // The greedy client takes next to nothing from the kernel, whose buffers are small on both
    // ends: the answers pile up in the server's process soon.
    QObject::disconnect(&greedy.socket, &QTcpSocket::readyRead, nullptr, nullptr);
    greedy.socket.setReadBufferSize(16);
    greedy.socket.setSocketOption(QAbstractSocket::ReceiveBufferSizeSocketOption, 4096);
    m_server->findChild<QTcpSocket *>()->setSocketOption(
        QAbstractSocket::SendBufferSizeSocketOption, 4096);
    greedy.send(QByteArray("TP\r").repeated(40000)); // 520 kB of answers, never read
    QTRY_VERIFY(m_server->peakQueuedBytes() > kLimit);

    // A well-behaved client is served within the client's normal timeout meanwhile.
    Peer polite(m_server->port());
    QVERIFY(polite.waitConnected());
    polite.send("TP\r");
    QTRY_COMPARE_WITH_TIMEOUT(polite.received, QByteArray("TP\r\n-3658\r\n>"),
                              RefgoClient::kDefaultTimeoutMs);

    QCOMPARE(m_server->clientCount(), 2);
    QTRY_COMPARE_WITH_TIMEOUT(m_server->clientCount(), 1, 5000); // the greedy one is dropped
    QVERIFY2(m_server->peakQueuedBytes() <= 2 * kLimit,
             qPrintable(QString::number(m_server->peakQueuedBytes())));
    polite.send("TP\r");
    QTRY_COMPARE(polite.received, QByteArray("TP\r\n-3658\r\n>").repeated(2));
}

void TstRefgoServer::endlessAnswerIsTooLong_data()
{
    QTest::addColumn<QByteArray>("chunk");
    QTest::addColumn<bool>("endless");
    QTest::newRow("10 MB line") << QByteArray("TP\r\n") + QByteArray(10 << 20, 'x') + "\r\n"
                                << false;
    QTest::newRow("endless data without a line end") << QByteArray(64 * 1024, 'y') << true;
}

void TstRefgoServer::endlessAnswerIsTooLong()
{
    QFETCH(QByteArray, chunk);
    QFETCH(bool, endless);
    QTcpServer peer;
    QVERIFY(peer.listen(QHostAddress::LocalHost, 0));
    TcpStream stream(QStringLiteral("127.0.0.1"), peer.serverPort());
    RefgoClient client(&stream);
    QSignalSpy opened(&stream, &ByteStream::opened);
    stream.open();
    QVERIFY(opened.wait(kWaitMs));
    QTRY_VERIFY(peer.hasPendingConnections());
    QTcpSocket *socket = peer.nextPendingConnection();
    qint64 sent = 0;
    // Writes whenever the link has taken the last chunk: as fast as the client reads.
    const auto refill = [&] {
        if ((endless || sent == 0) && socket->bytesToWrite() < chunk.size()) {
            socket->write(chunk);
            sent += chunk.size();
        }
    };
    connect(socket, &QTcpSocket::bytesWritten, this, refill);
    QElapsedTimer clock;
    clock.start();
    std::unique_ptr<Reply> reply(client.tellPosition());
    refill();
    QTRY_VERIFY_WITH_TIMEOUT(reply->isFinished(), kWaitMs);
    QCOMPARE(reply->error().kind(), Error::Kind::Malformed);
    QVERIFY2(reply->error().message().contains(QLatin1String("answer too long")),
             qPrintable(reply->error().message()));
    QVERIFY(clock.elapsed() < RefgoClient::kDefaultTimeoutMs); // the error, not the timeout
    QTRY_VERIFY(sent > 2 * Framer::kMaxAnswerBytes);
    QVERIFY(client.bufferedBytes() <= Framer::kMaxAnswerBytes);
    socket->disconnect(this);
}

QTEST_GUILESS_MAIN(TstRefgoServer)
#include "tst_refgoserver.moc"
