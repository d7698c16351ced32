#pragma once
// Min/max decimation of a recorded channel for drawing: a visible time range becomes a few
// points per pixel column, with the exact minimum and maximum of every column and the
// recording's gaps kept as NaN breaks. Pure (no widgets); the scope view feeds the result to
// QCustomPlot.
#include "tracebuffer.h"

#include <QtGlobal>

#include <vector>

namespace db::scope {

// Decimated points of one channel in buffer (raw) units, in time order; a NaN value marks a
// break in the line (a gap in the recording).
struct DecimatedSeries
{
    std::vector<double> time;
    std::vector<double> value;
    qint64 visibleSamples = 0; // buffer samples with t0 <= t <= t1
    bool decimated = false; // false: every sample in range was copied as is
    // Samples per summary block the columns were snapped to (1: not snapped); see decimate().
    qint64 unit = 1;
};

// Decimates buffer over [t0, t1] into `columns` equal time columns (columns >= 1, t1 > t0),
// reading the buffer's min/max summary so that the cost depends on the columns, not on the
// samples. One sample on each side of the range is added so that lines reach the plot's edges.
// - When the range holds at most 2 * columns samples, they are copied unchanged.
// - Otherwise the columns are snapped to summary blocks: unit is the largest block size
//   (TraceBuffer::summaryBlockSize) not above the visible samples per column (1 when that is
//   below one block, i.e. no snapping), so a column spans 1 to kSummaryFanout blocks. Sample i of
//   the visible index range [lo, hi) belongs to the column of the time of sample
//   u(i) = max(start of i's unit-sized block, lo, the last gap sample <= i), where the column of
//   time t is clamp(int((t - t0) * (columns / (t1 - t0))), 0, columns - 1).
// - Each column yields the exact minimum and maximum of its samples, in the order they occur, at
//   the times of its first sample and of the first sample of its last unit (one point when
//   both are the same and so are minimum and maximum); a column with a gap is split at it and each
//   part decimated alike. (Reading the times from the summary keeps a frame's memory reads
//   sequential.)
// - A NaN point is inserted wherever a sample starts a gap (including at the range's edges).
// Cost: O(columns * kSummaryFanout + kSummaryFanout * kSummaryLevels * (gaps in range + 1)).
DecimatedSeries decimate(const TraceBuffer &buffer, double t0, double t1, int columns);
// The same into `out`, reusing its memory (a view that decimates every frame allocates nothing).
void decimate(const TraceBuffer &buffer, double t0, double t1, int columns, DecimatedSeries &out);

} // namespace db::scope
