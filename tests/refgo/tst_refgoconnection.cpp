// Level 2: RefgoConnection over a scripted stream: OR/OW with type conversion, missing ",OK",
// unsupported types, raw commands, store, connect errors, lost link, auto-reconnect.

#include "objectdefs.h"
#include "parameters/parameterrunner.h"
#include "refgo/refgoconnection.h"
#include "scriptedstream.h"
#include "wait.h"

#include <QtTest>

using namespace db;
using namespace db::refgo;

namespace {

constexpr int kWaitMs = 5000;

ObjectDictionary dictionary()
{
    ObjectDictionary dict;
    dict.insert(test::namedObjectDef(0x3511, 0x08, DataType::Integer32, Access::ReadWrite,
                                     QStringLiteral("IN1 target position")));
    dict.insert(test::namedObjectDef(0x6041, 0x00, DataType::Unsigned16, Access::ReadWrite,
                                     QStringLiteral("Statusword")));
    dict.insert(test::namedObjectDef(0x6078, 0x00, DataType::Integer16, Access::ReadWrite,
                                     QStringLiteral("Current actual value")));
    dict.insert(test::namedObjectDef(0x60FD, 0x00, DataType::Unsigned32, Access::ReadWrite,
                                     QStringLiteral("Digital inputs")));
    dict.insert(test::namedObjectDef(0x1003, 0x01, DataType::Unsigned32, Access::ReadWrite,
                                     QStringLiteral("Error history 1")));
    dict.insert(test::namedObjectDef(0x2001, 0x00, DataType::Boolean, Access::ReadWrite,
                                     QStringLiteral("Some flag")));
    dict.insert(test::namedObjectDef(0x2002, 0x00, DataType::Unsigned8, Access::ReadWrite,
                                     QStringLiteral("Small")));
    dict.insert(test::namedObjectDef(0x1010, 0x01, DataType::Unsigned32, Access::ReadWrite,
                                     QStringLiteral("Save all parameters")));
    dict.insert(test::namedObjectDef(0x1008, 0x00, DataType::VisibleString, Access::ReadWrite,
                                     QStringLiteral("Device name")));
    dict.insert(test::namedObjectDef(0x2003, 0x00, DataType::Real32, Access::ReadWrite,
                                     QStringLiteral("Gain")));
    dict.insert(test::namedObjectDef(0x2004, 0x00, DataType::Domain, Access::ReadWrite,
                                     QStringLiteral("Blob")));
    dict.insert(test::namedObjectDef(0x2005, 0x00, DataType::OctetString, Access::ReadWrite,
                                     QStringLiteral("Bytes")));
    return dict;
}

} // namespace

class TstRefgoConnection : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void init();
    void cleanup();

    void identity();
    void readConvertsToDictionaryType_data();
    void readConvertsToDictionaryType();
    void readValueOutOfTypeRangeFails();
    void writeSendsOwAndSucceedsOnOk();
    void writeWithoutOkIsDeviceError();
    void deletedReadIsWithdrawnButDeletedWriteIsSent();
    void unsupportedTypesAreRefusedWithoutTraffic_data();
    void unsupportedTypesAreRefusedWithoutTraffic();
    void storeParametersWritesSaveSignature();
    void commandReturnsResultLines();
    void requestTimeoutOfConnectionApplies();
    void logLinesReachTheConsole();
    void refusedConnectGoesThroughDisconnected();
    void lostLinkFailsPendingRead();
    void autoReconnectAfterLostLink();
    void closeWhileWaitingToReconnectStopsIt();
    void closeEndsDisconnectedWithoutError();

private:
    void connectNow();

    test::ScriptedStream *m_stream = nullptr;
    RefgoConnection *m_connection = nullptr;
};

void TstRefgoConnection::init()
{
    m_stream = new test::ScriptedStream;
    m_connection = new RefgoConnection(
        ConnectionUri::parse(QStringLiteral("refgo://127.0.0.1")).value(), m_stream);
    m_connection->setDictionary(dictionary());
}

void TstRefgoConnection::cleanup()
{
    delete m_connection;
    delete m_stream;
}

void TstRefgoConnection::connectNow()
{
    m_connection->open();
    QTRY_COMPARE(m_connection->state(), DeviceConnection::State::Connected);
}

void TstRefgoConnection::identity()
{
    QCOMPARE(m_connection->protocolKey(), QStringLiteral("refgo"));
    QVERIFY(m_connection->capabilities().testFlag(DeviceConnection::Capability::RawCommands));
    QVERIFY(m_connection->capabilities().testFlag(DeviceConnection::Capability::StoreNonVolatile));
    QVERIFY(m_connection->client());
}

void TstRefgoConnection::readConvertsToDictionaryType_data()
{
    QTest::addColumn<int>("index");
    QTest::addColumn<int>("sub");
    QTest::addColumn<QByteArray>("tx");
    QTest::addColumn<QByteArray>("resultLine");
    QTest::addColumn<QVariant>("expected");
    QTest::newRow("docklight INTEGER32") << 0x3511 << 8 << QByteArray("OR3511,8")
                                         << QByteArray("OR3511,8,110") << QVariant(qlonglong(110));
    QTest::newRow("UNSIGNED16 decimal")
        << 0x6041 << 0 << QByteArray("OR6041,0") << QByteArray("OR6041,0,1063")
        << QVariant(qulonglong(1063));
    QTest::newRow("erratum 14 hex answer")
        << 0x6041 << 0 << QByteArray("OR6041,0") << QByteArray("OR6041,0,427h")
        << QVariant(qulonglong(0x427));
    QTest::newRow("INTEGER16 negative") << 0x6078 << 0 << QByteArray("OR6078,0")
                                        << QByteArray("OR6078,0,-103") << QVariant(qlonglong(-103));
    QTest::newRow("INTEGER16 hex bit pattern")
        << 0x6078 << 0 << QByteArray("OR6078,0") << QByteArray("OR6078,0,FF99h")
        << QVariant(qlonglong(-103));
    QTest::newRow("UNSIGNED32 printed signed")
        << 0x60FD << 0 << QByteArray("OR60FD,0") << QByteArray("OR60FD,0,-2147483648")
        << QVariant(qulonglong(0x80000000));
    QTest::newRow("error history hex")
        << 0x1003 << 1 << QByteArray("OR1003,1") << QByteArray("OR1003,1,3221h")
        << QVariant(qulonglong(0x3221));
    QTest::newRow("BOOLEAN") << 0x2001 << 0 << QByteArray("OR2001,0") << QByteArray("OR2001,0,1")
                             << QVariant(true);
    QTest::newRow("unknown object is qlonglong")
        << 0x2100 << 3 << QByteArray("OR2100,3") << QByteArray("OR2100,3,42")
        << QVariant(qlonglong(42));
}

void TstRefgoConnection::readConvertsToDictionaryType()
{
    QFETCH(int, index);
    QFETCH(int, sub);
    QFETCH(QByteArray, tx);
    QFETCH(QByteArray, resultLine);
    QFETCH(QVariant, expected);
    connectNow();
    Reply *reply = m_connection->read(ObjectAddress(quint16(index), quint8(sub)));
    QCOMPARE(m_stream->takeWritten(), tx + '\r');
    m_stream->feed(tx + "\r\n" + resultLine + "\r\n>");
    const auto r = test::await(reply, kWaitMs);
    QVERIFY2(r.ok(), qPrintable(r.error().toString()));
    QCOMPARE(r.value().typeId(), expected.typeId());
    QCOMPARE(r.value(), expected);
}

void TstRefgoConnection::readValueOutOfTypeRangeFails()
{
    connectNow();
    Reply *reply = m_connection->read({ 0x2002, 0 });
    m_stream->feed("OR2002,0\r\nOR2002,0,300\r\n>");
    const auto r = test::await(reply, kWaitMs);
    QCOMPARE(r.error().kind(), Error::Kind::OutOfRange);
    QVERIFY(r.error().message().contains(QLatin1String("2002")));
}

void TstRefgoConnection::writeSendsOwAndSucceedsOnOk()
{
    connectNow();
    Reply *reply = m_connection->write({ 0x3511, 8 }, qlonglong(120));
    QCOMPARE(m_stream->takeWritten(), QByteArray("OW3511,8,120\r"));
    m_stream->feed("OW3511,8,120\r\nOW3511,8,120,OK\r\n>");
    QVERIFY(test::await(reply, kWaitMs).ok());

    reply = m_connection->write({ 0x6041, 0 }, 0x80); // int normalised to UNSIGNED16
    QCOMPARE(m_stream->takeWritten(), QByteArray("OW6041,0,128\r"));
    m_stream->feed("OW6041,0,128\r\nOW6041,0,128,OK\r\n>");
    QVERIFY(test::await(reply, kWaitMs).ok());
}

void TstRefgoConnection::writeWithoutOkIsDeviceError()
{
    connectNow();
    Reply *reply = m_connection->write({ 0x3511, 8 }, qlonglong(120));
    m_stream->feed("OW3511,8,120\r\nOW3511,8,120\r\n>");
    QCOMPARE(test::await(reply, kWaitMs).error().kind(), Error::Kind::DeviceError);
}

void TstRefgoConnection::unsupportedTypesAreRefusedWithoutTraffic_data()
{
    QTest::addColumn<int>("index");
    QTest::addColumn<QVariant>("value");
    QTest::newRow("VISIBLE_STRING") << 0x1008 << QVariant(QStringLiteral("drive"));
    QTest::newRow("REAL32") << 0x2003 << QVariant(1.5);
    QTest::newRow("DOMAIN") << 0x2004 << QVariant(QByteArray("\x01\x02"));
    QTest::newRow("OCTET_STRING") << 0x2005 << QVariant(QByteArray("\x01"));
}

void TstRefgoConnection::unsupportedTypesAreRefusedWithoutTraffic()
{
    QFETCH(int, index);
    QFETCH(QVariant, value);
    connectNow();
    const ObjectAddress address(quint16(index), 0);
    const auto read = test::await(m_connection->read(address), kWaitMs);
    QCOMPARE(read.error().kind(), Error::Kind::NotSupported);
    QVERIFY(read.error().message().contains(QLatin1String("integers only")));
    const auto write = test::await(m_connection->write(address, value), kWaitMs);
    QCOMPARE(write.error().kind(), Error::Kind::NotSupported);
    QVERIFY(m_stream->takeWritten().isEmpty());
}

void TstRefgoConnection::storeParametersWritesSaveSignature()
{
    connectNow();
    Reply *reply = m_connection->storeNonVolatile(); // OW1010,1,"save"
    QCOMPARE(m_stream->takeWritten(), QByteArray("OW1010,1,1702257011\r"));
    m_stream->feed("OW1010,1,1702257011\r\nOW1010,1,1702257011,OK\r\n>");
    QVERIFY(test::await(reply, kWaitMs).ok());
}

void TstRefgoConnection::commandReturnsResultLines()
{
    QCOMPARE(test::await(m_connection->command(QStringLiteral("TP")), kWaitMs).error().kind(),
             Error::Kind::Disconnected);
    connectNow();
    Reply *reply = m_connection->command(QStringLiteral("TP"));
    QCOMPARE(m_stream->takeWritten(), QByteArray("TP\r"));
    m_stream->feed("TP\r\n-3658\r\n>");
    QCOMPARE(test::await(reply, kWaitMs).value().toStringList(), QStringList { "-3658" });
}

void TstRefgoConnection::requestTimeoutOfConnectionApplies()
{
    connectNow();
    m_connection->setRequestTimeoutMs(50);
    const auto r = test::await(m_connection->read({ 0x6041, 0 }), kWaitMs);
    QCOMPARE(r.error().kind(), Error::Kind::Timeout);
    QVERIFY(r.error().message().contains(QLatin1String("50 ms")));
}

// A requester that stops waiting for a queued read withdraws it (the drive is not asked); a
// write whose reply is deleted still goes out (a halt from a closing panel must reach it).
void TstRefgoConnection::deletedReadIsWithdrawnButDeletedWriteIsSent()
{
    connectNow();
    Reply *first = m_connection->read({ 0x3511, 8 });
    delete m_connection->read({ 0x6041, 0 });
    delete m_connection->write({ 0x3511, 8 }, qlonglong(5));
    Reply *last = m_connection->read({ 0x6078, 0 });
    QCOMPARE(m_stream->takeWritten(), QByteArray("OR3511,8\r"));
    m_stream->feed("OR3511,8\r\nOR3511,8,110\r\n>");
    QCOMPARE(m_stream->takeWritten(), QByteArray("OW3511,8,5\r"));
    m_stream->feed("OW3511,8,5\r\nOW3511,8,5,OK\r\n>");
    QCOMPARE(m_stream->takeWritten(), QByteArray("OR6078,0\r"));
    m_stream->feed("OR6078,0\r\nOR6078,0,-3\r\n>");
    QCOMPARE(test::await(first, kWaitMs).value(), QVariant::fromValue<qlonglong>(110));
    QCOMPARE(test::await(last, kWaitMs).value(), QVariant::fromValue<qlonglong>(-3));
}

void TstRefgoConnection::logLinesReachTheConsole()
{
    QSignalSpy log(m_connection, &DeviceConnection::logLine);
    connectNow();
    Reply *reply = m_connection->read({ 0x3511, 8 });
    m_stream->feed("OR3511,8\r\nOR3511,8,110\r\n>");
    QVERIFY(test::await(reply, kWaitMs).ok());
    QStringList lines;
    for (const auto &args : log)
        lines << args.at(0).toString();
    QVERIFY2(lines.contains(QStringLiteral("> OR3511,8")), qPrintable(lines.join('|')));
    QVERIFY(lines.contains(QStringLiteral("< OR3511,8,110")));
}

void TstRefgoConnection::refusedConnectGoesThroughDisconnected()
{
    QSignalSpy errors(m_connection, &DeviceConnection::errorOccurred);
    const Error refused(Error::Kind::ConnectionRefused, QStringLiteral("scripted:0 refused"));
    m_stream->refuseNextOpen(refused);
    m_connection->open();
    QCOMPARE(m_connection->state(), DeviceConnection::State::Connecting);
    QTRY_COMPARE(m_connection->state(), DeviceConnection::State::Disconnected);
    QCOMPARE(m_connection->lastError(), refused);
    QCOMPARE(errors.size(), 1);
}

void TstRefgoConnection::lostLinkFailsPendingRead()
{
    connectNow();
    Reply *reply = m_connection->read({ 0x6041, 0 });
    const Error lost(Error::Kind::Disconnected, QStringLiteral("scripted:0 reset"));
    m_stream->drop(lost);
    QCOMPARE(test::await(reply, kWaitMs).error(), lost);
    QCOMPARE(m_connection->state(), DeviceConnection::State::Disconnected);
    QCOMPARE(m_connection->lastError(), lost);
}

void TstRefgoConnection::autoReconnectAfterLostLink()
{
    m_connection->setAutoReconnect(true, 10);
    QVERIFY(m_connection->autoReconnect());
    connectNow();
    QSignalSpy states(m_connection, &DeviceConnection::stateChanged);
    m_stream->drop(Error(Error::Kind::Disconnected, QStringLiteral("gone")));
    QCOMPARE(m_connection->state(), DeviceConnection::State::Disconnected);
    QVERIFY(m_connection->isReconnectScheduled());
    QTRY_COMPARE(m_connection->state(), DeviceConnection::State::Connected);
    QVERIFY(states.size() >= 3); // Disconnected, Connecting, Connected
}

void TstRefgoConnection::closeWhileWaitingToReconnectStopsIt()
{
    m_connection->setAutoReconnect(true, 60000);
    connectNow();
    m_stream->drop(Error(Error::Kind::Disconnected, QStringLiteral("gone")));
    QVERIFY(m_connection->isReconnectScheduled());
    m_connection->close();
    QVERIFY(!m_connection->isReconnectScheduled());
    QCOMPARE(m_connection->state(), DeviceConnection::State::Disconnected);
}

void TstRefgoConnection::closeEndsDisconnectedWithoutError()
{
    m_connection->setAutoReconnect(true, 10);
    connectNow();
    QSignalSpy errors(m_connection, &DeviceConnection::errorOccurred);
    m_connection->close();
    QTRY_COMPARE(m_connection->state(), DeviceConnection::State::Disconnected);
    QCOMPARE(errors.size(), 0);
    QVERIFY(!m_connection->isReconnectScheduled()); // no reconnect after a user's close
}

QTEST_GUILESS_MAIN(TstRefgoConnection)
#include "tst_refgoconnection.moc"
