// TcpStream against real loopback sockets: open, bytes both ways, refusals and lost links that
// name the address, clean close.
#include "transport/tcpstream.h"

#include <QSignalSpy>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTest>

#include <sys/socket.h>

using namespace db;

class TestTcpStream : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void opensAndCarriesBytesBothWays();
    void refusedConnectionNamesTheAddress();
    void peerClosingReportsDisconnected();
    void closeIsCleanAndSilent();
    void writeWhileClosedDoesNothing();
    void reopensAfterClose();
    void writeIsOnTheWireWhenWriteReturns();
    void floodArrivesInBoundedChunks();
    void keptBytesStayAsTheyCame();
    void bytesThePeerCannotTakeYetFollowInOrder();
    void writeToAResetPeerFailsFromTheLoop();
    void receiverWithItsOwnEventLoopKeepsItsBytes();
};

void TestTcpStream::opensAndCarriesBytesBothWays()
{
    QTcpServer server;
    QVERIFY(server.listen(QHostAddress::LocalHost, 0));
    TcpStream stream(QStringLiteral("127.0.0.1"), server.serverPort());
    QSignalSpy opened(&stream, &ByteStream::opened);
    QByteArray all;
    connect(&stream, &ByteStream::received, this, [&all](const QByteArray &b) { all += b; });
    stream.open();
    QCOMPARE(stream.state(), ByteStream::State::Opening);
    QVERIFY(opened.wait(3000));
    QVERIFY(stream.isOpen());
    QTRY_VERIFY(server.hasPendingConnections());
    QTcpSocket *peer = server.nextPendingConnection();
    QVERIFY(stream.write("TP\r"));
    QTRY_COMPARE(peer->bytesAvailable(), 3);
    QCOMPARE(peer->readAll(), QByteArray("TP\r"));
    peer->write("TP\r\n-3658\r\n>");
    QTRY_COMPARE(all, QByteArray("TP\r\n-3658\r\n>"));
    QCOMPARE(stream.peerName(), QStringLiteral("127.0.0.1:%1").arg(server.serverPort()));
}

void TestTcpStream::refusedConnectionNamesTheAddress()
{
    QTcpServer probe;
    QVERIFY(probe.listen(QHostAddress::LocalHost, 0));
    const quint16 port = probe.serverPort();
    probe.close();
    TcpStream stream(QStringLiteral("127.0.0.1"), port);
    QSignalSpy closed(&stream, &ByteStream::closed);
    stream.open();
    QVERIFY(closed.wait(3000));
    const Error e = closed.first().first().value<Error>();
    QCOMPARE(e.kind(), Error::Kind::ConnectionRefused);
    QVERIFY(e.message().contains(QStringLiteral("127.0.0.1:%1").arg(port)));
    QCOMPARE(stream.state(), ByteStream::State::Closed);
}

void TestTcpStream::peerClosingReportsDisconnected()
{
    QTcpServer server;
    QVERIFY(server.listen(QHostAddress::LocalHost, 0));
    TcpStream stream(QStringLiteral("127.0.0.1"), server.serverPort());
    QSignalSpy opened(&stream, &ByteStream::opened);
    QSignalSpy closed(&stream, &ByteStream::closed);
    stream.open();
    QVERIFY(opened.wait(3000));
    QTRY_VERIFY(server.hasPendingConnections());
    server.nextPendingConnection()->close();
    QVERIFY(closed.wait(3000));
    const Error e = closed.first().first().value<Error>();
    QCOMPARE(e.kind(), Error::Kind::Disconnected);
    QVERIFY(e.message().contains(QLatin1String("closed the connection")));
}

void TestTcpStream::closeIsCleanAndSilent()
{
    QTcpServer server;
    QVERIFY(server.listen(QHostAddress::LocalHost, 0));
    TcpStream stream(QStringLiteral("127.0.0.1"), server.serverPort());
    QSignalSpy opened(&stream, &ByteStream::opened);
    QSignalSpy closed(&stream, &ByteStream::closed);
    stream.open();
    QVERIFY(opened.wait(3000));
    stream.close();
    QTRY_COMPARE(closed.count(), 1);
    QVERIFY(!closed.first().first().value<Error>().isError());
    QCOMPARE(stream.state(), ByteStream::State::Closed);
}

void TestTcpStream::writeWhileClosedDoesNothing()
{
    TcpStream stream(QStringLiteral("127.0.0.1"), 1);
    QVERIFY(!stream.write("TP\r"));
}

void TestTcpStream::reopensAfterClose()
{
    QTcpServer server;
    QVERIFY(server.listen(QHostAddress::LocalHost, 0));
    TcpStream stream(QStringLiteral("127.0.0.1"), server.serverPort());
    QSignalSpy opened(&stream, &ByteStream::opened);
    QSignalSpy closed(&stream, &ByteStream::closed);
    stream.open();
    QVERIFY(opened.wait(3000));
    stream.close();
    QTRY_COMPARE(closed.count(), 1);
    stream.open();
    QVERIFY(opened.wait(3000));
    QCOMPARE(opened.count(), 2);
}

QTEST_GUILESS_MAIN(TestTcpStream)
#include "tst_tcpstream.moc"

// A request/response client sends the next request from the previous answer's handler; the
// bytes must leave at once, not one event-loop pass later.
void TestTcpStream::writeIsOnTheWireWhenWriteReturns()
{
    QTcpServer server;
    QVERIFY(server.listen(QHostAddress::LocalHost, 0));
    TcpStream stream(QStringLiteral("127.0.0.1"), server.serverPort());
    QSignalSpy opened(&stream, &ByteStream::opened);
    stream.open();
    QVERIFY(opened.wait(3000));
    QTRY_VERIFY(server.hasPendingConnections());
    QTcpSocket *peer = server.nextPendingConnection();
    QVERIFY(stream.write("OR6041,0\r"));
    // Blocks on the peer's socket only: this thread's event loop does not run meanwhile.
    QVERIFY(peer->waitForReadyRead(2000));
    QCOMPARE(peer->readAll(), QByteArray("OR6041,0\r"));
}

void TestTcpStream::floodArrivesInBoundedChunks()
{
    QTcpServer server;
    QVERIFY(server.listen(QHostAddress::LocalHost, 0));
    TcpStream stream(QStringLiteral("127.0.0.1"), server.serverPort());
    QSignalSpy opened(&stream, &ByteStream::opened);
    QByteArray all;
    qint64 largest = 0;
    connect(&stream, &ByteStream::received, this, [&](const QByteArray &b) {
        all += b;
        largest = qMax(largest, qint64(b.size()));
    });
    stream.open();
    QVERIFY(opened.wait(3000));
    QTRY_VERIFY(server.hasPendingConnections());
    QTcpSocket *peer = server.nextPendingConnection();
    QByteArray flood(5 * TcpStream::kReadBufferBytes, '\0');
    for (qsizetype i = 0; i < flood.size(); ++i)
        flood[i] = char(i * 7);
    peer->write(flood);
    QTRY_COMPARE(all.size(), flood.size());
    QCOMPARE(all, flood);
    QVERIFY(largest <= TcpStream::kReadBufferBytes);
}

namespace {
// A stream connected to a loopback server, and the server's end of the connection.
struct Connected
{
    QTcpServer server;
    std::unique_ptr<TcpStream> stream;
    QTcpSocket *peer = nullptr;

    bool open()
    {
        if (!server.listen(QHostAddress::LocalHost, 0))
            return false;
        stream = std::make_unique<TcpStream>(QStringLiteral("127.0.0.1"), server.serverPort());
        QSignalSpy opened(stream.get(), &ByteStream::opened);
        stream->open();
        if (!opened.wait(3000)
            || (!server.hasPendingConnections() && !server.waitForNewConnection(3000)))
            return false;
        peer = server.nextPendingConnection();
        return peer != nullptr;
    }
};
} // namespace

// Every read is delivered in the same array when nobody keeps it; a receiver that keeps a copy
// must still see its bytes unchanged after later reads.
void TestTcpStream::keptBytesStayAsTheyCame()
{
    Connected link;
    QVERIFY(link.open());
    TcpStream &stream = *link.stream;
    QTcpSocket *peer = link.peer;
    QByteArrayList kept;
    connect(&stream, &ByteStream::received, this, [&kept](const QByteArray &b) { kept += b; });
    const QByteArrayList sent { "OR6041,0,1591\r\n>", "x", "OR6064,0,-120000\r\n>" };
    for (const QByteArray &bytes : sent) {
        const qsizetype before = kept.size();
        peer->write(bytes);
        QTRY_VERIFY(kept.size() > before);
    }
    QCOMPARE(kept.join(), sent.join());
    QCOMPARE(kept, sent);
}

// A peer that does not read fills the kernel's buffers: what the kernel does not take waits in
// the stream and follows in order once the peer reads again.
void TestTcpStream::bytesThePeerCannotTakeYetFollowInOrder()
{
    Connected link;
    QVERIFY(link.open());
    TcpStream &stream = *link.stream;
    QTcpSocket *peer = link.peer;
    peer->setReadBufferSize(1); // reads almost nothing until the test takes the bytes
    QByteArray sent;
    for (int chunk = 0; chunk < 256; ++chunk) {
        QByteArray bytes(32 * 1024, '\0');
        for (qsizetype i = 0; i < bytes.size(); ++i)
            bytes[i] = char(chunk * 31 + i * 7);
        QVERIFY(stream.write(bytes));
        sent += bytes;
    }
    QByteArray got;
    connect(peer, &QTcpSocket::readyRead, this, [&] { got += peer->readAll(); });
    peer->setReadBufferSize(0);
    got += peer->readAll();
    QTRY_COMPARE_WITH_TIMEOUT(got.size(), sent.size(), 10000);
    QCOMPARE(got, sent);
    QVERIFY(stream.isOpen());
}

// A write to a connection the peer has reset does not report from inside write(); the stream
// closes from the event loop, naming the peer.
void TestTcpStream::writeToAResetPeerFailsFromTheLoop()
{
    Connected link;
    QVERIFY(link.open());
    TcpStream &stream = *link.stream;
    QTcpSocket *peer = link.peer;
    QSignalSpy closed(&stream, &ByteStream::closed);
    peer->write("unread by the stream");
    QVERIFY(peer->waitForBytesWritten(1000));
    // A zero linger time makes closing reset the connection.
    const linger reset { 1, 0 };
    QCOMPARE(
        ::setsockopt(int(peer->socketDescriptor()), SOL_SOCKET, SO_LINGER, &reset, sizeof reset),
        0);
    peer->abort();
    for (int i = 0; i < 20 && closed.isEmpty(); ++i) {
        stream.write("OR6041,0\r");
        QCOMPARE(closed.count(), 0); // never from inside write()
        QTest::qWait(10);
    }
    QTRY_COMPARE(closed.count(), 1);
    const Error e = closed.first().first().value<Error>();
    QCOMPARE(e.kind(), Error::Kind::Disconnected);
    QVERIFY2(e.message().contains(QLatin1String("closed the connection")), qPrintable(e.message()));
    QVERIFY(!stream.isOpen());
}

// A receiver that runs an event loop of its own (a dialog, a wait) while more bytes arrive gets
// them delivered meanwhile, and the bytes it is holding do not change under it.
void TestTcpStream::receiverWithItsOwnEventLoopKeepsItsBytes()
{
    Connected link;
    QVERIFY(link.open());
    QTcpSocket *peer = link.peer;
    QByteArrayList seen;
    QByteArray outerAfterLoop;
    connect(link.stream.get(), &ByteStream::received, this, [&](const QByteArray &b) {
        seen += QByteArray(b.constData(), b.size());
        if (seen.size() != 1)
            return;
        peer->write("second");
        QTRY_COMPARE(seen.size(), 2); // an event loop inside the receiver while "second" arrives
        outerAfterLoop = QByteArray(b.constData(), b.size());
    });
    peer->write("first");
    QTRY_VERIFY(!outerAfterLoop.isEmpty());
    QCOMPARE(seen, (QByteArrayList { "first", "second" }));
    QCOMPARE(outerAfterLoop, QByteArray("first"));
}
