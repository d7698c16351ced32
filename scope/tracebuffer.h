#pragma once
// Bounded sample storage of one channel: a ring of (time, raw value, gap flag) with a min/max
// summary that append() keeps up to date.
#include <QtGlobal>

#include <algorithm>
#include <array>
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
// - Min/max summary: a pyramid of blocks of kSummaryFanout^(L+1) samples (level L), built
//   incrementally by append() (O(1) amortised per sample). Blocks are aligned to the count of
//   samples ever appended since the last clear(), not to index 0, so that front drops and a full
//   ring move nothing; a block is used only while every one of its samples is held. extent()
//   of any index range then costs O(kSummaryFanout * kSummaryLevels), whatever its length.
//   Memory: about 2.1 bytes per sample slot on top of the 17 of the samples.
// - Value type: copyable; not thread-safe (lives on the recorder's thread).
class TraceBuffer
{
public:
    static constexpr qint64 kDefaultCapacity = 10'000'000;
    static constexpr int kSummaryFanout = 16;
    static constexpr int kSummaryLevels = 5; // blocks of 16 .. 16^5 samples

    // Minimum and maximum of some samples, and which of them occurs first.
    struct Extent
    {
        double min = 0.0;
        double max = 0.0;
        bool minFirst = true; // the minimum's first occurrence precedes the maximum's
        bool valid = false; // false: no sample, or only NaN values

        // Adds the extent of samples that follow the ones already added (ties keep the first).
        void add(const Extent &later)
        {
            if (!later.valid)
                return;
            if (!valid) {
                *this = later;
                return;
            }
            const bool newMin = later.min < min;
            const bool newMax = later.max > max;
            if (newMin && newMax) {
                min = later.min;
                max = later.max;
                minFirst = later.minFirst;
            } else if (newMin) {
                min = later.min;
                minFirst = false; // the old maximum precedes the later piece
            } else if (newMax) {
                max = later.max;
                minFirst = true;
            }
        }
        void addSample(double v)
        {
            if (v != v) // NaN
                return;
            if (!valid) {
                *this = { v, v, true, true };
            } else if (v < min) {
                min = v;
                minFirst = false;
            } else if (v > max) {
                max = v;
                minFirst = true;
            }
        }
    };
    // One block of the summary: the extent of its samples and the time of its first one.
    struct SummaryBlock
    {
        Extent extent;
        double firstTime = 0.0;
    };

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

    // The samples from index i on that lie one after the other in memory (the ring wraps after
    // them): pointers to time(i) and value(i) and their count (>= 1 for 0 <= i < size()).
    struct Run
    {
        const double *time;
        const double *value;
        qint64 count;
    };
    Run run(qint64 i) const
    {
        const size_t s = slot(i);
        return { &m_time[s], &m_value[s], std::min(m_size - i, qint64(m_time.size() - s)) };
    }

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

    // --- min/max summary
    // Samples in one block of `level` (0 <= level < kSummaryLevels).
    static constexpr qint64 summaryBlockSize(int level)
    {
        qint64 size = kSummaryFanout;
        for (int l = 0; l < level; ++l)
            size *= kSummaryFanout;
        return size;
    }
    // Index of the first sample of the level-`level` block that holds index i; less than 0 (or
    // than an index that left the front) when the block started before the oldest sample held.
    qint64 summaryBlockStart(int level, qint64 i) const
    {
        return i - (m_base + i) % summaryBlockSize(level);
    }
    // Extent of indices [begin, end), 0 <= begin <= end <= size(); NaN values are skipped.
    Extent extent(qint64 begin, qint64 end) const;
    // The level-`level` block that starts at index i (summaryBlockStart(level, i) == i, i >= 0,
    // i + summaryBlockSize(level) <= size()): one read, sequential for consecutive blocks.
    const SummaryBlock &summaryBlock(int level, qint64 i) const
    {
        const std::vector<SummaryBlock> &nodes = m_nodes[size_t(level)];
        return nodes[size_t(((m_base + i) / summaryBlockSize(level)) % qint64(nodes.size()))];
    }
    // Indices (ascending) in [begin, end) of the samples that start a gap.
    std::vector<qint64> gapsIn(qint64 begin, qint64 end) const;

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

    void resizeSummary();
    void completeBlocks(qint64 absoluteEnd);
    void rebuildSummary();

    qint64 m_capacity;
    qint64 m_base = 0; // samples appended since clear() before index 0 (absolute index of 0)
    qint64 m_head = 0; // storage slot of index 0
    qint64 m_size = 0;
    std::vector<double> m_time;
    std::vector<double> m_value;
    std::vector<quint8> m_gap;
    // Summary level L: block k (absolute samples [k*B, (k+1)*B)) in slot k % size(); at least
    // storage/B + 2 slots, so a block is overwritten only after it left the held window.
    std::array<std::vector<SummaryBlock>, kSummaryLevels> m_nodes;
    std::vector<qint64> m_gapIndex; // absolute indices of gap samples, ascending (may hold stale)
    qint64 m_overwritten = 0;
    qint64 m_lost = 0;
    bool m_gapPending = false;
};

} // namespace db::scope
