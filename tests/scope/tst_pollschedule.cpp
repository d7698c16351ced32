// Level 1: the polling schedule driven by a clock the test controls (no wall clock): late
// wake-ups are caught up without drift, a wake-up or a read late by several periods is caught
// up read by read without a lost sample, a stall longer than the catch-up window loses only the
// oldest slots, a stalled link counts every slot that ended, mixed rates on a simulated link
// that serves one read at a time lose nothing below its capacity (also when the host stalls
// now and then) and count honestly above it.
#include "scope/pollschedule.h"

#include <QtTest>

#include <algorithm>
#include <deque>

using namespace db::scope;

namespace {

constexpr qint64 kMs = 1000000;
constexpr qint64 kUs = 1000;

// A link that answers one read at a time, in order, each after `serviceNs`, and a host that
// wakes `wakeLateNs` after each deadline and, with stallNs > 0, sleeps through the first
// stallNs of every stallEveryNs (a loaded machine); time jumps from event to event.
struct SimulatedLink
{
    SimulatedLink(PollSchedule &s, qint64 service, qint64 wakeLate, qint64 stallEvery = 0,
                  qint64 stall = 0)
        : schedule(s)
        , serviceNs(service)
        , wakeLateNs(wakeLate)
        , stallEveryNs(stallEvery)
        , stallNs(stall)
    { }

    PollSchedule &schedule;
    qint64 serviceNs;
    qint64 wakeLateNs;
    qint64 stallEveryNs;
    qint64 stallNs;
    qint64 now = 0;
    std::deque<int> queue; // channels whose read waits for (or is on) the link
    qint64 busyUntil = 0;
    QList<qint64> delivered;
    QList<qint64> lost;

    void start()
    {
        delivered = lost = QList<qint64>(schedule.channelCount(), 0);
        schedule.start(now);
        pump();
    }
    void pump()
    {
        for (const PollSchedule::Read &r : schedule.due(now)) {
            lost[r.channel] += r.lostBefore;
            if (queue.empty())
                busyUntil = now + serviceNs;
            queue.push_back(r.channel);
        }
    }
    void runUntil(qint64 end)
    {
        while (true) {
            qint64 next = end;
            if (const auto due = schedule.nextDueNs()) {
                qint64 wake = std::max(now, *due + wakeLateNs);
                if (stallNs > 0 && wake % stallEveryNs < stallNs)
                    wake += stallNs - wake % stallEveryNs; // asleep: the host wakes after it
                next = std::min(next, wake);
            }
            if (!queue.empty())
                next = std::min(next, busyUntil);
            if (next >= end) {
                now = end;
                return;
            }
            now = next;
            if (!queue.empty() && busyUntil == now) {
                const int channel = queue.front();
                queue.pop_front();
                ++delivered[channel];
                schedule.finished(channel);
                if (!queue.empty())
                    busyUntil = now + serviceNs;
            }
            pump();
        }
    }
    void stop()
    {
        const QList<qint64> more = schedule.lostUntil(now);
        for (int i = 0; i < more.size(); ++i)
            lost[i] += more.at(i);
    }
};

} // namespace

class TstPollSchedule : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void onTimeEverySlotGetsItsRead()
    {
        PollSchedule s;
        s.addChannel(1 * kMs);
        s.start(0);
        for (int k = 0; k < 5; ++k) {
            const auto reads = s.due(k * kMs);
            QCOMPARE(reads.size(), 1);
            QCOMPARE(reads.at(0).lostBefore, 0);
            QCOMPARE(s.nextDueNs(), std::nullopt); // its read is in flight
            s.finished(0);
            QCOMPARE(s.nextDueNs(), (k + 1) * kMs);
            QVERIFY(s.due((k + 1) * kMs - 1).isEmpty());
        }
    }

    void lateWakeUpsAreCaughtUpWithoutDrift()
    {
        PollSchedule s;
        s.addChannel(1 * kMs);
        s.start(0);
        // Every wake-up comes 0.9 ms late: each read still starts inside its own slot, and the
        // next deadline is the slot after it, not "now + period".
        for (int k = 0; k < 100; ++k) {
            const auto reads = s.due(k * kMs + 900 * kUs);
            QCOMPARE(reads.size(), 1);
            QCOMPARE(reads.at(0).lostBefore, 0);
            s.finished(0);
            QCOMPARE(s.nextDueNs(), (k + 1) * kMs);
        }
    }

    void wakeUpPastTheNextSlotIsCaughtUpReadByRead()
    {
        PollSchedule s;
        s.addChannel(1 * kMs);
        s.start(0);
        QCOMPARE(s.due(0).size(), 1);
        s.finished(0);
        // The host slept from 0 to 3.5 ms: slots 1, 2 and 3 have begun. Each gets a read of its
        // own, back to back, and none is lost.
        for (int k = 1; k <= 3; ++k) {
            QCOMPARE(s.nextDueNs(), k * kMs); // in the past: due at once
            const auto reads = s.due(3500 * kUs);
            QCOMPARE(reads.size(), 1);
            QCOMPARE(reads.at(0).lostBefore, 0);
            s.finished(0);
        }
        QCOMPARE(s.nextDueNs(), 4 * kMs); // caught up, and on the old grid
        QVERIFY(s.due(3500 * kUs).isEmpty());
    }

    void withoutCatchUpALateWakeUpLosesTheSkippedSlots()
    {
        PollSchedule s;
        s.setCatchUpNs(0);
        s.addChannel(1 * kMs);
        s.start(0);
        QCOMPARE(s.due(0).size(), 1);
        s.finished(0);
        // The host slept from 0 to 3.5 ms: slots 1 and 2 ended unread, slot 3 is served.
        const auto reads = s.due(3500 * kUs);
        QCOMPARE(reads.size(), 1);
        QCOMPARE(reads.at(0).lostBefore, 2);
        s.finished(0);
        QCOMPARE(s.nextDueNs(), 4 * kMs);
        // Exactly at the next slot's begin the previous one has ended.
        QCOMPARE(s.due(5 * kMs).at(0).lostBefore, 1);
    }

    void stallLongerThanTheWindowLosesOnlyTheOldestSlots()
    {
        PollSchedule s;
        s.setCatchUpNs(10 * kMs);
        s.addChannel(1 * kMs);
        s.start(0);
        QCOMPARE(s.due(0).size(), 1);
        s.finished(0);
        // Asleep until 25.5 ms: slots 1..25 have begun, only the newest 10 can be caught up.
        auto reads = s.due(25500 * kUs);
        QCOMPARE(reads.size(), 1);
        QCOMPARE(reads.at(0).lostBefore, 15);
        s.finished(0);
        for (int k = 17; k <= 25; ++k) {
            QCOMPARE(s.nextDueNs(), k * kMs);
            reads = s.due(25800 * kUs);
            QCOMPARE(reads.size(), 1);
            QCOMPARE(reads.at(0).lostBefore, 0);
            s.finished(0);
        }
        QCOMPARE(s.nextDueNs(), 26 * kMs);
        // A slow channel may owe kMinCatchUpSlots slots even when they exceed the window.
        PollSchedule slow;
        slow.setCatchUpNs(10 * kMs);
        slow.addChannel(100 * kMs);
        slow.start(0);
        QCOMPARE(slow.due(0).size(), 1);
        slow.finished(0);
        QCOMPARE(slow.due(250 * kMs).at(0).lostBefore, 0); // slots 1 and 2 owed: both read
        slow.finished(0);
        QCOMPARE(slow.due(250 * kMs).at(0).lostBefore, 0);
    }

    void slowReadIsCaughtUp()
    {
        PollSchedule s;
        s.addChannel(1 * kMs);
        s.start(0);
        QCOMPARE(s.due(0).size(), 1);
        QVERIFY(s.due(1 * kMs).isEmpty()); // slot 1 begins while the read is still in flight
        QCOMPARE(s.nextDueNs(), std::nullopt);
        s.finished(0); // answered after 1.5 ms: slot 1's read starts late but inside slot 1
        QCOMPARE(s.nextDueNs(), 1 * kMs);
        auto reads = s.due(1500 * kUs);
        QCOMPARE(reads.size(), 1);
        QCOMPARE(reads.at(0).lostBefore, 0);
        // That read takes 2.2 ms: slots 2 and 3 have begun; both are read, one after the other.
        s.finished(0);
        reads = s.due(3700 * kUs);
        QCOMPARE(reads.at(0).lostBefore, 0);
        s.finished(0);
        QCOMPARE(s.nextDueNs(), 3 * kMs);
        reads = s.due(3750 * kUs);
        QCOMPARE(reads.at(0).lostBefore, 0);
        s.finished(0);
        QCOMPARE(s.nextDueNs(), 4 * kMs);
    }

    void stalledLinkCountsEveryEndedSlotOnce()
    {
        PollSchedule s;
        s.addChannel(1 * kMs);
        s.addChannel(4 * kMs);
        s.start(0);
        QCOMPARE(s.due(0).size(), 2);
        // No answer comes; at 10.5 ms slots 1..9 (and 1 of the slow channel) have ended.
        const QList<qint64> lost = s.lostUntil(10500 * kUs);
        QCOMPARE(lost, (QList<qint64> { 9, 1 }));
        QCOMPARE(s.lostUntil(10500 * kUs), (QList<qint64> { 0, 0 }));
        QCOMPARE(s.lostUntil(11 * kMs), (QList<qint64> { 1, 0 }));
    }

    void freeRunningChannelsAreAlwaysDueAndNeverLose()
    {
        PollSchedule s;
        s.addChannel(0);
        s.addChannel(2 * kMs);
        s.start(0);
        auto reads = s.due(0);
        QCOMPARE(reads.size(), 2);
        QCOMPARE(reads.at(0).channel, 1); // fixed-rate channels first
        QCOMPARE(reads.at(1).channel, 0);
        QVERIFY(s.due(50 * kMs).isEmpty()); // both in flight: nothing twice
        s.finished(0);
        QVERIFY(*s.nextDueNs() <= 50 * kMs);
        reads = s.due(50 * kMs);
        QCOMPARE(reads.size(), 1);
        QCOMPARE(reads.at(0).lostBefore, 0);
        QCOMPARE(s.lostUntil(100 * kMs).at(0), 0);
    }

    void oldestSlotIsReadFirst()
    {
        PollSchedule s;
        s.addChannel(3 * kMs);
        s.addChannel(2 * kMs);
        s.start(0);
        QCOMPARE(s.due(0).size(), 2);
        s.finished(0);
        s.finished(1);
        // At 3.2 ms channel 1's slot began at 2 ms, channel 0's at 3 ms: channel 1 goes first.
        const auto reads = s.due(3200 * kUs);
        QCOMPARE(reads.size(), 2);
        QCOMPARE(reads.at(0).channel, 1);
        QCOMPARE(reads.at(1).channel, 0);
        QCOMPARE(reads.at(0).lostBefore, 0);
    }

    void mixedRatesBelowCapacityLoseNothing_data()
    {
        QTest::addColumn<qint64>("serviceNs");
        QTest::addColumn<qint64>("wakeLateNs");
        QTest::addColumn<qint64>("stallEveryNs");
        QTest::addColumn<qint64>("stallNs");
        QTest::newRow("fast link, prompt host") << 50 * kUs << 0ll << 0ll << 0ll;
        QTest::newRow("fast link, host 0.7 ms late") << 50 * kUs << 700 * kUs << 0ll << 0ll;
        // 16 reads of 55 us in the busiest millisecond: the link is ~90 % busy at worst.
        QTest::newRow("busy link") << 55 * kUs << 20 * kUs << 0ll << 0ll;
        // A loaded machine: the host sleeps through 8 ms of every 50 (several periods of the
        // 1 ms channels) with the link at half its capacity.
        QTest::newRow("half-busy link, host stalls 8 ms")
            << 30 * kUs << 50 * kUs << 50 * kMs << 8 * kMs;
        QTest::newRow("fast link, host stalls 40 ms") << 10 * kUs << 0ll << 200 * kMs << 40 * kMs;
    }
    void mixedRatesBelowCapacityLoseNothing()
    {
        QFETCH(qint64, serviceNs);
        QFETCH(qint64, wakeLateNs);
        QFETCH(qint64, stallEveryNs);
        QFETCH(qint64, stallNs);
        PollSchedule s;
        const QList<qint64> periods { 1, 1, 1, 1, 2, 2, 2, 2, 5, 5, 5, 5, 10, 10, 10, 10 };
        for (qint64 p : periods)
            s.addChannel(p * kMs);
        SimulatedLink link { s, serviceNs, wakeLateNs, stallEveryNs, stallNs };
        link.start();
        link.runUntil(1000 * kMs);
        link.stop();
        for (int i = 0; i < periods.size(); ++i) {
            QCOMPARE(link.lost.at(i), 0);
            // Every slot that began before the end got its read (the last one may be on the way).
            QVERIFY2(std::abs(link.delivered.at(i) - 1000 / periods.at(i)) <= 1,
                     qPrintable(QStringLiteral("channel %1: %2").arg(i).arg(link.delivered.at(i))));
        }
    }

    void overloadedLinkCountsEverySlotItCouldNotServe()
    {
        PollSchedule s;
        for (int i = 0; i < 8; ++i)
            s.addChannel(1 * kMs);
        // 8 reads of 150 us per 1 ms slot: the link can do 1000 / 0.15 = 6667 of 8000 reads/s.
        SimulatedLink link { s, 150 * kUs, 0 };
        link.start();
        link.runUntil(1000 * kMs);
        link.stop();
        qint64 delivered = 0;
        qint64 lost = 0;
        for (int i = 0; i < 8; ++i) {
            delivered += link.delivered.at(i);
            lost += link.lost.at(i);
            // Every slot that began is accounted for: read, lost, or its read still running.
            QVERIFY(std::abs(link.delivered.at(i) + link.lost.at(i) - 1000) <= 1);
        }
        QVERIFY2(lost > 0, "an overloaded link must show lost samples");
        // The link was kept busy: what it could carry was delivered.
        QVERIFY2(delivered >= 6600, qPrintable(QString::number(delivered)));
    }
};

QTEST_GUILESS_MAIN(TstPollSchedule)
#include "tst_pollschedule.moc"
