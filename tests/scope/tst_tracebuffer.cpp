// Level 1: the bounded ring buffer of one channel: bounds, order, gaps, counters, search.
#include "scope/tracebuffer.h"

#include <QtTest>

using namespace db::scope;

class TstTraceBuffer : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void appendsInOrder()
    {
        TraceBuffer b(10);
        QVERIFY(b.isEmpty());
        for (int i = 0; i < 5; ++i)
            b.append(i * 0.1, i * 10);
        QCOMPARE(b.size(), 5);
        QCOMPARE(b.time(0), 0.0);
        QCOMPARE(b.value(4), 40.0);
        QCOMPARE(b.dropped(), 0);
    }
    void ringOverwritesOldestAndCountsThem()
    {
        TraceBuffer b(3);
        for (int i = 0; i < 10; ++i)
            b.append(i, i);
        QCOMPARE(b.size(), 3);
        QCOMPARE(b.value(0), 7.0);
        QCOMPARE(b.value(2), 9.0);
        QCOMPARE(b.droppedOverwritten(), 7);
        QCOMPARE(b.lostAtSource(), 0);
        QCOMPARE(b.lowerBound(8.0), 1);
    }
    void growsBeyondInitialStorageWithoutLoss()
    {
        TraceBuffer b(5000);
        for (int i = 0; i < 4000; ++i)
            b.append(i * 1e-3, i);
        QCOMPARE(b.size(), 4000);
        for (int i = 0; i < 4000; i += 397)
            QCOMPARE(b.value(i), double(i));
        QCOMPARE(b.dropped(), 0);
    }
    void growsAfterWrapAndDrop()
    {
        // Drop the front so the head moves, then grow: order must survive the unwrap.
        TraceBuffer b(100000);
        for (int i = 0; i < 1024; ++i)
            b.append(i, i);
        b.dropFront(500);
        for (int i = 1024; i < 3000; ++i)
            b.append(i, i);
        QCOMPARE(b.size(), 2500);
        for (qint64 i = 0; i < b.size(); ++i)
            QCOMPARE(b.value(i), double(i + 500));
    }
    void lossMarksTheNextSampleAsGap()
    {
        TraceBuffer b(100);
        b.append(0, 1);
        b.markLost(3);
        b.append(1, 2);
        b.append(2, 3);
        QVERIFY(!b.startsGap(0));
        QVERIFY(b.startsGap(1));
        QVERIFY(!b.startsGap(2));
        QCOMPARE(b.lostAtSource(), 3);
        QCOMPARE(b.dropped(), 3);
    }
    void timeNeverGoesBack()
    {
        TraceBuffer b(10);
        b.append(1.0, 1);
        b.append(0.5, 2);
        QCOMPARE(b.time(1), 1.0);
    }
    void searchAndTrim()
    {
        TraceBuffer b(100);
        for (int i = 0; i < 10; ++i)
            b.append(i, i);
        QCOMPARE(b.lowerBound(3.5), 4);
        QCOMPARE(b.lowerBound(3.0), 3);
        QCOMPARE(b.upperBound(3.0), 4);
        QCOMPARE(b.lowerBound(-1), 0);
        QCOMPARE(b.lowerBound(100), 10);
        b.dropBefore(2.0);
        QCOMPARE(b.firstTime(), 2.0);
        b.dropAfter(6.0);
        QCOMPARE(b.lastTime(), 6.0);
        QCOMPARE(b.size(), 5);
        QCOMPARE(b.dropped(), 0); // intentional trimming is not a loss
    }
    void shrinkingCapacityKeepsNewest()
    {
        TraceBuffer b(100);
        for (int i = 0; i < 50; ++i)
            b.append(i, i);
        b.setCapacity(10);
        QCOMPARE(b.size(), 10);
        QCOMPARE(b.value(0), 40.0);
        QCOMPARE(b.droppedOverwritten(), 40);
        b.append(50, 50);
        QCOMPARE(b.value(0), 41.0);
    }
    void memoryStaysBoundedAtCapacity()
    {
        TraceBuffer b(1000);
        for (int i = 0; i < 100000; ++i)
            b.append(i, i);
        QCOMPARE(b.size(), 1000);
        QCOMPARE(b.droppedOverwritten(), 99000);
        QCOMPARE(b.value(999), 99999.0);
    }
};

QTEST_GUILESS_MAIN(TstTraceBuffer)
#include "tst_tracebuffer.moc"
