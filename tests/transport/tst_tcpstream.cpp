// TcpStream against real loopback sockets: open, bytes both ways, refusals and lost links that
// name the address, clean close.
#include "transport/tcpstream.h"

#include <QSignalSpy>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTest>

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
