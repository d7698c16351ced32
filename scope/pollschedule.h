#pragma once
// When each channel of a host-polling source is read: deadlines on a caller's monotonic clock.
#include <QList>
#include <QtGlobal>

#include <algorithm>
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
// - A read that comes late does not cost a sample: when the caller woke late, or the channel's
//   previous read was slow, the slots that have begun since are each served by a read of their
//   own, back to back (due() again as soon as the previous one finished), until the channel has
//   caught up. Their samples carry the time they were read.
// - A slot is lost only when the channel is further behind than its catch-up window
//   (catchUpNs(), at least kMinCatchUpSlots slots): the link cannot keep up, or the caller
//   stalled that long. due() then skips the oldest slots and reports them (lostBefore).
// - Channels of period 0 are due whenever they have no read in flight and never lose a slot.
class PollSchedule
{
public:
    struct Read
    {
        int channel = -1;
        qint64 lostBefore = 0; // slots of this channel skipped since its previous read
    };

    // How far behind a channel may fall and still catch up: a stall of the host or the link
    // this long costs no sample.
    static constexpr qint64 kDefaultCatchUpNs = 100 * 1000000;
    // A slow channel may owe this many slots whatever its period.
    static constexpr qint64 kMinCatchUpSlots = 2;

    qint64 catchUpNs() const { return m_catchUpNs; }
    // 0: no catching up; a slot is lost as soon as the next one has begun.
    void setCatchUpNs(qint64 ns) { m_catchUpNs = std::max<qint64>(0, ns); }

    // Appends a channel (period in ns, < 0 taken as 0) and returns its index.
    int addChannel(qint64 periodNs);
    int channelCount() const { return int(m_channels.size()); }
    qint64 periodNs(int channel) const { return m_channels.at(channel).periodNs; }

    // Every channel's first slot begins at nowNs; nothing is in flight.
    void start(qint64 nowNs);
    // Reads to start now, each marked in flight: fixed-rate channels in the order of the slots
    // they serve (the oldest first, ties by channel index), then channels of period 0. A
    // channel that is behind serves its oldest slot within the catch-up window.
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
    // Slots a channel of this period may owe (begun, not yet read) before the oldest is lost.
    qint64 maxOwed(qint64 periodNs) const;

    struct Channel
    {
        qint64 periodNs = 0;
        qint64 nextSlotNs = 0; // begin of the first slot not yet served
        bool inFlight = false;
    };
    QList<Channel> m_channels;
    qint64 m_catchUpNs = kDefaultCatchUpNs;
};

} // namespace db::scope
