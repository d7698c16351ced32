#pragma once
// CSV export/import of a Recording.
//
// Format (UTF-8, '\n' line ends, ',' separator, '.' decimal point):
//   # drivebench recording v1
//   # device: refgo://127.0.0.1:10001
//   # started: 2026-11-21T21:00:00.000Z
//   # mode: single
//   # trigger: 6064:0,rising,100; pre 0.1 s; post 0.5 s; at 1.234567000 s
//   # channel: 6064:0; name: Position actual value; unit: inc; scale: 1; offset: 0; rate-ms: 10; …
//   # channel: …   (one line per channel in column order, ending "dropped: N; lost: N", then
//                    "decimals: N" and "device-name: NAME" when known)
//   # channel-device: 6064:0; refgo://127.0.0.2:10001   (after the channel line of a channel
//                    from another device than the "device" line's)
//   # range: 0.000812345 .. 2.500000000 s
//   time_s,6064:0 Position actual value,6078:0 Current actual value
//   0.000812345,1000,
//   0.001310000,,42
// - First column: time in seconds with 9 decimals (1 ns, the time base's resolution, so a
//   round trip is exact); then one column per channel headed "index:sub name" (label(),
//   quoted as in RFC 4180 when it holds ',' or '"').
// - Channels sampled at different times: one row per distinct time stamp; a channel without a
//   sample at that time has an EMPTY cell. Samples with exactly the same time share a row.
// - Cells hold RAW values (integers as integers, others in the shortest form that reads back
//   exactly); the display scaling is in the channel line, so an import restores raw values and
//   scaling.
// - Gaps (a sample after lost samples) are listed in comment lines after the channel lines,
//   "# gaps: 6064:0; 1.234001000 2.500000000" (the times of the samples that start a gap), so the
//   data columns stay plain numbers for spreadsheets; the importer restores startsGap(). A
//   channel of another device than the "device" line's has
//   "# device-gaps: 6064:0; refgo://127.0.0.2:10001; 1.234001000" instead, so the same object
//   of two devices keeps its own gaps.
// - In the "# key: value; key: value" lines a backslash escapes ';', '\' and line breaks
//   ("\;", "\\", "\n") inside values. The device line holds one URI, or several joined by "; "
//   (escaped).
// - Unknown "# key:" comment lines are ignored; other '#' lines too.
#include "core/result.h"
#include "recording.h"
#include <QByteArray>
#include <QString>
#include <limits>

namespace db::scope::csv {

constexpr double kAllTimes = std::numeric_limits<double>::infinity();

// The CSV text of `recording`, samples with t0 <= t <= t1 only (the visible range).
QByteArray toCsv(const Recording &recording, double t0 = -kAllTimes, double t1 = kAllTimes);

// Writes atomically (QSaveFile): the file is either the complete new CSV or untouched.
// Io error naming the file and the cause.
Result<void> save(const QString &fileName, const Recording &recording, double t0 = -kAllTimes,
                  double t1 = kAllTimes);

// Parses a CSV written by toCsv(). Malformed error with "line N: cause" for a bad header,
// a row with the wrong number of cells, a non-number cell, or time going back.
Result<Recording> fromCsv(const QByteArray &text);
// Io error when the file cannot be read; otherwise fromCsv() with the file name in front.
Result<Recording> load(const QString &fileName);

} // namespace db::scope::csv
