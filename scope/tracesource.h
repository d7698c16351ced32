#pragma once
// Where samples come from: host polling, passive PDO sampling, drive-side capture.
#include "channel.h"
#include "core/error.h"
#include <QElapsedTimer>
#include <QList>
#include <QObject>

namespace db::scope {

struct TraceSample
{
    double t = 0; // seconds on the recording's time base (see TraceSource::start)
    double raw = 0; // raw value as the device sent it (no scaling)
};
using TraceSamples = QList<TraceSample>;

// Abstract producer of samples for one or more channels (indices 0..channels().size()-1,
// local to the source). Owned by whoever creates it (app/widget/CLI); the Recorder only
// connects to it, starts and stops it.
//
// Contract for implementations:
// - start(timeBase): begin sampling; every sample's t is timeBase.nsecsElapsed() * 1e-9 taken
//   when the value arrives (so all channels of all sources share the recorder's time base).
//   Emits runningChanged(true). Ignored while running.
// - stop(): stop sampling, drop pending requests' results; emits runningChanged(false).
//   Ignored while stopped. Never emits samples after stop() returns.
// - samplesReady(): one or more samples of one channel, in time order, on the event loop.
// - samplesLost(channel, count): samples that should have come and did not (failed read,
//   timeout, sequence gap); the recorder counts them and marks a gap.
// - errorOccurred(error): a fatal problem (connection lost, bus error); the source has stopped
//   (runningChanged(false) follows or has been emitted).
// - Channels may only be added/removed while stopped; channelsChanged() then fires.
class TraceSource : public QObject
{
    Q_OBJECT
public:
    using QObject::QObject;

    virtual QList<ChannelInfo> channels() const = 0;
    virtual bool isRunning() const = 0;
    virtual void start(const QElapsedTimer &timeBase) = 0;
    virtual void stop() = 0;

Q_SIGNALS:
    void samplesReady(int channel, const db::scope::TraceSamples &samples);
    void samplesLost(int channel, qint64 count);
    void errorOccurred(const db::Error &error);
    void runningChanged(bool running);
    void channelsChanged();
};

} // namespace db::scope

Q_DECLARE_METATYPE(db::scope::TraceSample)
