// Level 2: the RefGo engine over a scripted stream: expected TX, scripted RX (movingcap.md 3.8),
// split answers, timeouts, late answers, garbage, wrong echoes, disconnects.

#include "refgo/refgoclient.h"
#include "scriptedstream.h"
#include "wait.h"

#include <QtTest>

#include <functional>

using namespace db;
using namespace db::refgo;

namespace {

constexpr int kShortTimeoutMs = 50;
constexpr int kWaitMs = 5000;

struct Row
{
    std::function<Reply *(RefgoClient &)> call;
    QByteArray tx;
    QByteArray rx;
    QVariant value;
};

// movingcap.md 3.8 rows 1-14, byte for byte, through the typed calls.
QList<Row> docklightRows()
{
    const ObjectAddress obj(0x3511, 0x08);
    return {
        { [](RefgoClient &c) { return c.reference(35); }, "REF35\r", "REF35\r\n>", {} },
        { [](RefgoClient &c) { return c.speed(720); }, "SP720\r", "SP720\r\n>", {} },
        { [](RefgoClient &c) { return c.acceleration(5000); }, "AC5000\r", "AC5000\r\n>", {} },
        { [](RefgoClient &c) { return c.deceleration(1000); }, "DE1000\r", "DE1000\r\n>", {} },
        { [](RefgoClient &c) { return c.go(360); }, "G360\r", "G360\r\n>", {} },
        { [](RefgoClient &c) { return c.go(-7200); }, "G-7200\r", "G-7200\r\n>", {} },
        { [](RefgoClient &c) { return c.tellProcessStatus(); }, "TPSR\r", "TPSR\r\n00000006\r\n>",
          QVariant::fromValue<quint32>(0x6) },
        { [](RefgoClient &c) { return c.tellPosition(); }, "TP\r", "TP\r\n-3658\r\n>",
          QVariant(qlonglong(-3658)) },
        { [](RefgoClient &c) { return c.tellProcessStatus(); }, "TPSR\r", "TPSR\r\n0000000a\r\n>",
          QVariant::fromValue<quint32>(0xA) },
        { [](RefgoClient &c) { return c.tellPosition(); }, "TP\r", "TP\r\n-7200\r\n>",
          QVariant(qlonglong(-7200)) },
        { [](RefgoClient &c) { return c.powerQuit(); }, "PQ\r", "PQ\r\n>", {} },
        { [obj](RefgoClient &c) { return c.objectRead(obj); }, "OR3511,8\r",
          "OR3511,8\r\nOR3511,8,110\r\n>", QVariant(qlonglong(110)) },
        { [obj](RefgoClient &c) { return c.objectWrite(obj, qlonglong(120)); },
          "OW3511,8,120\r",
          "OW3511,8,120\r\nOW3511,8,120,OK\r\n>",
          {} },
        { [obj](RefgoClient &c) { return c.objectRead(obj); }, "OR3511,8\r",
          "OR3511,8\r\nOR3511,8,120\r\n>", QVariant(qlonglong(120)) },
    };
}

} // namespace

class TstRefgoClient : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void init();
    void cleanup();

    void docklightTranscriptByteExact();
    void docklightTranscriptAsRawCommands();
    void docklightAnswersSplitAtEveryByte();
    void typedCallsSendEveryCommand_data();
    void typedCallsSendEveryCommand();
    void tellInputAndTellStatusValues();
    void objectReadHexOutput();
    void onlyOneCommandInFlight();
    void silenceTimesOutAndNextCommandIsSent();
    void lateAnswerAfterTimeoutIsDroppedNotGivenToNextRequest();
    void lateAnswerToSameCommandTextIsDropped();
    void unansweredTimedOutCommandDoesNotSwallowNextAnswer();
    void drivePolledInTurnAnswersAgainAfterASilence();
    void garbageAnswerIsMalformed();
    void mismatchedEchoIsMalformedNamingBothTexts();
    void unsolicitedAnswerIsDropped();
    void oversizeAnswerFailsRequest();
    void deviceErrorLineIsDeviceError_data();
    void deviceErrorLineIsDeviceError();
    void objectWriteWithoutOkIsDeviceError_data();
    void objectWriteWithoutOkIsDeviceError();
    void objectReadWithoutValueIsDeviceError_data();
    void objectReadWithoutValueIsDeviceError();
    void objectReadAnswerForOtherObjectIsMalformed();
    void objectReadWithBrokenNumberIsMalformed_data();
    void objectReadWithBrokenNumberIsMalformed();
    void objectWriteOfTextIsRefused();
    void disconnectFailsPendingWithCloseError();
    void requestWhileClosedFailsAtOnce();
    void rawCommandWithLineBreakIsRefused_data();
    void rawCommandWithLineBreakIsRefused();
    void badArgumentsAreRefused();
    void deletedQueuedReplyIsSkipped();
    void logLinesShowRequestAndAnswer();

private:
    test::ScriptedStream *m_stream = nullptr;
    RefgoClient *m_client = nullptr;
};

void TstRefgoClient::init()
{
    m_stream = new test::ScriptedStream;
    m_client = new RefgoClient(m_stream);
    m_stream->open();
    QTRY_VERIFY(m_stream->isOpen());
}

void TstRefgoClient::cleanup()
{
    delete m_client;
    delete m_stream;
}

void TstRefgoClient::docklightTranscriptByteExact()
{
    for (const Row &row : docklightRows()) {
        Reply *reply = row.call(*m_client);
        QCOMPARE(m_stream->takeWritten(), row.tx);
        m_stream->feed(row.rx);
        const auto result = test::await(reply, kWaitMs);
        QVERIFY2(result.ok(), qPrintable(result.error().toString()));
        QCOMPARE(result.value(), row.value);
    }
    QCOMPARE(m_client->pendingCount(), 0);
}

void TstRefgoClient::docklightTranscriptAsRawCommands()
{
    for (const Row &row : docklightRows()) {
        Reply *reply = m_client->execute(QString::fromLatin1(row.tx.chopped(1)));
        QCOMPARE(m_stream->takeWritten(), row.tx);
        m_stream->feed(row.rx);
        const auto result = test::await(reply, kWaitMs);
        QVERIFY(result.ok());
        QStringList expected = QString::fromLatin1(row.rx).split(QStringLiteral("\r\n"));
        expected.removeFirst(); // echo
        expected.removeLast(); // prompt
        QCOMPARE(result.value().toStringList(), expected);
    }
}

void TstRefgoClient::docklightAnswersSplitAtEveryByte()
{
    for (const Row &row : docklightRows()) {
        Reply *reply = row.call(*m_client);
        QCOMPARE(m_stream->takeWritten(), row.tx);
        for (char c : row.rx)
            m_stream->feed(QByteArray(1, c));
        const auto result = test::await(reply, kWaitMs);
        QVERIFY(result.ok());
        QCOMPARE(result.value(), row.value);
    }
}

void TstRefgoClient::typedCallsSendEveryCommand_data()
{
    QTest::addColumn<int>("which");
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("result");
    const char *rows[][2] = {
        { "G", "" },
        { "G10000", "" },
        { "GW", "" },
        { "GW-5000", "" },
        { "PO10000", "" },
        { "WA-5000", "" },
        { "SM", "" },
        { "PWC", "" },
        { "CM", "" },
        { "REF-18", "" },
        { "PQ", "" },
        { "SP500", "" },
        { "AC2000", "" },
        { "DE2000", "" },
        { "ACV100000", "" },
        { "JP", "" },
        { "JP500", "" },
        { "JN", "" },
        { "JN1000", "" },
        { "RR", "" },
        { "RR-10000", "" },
        { "RW2000", "" },
        { "WT5000", "" },
        { "SO2", "" },
        { "CO2", "" },
        { "TI3", "1" },
        { "TS", "2" },
        { "TP", "342344" },
        { "TPSR", "00000106" },
        { "OR6067,0", "OR6067,0,100" },
        { "OW6067,0,100", "OW6067,0,100,OK" },
    };
    int i = 0;
    for (const auto &r : rows)
        QTest::newRow(r[0]) << i++ << QString::fromLatin1(r[0]) << QString::fromLatin1(r[1]);
}

void TstRefgoClient::typedCallsSendEveryCommand()
{
    QFETCH(int, which);
    QFETCH(QString, text);
    QFETCH(QString, result);
    RefgoClient &c = *m_client;
    const std::function<Reply *()> calls[] = {
        [&] { return c.go(); },
        [&] { return c.go(10000); },
        [&] { return c.goWay(); },
        [&] { return c.goWay(-5000); },
        [&] { return c.setTargetPosition(10000); },
        [&] { return c.setWay(-5000); },
        [&] { return c.stopMotion(); },
        [&] { return c.powerContinue(); },
        [&] { return c.continueMotion(); },
        [&] { return c.reference(-18); },
        [&] { return c.powerQuit(); },
        [&] { return c.speed(500); },
        [&] { return c.acceleration(2000); },
        [&] { return c.deceleration(2000); },
        [&] { return c.jerk(100000); },
        [&] { return c.jogPositive(); },
        [&] { return c.jogPositive(500); },
        [&] { return c.jogNegative(); },
        [&] { return c.jogNegative(1000); },
        [&] { return c.repeatReverse(); },
        [&] { return c.repeatReverse(-10000); },
        [&] { return c.repeatWay(2000); },
        [&] { return c.waitRepeat(5000); },
        [&] { return c.setOutput(2); },
        [&] { return c.clearOutput(2); },
        [&] { return c.tellInput(3); },
        [&] { return c.tellStatus(); },
        [&] { return c.tellPosition(); },
        [&] { return c.tellProcessStatus(); },
        [&] {
            return c.objectRead({ 0x6067, 0 });
        },
        [&] {
            return c.objectWrite({ 0x6067, 0 }, 100);
        },
    };
    QCOMPARE(int(std::size(calls)), 31);
    Reply *reply = calls[which]();
    QCOMPARE(m_stream->takeWritten(), text.toLatin1() + '\r');
    QByteArray rx = text.toLatin1() + "\r\n";
    if (!result.isEmpty())
        rx += result.toLatin1() + "\r\n";
    m_stream->feed(rx + '>');
    const auto r = test::await(reply, kWaitMs);
    QVERIFY2(r.ok(), qPrintable(r.error().toString()));
}

void TstRefgoClient::tellInputAndTellStatusValues()
{
    Reply *input = m_client->tellInput(3);
    m_stream->feed("TI3\r\n1\r\n>");
    QCOMPARE(test::await(input, kWaitMs).value(), QVariant(true));
    Reply *status = m_client->tellStatus();
    m_stream->feed("TS\r\n9\r\n>");
    QCOMPARE(test::await(status, kWaitMs).value(), QVariant(9));
}

void TstRefgoClient::objectReadHexOutput()
{
    Reply *reply = m_client->objectRead({ 0x6041, 0 }, true);
    QCOMPARE(reply->address(), ObjectAddress(0x6041, 0));
    QCOMPARE(m_stream->takeWritten(), QByteArray("OR6041,0,h\r"));
    m_stream->feed("OR6041,0,h\r\nOR6041,0,427h\r\n>");
    QCOMPARE(test::await(reply, kWaitMs).value(), QVariant(qlonglong(0x427)));
}

void TstRefgoClient::onlyOneCommandInFlight()
{
    Reply *tp = m_client->tellPosition();
    Reply *ts = m_client->tellStatus();
    Reply *go = m_client->go(360);
    QCOMPARE(m_client->pendingCount(), 3);
    QCOMPARE(m_stream->takeWritten(), QByteArray("TP\r"));
    m_stream->feed("TP\r\n-3658\r\n>");
    QCOMPARE(m_stream->takeWritten(), QByteArray("TS\r"));
    m_stream->feed("TS\r\n2\r\n>");
    QCOMPARE(m_stream->takeWritten(), QByteArray("G360\r"));
    m_stream->feed("G360\r\n>");
    QCOMPARE(test::await(tp, kWaitMs).value(), QVariant(qlonglong(-3658)));
    QCOMPARE(test::await(ts, kWaitMs).value(), QVariant(2));
    QVERIFY(test::await(go, kWaitMs).ok());
    QCOMPARE(m_client->pendingCount(), 0);
}

void TstRefgoClient::silenceTimesOutAndNextCommandIsSent()
{
    m_client->setTimeoutMs(kShortTimeoutMs);
    Reply *tp = m_client->tellPosition();
    Reply *ts = m_client->tellStatus();
    QCOMPARE(m_stream->takeWritten(), QByteArray("TP\r"));
    const auto first = test::await(tp, kWaitMs);
    QCOMPARE(first.error().kind(), Error::Kind::Timeout);
    QVERIFY(first.error().message().contains(QLatin1String("'TP'")));
    QVERIFY(first.error().message().contains(QLatin1String("scripted:0")));
    // Sent once the grace time for a late answer to TP is over.
    QVERIFY(m_stream->takeWritten().isEmpty());
    QTRY_COMPARE(m_stream->writes().last(), QByteArray("TS\r"));
    m_stream->feed("TS\r\n1\r\n>");
    QCOMPARE(test::await(ts, kWaitMs).value(), QVariant(1));
}

void TstRefgoClient::lateAnswerAfterTimeoutIsDroppedNotGivenToNextRequest()
{
    m_client->setTimeoutMs(kShortTimeoutMs);
    Reply *tp = m_client->tellPosition();
    QCOMPARE(test::await(tp, kWaitMs).error().kind(), Error::Kind::Timeout);
    m_client->setTimeoutMs(RefgoClient::kDefaultTimeoutMs);
    Reply *ts = m_client->tellStatus();
    m_stream->takeWritten();
    QTest::ignoreMessage(QtWarningMsg, QRegularExpression("dropping late answer to \"?TP"));
    m_stream->feed("TP\r\n-3658\r\n>");
    QVERIFY(!ts->isFinished());
    QTRY_COMPARE(m_stream->writes().last(), QByteArray("TS\r"));
    m_stream->feed("TS\r\n2\r\n>");
    QCOMPARE(test::await(ts, kWaitMs).value(), QVariant(2));
}

void TstRefgoClient::lateAnswerToSameCommandTextIsDropped()
{
    m_client->setTimeoutMs(kShortTimeoutMs);
    QCOMPARE(test::await(m_client->tellPosition(), kWaitMs).error().kind(), Error::Kind::Timeout);
    m_client->setTimeoutMs(RefgoClient::kDefaultTimeoutMs);
    Reply *second = m_client->tellPosition();
    QTest::ignoreMessage(QtWarningMsg, QRegularExpression("dropping late answer"));
    m_stream->feed("TP\r\n111\r\n>"); // the drive answers in order: this is the first TP's
    QVERIFY(!second->isFinished());
    QTRY_COMPARE(m_stream->writes().size(), 2);
    m_stream->feed("TP\r\n222\r\n>");
    QCOMPARE(test::await(second, kWaitMs).value(), QVariant(qlonglong(222)));
}

void TstRefgoClient::unansweredTimedOutCommandDoesNotSwallowNextAnswer()
{
    m_client->setTimeoutMs(kShortTimeoutMs);
    QCOMPARE(test::await(m_client->tellPosition(), kWaitMs).error().kind(), Error::Kind::Timeout);
    m_client->setTimeoutMs(RefgoClient::kDefaultTimeoutMs);
    Reply *ts = m_client->tellStatus();
    QTRY_COMPARE(m_stream->writes().size(), 2);
    m_stream->feed("TS\r\n2\r\n>"); // the TP was lost; TS's answer is TS's
    QCOMPARE(test::await(ts, kWaitMs).value(), QVariant(2));
}

// A drive polled for two objects in turn falls silent (both commands time out, again and again)
// and comes back: the next command's answer is its own, not taken for the lost command with the
// same text (which would make every later command time out in turn).
void TstRefgoClient::drivePolledInTurnAnswersAgainAfterASilence()
{
    m_client->setTimeoutMs(kShortTimeoutMs);
    for (int round = 0; round < 3; ++round) {
        QCOMPARE(test::await(m_client->objectRead({ 0x6041, 0 }), kWaitMs).error().kind(),
                 Error::Kind::Timeout);
        QCOMPARE(test::await(m_client->objectRead({ 0x6061, 0 }), kWaitMs).error().kind(),
                 Error::Kind::Timeout);
    }
    for (int round = 0; round < 2; ++round) {
        for (const char *object : { "6041,0", "6061,0" }) {
            const qsizetype before = m_stream->writes().size();
            const ObjectAddress address = QByteArray(object) == "6041,0" ? ObjectAddress(0x6041, 0)
                                                                         : ObjectAddress(0x6061, 0);
            Reply *reply = m_client->objectRead(address);
            QTRY_COMPARE(m_stream->writes().size(), before + 1);
            m_stream->feed(QByteArray("OR") + object + "\r\nOR" + object + ",7\r\n>");
            const auto r = test::await(reply, kWaitMs);
            QVERIFY2(r.ok(), qPrintable(r.error().toString()));
            QCOMPARE(r.value(), QVariant::fromValue<qlonglong>(7));
        }
    }
}

void TstRefgoClient::garbageAnswerIsMalformed()
{
    Reply *tp = m_client->tellPosition();
    Reply *ts = m_client->tellStatus();
    m_stream->feed(QByteArray("\x07\x01garbage\x00\r\n>", 13));
    const auto r = test::await(tp, kWaitMs);
    QCOMPARE(r.error().kind(), Error::Kind::Malformed);
    QVERIFY(r.error().message().contains(QLatin1String("garbage")));
    // The engine carries on with the next request.
    m_stream->takeWritten();
    m_stream->feed("TS\r\n2\r\n>");
    QCOMPARE(test::await(ts, kWaitMs).value(), QVariant(2));
}

void TstRefgoClient::mismatchedEchoIsMalformedNamingBothTexts()
{
    Reply *reply = m_client->tellPosition();
    m_stream->feed("TS\r\n2\r\n>");
    const auto r = test::await(reply, kWaitMs);
    QCOMPARE(r.error().kind(), Error::Kind::Malformed);
    QVERIFY2(r.error().message().contains(QLatin1String("'TP'"))
                 && r.error().message().contains(QLatin1String("'TS'")),
             qPrintable(r.error().message()));
}

void TstRefgoClient::unsolicitedAnswerIsDropped()
{
    QTest::ignoreMessage(QtWarningMsg, QRegularExpression("unsolicited"));
    m_stream->feed("TP\r\n1\r\n>");
    Reply *ts = m_client->tellStatus();
    m_stream->feed("TS\r\n1\r\n>");
    QCOMPARE(test::await(ts, kWaitMs).value(), QVariant(1));
}

void TstRefgoClient::oversizeAnswerFailsRequest()
{
    Reply *reply = m_client->tellPosition();
    QTest::ignoreMessage(QtWarningMsg, QRegularExpression("too long without prompt"));
    m_stream->feed("TP\r\n" + QByteArray(Framer::kMaxAnswerBytes, '9'));
    const auto r = test::await(reply, kWaitMs);
    QCOMPARE(r.error().kind(), Error::Kind::Malformed);
    QVERIFY(r.error().message().contains(QLatin1String("too long without prompt")));
}

void TstRefgoClient::deviceErrorLineIsDeviceError_data()
{
    QTest::addColumn<QByteArray>("rx");
    QTest::newRow("simulator ERROR") << QByteArray("G360\r\nERROR drive not enabled\r\n>");
    QTest::newRow("lower-case error") << QByteArray("G360\r\nerror\r\n>");
    QTest::newRow("question mark") << QByteArray("G360\r\n?\r\n>");
}

void TstRefgoClient::deviceErrorLineIsDeviceError()
{
    QFETCH(QByteArray, rx);
    Reply *reply = m_client->go(360);
    m_stream->feed(rx);
    const auto r = test::await(reply, kWaitMs);
    QCOMPARE(r.error().kind(), Error::Kind::DeviceError);
    QVERIFY(r.error().message().contains(QLatin1String("G360")));
}

void TstRefgoClient::objectWriteWithoutOkIsDeviceError_data()
{
    QTest::addColumn<QByteArray>("rx");
    QTest::newRow("no result line") << QByteArray("OW3511,8,120\r\n>");
    QTest::newRow("no OK") << QByteArray("OW3511,8,120\r\nOW3511,8,120\r\n>");
    QTest::newRow("NOK") << QByteArray("OW3511,8,120\r\nOW3511,8,120,FAIL\r\n>");
}

void TstRefgoClient::objectWriteWithoutOkIsDeviceError()
{
    QFETCH(QByteArray, rx);
    Reply *reply = m_client->objectWrite({ 0x3511, 8 }, 120);
    m_stream->feed(rx);
    const auto r = test::await(reply, kWaitMs);
    QCOMPARE(r.error().kind(), Error::Kind::DeviceError);
    QVERIFY(r.error().message().contains(QLatin1String(",OK")));
}

void TstRefgoClient::objectReadWithoutValueIsDeviceError_data()
{
    QTest::addColumn<QByteArray>("rx");
    QTest::newRow("no result line") << QByteArray("OR3511,8\r\n>");
    QTest::newRow("no third field") << QByteArray("OR3511,8\r\nOR3511,8\r\n>");
    QTest::newRow("not numeric") << QByteArray("OR3511,8\r\nOR3511,8,none\r\n>");
}

void TstRefgoClient::objectReadWithoutValueIsDeviceError()
{
    QFETCH(QByteArray, rx);
    Reply *reply = m_client->objectRead({ 0x3511, 8 });
    m_stream->feed(rx);
    QCOMPARE(test::await(reply, kWaitMs).error().kind(), Error::Kind::DeviceError);
}

void TstRefgoClient::objectReadWithBrokenNumberIsMalformed_data()
{
    QTest::addColumn<QByteArray>("rx");
    QTest::newRow("NUL inside") << QByteArray("OR3511,8\r\nOR3511,8,12") + '\0' + "34\r\n>";
    QTest::newRow("beyond 64 bits")
        << QByteArray("OR3511,8\r\nOR3511,8,99999999999999999999999\r\n>");
}

void TstRefgoClient::objectReadWithBrokenNumberIsMalformed()
{
    QFETCH(QByteArray, rx);
    Reply *reply = m_client->objectRead({ 0x3511, 8 });
    m_stream->feed(rx);
    QCOMPARE(test::await(reply, kWaitMs).error().kind(), Error::Kind::Malformed);
}

void TstRefgoClient::objectReadAnswerForOtherObjectIsMalformed()
{
    Reply *reply = m_client->objectRead({ 0x3511, 8 });
    m_stream->feed("OR3511,8\r\nOR3511,9,110\r\n>");
    QCOMPARE(test::await(reply, kWaitMs).error().kind(), Error::Kind::Malformed);
}

void TstRefgoClient::objectWriteOfTextIsRefused()
{
    const auto r =
        test::await(m_client->objectWrite({ 0x1008, 0 }, QStringLiteral("name")), kWaitMs);
    QCOMPARE(r.error().kind(), Error::Kind::InvalidArgument);
    QVERIFY(m_stream->takeWritten().isEmpty());
}

void TstRefgoClient::disconnectFailsPendingWithCloseError()
{
    Reply *a = m_client->tellPosition();
    Reply *b = m_client->tellStatus();
    Reply *c = m_client->go(1);
    m_stream->feed("TP\r\n-36"); // partial answer is forgotten too
    const Error lost(Error::Kind::Disconnected, QStringLiteral("scripted:0 reset the link"));
    m_stream->drop(lost);
    for (Reply *reply : { a, b, c })
        QCOMPARE(test::await(reply, kWaitMs).error(), lost);
    QCOMPARE(m_client->pendingCount(), 0);
}

void TstRefgoClient::requestWhileClosedFailsAtOnce()
{
    m_stream->close();
    const auto r = test::await(m_client->tellPosition(), kWaitMs);
    QCOMPARE(r.error().kind(), Error::Kind::Disconnected);
    QVERIFY(m_stream->takeWritten().isEmpty());
}

void TstRefgoClient::rawCommandWithLineBreakIsRefused_data()
{
    QTest::addColumn<QString>("command");
    QTest::newRow("CR") << "TP\rTS";
    QTest::newRow("LF") << "TP\n";
    QTest::newRow("empty") << "";
    QTest::newRow("blank") << "   ";
    QTest::newRow("control char") << "T\x01P";
}

void TstRefgoClient::rawCommandWithLineBreakIsRefused()
{
    QFETCH(QString, command);
    const auto r = test::await(m_client->execute(command), kWaitMs);
    QCOMPARE(r.error().kind(), Error::Kind::InvalidArgument);
    QVERIFY(m_stream->takeWritten().isEmpty());
}

void TstRefgoClient::badArgumentsAreRefused()
{
    QCOMPARE(test::await(m_client->send(Command::SM, 5), kWaitMs).error().kind(),
             Error::Kind::InvalidArgument);
    QCOMPARE(test::await(m_client->send(Command::SP), kWaitMs).error().kind(),
             Error::Kind::InvalidArgument);
    QCOMPARE(test::await(m_client->send(Command::OR), kWaitMs).error().kind(),
             Error::Kind::InvalidArgument);
    QVERIFY(m_stream->takeWritten().isEmpty());
}

void TstRefgoClient::deletedQueuedReplyIsSkipped()
{
    Reply *tp = m_client->tellPosition();
    Reply *dropped = m_client->tellStatus();
    Reply *go = m_client->go(5);
    delete dropped;
    m_stream->takeWritten();
    m_stream->feed("TP\r\n1\r\n>");
    QCOMPARE(m_stream->takeWritten(), QByteArray("G5\r"));
    m_stream->feed("G5\r\n>");
    QVERIFY(test::await(tp, kWaitMs).ok());
    QVERIFY(test::await(go, kWaitMs).ok());
}

void TstRefgoClient::logLinesShowRequestAndAnswer()
{
    QSignalSpy log(m_client, &RefgoClient::logLine);
    Reply *reply = m_client->tellPosition();
    m_stream->feed("TP\r\n-3658\r\n>");
    QVERIFY(test::await(reply, kWaitMs).ok());
    QCOMPARE(log.size(), 2);
    QCOMPARE(log.at(0).at(0).toString(), QStringLiteral("> TP"));
    QCOMPARE(log.at(1).at(0).toString(), QStringLiteral("< -3658"));
}

QTEST_GUILESS_MAIN(TstRefgoClient)
#include "tst_refgoclient.moc"
