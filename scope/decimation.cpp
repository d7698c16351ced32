#include "decimation.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace db::scope {

namespace {

constexpr std::array<qint64, MinMaxPyramid::kLevels> kBlockSize = [] {
    std::array<qint64, MinMaxPyramid::kLevels> sizes {};
    qint64 size = MinMaxPyramid::kFanout;
    for (qint64 &s : sizes) {
        s = size;
        size *= MinMaxPyramid::kFanout;
    }
    return sizes;
}();

constexpr qint64 blockSize(int level)
{
    return kBlockSize[size_t(level)];
}

// Stale nodes (before the buffer's front) are erased once there are this many, so that a roll
// window or a full ring does not pay a vector shift on every sync.
constexpr qint64 kEraseThreshold = 4096;

// Running min/max over ordered pieces that remembers whether the minimum came first.
// Ties keep the first occurrence.
struct Accumulator
{
    double min = std::numeric_limits<double>::infinity();
    double max = -std::numeric_limits<double>::infinity();
    bool minFirst = true;
    bool any = false;

    void add(double pieceMin, double pieceMax, bool pieceMinFirst)
    {
        if (!(pieceMin <= pieceMax))
            return; // empty piece (all NaN)
        if (!any) {
            min = pieceMin;
            max = pieceMax;
            minFirst = pieceMinFirst;
            any = true;
            return;
        }
        const bool newMin = pieceMin < min;
        const bool newMax = pieceMax > max;
        if (newMin && newMax) {
            min = pieceMin;
            max = pieceMax;
            minFirst = pieceMinFirst;
        } else if (newMin) {
            min = pieceMin;
            minFirst = false; // the old maximum precedes this piece
        } else if (newMax) {
            max = pieceMax;
            minFirst = true;
        }
    }
    void addSample(double v)
    {
        if (!std::isnan(v))
            add(v, v, true);
    }
};

template<typename Vector>
void eraseFront(Vector &v, qint64 count)
{
    v.erase(v.begin(), v.begin() + std::min<qint64>(count, qint64(v.size())));
}

// First index in [lo, hi) whose time is >= t (hi when none).
qint64 lowerBoundIn(const TraceBuffer &buffer, double t, qint64 lo, qint64 hi)
{
    while (lo < hi) {
        const qint64 mid = lo + (hi - lo) / 2;
        if (buffer.time(mid) < t)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

} // namespace

void MinMaxPyramid::clear()
{
    for (Level &level : m_levels) {
        level.nodes.clear();
        level.firstBlock = 0;
    }
    m_gaps.clear();
    m_offset = 0;
    m_size = 0;
}

void MinMaxPyramid::sync(const TraceBuffer &buffer)
{
    if (buffer.isEmpty()) {
        clear();
        return;
    }
    if (m_size == 0) {
        rebuild(buffer);
        return;
    }
    // Find the newest indexed sample again: samples before it may have left the front, samples
    // after it are new. A time that is not unique cannot be matched, so that means a rebuild.
    const qint64 j = buffer.lowerBound(m_lastTime);
    const bool found = j < buffer.size() && buffer.time(j) == m_lastTime
        && (buffer.value(j) == m_lastValue
            || (std::isnan(buffer.value(j)) && std::isnan(m_lastValue)))
        && (j + 1 >= buffer.size() || buffer.time(j + 1) != m_lastTime) && j <= m_size - 1;
    if (!found) {
        rebuild(buffer);
        return;
    }
    const qint64 removedFront = (m_size - 1) - j;
    m_offset += removedFront;
    m_size -= removedFront;
    dropBelow(m_offset);
    appendFrom(buffer, m_size);
}

void MinMaxPyramid::rebuild(const TraceBuffer &buffer)
{
    clear();
    appendFrom(buffer, 0);
}

void MinMaxPyramid::dropBelow(qint64 absoluteFirst)
{
    for (int l = 0; l < kLevels; ++l) {
        Level &level = m_levels[size_t(l)];
        const qint64 stale = absoluteFirst / blockSize(l) - level.firstBlock;
        if (stale >= kEraseThreshold || stale >= qint64(level.nodes.size())) {
            const qint64 n = std::clamp<qint64>(stale, 0, qint64(level.nodes.size()));
            eraseFront(level.nodes, n);
            level.firstBlock += n;
            if (level.nodes.empty())
                level.firstBlock = (absoluteFirst + blockSize(l) - 1) / blockSize(l);
        }
    }
    const auto live = std::lower_bound(m_gaps.begin(), m_gaps.end(), absoluteFirst);
    if (live - m_gaps.begin() >= kEraseThreshold)
        m_gaps.erase(m_gaps.begin(), live);
}

void MinMaxPyramid::appendFrom(const TraceBuffer &buffer, qint64 from)
{
    const qint64 end = buffer.size();
    for (qint64 i = from; i < end; ++i) {
        if (buffer.startsGap(i))
            m_gaps.push_back(m_offset + i);
    }
    m_size = end;
    m_lastTime = buffer.time(end - 1);
    m_lastValue = buffer.value(end - 1);

    const qint64 absoluteEnd = m_offset + end;
    // Level 0 from the samples: blocks that lie completely inside the buffer.
    Level &base = m_levels[0];
    if (base.nodes.empty())
        base.firstBlock = (m_offset + kFanout - 1) / kFanout;
    for (qint64 b = base.firstBlock + qint64(base.nodes.size()); (b + 1) * kFanout <= absoluteEnd;
         ++b) {
        Accumulator acc;
        const qint64 first = b * kFanout - m_offset;
        for (qint64 i = first; i < first + kFanout; ++i)
            acc.addSample(buffer.value(i));
        base.nodes.push_back({ acc.min, acc.max, acc.minFirst });
    }
    // Higher levels from complete runs of kFanout children.
    for (int l = 1; l < kLevels; ++l) {
        const Level &below = m_levels[size_t(l - 1)];
        Level &level = m_levels[size_t(l)];
        if (level.nodes.empty())
            level.firstBlock = (below.firstBlock + kFanout - 1) / kFanout;
        const qint64 belowEnd = below.firstBlock + qint64(below.nodes.size());
        for (qint64 b = level.firstBlock + qint64(level.nodes.size());
             (b + 1) * kFanout <= belowEnd; ++b) {
            Accumulator acc;
            for (qint64 c = b * kFanout; c < (b + 1) * kFanout; ++c) {
                const Node &child = below.nodes[size_t(c - below.firstBlock)];
                acc.add(child.min, child.max, child.minFirst);
            }
            level.nodes.push_back({ acc.min, acc.max, acc.minFirst });
        }
    }
}

const MinMaxPyramid::Node *MinMaxPyramid::node(int level, qint64 absoluteIndex) const
{
    const Level &l = m_levels[size_t(level)];
    const qint64 k = absoluteIndex / blockSize(level) - l.firstBlock;
    if (k < 0 || k >= qint64(l.nodes.size()))
        return nullptr;
    return &l.nodes[size_t(k)];
}

MinMaxPyramid::Extent MinMaxPyramid::extent(const TraceBuffer &buffer, qint64 begin,
                                            qint64 end) const
{
    Accumulator acc;
    qint64 i = m_offset + begin;
    const qint64 e = m_offset + end;
    const auto addSamples = [&](qint64 stop) {
        for (; i < stop; ++i)
            acc.addSample(buffer.value(i - m_offset));
    };
    while (i < e) {
        // Unaligned head or tail: samples up to the next block boundary.
        if (i % kFanout != 0 || i + kFanout > e) {
            addSamples(std::min(e, (i / kFanout + 1) * kFanout));
            continue;
        }
        // The largest aligned node that fits (aligned to a level implies aligned to those
        // below it); nodes here start at or after the buffer's front.
        int level = 0;
        while (level + 1 < kLevels && i % blockSize(level + 1) == 0
               && i + blockSize(level + 1) <= e)
            ++level;
        const Node *n = nullptr;
        for (; level >= 0 && !(n = node(level, i)); --level) { }
        if (!n) {
            addSamples(i + kFanout); // block not indexed (yet)
            continue;
        }
        acc.add(n->min, n->max, n->minFirst);
        i += blockSize(level);
    }
    return { acc.min, acc.max, acc.minFirst, acc.any };
}

std::vector<qint64> MinMaxPyramid::gapsIn(qint64 begin, qint64 end) const
{
    const auto from = std::lower_bound(m_gaps.begin(), m_gaps.end(), m_offset + begin);
    const auto to = std::lower_bound(from, m_gaps.end(), m_offset + end);
    std::vector<qint64> result;
    result.reserve(size_t(to - from));
    for (auto it = from; it != to; ++it)
        result.push_back(*it - m_offset);
    return result;
}

DecimatedSeries decimate(const TraceBuffer &buffer, const MinMaxPyramid &pyramid, double t0,
                         double t1, int columns)
{
    DecimatedSeries out;
    const qint64 n = buffer.size();
    if (n == 0 || columns < 1 || !(t1 > t0) || pyramid.size() != n)
        return out;
    const qint64 lo = buffer.lowerBound(t0);
    const qint64 hi = buffer.upperBound(t1);
    out.visibleSamples = hi - lo;
    const qint64 first = lo > 0 ? lo - 1 : 0; // one sample either side reaches the edges
    const qint64 last = hi < n ? hi + 1 : n;

    const std::vector<qint64> gaps = pyramid.gapsIn(first + 1, last);
    auto gap = gaps.begin();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const auto push = [&out](double t, double v) {
        out.time.push_back(t);
        out.value.push_back(v);
    };
    // Emits the break in front of sample i when i starts a gap (gaps are visited in order).
    const auto breakBefore = [&](qint64 i) {
        while (gap != gaps.end() && *gap < i)
            ++gap;
        if (gap != gaps.end() && *gap == i)
            push(buffer.time(i), nan);
    };
    const auto nextGapAfter = [&](qint64 i, qint64 limit) {
        auto it = std::upper_bound(gap, gaps.end(), i);
        return it != gaps.end() && *it < limit ? *it : limit;
    };

    if (hi - lo <= 2 * qint64(columns)) {
        out.time.reserve(size_t(last - first + qint64(gaps.size())));
        out.value.reserve(out.time.capacity());
        for (qint64 i = first; i < last; ++i) {
            breakBefore(i);
            push(buffer.time(i), buffer.value(i));
        }
        return out;
    }

    out.decimated = true;
    out.time.reserve(size_t(2 * columns + 4));
    out.value.reserve(size_t(2 * columns + 4));
    if (first < lo)
        push(buffer.time(first), buffer.value(first));
    const double width = (t1 - t0) / columns;
    qint64 colStart = lo;
    for (int c = 0; c < columns && colStart < hi; ++c) {
        const qint64 colEnd =
            c == columns - 1 ? hi : lowerBoundIn(buffer, t0 + (c + 1) * width, colStart, hi);
        for (qint64 s = colStart; s < colEnd;) {
            breakBefore(s);
            const qint64 e = nextGapAfter(s, colEnd);
            if (e - s == 1) {
                push(buffer.time(s), buffer.value(s));
            } else {
                const MinMaxPyramid::Extent x = pyramid.extent(buffer, s, e);
                if (x.valid) {
                    push(buffer.time(s), x.minFirst ? x.min : x.max);
                    push(buffer.time(e - 1), x.minFirst ? x.max : x.min);
                }
            }
            s = e;
        }
        colStart = colEnd;
    }
    if (hi < n) {
        breakBefore(hi);
        push(buffer.time(hi), buffer.value(hi));
    }
    return out;
}

} // namespace db::scope
