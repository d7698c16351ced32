#pragma once
// When each channel of a host-polling source is read: deadlines on a caller's monotonic clock.
#include <QList>
#include <QtGlobal>

#include <optional>

namespace db::scope {

// The scheduling of PollingSource as a pure value type, driven by the caller's clock (all times
// in ns on one monotonic clock, passed in; nothing here reads a clock), so that tests can play
// late wake-ups, slow reads and stalled links.
//
// Each channel has a period (0 = as fast as the link allows). A channel of period P owns the
// sample slots start + k * P. Contract:
// - At most one read per channel is in flight: due() starts a read only on channels whose last
//   read finished() (reads of different channels overlap; the link queues them).
// - Deadlines do not drift: after the read for slot k starts, the next deadline is slot k + 1,
//   however late slot k's read started (a late wake-up is caught up, not carried forward).
// - A slot is lost only when its read could not start before the next slot began (the link was
//   still busy with the channel's previous read, or the caller woke that late). due() then
//   serves the newest slot that has begun and reports the ones skipped (lostBefore).
// - Channels of period 0 are due whenever they have no read in flight and never lose a slot.
class PollSchedule
{
public:
    struct Read
    {
        int channel = -1;
        qint64 lostBefore = 0; // slots of this channel skipped since its previous read
    };

    // Appends a channel (period in ns, < 0 taken as 0) and returns its index.
    int addChannel(qint64 periodNs);
    int channelCount() const { return int(m_channels.size()); }
    qint64 periodNs(int channel) const { return m_channels.at(channel).periodNs; }

    // Every channel's first slot begins at nowNs; nothing is in flight.
    void start(qint64 nowNs);
    // Reads to start now, each marked in flight: fixed-rate channels in the order of the slots
    // they serve (the oldest first, ties by channel index), then channels of period 0.
    QList<Read> due(qint64 nowNs);
    // The channel's read has been answered or has failed: it may be read again.
    void finished(int channel);
    bool inFlight(int channel) const { return m_channels.at(channel).inFlight; }
    // When due() will next have a read to start, with no read finishing before then; nullopt
    // when every channel has a read in flight (or there is none). May lie in the past.
    std::optional<qint64> nextDueNs() const;
    // Slots of each channel that ended without a read by nowNs (for stopping: a read that
    // waited three periods for its answer has cost two samples); counted once.
    QList<qint64> lostUntil(qint64 nowNs);

private:
    struct Channel
    {
        qint64 periodNs = 0;
        qint64 nextSlotNs = 0; // begin of the first slot not yet served
        bool inFlight = false;
    };
    QList<Channel> m_channels;
};

} // namespace db::scope
