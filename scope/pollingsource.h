#pragma once
// Host polling of readable objects through DeviceConnection::read().
#include "core/deviceconnection.h"
#include "tracesource.h"
#include <QPointer>
#include <QTimer>

namespace db::scope {

// Samples objects of one DeviceConnection by reading them from the host.
//
// Scheduling: at most ONE read in flight on the connection (the protocols answer in order and a
// second request would only queue behind the first). Each channel has a period (rateMs; 0 = as
// fast as the link allows); when the link is free, the channel whose next due time is earliest
// is read (round-robin among equally due channels). A channel that is due again before its
// previous sample arrived is not queued twice: a read that starts more than one period late
// counts the missed periods as lost samples (a gap), so "zero lost samples" means every period
// got its sample. Rate 0 channels never lose samples that way.
// Timestamps: the time base's elapsed time when the reply ARRIVES (the value is at most one
// round trip old).
// stop() counts the periods that passed completely without a read as lost too (a read that
// has been waiting for its answer for three periods has cost two samples already), so that a
// source whose reads never come back does not end with "zero lost".
// Errors: a failed read (device error, timeout, malformed answer) counts one lost sample and
// the channel's next sample starts a gap; failedCount() and lastReadError() keep them apart from
// periods missed because the link is slow. The connection leaving Connected stops the source with
// errorOccurred(Disconnected). start() on a connection that is not connected fails the same way.
// Values that are not numbers (strings, domains) are rejected by addChannel().
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
    // The read that was still waiting for its answer when the source last stopped.
    Unanswered unansweredAtStop() const { return m_unanswered; }

private:
    struct Entry
    {
        ChannelInfo info;
        double nextDue = 0; // seconds on the time base
    };
    void pump();
    void onReply();
    void onConnectionState(DeviceConnection::State state);
    void fail(const Error &error);
    double nowS() const;

    QPointer<DeviceConnection> m_connection;
    QList<Entry> m_entries;
    QElapsedTimer m_timeBase;
    QTimer m_wakeup; // fires when the next channel is due and the link is idle
    QPointer<Reply> m_inFlight;
    int m_inFlightChannel = -1;
    double m_inFlightSinceS = 0;
    int m_lastServed = -1;
    bool m_running = false;
    qint64 m_delivered = 0;
    qint64 m_lost = 0;
    qint64 m_failed = 0;
    Error m_lastReadError;
    Unanswered m_unanswered;
};

} // namespace db::scope
