#include "tracebuffer.h"

#include <algorithm>

namespace db::scope {

namespace {
// Storage grows by doubling from this size up to the capacity, so short recordings with the
// default capacity of 1e7 do not reserve 170 MB per channel up front.
constexpr qint64 kInitialSlots = 1024;
// Stale gap indices (before the front) are erased once there are this many.
constexpr qint64 kGapEraseThreshold = 1024;
} // namespace

TraceBuffer::TraceBuffer(qint64 capacity)
    : m_capacity(std::max<qint64>(1, capacity))
{ }

void TraceBuffer::setCapacity(qint64 capacity)
{
    capacity = std::max<qint64>(1, capacity);
    if (capacity == m_capacity)
        return;
    // Re-pack the newest samples into fresh storage in index order (head = 0).
    const qint64 keep = std::min(m_size, capacity);
    const qint64 first = m_size - keep;
    std::vector<double> time(size_t(std::max(keep, std::min(capacity, kInitialSlots))));
    std::vector<double> value(time.size());
    std::vector<quint8> gap(time.size());
    for (qint64 i = 0; i < keep; ++i) {
        time[size_t(i)] = this->time(first + i);
        value[size_t(i)] = this->value(first + i);
        gap[size_t(i)] = startsGap(first + i) ? 1 : 0;
    }
    m_overwritten += first;
    m_time.swap(time);
    m_value.swap(value);
    m_gap.swap(gap);
    m_base += first;
    m_head = 0;
    m_size = keep;
    m_capacity = capacity;
    rebuildSummary();
}

void TraceBuffer::append(double t, double raw)
{
    if (m_size > 0 && t < lastTime())
        t = lastTime();
    const qint64 allocated = qint64(m_time.size()); // not "slots": a Qt macro
    if (m_size == allocated && allocated < m_capacity) {
        // Grow: unwrap into index order, then double (capped at the capacity).
        const qint64 grown = std::min(m_capacity, std::max(kInitialSlots, allocated * 2));
        std::rotate(m_time.begin(), m_time.begin() + m_head, m_time.end());
        std::rotate(m_value.begin(), m_value.begin() + m_head, m_value.end());
        std::rotate(m_gap.begin(), m_gap.begin() + m_head, m_gap.end());
        m_head = 0;
        m_time.resize(size_t(grown));
        m_value.resize(size_t(grown));
        m_gap.resize(size_t(grown));
        resizeSummary();
    }
    size_t s;
    if (m_size == qint64(m_time.size())) {
        // Full at capacity: overwrite the oldest.
        s = size_t(m_head);
        m_head = (m_head + 1) % qint64(m_time.size());
        ++m_base;
        ++m_overwritten;
    } else {
        s = slot(m_size);
        ++m_size;
    }
    m_time[s] = t;
    m_value[s] = raw;
    m_gap[s] = m_gapPending ? 1 : 0;
    if (m_gapPending) {
        const auto live = std::lower_bound(m_gapIndex.begin(), m_gapIndex.end(), m_base);
        if (live - m_gapIndex.begin() >= kGapEraseThreshold)
            m_gapIndex.erase(m_gapIndex.begin(), live);
        m_gapIndex.push_back(m_base + m_size - 1);
    }
    m_gapPending = false;
    completeBlocks(m_base + m_size);
}

void TraceBuffer::markLost(qint64 count)
{
    if (count <= 0)
        return;
    m_lost += count;
    m_gapPending = true;
}

qint64 TraceBuffer::lowerBound(double t) const
{
    qint64 lo = 0;
    qint64 hi = m_size;
    while (lo < hi) {
        const qint64 mid = lo + (hi - lo) / 2;
        if (time(mid) < t)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

qint64 TraceBuffer::upperBound(double t) const
{
    qint64 lo = 0;
    qint64 hi = m_size;
    while (lo < hi) {
        const qint64 mid = lo + (hi - lo) / 2;
        if (time(mid) <= t)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

void TraceBuffer::dropBefore(double t)
{
    dropFront(lowerBound(t));
}

void TraceBuffer::dropFront(qint64 count)
{
    count = std::clamp<qint64>(count, 0, m_size);
    if (count == 0)
        return;
    m_head = (m_head + count) % qint64(m_time.size());
    m_base += count;
    m_size -= count;
    if (m_size == 0)
        m_head = 0;
}

void TraceBuffer::dropAfter(double t)
{
    // Summary blocks that reach past the new end are no longer held and so no longer used;
    // appends complete them anew.
    m_size = upperBound(t);
    while (!m_gapIndex.empty() && m_gapIndex.back() >= m_base + m_size)
        m_gapIndex.pop_back();
    if (m_size == 0)
        m_head = 0;
}

void TraceBuffer::clear()
{
    // Stale summary blocks need no wiping: a block is used only once appends completed it.
    m_gapIndex.clear();
    m_base = 0;
    m_head = 0;
    m_size = 0;
    m_overwritten = 0;
    m_lost = 0;
    m_gapPending = false;
}

void TraceBuffer::setCounters(qint64 overwritten, qint64 lost)
{
    m_overwritten = std::max<qint64>(0, overwritten);
    m_lost = std::max<qint64>(0, lost);
}

// ---- min/max summary ----

void TraceBuffer::resizeSummary()
{
    const qint64 storage = qint64(m_time.size());
    for (int l = 0; l < kSummaryLevels; ++l) {
        const qint64 b = summaryBlockSize(l);
        std::vector<SummaryBlock> &nodes = m_nodes[size_t(l)];
        std::vector<SummaryBlock> grown(size_t(storage / b + 2));
        // Move the blocks that lie completely inside the held samples.
        if (!nodes.empty()) {
            for (qint64 k = (m_base + b - 1) / b; (k + 1) * b <= m_base + m_size; ++k)
                grown[size_t(k % qint64(grown.size()))] = nodes[size_t(k % qint64(nodes.size()))];
        }
        nodes.swap(grown);
    }
}

void TraceBuffer::rebuildSummary()
{
    resizeSummary();
    for (qint64 end = m_base + 1; end <= m_base + m_size; ++end)
        completeBlocks(end);
}

// Computes the blocks that the sample with absolute index absoluteEnd - 1 completes. Blocks that
// started before the oldest sample held are skipped (never used); a block's children are all
// held, so they were computed when they completed.
void TraceBuffer::completeBlocks(qint64 absoluteEnd)
{
    for (int l = 0; l < kSummaryLevels; ++l) {
        const qint64 b = summaryBlockSize(l);
        const qint64 start = absoluteEnd - b;
        if (absoluteEnd % b != 0 || start < m_base)
            return;
        SummaryBlock block;
        if (l == 0) {
            block.firstTime = time(start - m_base);
            for (qint64 i = start - m_base; i < absoluteEnd - m_base; ++i)
                block.extent.addSample(value(i));
        } else {
            const std::vector<SummaryBlock> &below = m_nodes[size_t(l - 1)];
            const qint64 childSize = b / kSummaryFanout;
            const qint64 first = start / childSize;
            block.firstTime = below[size_t(first % qint64(below.size()))].firstTime;
            for (qint64 k = first; k < absoluteEnd / childSize; ++k)
                block.extent.add(below[size_t(k % qint64(below.size()))].extent);
        }
        std::vector<SummaryBlock> &nodes = m_nodes[size_t(l)];
        nodes[size_t((start / b) % qint64(nodes.size()))] = block;
    }
}

TraceBuffer::Extent TraceBuffer::extent(qint64 begin, qint64 end) const
{
    Extent acc;
    qint64 i = begin;
    while (i < end) {
        // Unaligned head or tail: samples up to the next level-0 boundary.
        if (summaryBlockStart(0, i) != i || i + kSummaryFanout > end) {
            const qint64 stop = std::min(end, summaryBlockStart(0, i) + kSummaryFanout);
            for (; i < stop; ++i)
                acc.addSample(value(i));
            continue;
        }
        // The largest aligned block that fits (aligned to a level implies aligned to those
        // below it); it starts at i >= 0 and ends by `end`, so all of it is held.
        int level = 0;
        while (level + 1 < kSummaryLevels && summaryBlockStart(level + 1, i) == i
               && i + summaryBlockSize(level + 1) <= end)
            ++level;
        acc.add(summaryBlock(level, i).extent);
        i += summaryBlockSize(level);
    }
    return acc;
}

std::vector<qint64> TraceBuffer::gapsIn(qint64 begin, qint64 end) const
{
    const auto from = std::lower_bound(m_gapIndex.begin(), m_gapIndex.end(), m_base + begin);
    const auto to = std::lower_bound(from, m_gapIndex.end(), m_base + end);
    std::vector<qint64> result;
    result.reserve(size_t(to - from));
    for (auto it = from; it != to; ++it)
        result.push_back(*it - m_base);
    return result;
}

} // namespace db::scope
