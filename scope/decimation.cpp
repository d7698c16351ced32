#include "decimation.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace db::scope {

namespace {

// Extent of a few contiguous values without a branch per value that depends on the values
// (noisy signals would mispredict most of them): min/max first, then which comes first.
[[gnu::noinline]] TraceBuffer::Extent runExtent(const double *begin, const double *end)
{
    // Two chains each, so that one comparison need not wait for the one before.
    double lo = std::numeric_limits<double>::infinity();
    double hi = -lo;
    double lo2 = lo;
    double hi2 = hi;
    const double *v = begin;
    for (; end - v >= 2; v += 2) {
        lo = v[0] < lo ? v[0] : lo; // false for NaN: skipped
        hi = v[0] > hi ? v[0] : hi;
        lo2 = v[1] < lo2 ? v[1] : lo2;
        hi2 = v[1] > hi2 ? v[1] : hi2;
    }
    if (v != end) {
        lo = *v < lo ? *v : lo;
        hi = *v > hi ? *v : hi;
    }
    lo = std::min(lo, lo2);
    hi = std::max(hi, hi2);
    TraceBuffer::Extent x;
    if (!(lo <= hi))
        return x; // only NaN
    x = { lo, hi, true, true };
    for (v = begin; v != end; ++v) {
        if (*v == lo || *v == hi) {
            x.minFirst = *v == lo;
            break;
        }
    }
    return x;
}

} // namespace

DecimatedSeries decimate(const TraceBuffer &buffer, double t0, double t1, int columns)
{
    DecimatedSeries out;
    decimate(buffer, t0, t1, columns, out);
    return out;
}

void decimate(const TraceBuffer &buffer, double t0, double t1, int columns, DecimatedSeries &out)
{
    out.time.clear();
    out.value.clear();
    out.visibleSamples = 0;
    out.decimated = false;
    out.unit = 1;
    const qint64 n = buffer.size();
    if (n == 0 || columns < 1 || !(t1 > t0))
        return;
    const qint64 lo = buffer.lowerBound(t0);
    const qint64 hi = buffer.upperBound(t1);
    out.visibleSamples = hi - lo;
    const qint64 first = lo > 0 ? lo - 1 : 0; // one sample either side reaches the edges
    const qint64 last = hi < n ? hi + 1 : n;

    const std::vector<qint64> gaps = buffer.gapsIn(first + 1, last);
    auto gap = gaps.begin(); // the first gap at or after the sample being looked at
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const auto push = [&out](double t, double v) {
        out.time.push_back(t);
        out.value.push_back(v);
    };
    // Emits the break in front of sample i when i starts a gap (samples are visited in order).
    const auto breakBefore = [&](qint64 i) {
        while (gap != gaps.end() && *gap < i)
            ++gap;
        if (gap != gaps.end() && *gap == i) {
            push(buffer.time(i), nan);
            return true;
        }
        return false;
    };

    if (hi - lo <= 2 * qint64(columns)) {
        out.time.reserve(size_t(last - first + qint64(gaps.size())));
        out.value.reserve(out.time.capacity());
        for (qint64 i = first; i < last; ++i) {
            breakBefore(i);
            push(buffer.time(i), buffer.value(i));
        }
        return;
    }

    out.decimated = true;
    const double perColumn = double(hi - lo) / columns;
    int level = -1; // summary level the columns snap to; -1: single samples
    while (level + 1 < TraceBuffer::kSummaryLevels
           && double(TraceBuffer::summaryBlockSize(level + 1)) <= perColumn)
        ++level;
    const qint64 unit = level < 0 ? 1 : TraceBuffer::summaryBlockSize(level);
    out.unit = unit;
    out.time.reserve(size_t(2 * columns + 4 + 3 * qint64(gaps.size())));
    out.value.reserve(out.time.capacity());
    if (first < lo)
        push(buffer.time(first), buffer.value(first));

    // Columns by multiplication: every visible sample has t >= t0, so truncation is floor.
    const double scale = columns / (t1 - t0);
    const auto columnOf = [&](double t) {
        return std::clamp(int((t - t0) * scale), 0, columns - 1);
    };
    int column = -1; // column being accumulated; -1 after a gap
    TraceBuffer::Extent acc;
    double firstTime = 0.0; // of the column's first unit
    double lastTime = 0.0; // of the column's last unit
    const auto flush = [&] {
        if (acc.valid) {
            push(firstTime, acc.minFirst ? acc.min : acc.max);
            if (lastTime != firstTime || acc.max != acc.min)
                push(lastTime, acc.minFirst ? acc.max : acc.min);
        }
        acc = {};
        column = -1;
    };
    // Adds the unit that starts at time t to its column.
    const auto addUnit = [&](double t, const TraceBuffer::Extent &x) {
        const int c = columnOf(t);
        if (c != column) {
            flush();
            column = c;
            firstTime = t;
        }
        lastTime = t;
        acc.add(x);
    };

    for (qint64 i = lo; i < hi;) {
        breakBefore(i); // the part before it was flushed at the end of its stretch
        // The gap-free stretch [i, stretchEnd).
        const auto nextGap = std::upper_bound(gap, gaps.end(), i);
        const qint64 stretchEnd = nextGap != gaps.end() && *nextGap < hi ? *nextGap : hi;
        if (unit == 1) {
            const qint64 guess = std::max<qint64>(1, qint64(perColumn));
            // Runs of samples of one column, straight from the ring's memory (a column that
            // the ring's wrap splits is added in two pieces).
            while (i < stretchEnd) {
                const TraceBuffer::Run run = buffer.run(i);
                const qint64 n = std::min(run.count, stretchEnd - i);
                for (qint64 k = 0; k < n;) {
                    // The column's end: guessed from the samples per column, then stepped to
                    // the first sample of a later column (columns never decrease with time).
                    const int c = columnOf(run.time[k]);
                    qint64 j = std::min(n, k + guess);
                    while (j > k + 1 && columnOf(run.time[j - 1]) != c)
                        --j;
                    while (j < n && columnOf(run.time[j]) == c)
                        ++j;
                    addUnit(run.time[k], runExtent(run.value + k, run.value + j));
                    lastTime = run.time[j - 1];
                    k = j;
                }
                i += n;
            }
        }
        while (i < stretchEnd) {
            // Whole blocks are read from the summary alone (their extent and first time, one
            // sequential read each); a stretch's ragged head or tail from the samples.
            const qint64 blockStart = buffer.summaryBlockStart(level, i);
            const qint64 next = std::min(stretchEnd, blockStart + unit);
            if (blockStart == i && next - i == unit) {
                const TraceBuffer::SummaryBlock &block = buffer.summaryBlock(level, i);
                addUnit(block.firstTime, block.extent);
            } else {
                addUnit(buffer.time(i), buffer.extent(i, next));
            }
            i = next;
        }
        flush();
    }
    if (hi < n) {
        breakBefore(hi);
        push(buffer.time(hi), buffer.value(hi));
    }
}

} // namespace db::scope
