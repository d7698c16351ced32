// The Reply contract: finishes exactly once, finished() from the event loop, never twice.
#include "core/reply.h"

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTest>
#include <QTimer>

#include <memory>
#include <vector>

using namespace db;

class TestReply : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void finishesExactlyOnce();
    void failAfterFinishIsIgnored();
    void finishedComesFromTheEventLoop();
    void immediateFailureStillSignals();
    void waitReturnsTheResult();
    void waitReportsPendingAsTimeout();
    void waitOnAnAlreadyDeliveredReplyReturnsAtOnce();
    void forwardConvertsTheValueOrPassesTheError();
    void forwardSurvivesTheOuterReplyBeingDeleted();
    void finishedNeedsNoEventPerReply();
    void repliesFinishedTogetherSignalInOrder();
    void replyDeletedBeforeDeliveryIsSkipped();
    void finishedComesWithoutATimerPass();
    void finishedComesFromLoopsThatNeverWait();
    void loopsThatNeverWaitNeedNoTimerEither();
    void replyFinishedByAHandlerComesInTheNextPass();
};

void TestReply::finishesExactlyOnce()
{
    Reply reply(ObjectAddress(0x6041, 0));
    QSignalSpy spy(&reply, &Reply::finished);
    QVERIFY(reply.finish(QVariant::fromValue(0x427ULL)));
    QVERIFY(!reply.finish(QVariant::fromValue(1ULL)));
    QVERIFY(spy.wait(1000));
    QTest::qWait(20); // would catch a second emission
    QCOMPARE(spy.count(), 1);
    QCOMPARE(reply.value().toULongLong(), 0x427ULL);
    QVERIFY(reply.ok());
}

void TestReply::failAfterFinishIsIgnored()
{
    Reply reply;
    reply.finish(42);
    QVERIFY(!reply.fail(Error(Error::Kind::Timeout, QStringLiteral("late"))));
    QVERIFY(reply.ok());
    QCOMPARE(reply.error().kind(), Error::Kind::None);
}

void TestReply::finishedComesFromTheEventLoop()
{
    Reply reply;
    bool emittedInside = false;
    connect(&reply, &Reply::finished, this, [&] { emittedInside = true; });
    reply.fail(Error(Error::Kind::Timeout, QStringLiteral("no answer")));
    QVERIFY(!emittedInside);
    QTRY_VERIFY(emittedInside);
    QCOMPARE(reply.error().kind(), Error::Kind::Timeout);
}

void TestReply::immediateFailureStillSignals()
{
    Reply *reply = Reply::failed(ObjectAddress(1, 2),
                                 Error(Error::Kind::Disconnected, QStringLiteral("not connected")));
    QSignalSpy spy(reply, &Reply::finished);
    QVERIFY(spy.wait(1000));
    QCOMPARE(reply->address(), ObjectAddress(1, 2));
    delete reply;
}

void TestReply::waitReturnsTheResult()
{
    auto *reply = new Reply;
    QTimer::singleShot(10, reply, [reply] { reply->finish(QStringLiteral("ok")); });
    const auto result = Reply::wait(reply);
    QVERIFY(result.ok());
    QCOMPARE(result.value().toString(), QStringLiteral("ok"));
}

void TestReply::waitReportsPendingAsTimeout()
{
    auto *reply = new Reply;
    const auto result = Reply::wait(reply, 30);
    QCOMPARE(result.error().kind(), Error::Kind::Timeout);
}

void TestReply::waitOnAnAlreadyDeliveredReplyReturnsAtOnce()
{
    auto *reply = new Reply;
    QSignalSpy spy(reply, &Reply::finished);
    reply->finish(7);
    QVERIFY(spy.wait(1000));
    QElapsedTimer clock;
    clock.start();
    QCOMPARE(Reply::wait(reply, 5000).value().toInt(), 7);
    QVERIFY(clock.elapsed() < 1000);
}

void TestReply::forwardConvertsTheValueOrPassesTheError()
{
    QObject owner;
    auto *inner = new Reply;
    auto *outer = new Reply;
    Reply::forward(inner, outer, &owner, [](const QVariant &v) { return QVariant(v.toInt() * 2); });
    inner->finish(21);
    QCOMPARE(Reply::wait(outer, 1000).value().toInt(), 42);

    auto *failing = new Reply;
    auto *refused = new Reply;
    Reply::forward(failing, refused, &owner, [](const QVariant &) -> Result<QVariant> {
        return Error(Error::Kind::Malformed, QStringLiteral("not a number"));
    });
    failing->finish(1);
    QCOMPARE(Reply::wait(refused, 1000).error().kind(), Error::Kind::Malformed);

    auto *lost = new Reply;
    auto *plain = new Reply;
    Reply::forward(lost, plain, &owner);
    lost->fail(Error(Error::Kind::Timeout, QStringLiteral("no answer")));
    QCOMPARE(Reply::wait(plain, 1000).error().message(), QStringLiteral("no answer"));
}

void TestReply::forwardSurvivesTheOuterReplyBeingDeleted()
{
    QObject owner;
    auto *inner = new Reply;
    auto *outer = new Reply;
    Reply::forward(inner, outer, &owner);
    QSignalSpy innerDone(inner, &Reply::finished);
    delete outer;
    inner->finish(1);
    QVERIFY(innerDone.wait(1000)); // no crash touching the deleted outer reply
}

QTEST_GUILESS_MAIN(TestReply)
// A posted event per reply wakes the event dispatcher once per request; finished() of all the
// replies of a thread comes through one timer instead, so no event is sent to the reply itself.
void TestReply::finishedNeedsNoEventPerReply()
{
    Reply reply;
    int events = 0;
    struct Counter : QObject
    {
        int *count;
        explicit Counter(int *c)
            : count(c)
        { }
        bool eventFilter(QObject *, QEvent *) override
        {
            ++*count;
            return false;
        }
    } counter(&events);
    reply.installEventFilter(&counter);
    QSignalSpy finished(&reply, &Reply::finished);
    reply.finish(1);
    QVERIFY(finished.wait(1000));
    QCOMPARE(events, 0);
}

void TestReply::repliesFinishedTogetherSignalInOrder()
{
    QList<int> order;
    std::vector<std::unique_ptr<Reply>> replies;
    for (int i = 0; i < 5; ++i) {
        replies.push_back(std::make_unique<Reply>());
        connect(replies.back().get(), &Reply::finished, this, [&order, i] { order.append(i); });
    }
    for (int i : { 3, 0, 4, 1, 2 })
        replies[size_t(i)]->finish(i);
    QTRY_COMPARE(order.size(), 5);
    QCOMPARE(order, QList<int>({ 3, 0, 4, 1, 2 }));
}

void TestReply::replyDeletedBeforeDeliveryIsSkipped()
{
    auto *gone = new Reply;
    Reply kept;
    QSignalSpy keptFinished(&kept, &Reply::finished);
    gone->finish(1);
    kept.finish(2);
    delete gone;
    QVERIFY(keptFinished.wait(1000));
    QCOMPARE(keptFinished.count(), 1);
}

namespace {
// Counts the timer events of every object of the thread.
struct TimerEventCounter : QObject
{
    int count = 0;
    bool eventFilter(QObject *, QEvent *event) override
    {
        if (event->type() == QEvent::Timer)
            ++count;
        return false;
    }
};
} // namespace

// A reply finished while the event loop handles something (here a queued call; on a link the
// answer's socket notification) signals when the loop is about to wait again: no timer and no
// extra pass of the loop, whose poll would be one more system call per round trip.
void TestReply::finishedComesWithoutATimerPass()
{
    Reply reply;
    TimerEventCounter timers;
    QCoreApplication::instance()->installEventFilter(&timers);
    QSignalSpy finished(&reply, &Reply::finished);
    QMetaObject::invokeMethod(
        this, [&reply] { reply.finish(7); }, Qt::QueuedConnection);
    QVERIFY(finished.wait(1000));
    QCoreApplication::instance()->removeEventFilter(&timers);
    QCOMPARE(timers.count, 0);
    QCOMPARE(reply.value().toInt(), 7);
}

// A loop that only polls (processEvents() without waiting) never gets to "about to wait": the
// replies still come, through the zero timer.
void TestReply::finishedComesFromLoopsThatNeverWait()
{
    Reply reply;
    bool signalled = false;
    connect(&reply, &Reply::finished, this, [&] { signalled = true; });
    reply.finish(1);
    QElapsedTimer spent;
    spent.start();
    while (!signalled && spent.elapsed() < 1000)
        QCoreApplication::processEvents();
    QVERIFY(signalled);
}

// Such a loop's passes each begin with the dispatcher's awake(): the reply comes from there, so
// no request costs a timer registration, not even in a polling loop.
void TestReply::loopsThatNeverWaitNeedNoTimerEither()
{
    Reply reply;
    TimerEventCounter timers;
    QCoreApplication::instance()->installEventFilter(&timers);
    bool signalled = false;
    connect(&reply, &Reply::finished, this, [&] { signalled = true; });
    reply.finish(1);
    QCoreApplication::processEvents();
    QCoreApplication::instance()->removeEventFilter(&timers);
    QVERIFY(signalled);
    QCOMPARE(timers.count, 0);
}

// A reply finished from another reply's finished() handler is not delivered inside that
// handler but in a later pass, and both arrive once.
void TestReply::replyFinishedByAHandlerComesInTheNextPass()
{
    Reply first;
    Reply second;
    QList<int> order;
    bool insideFirst = false;
    connect(&first, &Reply::finished, this, [&] {
        insideFirst = true;
        second.finish(2);
        order.append(1);
        insideFirst = false;
    });
    connect(&second, &Reply::finished, this, [&] {
        QVERIFY(!insideFirst);
        order.append(2);
    });
    first.finish(1);
    QTRY_COMPARE(order.size(), 2);
    QCOMPARE(order, QList<int>({ 1, 2 }));
}

#include "tst_reply.moc"
