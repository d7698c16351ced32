// Level 2: the VABus/TCP client over a scripted stream: expected TX, scripted RX, answers split
// at every byte, error answers, silence, NAK, garbage, wrong echoes, late answers, keep-alive.

#include "scriptedstream.h"
#include "vabus/vabusclient.h"
#include "wait.h"

#include <QSignalSpy>
#include <QtTest>

#include <memory>

using namespace db;
using db::test::await;
using namespace db::vabus;

namespace {

constexpr int kShortTimeoutMs = 60;
constexpr int kWaitMs = 5000;

QByteArray hexBytes(const char *text)
{
    return QByteArray::fromHex(QByteArray(text).replace(' ', ""));
}

} // namespace

class TstVabusClient : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void init()
    {
        m_stream = new test::ScriptedStream;
        m_client = new VabusClient(m_stream);
        m_client->setKeepAliveIdleMs(0);
        m_stream->open();
        QTRY_VERIFY(m_stream->isOpen());
    }
    void cleanup()
    {
        delete m_client;
        delete m_stream;
    }

    void protocolExamplesByteExact_data()
    {
        QTest::addColumn<bool>("write");
        QTest::addColumn<int>("parameter");
        QTest::addColumn<int>("dataSet");
        QTest::addColumn<int>("type");
        QTest::addColumn<QVariant>("value");
        QTest::addColumn<QByteArray>("tx");
        QTest::addColumn<QByteArray>("rx");
        const auto u16 = int(DataType::Unsigned16);
        const auto i32 = int(DataType::Integer32);
        const auto str = int(DataType::VisibleString);
        QTest::newRow("T1/T2 372:2")
            << false << 372 << 2 << u16 << QVariant(qulonglong(1390))
            << hexBytes("00 04 00 02 74 01") << hexBytes("00 06 00 02 74 01 6E 05");
        QTest::newRow("T3/T4 481:1")
            << false << 481 << 1 << i32 << QVariant(qlonglong(1000))
            << hexBytes("00 04 00 01 E1 01") << hexBytes("00 08 00 01 E1 01 E8 03 00 00");
        QTest::newRow("T5/T6 12") << false << 12 << 0 << str
                                  << QVariant(QStringLiteral("5.3.2 STO"))
                                  << hexBytes("00 04 00 00 0C 00")
                                  << hexBytes("00 0D 00 00 0C 00 35 2E 33 2E 32 20 53 54 4F");
        QTest::newRow("T7/T8 376:4")
            << true << 376 << 4 << u16 << QVariant(qulonglong(15))
            << hexBytes("80 06 00 04 78 01 0F 00") << hexBytes("80 06 00 04 78 01 0F 00");
        QTest::newRow("T11/T12 482:9") << true << 482 << 9 << i32 << QVariant(qlonglong(4450))
                                       << hexBytes("80 08 00 09 E2 01 62 11 00 00")
                                       << hexBytes("80 08 00 09 E2 01 62 11 00 00");
    }
    void protocolExamplesByteExact()
    {
        QFETCH(bool, write);
        QFETCH(int, parameter);
        QFETCH(int, dataSet);
        QFETCH(int, type);
        QFETCH(QVariant, value);
        QFETCH(QByteArray, tx);
        QFETCH(QByteArray, rx);
        // Whole, then split at every byte.
        for (const bool split : { false, true }) {
            Reply *reply = write
                ? m_client->write(quint16(parameter), quint8(dataSet), DataType(type), value)
                : m_client->read(quint16(parameter), quint8(dataSet), DataType(type));
            QCOMPARE(m_stream->takeWritten(), tx);
            if (split) {
                for (const char c : rx) {
                    QVERIFY(!reply->isFinished());
                    m_stream->feed(QByteArray(1, c));
                }
            } else {
                m_stream->feed(rx);
            }
            const auto result = await(reply);
            QVERIFY2(result.ok(), qPrintable(result.error().toString()));
            QCOMPARE(result.value(), write ? QVariant() : value);
        }
        QCOMPARE(m_client->pendingCount(), 0);
        QCOMPARE(m_client->bufferedBytes(), 0);
    }

    void readWithoutTypeTakesSizeFromAnswer()
    {
        Reply *reply = m_client->read(481, 1);
        m_stream->feed(hexBytes("00 08 00 01 E1 01 18 FC FF FF"));
        QCOMPARE(await(reply).value(), QVariant(qlonglong(-1000)));
    }

    void emptyStringIsAnAnswerWithoutData()
    {
        Reply *reply = m_client->read(1441, 0, DataType::VisibleString);
        m_stream->feed(hexBytes("00 04 00 00 A1 05"));
        QCOMPARE(await(reply).value(), QVariant(QString()));
        // A word without data is no answer: sent again.
        reply = m_client->read(372, 2, DataType::Unsigned16);
        m_stream->feed(hexBytes("00 04 00 02 74 01"));
        QCOMPARE(m_stream->writes().size(), 3);
        m_stream->feed(hexBytes("00 06 00 02 74 01 6E 05"));
        QVERIFY(await(reply).ok());
    }

    void errorAnswerIsDeviceErrorWithCodeAndText()
    {
        Reply *reply = m_client->write(376, 4, DataType::Unsigned16, qulonglong(0));
        QCOMPARE(m_stream->takeWritten(), hexBytes("80 06 00 04 78 01 00 00"));
        m_stream->feed(hexBytes("C0 06 00 04 78 01 01 00"));
        const auto result = await(reply);
        QCOMPARE(result.error().kind(), Error::Kind::DeviceError);
        QCOMPARE(result.error().deviceCode(), quint32(1));
        QVERIFY2(result.error().message().contains(QLatin1String("invalid parameter value")),
                 qPrintable(result.error().message()));
        QVERIFY(result.error().message().contains(QLatin1String("376:4")));
        QCOMPARE(m_stream->writes().size(), 1); // an error answer is not retransmitted

        reply = m_client->read(1599, 0);
        m_stream->feed(hexBytes("40 06 00 00 3F 06 0B 00"));
        const auto unknown = await(reply);
        QCOMPARE(unknown.error().deviceCode(), quint32(11));
        QVERIFY(unknown.error().message().contains(QLatin1String("unknown parameter")));
    }

    void silenceGivesThreeTransmissionsThenTimeout()
    {
        m_client->setTimeoutMs(kShortTimeoutMs);
        Reply *reply = m_client->read(372, 2);
        const auto result = await(reply);
        QCOMPARE(result.error().kind(), Error::Kind::Timeout);
        QCOMPARE(m_stream->writes().size(), 3);
        for (const QByteArray &w : m_stream->writes())
            QCOMPARE(w, hexBytes("00 04 00 02 74 01"));
    }

    void lateAnswerAfterRetransmissionIsTaken()
    {
        m_client->setTimeoutMs(kShortTimeoutMs);
        Reply *reply = m_client->read(372, 2, DataType::Unsigned16);
        QTRY_COMPARE(m_stream->writes().size(), 2);
        m_stream->feed(hexBytes("00 06 00 02 74 01 6E 05"));
        QCOMPARE(await(reply).value(), QVariant(qulonglong(1390)));
    }

    void nakIsFailedTransmissionAndSentAgainAtOnce()
    {
        Reply *reply = m_client->read(372, 2, DataType::Unsigned16);
        m_stream->feed(QByteArray(1, char(kNak)));
        QCOMPARE(m_stream->writes().size(), 2);
        m_stream->feed(hexBytes("00 06 00 02 74 01 6E 05"));
        QCOMPARE(await(reply).value(), QVariant(qulonglong(1390)));
    }

    void garbageInEveryTransmissionIsMalformed()
    {
        Reply *reply = m_client->read(372, 2, DataType::Unsigned16);
        for (int i = 0; i < 3; ++i) {
            QCOMPARE(m_stream->writes().size(), i + 1);
            m_stream->feed("hello\r\n");
        }
        const auto result = await(reply);
        QCOMPARE(result.error().kind(), Error::Kind::Malformed);
        QVERIFY2(result.error().message().contains(QLatin1String("372:2")),
                 qPrintable(result.error().message()));
        QCOMPARE(m_stream->writes().size(), 3);
        QCOMPARE(m_client->bufferedBytes(), 0);
    }

    void wrongWriteEchoIsSentAgain()
    {
        Reply *reply = m_client->write(376, 4, DataType::Unsigned16, qulonglong(15));
        m_stream->feed(hexBytes("80 06 00 04 78 01 0E 00"));
        QCOMPARE(m_stream->writes().size(), 2);
        m_stream->feed(hexBytes("80 06 00 04 78 01 0F 00"));
        QVERIFY(await(reply).ok());
    }

    void valueOfWrongSizeIsSentAgain()
    {
        Reply *reply = m_client->read(481, 1, DataType::Integer32);
        m_stream->feed(hexBytes("00 06 00 01 E1 01 E8 03"));
        QCOMPARE(m_stream->writes().size(), 2);
        m_stream->feed(hexBytes("00 08 00 01 E1 01 E8 03 00 00"));
        QCOMPARE(await(reply).value(), QVariant(qlonglong(1000)));
    }

    void answerToOtherParameterIsDroppedAndRequestRetried()
    {
        m_client->setTimeoutMs(kShortTimeoutMs);
        QSignalSpy log(m_client, &VabusClient::logLine);
        Reply *reply = m_client->read(372, 2, DataType::Unsigned16);
        m_stream->feed(hexBytes("00 06 00 01 74 01 6E 05")); // data set 1, not 2
        m_stream->feed(hexBytes("80 06 00 02 74 01 6E 05")); // a write answer
        m_stream->feed(hexBytes("00 06 47 02 74 01 6E 05")); // another node
        QVERIFY(!reply->isFinished());
        QTRY_COMPARE(m_stream->writes().size(), 2);
        m_stream->feed(hexBytes("00 06 00 02 74 01 6E 05"));
        QCOMPARE(await(reply).value(), QVariant(qulonglong(1390)));
        bool logged = false;
        for (const auto &args : log)
            logged |= args.at(0).toString().contains(QLatin1String("372:1"));
        QVERIFY(logged);
    }

    void lateAnswerIsNotGivenToNextRequest()
    {
        m_client->setTimeoutMs(kShortTimeoutMs);
        Reply *first = m_client->read(372, 2, DataType::Unsigned16);
        QCOMPARE(await(first).error().kind(), Error::Kind::Timeout);
        // The next request waits out the grace time; answers to the first that come meanwhile
        // are dropped, never given to it.
        Reply *second = m_client->read(372, 2, DataType::Unsigned16);
        QCOMPARE(m_stream->writes().size(), 3);
        for (int i = 0; i < 3; ++i)
            m_stream->feed(hexBytes("00 06 00 02 74 01 01 00"));
        QTRY_COMPARE(m_stream->writes().size(), 4);
        QVERIFY(!second->isFinished());
        m_stream->feed(hexBytes("00 06 00 02 74 01 6E 05"));
        QCOMPARE(await(second).value(), QVariant(qulonglong(1390)));
    }

    // Answers that have not come within the grace time are lost: a device that stayed silent
    // (still starting) and then answers gives the identical next request its answer.
    void silenceThenAnswerGoesToNextRequest()
    {
        m_client->setTimeoutMs(kShortTimeoutMs);
        QCOMPARE(await(m_client->read(12, 0)).error().kind(), Error::Kind::Timeout);
        Reply *again = m_client->read(12, 0);
        QTRY_COMPARE(m_stream->writes().size(), 4);
        m_stream->feed(hexBytes("00 0D 00 00 0C 00 35 2E 33 2E 32 20 53 54 4F"));
        QCOMPARE(await(again).value(), QVariant(QStringLiteral("5.3.2 STO")));
    }

    void partialAnswerIsDroppedWhenTransmissionTimesOut()
    {
        m_client->setTimeoutMs(kShortTimeoutMs);
        Reply *reply = m_client->read(481, 1, DataType::Integer32);
        m_stream->feed(hexBytes("00 08 00 01 E1")); // the rest never comes
        QTRY_COMPARE(m_stream->writes().size(), 2);
        m_stream->feed(hexBytes("00 08 00 01 E1 01 E8 03 00 00"));
        QCOMPARE(await(reply).value(), QVariant(qlonglong(1000)));
    }

    void oneRequestInFlight()
    {
        Reply *a = m_client->read(372, 2, DataType::Unsigned16);
        Reply *b = m_client->read(481, 1, DataType::Integer32);
        QCOMPARE(m_stream->takeWritten(), hexBytes("00 04 00 02 74 01"));
        QCOMPARE(m_client->pendingCount(), 2);
        // Both answers in one segment: the second request goes out after the first answer.
        m_stream->feed(hexBytes("00 06 00 02 74 01 6E 05"));
        QCOMPARE(m_stream->takeWritten(), hexBytes("00 04 00 01 E1 01"));
        m_stream->feed(hexBytes("00 08 00 01 E1 01 E8 03 00 00"));
        QCOMPARE(await(a).value(), QVariant(qulonglong(1390)));
        QCOMPARE(await(b).value(), QVariant(qlonglong(1000)));
    }

    void keepAliveReadsStatusWordWhenIdle()
    {
        m_client->setKeepAliveIdleMs(80);
        QTRY_COMPARE_WITH_TIMEOUT(m_stream->writes().size(), 1, kWaitMs);
        QCOMPARE(m_stream->takeWritten(), hexBytes("00 04 00 00 9B 01"));
        m_stream->feed(hexBytes("00 06 00 00 9B 01 37 02"));
        // The next one comes after the next idle time, and a user request is never delayed.
        Reply *reply = m_client->read(372, 2, DataType::Unsigned16);
        QCOMPARE(m_stream->takeWritten(), hexBytes("00 04 00 02 74 01"));
        m_stream->feed(hexBytes("00 06 00 02 74 01 6E 05"));
        QVERIFY(await(reply).ok());
        QTRY_COMPARE_WITH_TIMEOUT(m_stream->writes().size(), 3, kWaitMs);
        QCOMPARE(m_stream->takeWritten(), hexBytes("00 04 00 00 9B 01"));
        QVERIFY(VabusClient::kDefaultKeepAliveIdleMs * 3 < VabusClient::kWatchdogMs);
    }

    void keepAliveUsesSys()
    {
        m_client->setSys(0x47);
        m_client->setKeepAliveIdleMs(50);
        QTRY_COMPARE_WITH_TIMEOUT(m_stream->writes().size(), 1, kWaitMs);
        QCOMPARE(m_stream->takeWritten(), hexBytes("00 04 47 00 9B 01"));
    }

    void refusedBeforeSending()
    {
        QCOMPARE(await(m_client->read(372, 5)).error().kind(), Error::Kind::InvalidArgument);
        QCOMPARE(await(m_client->writeData(372, 10, "ab")).error().kind(),
                 Error::Kind::InvalidArgument);
        QCOMPARE(await(m_client->read(1600, 0)).error().kind(), Error::Kind::InvalidArgument);
        QCOMPARE(
            await(m_client->write(376, 4, DataType::Unsigned16, qlonglong(70000))).error().kind(),
            Error::Kind::OutOfRange);
        QCOMPARE(await(m_client->read(12, 0, DataType::Real32)).error().kind(),
                 Error::Kind::NotSupported);
        QVERIFY(m_stream->writes().isEmpty());
    }

    void disconnectFailsPending()
    {
        Reply *reply = m_client->read(372, 2);
        m_stream->drop(Error(Error::Kind::Disconnected, QStringLiteral("peer closed")));
        QCOMPARE(await(reply).error().kind(), Error::Kind::Disconnected);
        QCOMPARE(await(m_client->read(372, 2)).error().kind(), Error::Kind::Disconnected);
    }

private:
    test::ScriptedStream *m_stream = nullptr;
    VabusClient *m_client = nullptr;
};

QTEST_GUILESS_MAIN(TstVabusClient)
#include "tst_vabusclient.moc"
