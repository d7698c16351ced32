// Level 1: the trace buffer's min/max summary and the decimation that reads it, against brute
// force (no wall-clock assertions).
#include "scope/decimation.h"

#include <QTest>

#include <cmath>
#include <map>
#include <random>

using namespace db::scope;

namespace {

// Samples every `period` seconds from t = 0 with values from `gen`.
template<typename Gen>
TraceBuffer makeBuffer(qint64 count, double period, Gen gen, qint64 capacity = 0)
{
    TraceBuffer buffer(capacity > 0 ? capacity : count);
    for (qint64 i = 0; i < count; ++i)
        buffer.append(double(i) * period, gen(i));
    return buffer;
}

struct Column
{
    double min = INFINITY;
    double max = -INFINITY;
    int samples = 0;
};

// Brute-force extent of [lo, hi): min, max and whether the minimum comes first.
TraceBuffer::Extent bruteExtent(const TraceBuffer &b, qint64 lo, qint64 hi)
{
    qint64 iMin = -1, iMax = -1;
    for (qint64 i = lo; i < hi; ++i) {
        if (std::isnan(b.value(i)))
            continue;
        if (iMin < 0 || b.value(i) < b.value(iMin))
            iMin = i;
        if (iMax < 0 || b.value(i) > b.value(iMax))
            iMax = i;
    }
    if (iMin < 0)
        return {};
    return { b.value(iMin), b.value(iMax), iMin <= iMax, true };
}

void verifyExtents(const TraceBuffer &b, int ranges, quint32 seed)
{
    std::mt19937 rng(seed);
    std::uniform_int_distribution<qint64> index(0, b.size());
    for (int k = 0; k < ranges; ++k) {
        qint64 lo = index(rng);
        qint64 hi = k % 3 == 0 ? std::min(b.size(), lo + index(rng) % 40) : index(rng);
        if (lo > hi)
            std::swap(lo, hi);
        const TraceBuffer::Extent x = b.extent(lo, hi);
        const TraceBuffer::Extent e = bruteExtent(b, lo, hi);
        QCOMPARE(x.valid, e.valid);
        if (!e.valid)
            continue;
        QCOMPARE(x.min, e.min);
        QCOMPARE(x.max, e.max);
        if (x.min != x.max)
            QCOMPARE(x.minFirst, e.minFirst);
    }
}

// The column part a visible sample belongs to under decimate()'s snapping rule: the column of
// the time of u(i) = max(start of i's unit block, lo, last gap <= i), and the gap stretch.
struct Binning
{
    const TraceBuffer &b;
    double t0, t1;
    int columns;
    qint64 lo, hi, unit;
    int level;

    Binning(const TraceBuffer &buffer, double from, double to, int cols, qint64 u)
        : b(buffer)
        , t0(from)
        , t1(to)
        , columns(cols)
        , lo(buffer.lowerBound(from))
        , hi(buffer.upperBound(to))
        , unit(u)
        , level(-1)
    {
        while (level + 1 < TraceBuffer::kSummaryLevels
               && TraceBuffer::summaryBlockSize(level + 1) <= unit)
            ++level;
    }
    std::pair<int, qint64> key(qint64 i, qint64 lastGap) const
    {
        qint64 u = unit == 1 ? i : b.summaryBlockStart(level, i);
        u = std::max({ u, lo, lastGap });
        const int c = std::clamp(int((b.time(u) - t0) * (columns / (t1 - t0))), 0, columns - 1);
        return { c, lastGap };
    }
};

// Checks that every column part of the output reproduces its exact minimum and maximum with at
// most two points, against a brute-force scan with the documented binning; returns the parts.
int verifyColumns(const TraceBuffer &b, const DecimatedSeries &d, double t0, double t1, int columns)
{
    const Binning bin(b, t0, t1, columns, d.unit);
    std::map<std::pair<int, qint64>, Column> expected;
    std::vector<qint64> lastGapOf(size_t(std::max<qint64>(0, bin.hi - bin.lo)));
    qint64 lastGap = -1;
    for (qint64 i = bin.lo; i < bin.hi; ++i) {
        if (b.startsGap(i) && i > bin.lo)
            lastGap = i;
        lastGapOf[size_t(i - bin.lo)] = lastGap;
        Column &col = expected[bin.key(i, lastGap)];
        if (std::isnan(b.value(i)))
            continue;
        col.min = std::min(col.min, b.value(i));
        col.max = std::max(col.max, b.value(i));
        ++col.samples;
    }
    std::map<std::pair<int, qint64>, Column> got;
    for (size_t k = 0; k < d.time.size(); ++k) {
        if (std::isnan(d.value[k]))
            continue;
        const qint64 j = b.lowerBound(d.time[k]); // times are unique in these tests
        if (j < bin.lo || j >= bin.hi)
            continue; // the neighbours that reach the edges
        Column &col = got[bin.key(j, lastGapOf[size_t(j - bin.lo)])];
        col.min = std::min(col.min, d.value[k]);
        col.max = std::max(col.max, d.value[k]);
        ++col.samples;
    }
    int parts = 0;
    for (const auto &[key, e] : expected) {
        const QString where = QStringLiteral("column %1 part %2").arg(key.first).arg(key.second);
        if (e.samples == 0)
            continue;
        ++parts;
        const auto it = got.find(key);
        if (it == got.end())
            QTest::qFail(qPrintable(where + QStringLiteral(" missing")), __FILE__, __LINE__);
        if (it == got.end())
            return -1;
        if (d.decimated && it->second.samples > 2)
            QTest::qFail(qPrintable(where + QStringLiteral(": more than two points")), __FILE__,
                         __LINE__);
        if (it->second.min != e.min || it->second.max != e.max)
            QTest::qFail(qPrintable(QStringLiteral("%1: %2..%3, expected %4..%5")
                                        .arg(where)
                                        .arg(it->second.min)
                                        .arg(it->second.max)
                                        .arg(e.min)
                                        .arg(e.max)),
                         __FILE__, __LINE__);
    }
    if (got.size() != size_t(parts))
        QTest::qFail("points in a column part that has no samples", __FILE__, __LINE__);
    return parts;
}

void verifySorted(const DecimatedSeries &d)
{
    QCOMPARE(d.time.size(), d.value.size());
    for (size_t k = 1; k < d.time.size(); ++k)
        QVERIFY2(d.time[k] >= d.time[k - 1], qPrintable(QString::number(k)));
}

int countNan(const DecimatedSeries &d)
{
    return int(
        std::count_if(d.value.begin(), d.value.end(), [](double v) { return std::isnan(v); }));
}

// Snapping bounds the work per column: a column spans at most kSummaryFanout units.
void verifyUnit(const DecimatedSeries &d, int columns)
{
    const double perColumn = double(d.visibleSamples) / columns;
    QVERIFY(d.unit >= 1);
    QVERIFY(double(d.unit) <= std::max(1.0, perColumn));
    if (perColumn >= TraceBuffer::kSummaryFanout
        && d.unit < TraceBuffer::summaryBlockSize(TraceBuffer::kSummaryLevels - 1))
        QVERIFY(perColumn < double(d.unit * TraceBuffer::kSummaryFanout));
}

} // namespace

class TstDecimation : public QObject
{
    Q_OBJECT

private slots:
    void emptyAndDegenerateRanges()
    {
        TraceBuffer empty(10);
        QVERIFY(decimate(empty, 0, 1, 100).time.empty());
        QVERIFY(!empty.extent(0, 0).valid);

        TraceBuffer b = makeBuffer(100, 0.01, [](qint64 i) { return double(i); });
        QVERIFY(decimate(b, 1, 1, 100).time.empty()); // t1 == t0
        QVERIFY(decimate(b, 0, 1, 0).time.empty()); // no columns
        QVERIFY(!b.extent(40, 40).valid);
    }

    void fewSamplesAreCopiedUnchanged()
    {
        TraceBuffer b = makeBuffer(50, 0.1, [](qint64 i) { return std::sin(double(i)); });
        const DecimatedSeries d = decimate(b, 0, 4.9, 100);
        QVERIFY(!d.decimated);
        QCOMPARE(d.visibleSamples, 50);
        QCOMPARE(qint64(d.time.size()), 50);
        for (qint64 i = 0; i < 50; ++i) {
            QCOMPARE(d.time[size_t(i)], b.time(i));
            QCOMPARE(d.value[size_t(i)], b.value(i));
        }
        // A sub-range brings one neighbour on each side for the line to reach the edges.
        const DecimatedSeries z = decimate(b, 1.05, 2.05, 100);
        QCOMPARE(z.visibleSamples, 10);
        QCOMPARE(z.time.front(), b.time(10));
        QCOMPARE(z.time.back(), b.time(21));
    }

    void minMaxExactPerColumn_data()
    {
        QTest::addColumn<qint64>("count");
        QTest::addColumn<double>("t0");
        QTest::addColumn<double>("t1");
        QTest::addColumn<int>("columns");
        QTest::newRow("full view") << qint64(200000) << 0.0 << 199.999 << 800;
        QTest::newRow("zoomed") << qint64(200000) << 50.1234 << 61.77 << 1000;
        QTest::newRow("zoomed below one block") << qint64(200000) << 20.0 << 25.0 << 600;
        QTest::newRow("range beyond data") << qint64(200000) << -30.0 << 400.0 << 1200;
        QTest::newRow("few columns") << qint64(200000) << 3.0 << 150.0 << 7;
        QTest::newRow("one column") << qint64(200000) << 3.0 << 150.0 << 1;
        QTest::newRow("odd sizes") << qint64(4099) << 0.3 << 3.7 << 333;
    }
    void minMaxExactPerColumn()
    {
        QFETCH(qint64, count);
        QFETCH(double, t0);
        QFETCH(double, t1);
        QFETCH(int, columns);
        std::mt19937 rng(7);
        std::normal_distribution<double> noise(0.0, 50.0);
        TraceBuffer b = makeBuffer(count, 0.001, [&](qint64 i) {
            return 1000.0 * std::sin(double(i) * 0.0007) + noise(rng) + (i % 9973 == 0 ? 5e4 : 0);
        });
        const DecimatedSeries d = decimate(b, t0, t1, columns);
        QVERIFY(d.decimated);
        QVERIFY(qint64(d.time.size()) <= 2 * columns + 2);
        verifySorted(d);
        verifyUnit(d, columns);
        QVERIFY(verifyColumns(b, d, t0, t1, columns) > 0);
        QCOMPARE(countNan(d), 0);
        // The extremes of the whole view are in the points: nothing is lost by snapping.
        const TraceBuffer::Extent all = bruteExtent(b, b.lowerBound(t0), b.upperBound(t1));
        QVERIFY(std::find(d.value.begin(), d.value.end(), all.min) != d.value.end());
        QVERIFY(std::find(d.value.begin(), d.value.end(), all.max) != d.value.end());
    }

    void extentMatchesBruteForce()
    {
        std::mt19937 rng(11);
        std::uniform_real_distribution<double> value(-1e6, 1e6);
        TraceBuffer b = makeBuffer(70000, 1e-4, [&](qint64 i) {
            return i % 5003 == 17 ? std::nan("") : value(rng); // NaN values are skipped
        });
        verifyExtents(b, 400, 1);
    }

    void gapsBecomeBreaks()
    {
        TraceBuffer b(100000);
        const QList<qint64> gapAt = { 1000, 1001, 25000, 25003, 70000, 99999 };
        for (qint64 i = 0; i < 100000; ++i) {
            if (gapAt.contains(i))
                b.markLost(3);
            b.append(double(i) * 0.001, double(i % 100) + (i == 25001 ? 500 : 0));
        }
        QCOMPARE(b.gapsIn(0, b.size()), std::vector<qint64>(gapAt.begin(), gapAt.end()));
        QCOMPARE(b.gapsIn(1001, 70000), std::vector<qint64>({ 1001, 25000, 25003 }));

        // Decimated: every gap inside the view is one NaN, right at the gap sample's time.
        const DecimatedSeries d = decimate(b, 0, 99.999, 500);
        QVERIFY(d.decimated);
        verifySorted(d);
        QCOMPARE(countNan(d), gapAt.size());
        for (qint64 g : gapAt) {
            const auto it = std::find(d.time.begin(), d.time.end(), b.time(g));
            QVERIFY(it != d.time.end());
            QVERIFY(std::isnan(d.value[size_t(it - d.time.begin())]));
        }
        verifyColumns(b, d, 0, 99.999, 500);
        // The short stretch between two gaps keeps its own peak.
        QVERIFY(std::find(d.value.begin(), d.value.end(), 501.0) != d.value.end());

        // Raw copy (zoomed in): the NaN sits between the samples around the gap.
        const DecimatedSeries z = decimate(b, 24.99, 25.01, 500);
        QVERIFY(!z.decimated);
        QCOMPARE(countNan(z), 2);
        const auto nanAt =
            std::find_if(z.value.begin(), z.value.end(), [](double v) { return std::isnan(v); });
        const size_t k = size_t(nanAt - z.value.begin());
        QCOMPARE(z.time[k - 1], b.time(24999));
        QCOMPARE(z.time[k + 1], b.time(25000));

        // The sample just right of the view starts a gap: the break is still drawn.
        const DecimatedSeries edge = decimate(b, 0.5, 69.9995, 300);
        QCOMPARE(countNan(edge), 5);
    }

    void summaryFollowsIncrementalAppends()
    {
        // Appended in pieces of every size, with checks in between: the same answers as a
        // brute-force scan at every step (blocks complete one sample at a time).
        TraceBuffer b(1'000'000);
        std::mt19937 rng(5);
        std::uniform_real_distribution<double> value(-100, 100);
        std::uniform_int_distribution<int> piece(1, 5000);
        qint64 n = 0;
        for (int round = 0; round < 40; ++round) {
            const int count = round < 20 ? round + 1 : piece(rng);
            for (int i = 0; i < count; ++i, ++n)
                b.append(double(n) * 1e-3, value(rng));
            verifyExtents(b, 30, quint32(round));
            if (QTest::currentTestFailed())
                return;
        }
        const DecimatedSeries d = decimate(b, 0, b.lastTime(), 300);
        QVERIFY(d.unit > 1);
        verifyColumns(b, d, 0, b.lastTime(), 300);
    }

    void summaryFollowsRingDropsAndClear()
    {
        TraceBuffer b(50000); // ring: the oldest samples get overwritten
        std::mt19937 rng(3);
        std::uniform_real_distribution<double> value(-10, 10);
        qint64 n = 0; // samples appended since the last clear()
        const auto appendSome = [&](qint64 count) {
            for (qint64 i = 0; i < count; ++i, ++n) {
                if (n % 7919 == 0)
                    b.markLost(1);
                b.append(double(n) * 0.001, value(rng));
            }
        };
        const auto check = [&]() {
            // Blocks are aligned to the samples appended since clear(), not to index 0.
            const qint64 base = n - b.size();
            for (qint64 i : { qint64(0), qint64(1), b.size() / 2, b.size() - 1 })
                QCOMPARE(b.summaryBlockStart(1, i), i - (base + i) % 256);
            verifyExtents(b, 60, quint32(n));
            const double t0 = b.firstTime();
            const double t1 = b.lastTime();
            const DecimatedSeries d = decimate(b, t0, t1, 640);
            verifySorted(d);
            verifyColumns(b, d, t0, t1, 640);
            QCOMPARE(countNan(d), int(b.gapsIn(1, b.size()).size()));
        };
        appendSome(12345);
        check();
        for (int round = 0; round < 8; ++round) { // past capacity: overwrites
            appendSome(9001 + round * 17);
            check();
        }
        QVERIFY(b.droppedOverwritten() > 0);
        b.dropBefore(b.time(b.size() / 3)); // roll window
        appendSome(777);
        check();
        b.dropFront(4096);
        check();
        const qint64 before = b.size();
        b.dropAfter(b.time(b.size() / 2)); // capture cut: the blocks past the end are not used
        n -= before - b.size(); // appends go on from the cut
        check();
        appendSome(5000); // and are summarised anew
        check();
        b.setCapacity(20000); // re-packed, summary rebuilt
        check();
        b.clear();
        n = 0;
        appendSome(3000); // new recording with times from 0 again
        check();
        appendSome(40000);
        check();
    }

    void bigInputStaysBounded()
    {
        const qint64 count = 4'000'000;
        TraceBuffer b = makeBuffer(
            count, 1e-5, [](qint64 i) { return double((i * 2654435761LL) % 100003) - 50000.0; });
        const DecimatedSeries full = decimate(b, 0, b.lastTime(), 1600);
        QCOMPARE(full.visibleSamples, count);
        QVERIFY(qint64(full.time.size()) <= 2 * 1600 + 2);
        QCOMPARE(full.unit, 256); // 2500 samples per column: 9.8 blocks of 256 each
        verifyColumns(b, full, 0, b.lastTime(), 1600);
        const DecimatedSeries zoom = decimate(b, 12.0, 12.05, 1600);
        QCOMPARE(zoom.visibleSamples, 5001);
        QCOMPARE(zoom.unit, 1);
        verifyColumns(b, zoom, 12.0, 12.05, 1600);
    }

    void negativeScaleKeepsExtremesAfterTransform()
    {
        // The view applies display = raw * scale + offset after decimation; with a negative
        // scale the column's maximum becomes its minimum, still exact.
        TraceBuffer b = makeBuffer(10000, 0.001, [](qint64 i) { return double(i % 37) - 18; });
        const DecimatedSeries d = decimate(b, 0, 9.999, 50);
        double lo = INFINITY, hi = -INFINITY;
        for (double v : d.value) {
            lo = std::min(lo, -2 * v + 1);
            hi = std::max(hi, -2 * v + 1);
        }
        QCOMPARE(lo, -2 * 18.0 + 1);
        QCOMPARE(hi, -2 * -18.0 + 1);
    }
};

QTEST_APPLESS_MAIN(TstDecimation)
#include "tst_decimation.moc"
