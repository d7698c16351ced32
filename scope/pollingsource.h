#pragma once
// Host polling of readable objects through DeviceConnection::read().
#include "core/deviceconnection.h"
#include "core/groupreader.h"
#include "pollschedule.h"
#include "tracesource.h"
#include "wakeuptimer.h"
#include <QPointer>

namespace db::scope {

// Samples objects of one DeviceConnection by reading them from the host.
//
// Scheduling (PollSchedule): each channel has a period (rateMs; 0 = as fast as the link allows)
// and owns the sample slots start + k * period on the time base. A channel's read starts at its
// slot's deadline, woken by a timer precise to tens of microseconds; the next deadline is the
// previous one plus the period, so a late wake-up is caught up instead of carried forward. At
// most one read per channel is in flight; reads of several channels are handed to the
// connection together and queue there (the protocols answer in order).
// Late reads: when the host woke late or a read was slow, the periods that began meanwhile are
// each read, back to back, until the channel has caught up (PollSchedule's catch-up window,
// 100 ms), so a loaded machine delays samples but does not lose them.
// Lost samples: a slot counts as lost only when the channel fell further behind than that
// window (the link cannot keep up, or the host stalled that long), so "zero lost samples" means
// every period got its sample. Rate 0 channels never lose samples.
// Timestamps: the time base's elapsed time when the reply ARRIVES (the value is at most one
// round trip old); a sample read to catch up carries the time it was read.
// stop() counts the slots that ended without a read as lost too (a read that has been waiting
// for its answer for three periods has cost two samples already), so that a source whose reads
// never come back does not end with "zero lost".
// Errors: a failed read (device error, timeout, malformed answer) counts one lost sample and
// the channel's next sample starts a gap; failedCount() and lastReadError() keep them apart from
// periods missed because the link is slow. The connection leaving Connected stops the source with
// errorOccurred(Disconnected). start() on a connection that is not connected fails the same way.
// Values that are not numbers (strings, domains) are rejected by addChannel().
// Reading together: where the connection reads several objects in one exchange (GroupReader, a
// VABus block), a source of two or more channels joins it while running, and the channels due
// at the same time that the group holds are read in one exchange (each still one sample of its
// own channel); the others are read one by one.
class PollingSource : public TraceSource
{
    Q_OBJECT
public:
    // The connection is not owned and must outlive the source (or the source stops when it goes).
    explicit PollingSource(DeviceConnection *connection, QObject *parent = nullptr);
    ~PollingSource() override;

    DeviceConnection *connection() const { return m_connection; }

    // Adds a channel reading `address` every rateMs (0 = as fast as possible); name, unit and
    // scaling come from the connection's dictionary. Returns the channel index, or an error
    // (InvalidArgument: running, negative rate, write-only or non-numeric object).
    Result<int> addChannel(ObjectAddress address, int rateMs = 0);
    // Same with a caller-made description (its address is read).
    Result<int> addChannel(const ChannelInfo &info);
    void removeChannel(int channel); // only while stopped
    void setRateMs(int channel, int rateMs); // only while stopped

    QList<ChannelInfo> channels() const override;
    bool isRunning() const override { return m_running; }
    void start(const QElapsedTimer &timeBase) override;
    void stop() override;

    // Whether channels join the connection's group reader (default on; off reads each channel
    // on its own, for comparisons). Only while stopped.
    void setReadTogether(bool on)
    {
        if (!m_running)
            m_readTogether = on;
    }
    bool readsTogether() const { return m_readTogether; }
    // Reads that went out since start(): exchanges with the device, one per group read.
    qint64 readCount() const { return m_reads; }
    // Totals since start() (for benchmarks and the CLI summary).
    qint64 deliveredCount() const { return m_delivered; }
    qint64 lostCount() const { return m_lost; }
    // Reads that failed (each also one lost sample) and the cause of the last one (no error when
    // none failed).
    qint64 failedCount() const { return m_failed; }
    const Error &lastReadError() const { return m_lastReadError; }
    struct Unanswered
    {
        int channel = -1; // -1: no read was in flight at stop()
        double waitedS = 0; // how long it had waited for its answer
    };
    // The read that had waited longest for its answer when the source last stopped.
    Unanswered unansweredAtStop() const { return m_unanswered; }

private:
    struct Entry
    {
        ChannelInfo info;
        QPointer<Reply> inFlight; // owned; at most one per channel
        qint64 sinceNs = 0; // when it was sent, on the time base
    };
    void pump();
    // `slot`: the channel's place in a group read's values; -1 for a read of its own.
    void onReply(int channel, Reply *reply, int slot = -1);
    void readAlone(int channel);
    void onConnectionState(DeviceConnection::State state);
    void fail(const Error &error);
    void countLost(int channel, qint64 count);
    qint64 nowNs() const;

    QPointer<DeviceConnection> m_connection;
    QList<Entry> m_entries;
    QPointer<GroupReader> m_group; // joined while running
    QList<ObjectAddress> m_groupHeld; // what the group holds for us, in the order of its values
    PollSchedule m_schedule;
    QElapsedTimer m_timeBase;
    WakeupTimer m_wakeup; // fires at the next deadline of a channel without a read in flight
    bool m_running = false;
    bool m_readTogether = true;
    bool m_holdPump = false; // a group read's channels take their samples first
    qint64 m_reads = 0;
    qint64 m_delivered = 0;
    qint64 m_lost = 0;
    qint64 m_failed = 0;
    Error m_lastReadError;
    Unanswered m_unanswered;
};

} // namespace db::scope
