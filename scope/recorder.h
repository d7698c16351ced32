#pragma once
// The recorder: channels from trace sources, one time base, bounded buffers, modes, trigger.
#include "recording.h"
#include "tracesource.h"
#include "wakeuptimer.h"
#include <QElapsedTimer>
#include <QList>
#include <QObject>
#include <QPointer>

namespace db::scope {

// Records channels of one or more TraceSources on one time base.
//
// Modes:
// - Run: record from start() until stop(); each channel keeps its newest capacity() samples
//   (older ones are overwritten and counted in TraceBuffer::droppedOverwritten()). No trigger.
// - Roll: like Run, but only the last rollWindowS() seconds are kept (older samples dropped).
// - Single: arm, keep the last preTriggerS while waiting, fire on the trigger, record
//   postTriggerS more, cut the capture to [triggerTime - pre, triggerTime + post], stop.
// - Normal: like Single, but after each capture it re-arms at once. channel(i).buffer (and
//   buffer(i)) then shows the LAST COMPLETED capture (empty until the first one) while the next
//   one is acquired out of sight; captureCompleted() fires after each capture.
// Single/Normal without a valid trigger fail start() with errorOccurred(InvalidArgument).
//
// States: Idle (never started / cleared) -> Recording (Run/Roll) or Armed (Single/Normal)
// -> Triggered (post window running) -> Stopped (stop(), Single capture done, source error).
// Normal goes Triggered -> Armed after each capture.
//
// Sources stamp samples when they ARRIVE (see TraceSource), so the first sample later than
// triggerTime + post ends a capture; a timer ends it at that time when no sample comes.
// Memory: each channel holds at most capacity() samples; while Armed only the last
// preTriggerS seconds are kept.
//
// Signals are emitted on the event loop of the recorder's thread. dataAppended() fires once per
// incoming batch (often per sample, hundreds to thousands per second): receivers that repaint
// must coalesce (e.g. a 30 Hz timer that checks a dirty flag).
//
// Sources are not owned; a source destroyed while its channels are in the recorder turns those
// channels into orphans (kept with their data, never sampled again). A channel refers to its
// source's channel by index: remove it from the recorder before removing it from the source.
class Recorder : public QObject
{
    Q_OBJECT
public:
    enum class Mode { Run, Single, Normal, Roll };
    Q_ENUM(Mode)
    enum class State { Idle, Recording, Armed, Triggered, Stopped };
    Q_ENUM(State)

    struct Channel
    {
        ChannelInfo info;
        const TraceBuffer *buffer = nullptr; // valid until the channel is removed
    };

    explicit Recorder(QObject *parent = nullptr);
    ~Recorder() override;

    // --- channels (only while not running: Idle or Stopped; otherwise ignored, -1 / false)
    // Adds channel `sourceChannel` of `source`; returns the recorder's channel index.
    int addChannel(TraceSource *source, int sourceChannel);
    // Adds every channel of `source`; returns their indices.
    QList<int> addSource(TraceSource *source);
    bool removeChannel(int index);
    void removeAllChannels();
    int channelCount() const { return int(m_channels.size()); }
    Channel channel(int index) const;
    const ChannelInfo &channelInfo(int index) const;
    const TraceBuffer &buffer(int index) const; // what to display (see Normal mode)
    // Display scaling, allowed any time (also after recording); emits channelsChanged(). A
    // running trigger keeps the scaling it was armed with (start()).
    void setScaling(int index, double scale, double offset);

    // --- settings (take effect at the next start())
    qint64 capacity() const { return m_capacity; } // samples per channel
    void setCapacity(qint64 samplesPerChannel);
    Mode mode() const { return m_mode; }
    void setMode(Mode mode);
    double rollWindowS() const { return m_rollWindowS; }
    void setRollWindowS(double seconds);
    const Trigger &trigger() const { return m_trigger; }
    void setTrigger(const Trigger &trigger);
    // Run and Roll: the recording stops by itself when the time base reaches this many seconds
    // (to within the event loop's latency, well under a millisecond on an idle machine) and
    // keeps no sample stamped later; 0 = until stop(). Single and Normal end by their trigger.
    double durationS() const { return m_durationS; }
    void setDurationS(double seconds);

    // --- running
    // Clears the buffers, restarts the time base at 0 and starts all sources.
    void start();
    // Stops the sources and keeps the data. In Triggered state the capture is completed with
    // what has arrived (cut to the pre window); Armed in Single keeps the pre-trigger samples;
    // Normal keeps showing the last completed capture.
    void stop();
    State state() const { return m_state; }
    bool isRunning() const { return m_state != State::Idle && m_state != State::Stopped; }
    // Seconds since start() on the time base (0 when never started).
    double now() const;
    // Time on the time base when the recording last stopped; NaN while running or never run.
    double stoppedAt() const { return m_stoppedAt; }
    // Time of the last trigger on the time base; NaN when none.
    double triggerTime() const { return m_triggerTime; }
    QDateTime startedAt() const { return m_startedAt; }

    // The displayed data as a value (channels, buffers, device, trigger, start time).
    Recording recording() const;
    // Shows a saved recording (stops first; channels become orphans without source). Pass an
    // rvalue to move the samples in instead of copying them.
    void load(Recording recording);

Q_SIGNALS:
    void stateChanged(db::scope::Recorder::State state);
    void dataAppended();
    void triggered(double time);
    void captureCompleted();
    void channelsChanged();
    void samplesLost(int channel, qint64 count);
    // A source failed (the recorder stops) or start() was refused.
    void errorOccurred(const db::Error &error);

private:
    struct Slot;
    void setState(State state);
    void onLost(int index, qint64 count);
    void onSourceError(const Error &error);
    void append(int index, const TraceSamples &samples);
    void fire(double time);
    void completeCapture();
    void connectSource(TraceSource *source);
    void stopSources();
    QList<TraceSource *> sources() const;

    QList<Slot *> m_channels;
    qint64 m_capacity = TraceBuffer::kDefaultCapacity;
    Mode m_mode = Mode::Run;
    double m_rollWindowS = 10;
    Trigger m_trigger;
    TriggerDetector m_detector;
    State m_state = State::Idle;
    bool m_showCapture = false; // Normal mode: buffer() is the last completed capture
    QElapsedTimer m_clock;
    QDateTime m_startedAt;
    double m_triggerTime;
    double m_stoppedAt;
    double m_durationS = 0;
    WakeupTimer m_postTimer; // ends a capture at triggerTime + post when no later sample arrives
    WakeupTimer m_endTimer; // ends a Run/Roll recording after durationS()
};

} // namespace db::scope
