#pragma once

// The one way tests wait: turn the event loop until a condition holds, waking on the signal
// that changes it, with a time limit. Never a fixed sleep. Header-only.

#include "core/reply.h"

#include <QDeadlineTimer>
#include <QEventLoop>
#include <QSignalSpy>
#include <QTimer>

#include <memory>

namespace db::test {

// Long enough for a loaded CI machine; a passing test never waits this long.
constexpr int kDefaultWaitMs = 5000;

// Turns the event loop until done() is true; done() is checked first and after every emission
// of `signal`. False when the time runs out first.
template<typename Sender, typename Signal, typename Done>
bool waitUntil(const Sender *sender, Signal signal, Done done, int timeoutMs = kDefaultWaitMs)
{
    if (done())
        return true;
    QSignalSpy spy(sender, signal);
    const QDeadlineTimer deadline(timeoutMs);
    while (!done()) {
        const qint64 left = deadline.remainingTime();
        if (left <= 0)
            return false;
        spy.wait(int(left));
    }
    return true;
}

// Turns the event loop until done() is true, checking it every `everyMs`: for conditions no
// signal announces (a simulator's state, a text that changes with time). Unlike
// QTest::qWaitFor (and so QTRY_*), which sleeps 10 ms after every turn of the loop, this
// sleeps only in the event loop, so a request and its answer between a client and a server in
// the same thread take microseconds, not 10 ms for each of their hops.
template<typename Done>
bool waitFor(Done done, int timeoutMs = kDefaultWaitMs, int everyMs = 2)
{
    if (done())
        return true;
    QEventLoop loop;
    QTimer check;
    QObject::connect(&check, &QTimer::timeout, &loop, [&] {
        if (done())
            loop.quit();
    });
    QTimer deadline;
    deadline.setSingleShot(true);
    QObject::connect(&deadline, &QTimer::timeout, &loop, &QEventLoop::quit);
    check.start(everyMs);
    deadline.start(timeoutMs);
    loop.exec();
    return done();
}

// Turns the event loop until `signal` has been emitted `count` times from now on.
template<typename Sender, typename Signal>
bool waitForSignal(const Sender *sender, Signal signal, int count = 1,
                   int timeoutMs = kDefaultWaitMs)
{
    QSignalSpy spy(sender, signal);
    return waitUntil(
        sender, signal, [&spy, count] { return spy.size() >= count; }, timeoutMs);
}

// Waits for a reply to finish and returns its result; the reply is deleted here. A reply that
// does not finish in time gives a Timeout error that says so.
inline Result<QVariant> await(Reply *reply, int timeoutMs = kDefaultWaitMs)
{
    std::unique_ptr<Reply> owner(reply);
    if (!waitUntil(
            reply, &Reply::finished, [reply] { return reply->isFinished(); }, timeoutMs))
        return Error(Error::Kind::Timeout, QStringLiteral("test: reply did not finish"));
    return reply->result();
}

// Starts a runner (anything with start() and a finished() signal that start() never emits
// itself) and waits for its end; true when finished() came exactly once.
template<typename Runner>
bool runToEnd(Runner *runner, int timeoutMs = kDefaultWaitMs)
{
    QSignalSpy spy(runner, &Runner::finished);
    runner->start();
    return spy.wait(timeoutMs) && spy.size() == 1;
}

} // namespace db::test

// QTRY_VERIFY / QTRY_COMPARE with a time limit, waiting with waitFor (see there) instead of
// QTest::qWaitFor. The same checks: the condition is tested once more by QVERIFY / QCOMPARE.
#define DB_TRY_VERIFY_WITH_TIMEOUT(expr, timeoutMs)                                                \
    do {                                                                                           \
        db::test::waitFor([&] { return bool(expr); }, timeoutMs);                                  \
        QVERIFY(expr);                                                                             \
    } while (false)
#define DB_TRY_VERIFY2_WITH_TIMEOUT(expr, message, timeoutMs)                                      \
    do {                                                                                           \
        db::test::waitFor([&] { return bool(expr); }, timeoutMs);                                  \
        QVERIFY2(expr, message);                                                                   \
    } while (false)
#define DB_TRY_COMPARE_WITH_TIMEOUT(actual, expected, timeoutMs)                                   \
    do {                                                                                           \
        db::test::waitFor([&] { return (actual) == (expected); }, timeoutMs);                      \
        QCOMPARE(actual, expected);                                                                \
    } while (false)
#define DB_TRY_VERIFY(expr) DB_TRY_VERIFY_WITH_TIMEOUT(expr, db::test::kDefaultWaitMs)
#define DB_TRY_COMPARE(actual, expected)                                                           \
    DB_TRY_COMPARE_WITH_TIMEOUT(actual, expected, db::test::kDefaultWaitMs)
