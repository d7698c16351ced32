#pragma once
// A finished (stopped, captured or loaded) recording as a value type: what the CSV stores.
#include "channel.h"
#include "tracebuffer.h"
#include "trigger.h"
#include <QDateTime>
#include <QList>
#include <cmath>
#include <limits>

namespace db::scope {

struct RecordedChannel
{
    ChannelInfo info;
    TraceBuffer buffer { 1 }; // capacity grows to the samples it holds
};

// Channels with their samples plus metadata. Times are seconds on the recording's time base
// (0 = recorder start). Copying copies the samples.
struct Recording
{
    QList<RecordedChannel> channels;
    QString device; // URI(s) of the device(s), "; "-separated when several
    QDateTime startedAt; // wall-clock time of time base 0 (UTC)
    QString mode; // "run", "single", "normal", "roll" (informative)
    Trigger trigger; // trigger.isValid() when the recording was triggered
    double triggerTime = std::numeric_limits<double>::quiet_NaN(); // seconds; NaN = none

    bool hasTriggerTime() const { return !std::isnan(triggerTime); }
    bool isEmpty() const;
    // Earliest/latest sample time over all channels (0, 0 when empty).
    double startTime() const;
    double endTime() const;
    // Index of the channel with this id ("6064:0", or another spelling of the address in the
    // channel's format), -1 when none.
    int indexOf(const QString &id) const;
    // A copy holding only samples with t0 <= t <= t1 (counters copied as they are).
    Recording slice(double t0, double t1) const;
};

} // namespace db::scope
