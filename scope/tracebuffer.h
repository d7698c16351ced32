#pragma once
// Bounded sample storage of one channel: a ring of (time, raw value, gap flag).
#include <QtGlobal>
#include <vector>

namespace db::scope {

// One channel's samples in time order, bounded to capacity() (the oldest are overwritten).
//
// Contract:
// - Index 0 is the oldest sample still held, size()-1 the newest; time(i) is in seconds on the
//   recording's one time base and never decreases with i (append() clamps a time that would go
//   back to the previous sample's time, so lowerBound() stays valid).
// - append() is O(1) amortised: memory grows on demand up to capacity() and is then reused.
// - Gaps: markLost(n) records that n samples were lost at the source (failed read, timeout,
//   missed PDO); the next appended sample then "starts a gap" (startsGap(i) == true), meaning
//   that a plot must not draw a line from sample i-1 to sample i.
// - dropped() = droppedOverwritten() + lostAtSource(): samples the buffer does not hold.
//   dropFront()/clear() (roll window, pre-trigger trimming, re-arm) are intentional and not
//   counted.
// - Value type: copyable; not thread-safe (lives on the recorder's thread).
class TraceBuffer
{
public:
    static constexpr qint64 kDefaultCapacity = 10'000'000;

    explicit TraceBuffer(qint64 capacity = kDefaultCapacity);

    qint64 capacity() const { return m_capacity; }
    // Changes the bound, keeping the newest min(size(), capacity) samples. capacity >= 1.
    void setCapacity(qint64 capacity);

    qint64 size() const { return m_size; }
    bool isEmpty() const { return m_size == 0; }

    void append(double t, double raw);
    // Counts `count` samples lost at the source and makes the next appended sample start a gap.
    void markLost(qint64 count);
    // Makes the next appended sample start a gap without counting a loss (e.g. restarted source).
    void markGap() { m_gapPending = true; }

    // 0 <= i < size(); i = 0 is the oldest.
    double time(qint64 i) const { return m_time[slot(i)]; }
    double value(qint64 i) const { return m_value[slot(i)]; }
    bool startsGap(qint64 i) const { return m_gap[slot(i)] != 0; }
    double firstTime() const { return time(0); } // size() > 0
    double lastTime() const { return time(m_size - 1); } // size() > 0

    // First index whose time is >= t (size() when none); binary search, O(log n).
    qint64 lowerBound(double t) const;
    // First index whose time is > t (size() when none).
    qint64 upperBound(double t) const;

    // Removes the oldest samples with time < t (not counted as dropped).
    void dropBefore(double t);
    // Removes the `count` oldest samples (not counted as dropped).
    void dropFront(qint64 count);
    // Removes the newest samples with time > t (used to cut a capture at its post window).
    void dropAfter(double t);
    // Removes all samples and resets the counters.
    void clear();

    qint64 droppedOverwritten() const { return m_overwritten; }
    qint64 lostAtSource() const { return m_lost; }
    qint64 dropped() const { return m_overwritten + m_lost; }
    // Restores counters (CSV import).
    void setCounters(qint64 overwritten, qint64 lost);

private:
    size_t slot(qint64 i) const
    {
        qint64 s = m_head + i;
        if (s >= qint64(m_time.size()))
            s -= qint64(m_time.size());
        return size_t(s);
    }

    qint64 m_capacity;
    qint64 m_head = 0; // storage slot of index 0
    qint64 m_size = 0;
    std::vector<double> m_time;
    std::vector<double> m_value;
    std::vector<quint8> m_gap;
    qint64 m_overwritten = 0;
    qint64 m_lost = 0;
    bool m_gapPending = false;
};

} // namespace db::scope
