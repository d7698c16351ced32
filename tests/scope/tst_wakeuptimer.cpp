// Level 1: the deadline timer of the polling source and the recorder: it fires once per
// deadline, never before it (also below a millisecond), from the event loop even when the
// deadline has passed, not after stop(), and a new deadline replaces the old one. Nothing here
// asserts how soon after the deadline it fires.
#include "scope/wakeuptimer.h"

#include <QSignalSpy>
#include <QtTest>

using db::scope::WakeupTimer;

namespace {
constexpr qint64 kMs = 1000000;
constexpr int kWaitMs = 5000;
constexpr int kQuietMs = 30; // long enough for a second (wrong) timeout to show
} // namespace

class TstWakeupTimer : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void firesOnceNotBeforeItsDeadline_data()
    {
        QTest::addColumn<qint64>("inNs");
        QTest::newRow("0.3 ms") << 300000ll;
        QTest::newRow("2 ms") << 2 * kMs;
        QTest::newRow("15 ms") << 15 * kMs;
    }
    void firesOnceNotBeforeItsDeadline()
    {
        QFETCH(qint64, inNs);
        QElapsedTimer clock;
        clock.start();
        WakeupTimer timer;
        qint64 firedAt = -1;
        connect(&timer, &WakeupTimer::timeout, this, [&] { firedAt = clock.nsecsElapsed(); });
        QSignalSpy spy(&timer, &WakeupTimer::timeout);
        const qint64 deadline = clock.nsecsElapsed() + inNs;
        timer.wakeAt(clock, deadline);
        QVERIFY(timer.isActive());
        QVERIFY(spy.wait(kWaitMs));
        QVERIFY2(firedAt >= deadline, qPrintable(QString::number(deadline - firedAt)));
        QVERIFY(!timer.isActive());
        QVERIFY(!spy.wait(kQuietMs));
        QCOMPARE(spy.count(), 1);
    }

    void passedDeadlineFiresFromTheLoop()
    {
        QElapsedTimer clock;
        clock.start();
        WakeupTimer timer;
        QSignalSpy spy(&timer, &WakeupTimer::timeout);
        timer.wakeAt(clock, 0);
        QCOMPARE(spy.count(), 0); // not from inside wakeAt()
        QVERIFY(spy.wait(kWaitMs));
        QCOMPARE(spy.count(), 1);
    }

    void stopCancels()
    {
        QElapsedTimer clock;
        clock.start();
        WakeupTimer timer;
        QSignalSpy spy(&timer, &WakeupTimer::timeout);
        timer.wakeAt(clock, clock.nsecsElapsed() + kMs);
        timer.stop();
        QVERIFY(!timer.isActive());
        QVERIFY(!spy.wait(kQuietMs));
        // An expiry that happened before stop() but was not yet delivered is dropped too.
        timer.wakeAt(clock, clock.nsecsElapsed() + kMs / 10);
        const qint64 spinUntil = clock.nsecsElapsed() + kMs; // no event processed meanwhile
        while (clock.nsecsElapsed() < spinUntil) { }
        timer.stop();
        QVERIFY(!spy.wait(kQuietMs));
        QCOMPARE(spy.count(), 0);
    }

    void newDeadlineReplacesTheOld()
    {
        QElapsedTimer clock;
        clock.start();
        WakeupTimer timer;
        qint64 firedAt = -1;
        connect(&timer, &WakeupTimer::timeout, this, [&] { firedAt = clock.nsecsElapsed(); });
        QSignalSpy spy(&timer, &WakeupTimer::timeout);
        timer.wakeAt(clock, clock.nsecsElapsed() + kMs);
        const qint64 later = clock.nsecsElapsed() + 20 * kMs;
        timer.wakeAt(clock, later);
        QVERIFY(spy.wait(kWaitMs));
        QVERIFY(firedAt >= later);
        QVERIFY(!spy.wait(kQuietMs));
        QCOMPARE(spy.count(), 1);
    }
};

QTEST_GUILESS_MAIN(TstWakeupTimer)
#include "tst_wakeuptimer.moc"
