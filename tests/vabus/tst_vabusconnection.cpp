// Level 2: VabusConnection over a scripted stream: parameter addresses, physical values with
// the parameter's decimals, RAM data sets, system bus nodes, error answers.

#include "scriptedstream.h"
#include "vabus/vabusconnection.h"
#include "wait.h"

#include <QSignalSpy>
#include <QtTest>

#include <algorithm>
#include <memory>

using namespace db;
using db::test::await;
using namespace db::vabus;

namespace {

QByteArray hexBytes(const char *text)
{
    return QByteArray::fromHex(QByteArray(text).replace(' ', ""));
}

ObjectDef parameter(quint16 number, quint8 dataSet, DataType type, int decimals,
                    const QString &unit)
{
    ObjectDef def;
    def.address = ObjectAddress(number, dataSet);
    def.name = QStringLiteral("P%1").arg(number);
    def.type = type;
    def.decimals = decimals;
    def.factor = std::pow(10.0, -decimals);
    def.unit = unit;
    return def;
}

ObjectDictionary dictionary()
{
    ObjectDictionary d;
    for (quint8 ds = 0; ds <= 4; ++ds) {
        d.insert(parameter(481, ds, DataType::Integer32, 2, QStringLiteral("Hz")));
        d.insert(parameter(482, ds, DataType::Integer32, 2, QStringLiteral("Hz")));
        d.insert(parameter(376, ds, DataType::Unsigned16, 1, QStringLiteral("kW")));
    }
    ObjectDef status = parameter(411, 0, DataType::Unsigned16, 0, {});
    status.access = Access::ReadOnly;
    d.insert(status);
    return d;
}

} // namespace

class TstVabusConnection : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void init() { open(QStringLiteral("vabus://127.0.0.1")); }
    void cleanup()
    {
        delete m_connection;
        delete m_stream;
    }

    void addressesAreParameterAndDataSet()
    {
        QCOMPARE(m_connection->addressFormat().key(), QStringLiteral("parameter"));
        QCOMPARE(m_connection->protocolKey(), QStringLiteral("vabus"));
        QCOMPARE(m_connection->addressFormat().parse(QStringLiteral("372:2")).value(),
                 ObjectAddress(372, 2));
    }

    void readShowsPhysicalValueWithDecimalsAndUnit()
    {
        Reply *reply = m_connection->read(ObjectAddress(481, 1));
        QCOMPARE(m_stream->takeWritten(), hexBytes("00 04 00 01 E1 01"));
        m_stream->feed(hexBytes("00 08 00 01 E1 01 E8 03 00 00"));
        const auto value = await(reply);
        QVERIFY2(value.ok(), qPrintable(value.error().toString()));
        const ObjectDef *def = m_connection->dictionary().find(ObjectAddress(481, 1));
        QCOMPARE(def->displayText(value.value()), QStringLiteral("10.00 Hz"));
    }

    void writeTakesPhysicalValue()
    {
        const ObjectDef *def = m_connection->dictionary().find(ObjectAddress(481, 1));
        const auto raw = def->parseText(QStringLiteral("10.5"));
        QVERIFY(raw.ok());
        Reply *reply = m_connection->write(ObjectAddress(481, 1), raw.value());
        QCOMPARE(m_stream->takeWritten(), hexBytes("80 08 00 01 E1 01 1A 04 00 00")); // 1050
        m_stream->feed(hexBytes("80 08 00 01 E1 01 1A 04 00 00"));
        QVERIFY(await(reply).ok());

        const ObjectDef *power = m_connection->dictionary().find(ObjectAddress(376, 4));
        Reply *t7 = m_connection->write(ObjectAddress(376, 4),
                                        power->parseText(QStringLiteral("1.5")).value());
        QCOMPARE(m_stream->takeWritten(), hexBytes("80 06 00 04 78 01 0F 00"));
        m_stream->feed(hexBytes("80 06 00 04 78 01 0F 00"));
        QVERIFY(await(t7).ok());
        QVERIFY(!power->parseText(QStringLiteral("1.55")).ok());
        QVERIFY(!power->parseText(QStringLiteral("fast")).ok());
    }

    void refusedValueNamesCodeAndText()
    {
        Reply *reply = m_connection->write(ObjectAddress(376, 4), qulonglong(0));
        QCOMPARE(m_stream->takeWritten(), hexBytes("80 06 00 04 78 01 00 00"));
        m_stream->feed(hexBytes("C0 06 00 04 78 01 01 00"));
        const auto result = await(reply);
        QCOMPARE(result.error().kind(), Error::Kind::DeviceError);
        QCOMPARE(result.error().deviceCode(), quint32(1));
        QVERIFY(result.error().message().contains(QLatin1String("invalid parameter value")));
    }

    void ramDataSetUsesEepromDescription()
    {
        // T11: 44.50 Hz to the RAM copy of data set 4.
        Reply *reply = m_connection->write(ObjectAddress(482, 9), qlonglong(4450));
        QCOMPARE(m_stream->takeWritten(), hexBytes("80 08 00 09 E2 01 62 11 00 00"));
        m_stream->feed(hexBytes("80 08 00 09 E2 01 62 11 00 00"));
        QVERIFY(await(reply).ok());
        // Checked against 482's type before anything is sent.
        QCOMPARE(
            await(m_connection->write(ObjectAddress(482, 9), QStringLiteral("x"))).error().kind(),
            Error::Kind::InvalidArgument);
        QVERIFY(m_stream->takeWritten().isEmpty());
    }

    void ramQueryWritesRamCopies()
    {
        cleanup();
        open(QStringLiteral("vabus://127.0.0.1?ram"));
        QVERIFY(m_connection->writesToRam());
        Reply *reply = m_connection->write(ObjectAddress(482, 4), qlonglong(4450));
        QCOMPARE(m_stream->takeWritten(), hexBytes("80 08 00 09 E2 01 62 11 00 00"));
        m_stream->feed(hexBytes("80 08 00 09 E2 01 62 11 00 00"));
        QVERIFY(await(reply).ok());
        // Reads are not redirected.
        Reply *read = m_connection->read(ObjectAddress(482, 4));
        QCOMPARE(m_stream->takeWritten(), hexBytes("00 04 00 04 E2 01"));
        m_stream->feed(hexBytes("00 08 00 04 E2 01 62 11 00 00"));
        QCOMPARE(await(read).value(), QVariant(qlonglong(4450)));
    }

    void sysQueryAddressesSystemBusSlave()
    {
        cleanup();
        open(QStringLiteral("vabus://127.0.0.1?sys=7"));
        Reply *reply = m_connection->read(ObjectAddress(12, 0));
        QCOMPARE(m_stream->takeWritten(), hexBytes("00 04 47 00 0C 00"));
        m_stream->feed(hexBytes("40 06 47 00 0C 00 14 00"));
        const auto result = await(reply);
        QCOMPARE(result.error().deviceCode(), quint32(20));
        QVERIFY(!VabusConnection::checkUri(
                     ConnectionUri::parse(QStringLiteral("vabus://h?sys=64")).value())
                     .ok());
        QVERIFY(VabusConnection::checkUri(
                    ConnectionUri::parse(QStringLiteral("vabus://h?sys=0")).value())
                    .ok());
    }

    void readOnlyParameterIsNotSent()
    {
        QCOMPARE(await(m_connection->write(ObjectAddress(411, 0), qulonglong(1))).error().kind(),
                 Error::Kind::AccessDenied);
        QVERIFY(m_stream->takeWritten().isEmpty());
    }

    void unknownParameterIsReadBySize()
    {
        Reply *reply = m_connection->read(ObjectAddress(12, 0));
        m_stream->feed(hexBytes("00 0D 00 00 0C 00 35 2E 33 2E 32 20 53 54 4F"));
        QCOMPARE(await(reply).value(), QVariant(QStringLiteral("5.3.2 STO")));
        QCOMPARE(await(m_connection->write(ObjectAddress(999, 0), qlonglong(1))).error().kind(),
                 Error::Kind::NotSupported);
    }

    // The stream connection the VABus and RefGo connections share: the connected line says
    // what the inverter does without traffic, a lost link is reported with its cause and,
    // when asked for, reconnected; a user's close() stops that.
    void lostLinkIsReportedAndReconnected()
    {
        QSignalSpy lines(m_connection, &DeviceConnection::logLine);
        m_connection->setAutoReconnect(true, 10);
        const Error lost(Error::Kind::Disconnected, QStringLiteral("scripted:0 reset"));
        m_stream->drop(lost);
        QCOMPARE(m_connection->state(), DeviceConnection::State::Disconnected);
        QCOMPARE(m_connection->lastError(), lost);
        QVERIFY(m_connection->isReconnectScheduled());
        QVERIFY(test::waitUntil(m_connection, &DeviceConnection::stateChanged,
                                [this] { return m_connection->isConnected(); }));
        QVERIFY(std::any_of(lines.begin(), lines.end(), [](const QList<QVariant> &l) {
            return l.at(0).toString().contains(QLatin1String("parameter 388"));
        }));
        m_stream->drop(lost);
        m_connection->close();
        QVERIFY(!m_connection->isReconnectScheduled());
    }

private:
    void open(const QString &uriText)
    {
        m_stream = new test::ScriptedStream;
        m_connection = new VabusConnection(ConnectionUri::parse(uriText).value(), m_stream);
        m_connection->client()->setKeepAliveIdleMs(0);
        m_connection->setDictionary(dictionary());
        QVERIFY(m_connection->openAndWait(2000).ok());
    }

    test::ScriptedStream *m_stream = nullptr;
    VabusConnection *m_connection = nullptr;
};

QTEST_GUILESS_MAIN(TstVabusConnection)
#include "tst_vabusconnection.moc"
