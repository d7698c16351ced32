#pragma once
// Min/max decimation of a recorded channel for drawing: a visible time range becomes at most
// about two points per pixel column, with the exact minimum and maximum of every column and the
// recording's gaps kept as NaN breaks. Pure (no widgets); the scope view feeds the result to
// QCustomPlot.
#include "tracebuffer.h"

#include <QtGlobal>

#include <array>
#include <vector>

namespace db::scope {

// A min/max pyramid over one TraceBuffer's values, so that the extent of any index range costs
// O(kFanout * kLevels) instead of O(samples): level L holds one node per kFanout^L samples.
//
// Contract:
// - sync(buffer) brings the pyramid up to date after samples were appended, overwritten (full
//   ring) or dropped from the front (roll window, pre-trigger trim); that costs O(new samples).
//   Any other change (clear, dropAfter, a different buffer) is detected from the last indexed
//   sample and answered with a full rebuild, O(size). Call clear() to force one.
// - Between sync() and the queries the buffer must not change.
// - Only complete nodes are stored; a query walks samples where a node is incomplete.
class MinMaxPyramid
{
public:
    static constexpr int kFanout = 16;
    static constexpr int kLevels = 5; // 16 .. 16^5 samples per node

    struct Extent
    {
        double min = 0.0;
        double max = 0.0;
        bool minFirst = true; // the minimum's first occurrence precedes the maximum's
        bool valid = false; // false for an empty range
    };

    void sync(const TraceBuffer &buffer);
    void clear();

    // Number of buffer samples indexed (== buffer.size() after sync()).
    qint64 size() const { return m_size; }
    // Extent of buffer indices [begin, end) (0 <= begin <= end <= size()); NaN values are skipped.
    Extent extent(const TraceBuffer &buffer, qint64 begin, qint64 end) const;
    // Buffer indices (ascending) in [begin, end) whose sample starts a gap.
    std::vector<qint64> gapsIn(qint64 begin, qint64 end) const;

private:
    struct Node
    {
        double min;
        double max;
        bool minFirst;
    };
    struct Level
    {
        std::vector<Node> nodes;
        qint64 firstBlock = 0; // absolute block number of nodes[0]
    };

    void rebuild(const TraceBuffer &buffer);
    void appendFrom(const TraceBuffer &buffer, qint64 from);
    void dropBelow(qint64 absoluteFirst);
    const Node *node(int level, qint64 absoluteIndex) const;

    std::array<Level, kLevels> m_levels;
    std::vector<qint64> m_gaps; // absolute indices of samples that start a gap
    qint64 m_offset = 0; // absolute index of buffer index 0
    qint64 m_size = 0;
    // Fingerprint of the newest indexed sample, to find it again after front drops.
    double m_lastTime = 0.0;
    double m_lastValue = 0.0;
};

// Decimated points of one channel in buffer (raw) units, in time order; a NaN value marks a
// break in the line (a gap in the recording).
struct DecimatedSeries
{
    std::vector<double> time;
    std::vector<double> value;
    qint64 visibleSamples = 0; // buffer samples with t0 <= t <= t1
    bool decimated = false; // false: every sample in range was copied as is
};

// Decimates buffer over [t0, t1] into `columns` equal time columns (columns >= 1, t1 > t0).
// One sample on each side of the range is added so that lines reach the plot's edges.
// - When the range holds at most 2 * columns samples, they are copied unchanged.
// - Otherwise each column with samples yields its minimum and maximum (exact values, in the
//   order they occur, at the times of the column's first and last sample; one point when both
//   are the same sample); a column with a gap is split at it and each part decimated alike.
// - A NaN point is inserted wherever a sample starts a gap (including at the range's edges).
// pyramid must be synced with buffer. Cost: O(columns * kFanout * kLevels + gaps in range).
DecimatedSeries decimate(const TraceBuffer &buffer, const MinMaxPyramid &pyramid, double t0,
                         double t1, int columns);

} // namespace db::scope
