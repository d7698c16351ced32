// Level 1: min/max decimation and its pyramid (scope/decimation.h) against brute force.
#include "scope/decimation.h"

#include <QTest>

#include <cmath>
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

// Brute-force min/max of every column of [t0, t1] (the same binning as decimate()).
std::vector<Column> bruteColumns(const TraceBuffer &b, double t0, double t1, int columns)
{
    std::vector<Column> cols(static_cast<size_t>(columns));
    const double width = (t1 - t0) / columns;
    for (qint64 i = 0; i < b.size(); ++i) {
        const double t = b.time(i);
        if (t < t0 || t > t1)
            continue;
        int c = std::clamp(int(std::floor((t - t0) / width)), 0, columns - 1);
        while (c + 1 < columns && t >= t0 + (c + 1) * width)
            ++c;
        while (c > 0 && t < t0 + c * width)
            --c;
        Column &col = cols[size_t(c)];
        col.min = std::min(col.min, b.value(i));
        col.max = std::max(col.max, b.value(i));
        ++col.samples;
    }
    return cols;
}

// Checks that the decimated points of every column (time inside it) reproduce its exact
// minimum and maximum and that nothing lies outside a column's value range.
void verifyColumns(const TraceBuffer &b, const DecimatedSeries &d, double t0, double t1,
                   int columns)
{
    const std::vector<Column> expected = bruteColumns(b, t0, t1, columns);
    std::vector<Column> got(static_cast<size_t>(columns));
    const double width = (t1 - t0) / columns;
    std::vector<int> breaks(static_cast<size_t>(columns));
    for (size_t k = 0; k < d.time.size(); ++k) {
        const double t = d.time[k];
        if (t < t0 || t > t1)
            continue;
        int c = int(std::floor((t - t0) / width));
        c = std::clamp(c, 0, columns - 1);
        while (c + 1 < columns && t >= t0 + (c + 1) * width)
            ++c;
        while (c > 0 && t < t0 + c * width)
            --c;
        if (std::isnan(d.value[k])) {
            ++breaks[size_t(c)];
            continue;
        }
        got[size_t(c)].min = std::min(got[size_t(c)].min, d.value[k]);
        got[size_t(c)].max = std::max(got[size_t(c)].max, d.value[k]);
        ++got[size_t(c)].samples;
    }
    for (int c = 0; c < columns; ++c) {
        const Column &e = expected[size_t(c)];
        const Column &g = got[size_t(c)];
        QVERIFY2((e.samples == 0) == (g.samples == 0), qPrintable(QString::number(c)));
        if (e.samples == 0)
            continue;
        // At most two points per column, or per part of a column split by gaps.
        QVERIFY2(g.samples <= 2 * (1 + breaks[size_t(c)]) || !d.decimated,
                 qPrintable(QString::number(c)));
        QCOMPARE(g.min, e.min);
        QCOMPARE(g.max, e.max);
    }
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

} // namespace

class TstDecimation : public QObject
{
    Q_OBJECT

private slots:
    void emptyAndDegenerateRanges()
    {
        TraceBuffer empty(10);
        MinMaxPyramid p;
        p.sync(empty);
        QVERIFY(decimate(empty, p, 0, 1, 100).time.empty());

        TraceBuffer b = makeBuffer(100, 0.01, [](qint64 i) { return double(i); });
        p.sync(b);
        QVERIFY(decimate(b, p, 1, 1, 100).time.empty()); // t1 == t0
        QVERIFY(decimate(b, p, 0, 1, 0).time.empty()); // no columns
        MinMaxPyramid stale; // not synced: refuses instead of reading out of range
        QVERIFY(decimate(b, stale, 0, 1, 100).time.empty());
    }

    void fewSamplesAreCopiedUnchanged()
    {
        TraceBuffer b = makeBuffer(50, 0.1, [](qint64 i) { return std::sin(double(i)); });
        MinMaxPyramid p;
        p.sync(b);
        const DecimatedSeries d = decimate(b, p, 0, 4.9, 100);
        QVERIFY(!d.decimated);
        QCOMPARE(d.visibleSamples, 50);
        QCOMPARE(qint64(d.time.size()), 50);
        for (qint64 i = 0; i < 50; ++i) {
            QCOMPARE(d.time[size_t(i)], b.time(i));
            QCOMPARE(d.value[size_t(i)], b.value(i));
        }
        // A sub-range brings one neighbour on each side for the line to reach the edges.
        const DecimatedSeries z = decimate(b, p, 1.05, 2.05, 100);
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
        QTest::newRow("range beyond data") << qint64(200000) << -30.0 << 400.0 << 1200;
        QTest::newRow("few columns") << qint64(200000) << 3.0 << 150.0 << 7;
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
        MinMaxPyramid p;
        p.sync(b);
        const DecimatedSeries d = decimate(b, p, t0, t1, columns);
        QVERIFY(d.decimated);
        QVERIFY(qint64(d.time.size()) <= 2 * columns + 2);
        verifySorted(d);
        verifyColumns(b, d, t0, t1, columns);
        QCOMPARE(countNan(d), 0);
    }

    void extentMatchesBruteForce()
    {
        std::mt19937 rng(11);
        std::uniform_real_distribution<double> value(-1e6, 1e6);
        TraceBuffer b = makeBuffer(70000, 1e-4, [&](qint64) { return value(rng); });
        MinMaxPyramid p;
        p.sync(b);
        std::uniform_int_distribution<qint64> index(0, b.size());
        for (int k = 0; k < 300; ++k) {
            qint64 lo = index(rng);
            qint64 hi = index(rng);
            if (lo > hi)
                std::swap(lo, hi);
            const MinMaxPyramid::Extent x = p.extent(b, lo, hi);
            QCOMPARE(x.valid, hi > lo);
            if (hi == lo)
                continue;
            qint64 iMin = lo, iMax = lo;
            for (qint64 i = lo; i < hi; ++i) {
                if (b.value(i) < b.value(iMin))
                    iMin = i;
                if (b.value(i) > b.value(iMax))
                    iMax = i;
            }
            QCOMPARE(x.min, b.value(iMin));
            QCOMPARE(x.max, b.value(iMax));
            if (iMin != iMax)
                QCOMPARE(x.minFirst, iMin < iMax);
        }
    }

    void gapsBecomeBreaks()
    {
        TraceBuffer b(100000);
        const QList<qint64> gapAt = { 1000, 1001, 25000, 25003, 70000, 99999 };
        for (qint64 i = 0; i < 100000; ++i) {
            if (gapAt.contains(i))
                b.markLost(3);
            b.append(double(i) * 0.001, double(i % 100));
        }
        MinMaxPyramid p;
        p.sync(b);
        QCOMPARE(p.gapsIn(0, b.size()), std::vector<qint64>(gapAt.begin(), gapAt.end()));

        // Decimated: every gap inside the view is one NaN, right at the gap sample's time.
        const DecimatedSeries d = decimate(b, p, 0, 99.999, 500);
        QVERIFY(d.decimated);
        verifySorted(d);
        QCOMPARE(countNan(d), gapAt.size());
        for (qint64 g : gapAt) {
            const auto it = std::find(d.time.begin(), d.time.end(), b.time(g));
            QVERIFY(it != d.time.end());
            QVERIFY(std::isnan(d.value[size_t(it - d.time.begin())]));
        }
        verifyColumns(b, d, 0, 99.999, 500);

        // Raw copy (zoomed in): the NaN sits between the samples around the gap.
        const DecimatedSeries z = decimate(b, p, 24.99, 25.01, 500);
        QVERIFY(!z.decimated);
        QCOMPARE(countNan(z), 2);
        const auto nanAt =
            std::find_if(z.value.begin(), z.value.end(), [](double v) { return std::isnan(v); });
        const size_t k = size_t(nanAt - z.value.begin());
        QCOMPARE(z.time[k - 1], b.time(24999));
        QCOMPARE(z.time[k + 1], b.time(25000));

        // The sample just right of the view starts a gap: the break is still drawn.
        const DecimatedSeries edge = decimate(b, p, 0.5, 69.9995, 300);
        QCOMPARE(countNan(edge), 5);
    }

    void syncFollowsAppendsOverwritesAndDrops()
    {
        TraceBuffer b(50000); // ring: the oldest samples get overwritten
        MinMaxPyramid p;
        MinMaxPyramid fresh;
        std::mt19937 rng(3);
        std::uniform_real_distribution<double> value(-10, 10);
        qint64 n = 0;
        const auto appendSome = [&](qint64 count) {
            for (qint64 i = 0; i < count; ++i, ++n) {
                if (n % 7919 == 0)
                    b.markLost(1);
                b.append(double(n) * 0.001, value(rng));
            }
        };
        const auto same = [&]() {
            p.sync(b);
            fresh.clear();
            fresh.sync(b);
            QCOMPARE(p.size(), b.size());
            QCOMPARE(p.gapsIn(0, b.size()), fresh.gapsIn(0, b.size()));
            const double t0 = b.firstTime();
            const double t1 = b.lastTime();
            const DecimatedSeries a = decimate(b, p, t0, t1, 640);
            const DecimatedSeries c = decimate(b, fresh, t0, t1, 640);
            QCOMPARE(a.time, c.time);
            QCOMPARE(a.value.size(), c.value.size());
            for (size_t k = 0; k < a.value.size(); ++k)
                QVERIFY(a.value[k] == c.value[k]
                        || (std::isnan(a.value[k]) && std::isnan(c.value[k])));
            verifyColumns(b, a, t0, t1, 640);
        };
        appendSome(12345);
        same();
        for (int round = 0; round < 8; ++round) { // past capacity: overwrites
            appendSome(9001 + round * 17);
            same();
        }
        b.dropBefore(b.time(b.size() / 3)); // roll window
        appendSome(777);
        same();
        b.dropFront(4096);
        same();
        b.dropAfter(b.time(b.size() / 2)); // capture cut: not a front drop, rebuilt
        same();
        b.clear();
        n = 0;
        appendSome(3000); // new recording with times from 0 again
        same();
    }

    void bigInputStaysBounded()
    {
        const qint64 count = 4'000'000;
        TraceBuffer b = makeBuffer(
            count, 1e-5, [](qint64 i) { return double((i * 2654435761LL) % 100003) - 50000.0; });
        MinMaxPyramid p;
        p.sync(b);
        QCOMPARE(p.size(), count);
        const DecimatedSeries full = decimate(b, p, 0, b.lastTime(), 1600);
        QCOMPARE(full.visibleSamples, count);
        QVERIFY(qint64(full.time.size()) <= 2 * 1600 + 2);
        verifyColumns(b, full, 0, b.lastTime(), 1600);
        const DecimatedSeries zoom = decimate(b, p, 12.0, 12.05, 1600);
        QCOMPARE(zoom.visibleSamples, 5001);
        verifyColumns(b, zoom, 12.0, 12.05, 1600);
    }

    void negativeScaleKeepsExtremesAfterTransform()
    {
        // The view applies display = raw * scale + offset after decimation; with a negative
        // scale the column's maximum becomes its minimum, still exact.
        TraceBuffer b = makeBuffer(10000, 0.001, [](qint64 i) { return double(i % 37) - 18; });
        MinMaxPyramid p;
        p.sync(b);
        const DecimatedSeries d = decimate(b, p, 0, 9.999, 50);
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
