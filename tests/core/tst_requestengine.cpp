// Level 2: the protocol-neutral request engine over a scripted stream, with a small line
// protocol ("tag=body\n") standing in for RefGo and VABus: one in flight, FIFO, split and
// coalesced answers, timeouts, late answers, resends, malformed and foreign answers,
// disconnects, keep-alive and the framer's buffer limit.

#include "scriptedstream.h"
#include "transport/requestengine.h"
#include "wait.h"

#include <QLoggingCategory>
#include <QtTest>

#include <memory>
#include <vector>

using namespace db;
using db::test::await;

namespace {

Q_LOGGING_CATEGORY(lcTest, "drivebench.test.engine")
Q_LOGGING_CATEGORY(lcTestRaw, "drivebench.test.engine.raw", QtWarningMsg)

constexpr int kShortTimeoutMs = 30;
constexpr int kWaitMs = 5000;

// "tag=body\n"; a line without '=' is a tag with an empty body.
struct LineAnswer
{
    QByteArray tag;
    QByteArray body;
};

class LineFramer
{
public:
    static constexpr qsizetype kMaxLineBytes = 32;

    std::vector<Result<LineAnswer>> feed(const QByteArray &bytes)
    {
        std::vector<Result<LineAnswer>> out;
        for (const char c : bytes) {
            if (c == '\n') {
                if (!m_discarding && !m_line.isEmpty()) {
                    const qsizetype eq = m_line.indexOf('=');
                    out.push_back(eq < 0 ? LineAnswer { m_line, {} }
                                         : LineAnswer { m_line.left(eq), m_line.mid(eq + 1) });
                }
                m_line.clear();
                m_discarding = false;
                continue;
            }
            if (m_discarding)
                continue;
            m_line.append(c);
            if (m_line.size() > kMaxLineBytes) {
                out.push_back(Error(
                    Error::Kind::Malformed,
                    QStringLiteral("answer too long (more than %1 bytes)").arg(kMaxLineBytes)));
                m_line.clear();
                m_discarding = true;
            }
        }
        return out;
    }
    void reset()
    {
        m_line.clear();
        m_discarding = false;
    }
    qsizetype bufferedBytes() const { return m_line.size(); }

private:
    QByteArray m_line;
    bool m_discarding = false;
};

struct LineProtocol
{
    using Answer = LineAnswer;
    using Framer = LineFramer;
    // body "bad": malformed; "busy": asks for a resend; "err...": the device refused.
    struct Matcher
    {
        QByteArray tag;
        Verdict operator()(const Answer &answer) const
        {
            if (answer.tag != tag)
                return Verdict::notMine(
                    QStringLiteral("tag is '%1'").arg(QString::fromLatin1(answer.tag)));
            if (answer.body == "bad")
                return Verdict::mine(Error(Error::Kind::Malformed, QStringLiteral("bad body")));
            if (answer.body == "busy")
                return Verdict::retry(Error(Error::Kind::Busy, QStringLiteral("device busy")));
            if (answer.body.startsWith("err"))
                return Verdict::mine(
                    Error(Error::Kind::DeviceError, QString::fromLatin1(answer.body)));
            return Verdict::mine(QVariant(QString::fromLatin1(answer.body)));
        }
    };
    static QString summary(const Answer &answer) { return QString::fromLatin1(answer.body); }
    static QString identify(const Answer &answer) { return QString::fromLatin1(answer.tag); }
};

using Engine = RequestEngine<LineProtocol>;

} // namespace

class TstRequestEngine : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void init();
    void cleanup();

    void secondRequestWaitsUntilFirstIsAnswered();
    void repliesFinishInSubmissionOrder();
    void answerSplitAcrossSegmentsIsReassembled();
    void twoAnswersInOneSegmentFinishTwoRequests();
    void silentDeviceTimesOutOnceAndNextRequestIsSent();
    void silentEpisodeIsLoggedOnceAtInfoLevel();
    void lateAnswerAfterTimeoutIsDroppedNotGivenToNextRequest();
    void lateAnswerWithSameTagIsDroppedNotGivenToNextRequest();
    void nextRequestWaitsOutLateGraceAfterTimeout();
    void answerMissingAfterLateGraceIsTakenAsLost();
    void timeoutResendsUntilMaxTransmissionsThenFails();
    void duplicateAnswerToResentRequestIsDropped();
    void retryVerdictResendsThenFailsWithItsReason();
    void malformedAnswerFailsOnlyItsRequest();
    void deviceRefusalIsDeviceError();
    void foreignAnswerIsDroppedAndRequestKeepsWaiting();
    void foreignAnswerFailsRequestWhenConfigured();
    void unsolicitedAnswerIsDropped();
    void disconnectFailsInFlightAndQueuedWithCloseError();
    void requestWhileClosedFailsAtOnce();
    void deletingEngineCancelsPendingReplies();
    void deletedQueuedReplyIsSkipped();
    void keepAliveIsNotSentWhileRequestIsInFlight();
    void userRequestWaitsAtMostOneKeepAliveRoundTrip();
    void keepAliveStopsOnDisconnectAndResumesOnReopen();
    void unansweredKeepAliveIsReportedAndNotResent();
    void oversizeAnswerFailsRequestAndBufferStaysBounded();
    void logLinesFollowTheirListeners();
    void handlerGetsTheAnswerAndItsRequestGoesOutAtOnce();
    void handlerIsNeverCalledFromInsideTheRequestCall();
    void handlerWhoseContextIsGoneIsSkippedAndNeverCalled();
    void deletingEngineCancelsHandlersFromTheLoop();

private:
    // Transmissions from the nth write on wait as long as the test needs, however late the
    // test gets to feed their answers (the short timeout is for the ones before).
    void longTimeoutFromWrite(qsizetype n)
    {
        connect(m_stream, &test::ScriptedStream::written, m_engine, [this, n] {
            if (m_stream->writes().size() >= n)
                m_engine->setTimeoutMs(kWaitMs);
        });
    }
    Reply *submit(const QByteArray &tag)
    {
        return m_engine->submit(tag + '\n', QString::fromLatin1(tag), { tag });
    }

    test::ScriptedStream *m_stream = nullptr;
    Engine *m_engine = nullptr;
};

void TstRequestEngine::init()
{
    m_stream = new test::ScriptedStream;
    m_engine = new Engine(m_stream, &lcTest, &lcTestRaw);
    m_stream->open();
    QTRY_VERIFY(m_stream->isOpen());
}

void TstRequestEngine::cleanup()
{
    delete m_engine;
    m_engine = nullptr;
    delete m_stream;
}

void TstRequestEngine::secondRequestWaitsUntilFirstIsAnswered()
{
    Reply *a = submit("a");
    Reply *b = submit("b");
    QCOMPARE(m_engine->pendingCount(), 2);
    QCOMPARE(m_stream->takeWritten(), QByteArray("a\n"));
    m_stream->feed("a=1\n");
    // Sent from the receive handler, with no event-loop hop.
    QCOMPARE(m_stream->takeWritten(), QByteArray("b\n"));
    m_stream->feed("b=2\n");
    QCOMPARE(await(a).value(), QVariant(QStringLiteral("1")));
    QCOMPARE(await(b).value(), QVariant(QStringLiteral("2")));
    QCOMPARE(m_engine->pendingCount(), 0);
}

void TstRequestEngine::repliesFinishInSubmissionOrder()
{
    QList<Reply *> replies;
    for (const char *tag : { "a", "b", "c", "d" })
        replies.append(submit(tag));
    QByteArray wire;
    for (const char *tag : { "a", "b", "c", "d" }) {
        wire += m_stream->takeWritten();
        m_stream->feed(QByteArray(tag) + '=' + tag + '\n');
    }
    QCOMPARE(wire, QByteArray("a\nb\nc\nd\n"));
    const QStringList expected { "a", "b", "c", "d" };
    for (qsizetype i = 0; i < replies.size(); ++i)
        QCOMPARE(await(replies.at(i)).value(), QVariant(expected.at(i)));
}

void TstRequestEngine::answerSplitAcrossSegmentsIsReassembled()
{
    Reply *reply = submit("pos");
    for (const char c : QByteArray("pos=-3658\n"))
        m_stream->feed(QByteArray(1, c));
    QCOMPARE(await(reply).value(), QVariant(QStringLiteral("-3658")));
    QCOMPARE(m_engine->bufferedBytes(), 0);
}

void TstRequestEngine::twoAnswersInOneSegmentFinishTwoRequests()
{
    Reply *a = submit("a");
    Reply *b = submit("b");
    m_stream->feed("a=1\nb=2\n");
    QCOMPARE(await(a).value(), QVariant(QStringLiteral("1")));
    QCOMPARE(await(b).value(), QVariant(QStringLiteral("2")));
    QCOMPARE(m_stream->writes(), QByteArrayList({ "a\n", "b\n" }));
}

void TstRequestEngine::silentDeviceTimesOutOnceAndNextRequestIsSent()
{
    m_engine->setTimeoutMs(kShortTimeoutMs);
    longTimeoutFromWrite(2);
    Reply *a = submit("a");
    Reply *b = submit("b");
    const auto first = await(a);
    QCOMPARE(first.error().kind(), Error::Kind::Timeout);
    QVERIFY(first.error().message().contains(QLatin1String("'a'")));
    QVERIFY(first.error().message().contains(QLatin1String("scripted:0")));
    // Default: one transmission, no resend.
    QCOMPARE(m_stream->writes(), QByteArrayList({ "a\n", "b\n" }));
    m_stream->feed("b=2\n");
    QCOMPARE(await(b).value(), QVariant(QStringLiteral("2")));
}

namespace {
// The info-level lines of the test engine's category (what the GUI's log console shows).
QStringList g_infoLines;
QtMessageHandler g_previous = nullptr;
void collectInfo(QtMsgType type, const QMessageLogContext &context, const QString &message)
{
    if (type == QtInfoMsg && context.category
        && qstrcmp(context.category, "drivebench.test.engine") == 0)
        g_infoLines.append(message);
    g_previous(type, context, message);
}
} // namespace

void TstRequestEngine::silentEpisodeIsLoggedOnceAtInfoLevel()
{
    g_infoLines.clear();
    g_previous = qInstallMessageHandler(collectInfo);
    auto restore = qScopeGuard([] { qInstallMessageHandler(g_previous); });
    m_engine->setTimeoutMs(kShortTimeoutMs);
    for (const char *tag : { "a", "b", "c", "d", "e" })
        QCOMPARE(await(submit(tag)).error().kind(), Error::Kind::Timeout);
    QCOMPARE(g_infoLines.size(), 1); // one line for the episode, not one per timeout
    QVERIFY2(g_infoLines.at(0).contains(QLatin1String("'a'")), qPrintable(g_infoLines.at(0)));
    m_engine->setTimeoutMs(kWaitMs);
    Reply *f = submit("f");
    QTRY_VERIFY(m_stream->writes().contains("f\n"));
    m_stream->feed("f=1\n");
    QCOMPARE(await(f).value(), QVariant(QStringLiteral("1")));
    QCOMPARE(g_infoLines.size(), 2);
    QVERIFY2(g_infoLines.at(1).contains(QLatin1String("answers again after 5 timeouts")),
             qPrintable(g_infoLines.at(1)));
    // The next silence is a new episode with its own line.
    m_engine->setTimeoutMs(kShortTimeoutMs);
    QCOMPARE(await(submit("g")).error().kind(), Error::Kind::Timeout);
    QCOMPARE(g_infoLines.size(), 3);
}

void TstRequestEngine::lateAnswerAfterTimeoutIsDroppedNotGivenToNextRequest()
{
    m_engine->setTimeoutMs(kShortTimeoutMs);
    QCOMPARE(await(submit("a")).error().kind(), Error::Kind::Timeout);
    m_engine->setTimeoutMs(kWaitMs);
    Reply *b = submit("b");
    QSignalSpy log(m_engine, &RequestEngineBase::logLine);
    QTest::ignoreMessage(QtWarningMsg, QRegularExpression("dropping late answer to a"));
    m_stream->feed("a=late\n");
    QVERIFY(!b->isFinished());
    QCOMPARE(log.size(), 1);
    QCOMPARE(log.at(0).at(0).toString(), QStringLiteral("! dropped late answer to 'a'"));
    m_stream->feed("b=2\n");
    QCOMPARE(await(b).value(), QVariant(QStringLiteral("2")));
}

void TstRequestEngine::lateAnswerWithSameTagIsDroppedNotGivenToNextRequest()
{
    m_engine->setTimeoutMs(kShortTimeoutMs);
    QCOMPARE(await(submit("a")).error().kind(), Error::Kind::Timeout);
    m_engine->setTimeoutMs(kWaitMs);
    Reply *again = submit("a");
    QTest::ignoreMessage(QtWarningMsg, QRegularExpression("dropping late answer"));
    m_stream->feed("a=old\n"); // devices answer in order: this is the first request's
    QVERIFY(!again->isFinished());
    m_stream->feed("a=new\n");
    QCOMPARE(await(again).value(), QVariant(QStringLiteral("new")));
}

void TstRequestEngine::nextRequestWaitsOutLateGraceAfterTimeout()
{
    m_engine->setTimeoutMs(kShortTimeoutMs);
    m_engine->setLateGraceMs(100);
    longTimeoutFromWrite(2);
    Reply *a = submit("a");
    Reply *b = submit("b");
    QCOMPARE(m_stream->takeWritten(), QByteArray("a\n"));
    QCOMPARE(await(a).error().kind(), Error::Kind::Timeout);
    QVERIFY(m_stream->takeWritten().isEmpty()); // quiet: a late answer may still come
    QTest::ignoreMessage(QtWarningMsg, QRegularExpression("dropping late answer to a"));
    m_stream->feed("a=late\n");
    QTRY_COMPARE(m_stream->writes().size(), 2);
    QCOMPARE(m_stream->writes().last(), QByteArray("b\n"));
    m_stream->feed("b=2\n");
    QCOMPARE(await(b).value(), QVariant(QStringLiteral("2")));
}

// A device that stayed silent (e.g. still starting) and then answers: the identical request
// sent after the grace time gets its own answer, not dropped as the first one's late one.
void TstRequestEngine::answerMissingAfterLateGraceIsTakenAsLost()
{
    m_engine->setTimeoutMs(kShortTimeoutMs);
    m_engine->setLateGraceMs(50);
    QCOMPARE(await(submit("a")).error().kind(), Error::Kind::Timeout);
    m_engine->setTimeoutMs(kWaitMs);
    Reply *again = submit("a");
    QTRY_COMPARE(m_stream->writes().size(), 2);
    m_stream->feed("a=new\n");
    QCOMPARE(await(again).value(), QVariant(QStringLiteral("new")));
}

void TstRequestEngine::timeoutResendsUntilMaxTransmissionsThenFails()
{
    m_engine->setTimeoutMs(kShortTimeoutMs);
    m_engine->setMaxTransmissions(3);
    const auto r = await(submit("a"));
    QCOMPARE(r.error().kind(), Error::Kind::Timeout);
    QVERIFY2(r.error().message().contains(QLatin1String("sent 3 times")),
             qPrintable(r.error().message()));
    QCOMPARE(m_stream->writes(), QByteArrayList({ "a\n", "a\n", "a\n" }));
    QCOMPARE(m_engine->pendingCount(), 0);
}

void TstRequestEngine::duplicateAnswerToResentRequestIsDropped()
{
    m_engine->setTimeoutMs(kShortTimeoutMs);
    m_engine->setMaxTransmissions(2);
    longTimeoutFromWrite(2);
    Reply *a = submit("a");
    QTRY_COMPARE(m_stream->writes().size(), 2);
    m_stream->feed("a=1\n"); // answer to the first transmission
    QCOMPARE(await(a).value(), QVariant(QStringLiteral("1")));
    Reply *next = submit("a");
    QTest::ignoreMessage(QtWarningMsg, QRegularExpression("dropping late answer to a"));
    m_stream->feed("a=1\n"); // the same answer to the second transmission
    QVERIFY(!next->isFinished());
    m_stream->feed("a=2\n");
    QCOMPARE(await(next).value(), QVariant(QStringLiteral("2")));
}

void TstRequestEngine::retryVerdictResendsThenFailsWithItsReason()
{
    m_engine->setMaxTransmissions(2);
    Reply *a = submit("a");
    m_stream->feed("a=busy\n");
    QCOMPARE(m_stream->writes(), QByteArrayList({ "a\n", "a\n" }));
    m_stream->feed("a=busy\n");
    const auto r = await(a);
    QCOMPARE(r.error().kind(), Error::Kind::Busy);
    QCOMPARE(r.error().message(), QStringLiteral("device busy"));
    QCOMPARE(m_stream->writes().size(), 2);

    Reply *b = submit("b");
    m_stream->feed("b=busy\n");
    m_stream->feed("b=ok\n");
    QCOMPARE(await(b).value(), QVariant(QStringLiteral("ok")));
}

void TstRequestEngine::malformedAnswerFailsOnlyItsRequest()
{
    Reply *a = submit("a");
    Reply *b = submit("b");
    m_stream->feed("a=bad\nb=2\n");
    QCOMPARE(await(a).error().kind(), Error::Kind::Malformed);
    QCOMPARE(await(b).value(), QVariant(QStringLiteral("2")));
}

void TstRequestEngine::deviceRefusalIsDeviceError()
{
    Reply *a = submit("a");
    m_stream->feed("a=error 7\n");
    const auto r = await(a);
    QCOMPARE(r.error().kind(), Error::Kind::DeviceError);
    QCOMPARE(r.error().message(), QStringLiteral("error 7"));
}

void TstRequestEngine::foreignAnswerIsDroppedAndRequestKeepsWaiting()
{
    Reply *a = submit("a");
    QTest::ignoreMessage(QtWarningMsg, QRegularExpression("does not belong to a.*tag is 'x'"));
    m_stream->feed("x=1\n");
    QVERIFY(!a->isFinished());
    m_stream->feed("a=1\n");
    QCOMPARE(await(a).value(), QVariant(QStringLiteral("1")));
}

void TstRequestEngine::foreignAnswerFailsRequestWhenConfigured()
{
    m_engine->setForeignAnswerFails(true);
    Reply *a = submit("a");
    Reply *b = submit("b");
    m_stream->feed("x=1\n");
    const auto r = await(a);
    QCOMPARE(r.error().kind(), Error::Kind::Malformed);
    QCOMPARE(r.error().message(),
             QStringLiteral("answer from scripted:0 does not belong to 'a': tag is 'x'"));
    m_stream->feed("b=2\n");
    QCOMPARE(await(b).value(), QVariant(QStringLiteral("2")));
}

void TstRequestEngine::unsolicitedAnswerIsDropped()
{
    QTest::ignoreMessage(QtWarningMsg, QRegularExpression("unsolicited answer x"));
    m_stream->feed("x=1\n");
    Reply *a = submit("a");
    m_stream->feed("a=1\n");
    QCOMPARE(await(a).value(), QVariant(QStringLiteral("1")));
}

void TstRequestEngine::disconnectFailsInFlightAndQueuedWithCloseError()
{
    Reply *a = submit("a");
    Reply *b = submit("b");
    m_stream->feed("a=partial");
    QVERIFY(m_engine->bufferedBytes() > 0);
    const Error lost(Error::Kind::Disconnected, QStringLiteral("scripted:0 reset the link"));
    m_stream->drop(lost);
    QCOMPARE(await(a).error(), lost);
    QCOMPARE(await(b).error(), lost);
    QCOMPARE(m_engine->pendingCount(), 0);
    QCOMPARE(m_engine->bufferedBytes(), 0);
}

void TstRequestEngine::requestWhileClosedFailsAtOnce()
{
    m_stream->close();
    const auto r = await(submit("a"));
    QCOMPARE(r.error().kind(), Error::Kind::Disconnected);
    QVERIFY(m_stream->writes().isEmpty());
}

void TstRequestEngine::deletingEngineCancelsPendingReplies()
{
    Reply *a = submit("a");
    Reply *b = submit("b");
    delete m_engine;
    m_engine = nullptr;
    QCOMPARE(await(a).error().kind(), Error::Kind::Cancelled);
    QCOMPARE(await(b).error().kind(), Error::Kind::Cancelled);
}

void TstRequestEngine::deletedQueuedReplyIsSkipped()
{
    Reply *a = submit("a");
    delete submit("b");
    Reply *c = submit("c");
    m_stream->feed("a=1\n");
    QCOMPARE(m_stream->writes(), QByteArrayList({ "a\n", "c\n" }));
    m_stream->feed("c=3\n");
    QVERIFY(await(a).ok());
    QVERIFY(await(c).ok());
}

void TstRequestEngine::keepAliveIsNotSentWhileRequestIsInFlight()
{
    constexpr int kIdleMs = 20;
    QSignalSpy log(m_engine, &RequestEngineBase::logLine);
    // What was sent and queued when 'a' timed out.
    qsizetype writesAtTimeout = -1;
    int pendingAtTimeout = -1;
    connect(m_engine, &RequestEngineBase::logLine, this, [&](const QString &line) {
        if (line.startsWith(QLatin1String("! no answer to 'a'"))) {
            writesAtTimeout = m_stream->writes().size();
            pendingAtTimeout = m_engine->pendingCount();
        }
    });
    m_engine->setTimeoutMs(10 * kIdleMs);
    Reply *a = submit("a");
    m_engine->setKeepAlive(kIdleMs, "ka\n", QStringLiteral("ka"), { "ka" });
    // The idle time passes several times while 'a' waits for its answer: no keep-alive is
    // sent, nor queued ahead of later requests.
    QCOMPARE(await(a).error().kind(), Error::Kind::Timeout);
    QCOMPARE(writesAtTimeout, 1);
    QCOMPARE(pendingAtTimeout, 0); // 'a' itself is done
    // Idle now: the keep-alive goes out, once per idle time, and stays out of the log console.
    QTRY_COMPARE(m_stream->writes().size(), 2);
    QCOMPARE(m_stream->writes().last(), QByteArray("ka\n"));
    const qsizetype lines = log.size();
    m_stream->feed("ka=alive\n");
    QCOMPARE(m_engine->pendingCount(), 0);
    QCOMPARE(log.size(), lines);
    QTRY_COMPARE(m_stream->writes().size(), 3);
    QCOMPARE(m_stream->writes().last(), QByteArray("ka\n"));
}

void TstRequestEngine::userRequestWaitsAtMostOneKeepAliveRoundTrip()
{
    m_engine->setKeepAlive(10, "ka\n", QStringLiteral("ka"), { "ka" });
    QTRY_COMPARE(m_stream->writes().size(), 1);
    QCOMPARE(m_stream->writes().last(), QByteArray("ka\n"));
    Reply *a = submit("a");
    QCOMPARE(m_stream->writes().size(), 1); // one request in flight: the keep-alive
    m_stream->feed("ka=alive\n");
    QCOMPARE(m_stream->writes().size(), 2); // right after its answer
    QCOMPARE(m_stream->writes().last(), QByteArray("a\n"));
    m_stream->feed("a=1\n");
    QCOMPARE(await(a).value(), QVariant(QStringLiteral("1")));
}

void TstRequestEngine::keepAliveStopsOnDisconnectAndResumesOnReopen()
{
    m_engine->setKeepAlive(10, "ka\n", QStringLiteral("ka"), { "ka" });
    QVERIFY(m_engine->isKeepAliveScheduled());
    QTRY_COMPARE(m_stream->writes().size(), 1);
    m_stream->drop(Error(Error::Kind::Disconnected, QStringLiteral("link lost")));
    QVERIFY(!m_engine->isKeepAliveScheduled());
    QCOMPARE(m_engine->pendingCount(), 0);
    m_stream->open();
    QTRY_VERIFY(m_stream->isOpen());
    QVERIFY(m_engine->isKeepAliveScheduled());
    QTRY_COMPARE(m_stream->writes().size(), 2);
    QCOMPARE(m_stream->writes().last(), QByteArray("ka\n"));
}

void TstRequestEngine::unansweredKeepAliveIsReportedAndNotResent()
{
    m_engine->setTimeoutMs(kShortTimeoutMs);
    m_engine->setMaxTransmissions(3); // for user requests; a keep-alive goes once
    qsizetype writesAtFailure = -1; // at the first failure: later keep-alives go on failing
    connect(m_engine, &RequestEngineBase::logLine, this, [&](const QString &line) {
        if (writesAtFailure < 0
            && line.startsWith(QLatin1String("! keep-alive: no answer to 'ka'")))
            writesAtFailure = m_stream->writes().size();
    });
    m_engine->setKeepAlive(10, "ka\n", QStringLiteral("ka"), { "ka" });
    QTRY_COMPARE(writesAtFailure, 1);
}

void TstRequestEngine::oversizeAnswerFailsRequestAndBufferStaysBounded()
{
    Reply *a = submit("a");
    Reply *b = submit("b");
    QTest::ignoreMessage(QtWarningMsg, QRegularExpression("answer too long"));
    m_stream->feed("a=" + QByteArray(4 * LineFramer::kMaxLineBytes, '9'));
    QVERIFY(m_engine->bufferedBytes() <= LineFramer::kMaxLineBytes);
    const auto r = await(a);
    QCOMPARE(r.error().kind(), Error::Kind::Malformed);
    QCOMPARE(r.error().message(),
             QStringLiteral("scripted:0: answer too long (more than 32 bytes)"));
    // The rest of the oversize answer is discarded; the next answer is b's.
    m_stream->feed("999\nb=2\n");
    QCOMPARE(await(b).value(), QVariant(QStringLiteral("2")));
}

// Whether anyone listens is remembered between requests: listeners that come and go after
// requests were made must still get every line, and one that goes must get none.
void TstRequestEngine::logLinesFollowTheirListeners()
{
    const auto roundTrip = [this](const QByteArray &tag) {
        Reply *r = submit(tag);
        m_stream->feed(tag + "=1\n");
        QVERIFY(await(r).ok());
    };
    roundTrip("a"); // nobody listens
    QStringList lines;
    auto *listener = new QObject(this);
    connect(m_engine, &RequestEngineBase::logLine, listener,
            [&lines](const QString &line) { lines.append(line); });
    roundTrip("b");
    QCOMPARE(lines, (QStringList { QStringLiteral("> b"), QStringLiteral("< 1") }));
    delete listener; // its connection goes with it
    roundTrip("c");
    QCOMPARE(lines.size(), 2);
    const auto connection = connect(m_engine, &RequestEngineBase::logLine, this,
                                    [&lines](const QString &line) { lines.append(line); });
    roundTrip("d");
    QCOMPARE(lines.size(), 4);
    QCOMPARE(lines.at(2), QStringLiteral("> d"));
    disconnect(connection);
    roundTrip("e");
    QCOMPARE(lines.size(), 4);
    QSignalSpy spy(m_engine, &RequestEngineBase::logLine);
    roundTrip("f");
    QCOMPARE(spy.size(), 2);
}

// A handler gets the answer from the receive handler; a request made there is written before
// the handler returns (no pass of the event loop between answer and next request).
void TstRequestEngine::handlerGetsTheAnswerAndItsRequestGoesOutAtOnce()
{
    QObject context;
    QList<QVariant> values;
    QByteArray writtenInHandler;
    m_engine->submit("a\n", QStringLiteral("a"), { "a" },
                     Completion(&context, [&](const Result<QVariant> &r) {
                         QVERIFY(r.ok());
                         values.append(r.value());
                         m_engine->submit("b\n", QStringLiteral("b"), { "b" },
                                          Completion(&context, [&](const Result<QVariant> &r2) {
                                              values.append(r2.ok() ? r2.value() : QVariant());
                                          }));
                         writtenInHandler = m_stream->writes().last();
                     }));
    QCOMPARE(m_stream->takeWritten(), QByteArray("a\n"));
    m_stream->feed("a=1\n");
    QCOMPARE(values, QList<QVariant>({ QStringLiteral("1") }));
    QCOMPARE(writtenInHandler, QByteArray("b\n"));
    m_stream->feed("b=2\n");
    QCOMPARE(values, QList<QVariant>({ QStringLiteral("1"), QStringLiteral("2") }));
    QCOMPARE(m_engine->pendingCount(), 0);
}

// Failures known at once (not connected) come from the event loop, after the call returned.
void TstRequestEngine::handlerIsNeverCalledFromInsideTheRequestCall()
{
    m_stream->close();
    QObject context;
    bool inCall = true;
    bool calledInCall = false;
    std::optional<Error> error;
    m_engine->submit("a\n", QStringLiteral("a"), { "a" },
                     Completion(&context, [&](const Result<QVariant> &r) {
                         calledInCall = inCall;
                         error = r.error();
                     }));
    inCall = false;
    QVERIFY(!error);
    QTRY_VERIFY(error);
    QVERIFY(!calledInCall);
    QCOMPARE(error->kind(), Error::Kind::Disconnected);
    QVERIFY(m_stream->writes().isEmpty());
}

// A requester withdraws a queued request by deleting its context: it is never sent and its
// handler never called; one already sent is answered, but its handler is not called either.
void TstRequestEngine::handlerWhoseContextIsGoneIsSkippedAndNeverCalled()
{
    auto first = std::make_unique<QObject>();
    auto second = std::make_unique<QObject>();
    QObject keeps;
    int called = 0;
    const auto count = [&](const Result<QVariant> &) {
        ++called;
    };
    m_engine->submit("a\n", QStringLiteral("a"), { "a" }, Completion(first.get(), count));
    m_engine->submit("b\n", QStringLiteral("b"), { "b" }, Completion(second.get(), count));
    m_engine->submit("c\n", QStringLiteral("c"), { "c" }, Completion(&keeps, count));
    QCOMPARE(m_stream->takeWritten(), QByteArray("a\n"));
    first.reset(); // sent already
    second.reset(); // still queued
    m_stream->feed("a=1\n");
    QCOMPARE(m_stream->takeWritten(), QByteArray("c\n"));
    QCOMPARE(called, 0);
    m_stream->feed("c=3\n");
    QCOMPARE(called, 1);
    QCOMPARE(m_engine->pendingCount(), 0);
}

// Deleting the engine cancels handlers too, from the loop (not from inside the destructor).
void TstRequestEngine::deletingEngineCancelsHandlersFromTheLoop()
{
    QObject context;
    QList<Error::Kind> kinds;
    for (const char *tag : { "a", "b" }) {
        m_engine->submit(QByteArray(tag) + '\n', QString::fromLatin1(tag), { tag },
                         Completion(&context, [&](const Result<QVariant> &r) {
                             kinds.append(r.error().kind());
                         }));
    }
    delete m_engine;
    m_engine = nullptr;
    QVERIFY(kinds.isEmpty());
    QTRY_COMPARE(kinds, QList<Error::Kind>({ Error::Kind::Cancelled, Error::Kind::Cancelled }));
}

QTEST_GUILESS_MAIN(TstRequestEngine)
#include "tst_requestengine.moc"
