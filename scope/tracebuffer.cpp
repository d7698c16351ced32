#include "tracebuffer.h"

#include <algorithm>

namespace db::scope {

namespace {
// Storage grows by doubling from this size up to the capacity, so short recordings with the
// default capacity of 1e7 do not reserve 170 MB per channel up front.
constexpr qint64 kInitialSlots = 1024;
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
    m_head = 0;
    m_size = keep;
    m_capacity = capacity;
}

void TraceBuffer::append(double t, double raw)
{
    if (m_size > 0 && t < lastTime())
        t = lastTime();
    const qint64 slots = qint64(m_time.size());
    if (m_size == slots && slots < m_capacity) {
        // Grow: unwrap into index order, then double (capped at the capacity).
        const qint64 grown = std::min(m_capacity, std::max(kInitialSlots, slots * 2));
        std::rotate(m_time.begin(), m_time.begin() + m_head, m_time.end());
        std::rotate(m_value.begin(), m_value.begin() + m_head, m_value.end());
        std::rotate(m_gap.begin(), m_gap.begin() + m_head, m_gap.end());
        m_head = 0;
        m_time.resize(size_t(grown));
        m_value.resize(size_t(grown));
        m_gap.resize(size_t(grown));
    }
    size_t s;
    if (m_size == qint64(m_time.size())) {
        // Full at capacity: overwrite the oldest.
        s = size_t(m_head);
        m_head = (m_head + 1) % qint64(m_time.size());
        ++m_overwritten;
    } else {
        s = slot(m_size);
        ++m_size;
    }
    m_time[s] = t;
    m_value[s] = raw;
    m_gap[s] = m_gapPending ? 1 : 0;
    m_gapPending = false;
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
    m_size -= count;
    if (m_size == 0)
        m_head = 0;
}

void TraceBuffer::dropAfter(double t)
{
    m_size = upperBound(t);
    if (m_size == 0)
        m_head = 0;
}

void TraceBuffer::clear()
{
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

} // namespace db::scope
