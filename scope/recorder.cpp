#include "recorder.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace db::scope {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kLongestS = 1e9; // ~31 years: beyond it a time would not fit in qint64 ns

// Seconds on the time base as ns, for the deadline timers.
qint64 toNs(double seconds)
{
    return qint64(std::llround(std::clamp(seconds, 0.0, kLongestS) * 1e9));
}

QString modeName(Recorder::Mode mode)
{
    switch (mode) {
    case Recorder::Mode::Run:
        return QStringLiteral("run");
    case Recorder::Mode::Single:
        return QStringLiteral("single");
    case Recorder::Mode::Normal:
        return QStringLiteral("normal");
    case Recorder::Mode::Roll:
        return QStringLiteral("roll");
    }
    return {};
}
} // namespace

struct Recorder::Slot
{
    ChannelInfo info;
    QPointer<TraceSource> source; // null for loaded channels and after the source went away
    int sourceChannel = -1;
    TraceBuffer live;
    TraceBuffer capture { 1 }; // Normal mode: the last completed capture
};

Recorder::Recorder(QObject *parent)
    : QObject(parent)
    , m_triggerTime(kNaN)
    , m_stoppedAt(kNaN)
{
    connect(&m_postTimer, &WakeupTimer::timeout, this, &Recorder::completeCapture);
    connect(&m_endTimer, &WakeupTimer::timeout, this, &Recorder::stop);
}

void Recorder::setDurationS(double seconds)
{
    m_durationS = std::isfinite(seconds) && seconds > 0 ? seconds : 0;
}

Recorder::~Recorder()
{
    for (TraceSource *source : sources())
        source->disconnect(this);
    qDeleteAll(m_channels);
}

int Recorder::addChannel(TraceSource *source, int sourceChannel)
{
    if (isRunning() || !source)
        return -1;
    const QList<ChannelInfo> infos = source->channels();
    if (sourceChannel < 0 || sourceChannel >= infos.size())
        return -1;
    const bool known = sources().contains(source);
    auto *slot = new Slot;
    slot->info = infos[sourceChannel];
    slot->source = source;
    slot->sourceChannel = sourceChannel;
    slot->live.setCapacity(m_capacity);
    m_channels.append(slot);
    if (!known)
        connectSource(source);
    Q_EMIT channelsChanged();
    return int(m_channels.size()) - 1;
}

QList<int> Recorder::addSource(TraceSource *source)
{
    QList<int> indices;
    if (!source)
        return indices;
    for (int i = 0; i < source->channels().size(); ++i) {
        const int index = addChannel(source, i);
        if (index >= 0)
            indices.append(index);
    }
    return indices;
}

bool Recorder::removeChannel(int index)
{
    if (isRunning() || index < 0 || index >= m_channels.size())
        return false;
    Slot *slot = m_channels.takeAt(index);
    TraceSource *source = slot->source;
    delete slot;
    if (source && !sources().contains(source))
        source->disconnect(this);
    if (m_trigger.channel == index)
        m_trigger.channel = -1;
    else if (m_trigger.channel > index)
        --m_trigger.channel;
    Q_EMIT channelsChanged();
    return true;
}

void Recorder::removeAllChannels()
{
    if (isRunning())
        return;
    for (TraceSource *source : sources())
        source->disconnect(this);
    qDeleteAll(m_channels);
    m_channels.clear();
    m_trigger.channel = -1;
    Q_EMIT channelsChanged();
}

Recorder::Channel Recorder::channel(int index) const
{
    return { channelInfo(index), &buffer(index) };
}

const ChannelInfo &Recorder::channelInfo(int index) const
{
    return m_channels.at(index)->info;
}

const TraceBuffer &Recorder::buffer(int index) const
{
    const Slot *slot = m_channels.at(index);
    return m_showCapture ? slot->capture : slot->live;
}

void Recorder::setScaling(int index, double scale, double offset)
{
    if (index < 0 || index >= m_channels.size() || scale == 0 || !std::isfinite(scale)
        || !std::isfinite(offset))
        return;
    m_channels[index]->info.scale = scale;
    m_channels[index]->info.offset = offset;
    Q_EMIT channelsChanged();
}

void Recorder::setCapacity(qint64 samplesPerChannel)
{
    m_capacity = std::max<qint64>(1, samplesPerChannel);
}

void Recorder::setMode(Mode mode)
{
    if (!isRunning())
        m_mode = mode;
}

void Recorder::setRollWindowS(double seconds)
{
    if (seconds > 0 && std::isfinite(seconds))
        m_rollWindowS = seconds;
}

void Recorder::setTrigger(const Trigger &trigger)
{
    if (!isRunning())
        m_trigger = trigger;
}

void Recorder::start()
{
    if (isRunning())
        return;
    if (m_channels.isEmpty()) {
        Q_EMIT errorOccurred(Error(Error::Kind::InvalidArgument, tr("no channels to record")));
        return;
    }
    const bool triggered = m_mode == Mode::Single || m_mode == Mode::Normal;
    if (triggered
        && (!m_trigger.isValid() || m_trigger.channel >= m_channels.size()
            || m_trigger.preTriggerS < 0 || m_trigger.postTriggerS < 0)) {
        Q_EMIT errorOccurred(Error(Error::Kind::InvalidArgument,
                                   tr("single and normal mode need a trigger on a recorded "
                                      "channel with pre/post times >= 0")));
        return;
    }
    for (Slot *slot : std::as_const(m_channels)) {
        if (!slot->source) {
            Q_EMIT errorOccurred(Error(Error::Kind::InvalidArgument,
                                       tr("channel %1 has no source (loaded from a file or its "
                                          "source was closed)")
                                           .arg(slot->info.label())));
            return;
        }
    }
    for (Slot *slot : std::as_const(m_channels)) {
        slot->live.clear();
        slot->live.setCapacity(m_capacity);
        slot->capture.clear();
    }
    m_showCapture = m_mode == Mode::Normal;
    m_triggerTime = kNaN;
    if (triggered) {
        const ChannelInfo &info = m_channels[m_trigger.channel]->info;
        m_detector = TriggerDetector(m_trigger, info.scale, info.offset);
    }
    m_stoppedAt = kNaN;
    m_clock.start();
    m_startedAt = QDateTime::currentDateTimeUtc();
    setState(triggered ? State::Armed : State::Recording);
    if (!triggered && m_durationS > 0)
        m_endTimer.wakeAt(m_clock, toNs(m_durationS));
    for (TraceSource *source : sources()) {
        if (source->isRunning())
            source->stop();
        source->start(m_clock);
    }
    Q_EMIT dataAppended();
}

void Recorder::stop()
{
    if (!isRunning())
        return;
    if (m_state == State::Triggered) {
        completeCapture(); // ends in Stopped (Single) or Armed (Normal)
        if (!isRunning())
            return;
    }
    m_postTimer.stop();
    stopSources();
    setState(State::Stopped);
    Q_EMIT dataAppended();
}

double Recorder::now() const
{
    return m_clock.isValid() ? double(m_clock.nsecsElapsed()) * 1e-9 : 0.0;
}

Recording Recorder::recording() const
{
    Recording rec;
    QStringList devices;
    for (int i = 0; i < m_channels.size(); ++i) {
        rec.channels.append({ m_channels[i]->info, buffer(i) });
        if (!devices.contains(m_channels[i]->info.device))
            devices.append(m_channels[i]->info.device);
    }
    rec.device = devices.join(QStringLiteral("; "));
    rec.startedAt = m_startedAt;
    rec.mode = modeName(m_mode);
    if (m_mode == Mode::Single || m_mode == Mode::Normal || !std::isnan(m_triggerTime))
        rec.trigger = m_trigger;
    rec.triggerTime = m_triggerTime;
    return rec;
}

void Recorder::load(Recording recording)
{
    stop();
    removeAllChannels();
    for (RecordedChannel &c : recording.channels) {
        auto *slot = new Slot;
        slot->info = c.info;
        slot->live = std::move(c.buffer);
        m_channels.append(slot);
    }
    m_showCapture = false;
    m_trigger = recording.trigger;
    m_triggerTime = recording.triggerTime;
    m_startedAt = recording.startedAt;
    m_clock.invalidate();
    setState(State::Stopped);
    Q_EMIT channelsChanged();
    Q_EMIT dataAppended();
}

void Recorder::setState(State state)
{
    if (m_state == state)
        return;
    m_state = state;
    Q_EMIT stateChanged(state);
}

QList<TraceSource *> Recorder::sources() const
{
    QList<TraceSource *> list;
    for (const Slot *slot : m_channels) {
        if (slot->source && !list.contains(slot->source.data()))
            list.append(slot->source.data());
    }
    return list;
}

void Recorder::stopSources()
{
    m_endTimer.stop();
    m_stoppedAt = now();
    for (TraceSource *source : sources())
        source->stop();
}

void Recorder::connectSource(TraceSource *source)
{
    connect(source, &TraceSource::samplesReady, this,
            [this, source](int channel, const TraceSamples &samples) {
                for (int i = 0; i < m_channels.size(); ++i) {
                    if (m_channels[i]->source == source && m_channels[i]->sourceChannel == channel)
                        append(i, samples);
                }
            });
    connect(source, &TraceSource::samplesLost, this, [this, source](int channel, qint64 count) {
        for (int i = 0; i < m_channels.size(); ++i) {
            if (m_channels[i]->source == source && m_channels[i]->sourceChannel == channel)
                onLost(i, count);
        }
    });
    connect(source, &TraceSource::errorOccurred, this, &Recorder::onSourceError);
}

void Recorder::onLost(int index, qint64 count)
{
    if (!isRunning() || count <= 0)
        return;
    m_channels[index]->live.markLost(count);
    Q_EMIT samplesLost(index, count);
}

void Recorder::onSourceError(const Error &error)
{
    if (!isRunning())
        return;
    m_postTimer.stop();
    stopSources();
    setState(State::Stopped);
    Q_EMIT errorOccurred(error);
    Q_EMIT dataAppended();
}

void Recorder::append(int index, const TraceSamples &samples)
{
    if (!isRunning() || samples.isEmpty())
        return;
    TraceBuffer &live = m_channels[index]->live;
    const bool isTriggerChannel = index == m_trigger.channel;
    bool pastEnd = false;
    const bool timed = m_durationS > 0 && (m_mode == Mode::Run || m_mode == Mode::Roll);
    for (const TraceSample &s : samples) {
        if (timed && s.t > m_durationS)
            break; // stamped after the end, before the end timer's turn came

        if (m_state == State::Triggered && s.t > m_triggerTime + m_trigger.postTriggerS) {
            pastEnd = true; // timestamps are arrival times: no later sample can be inside
            break;
        }
        live.append(s.t, s.raw);
        if (m_state == State::Armed && isTriggerChannel && m_detector.feed(s.raw))
            fire(s.t);
    }
    const double latest = live.isEmpty() ? 0 : live.lastTime();
    if (m_state == State::Armed)
        live.dropBefore(latest - m_trigger.preTriggerS);
    else if (m_mode == Mode::Roll)
        live.dropBefore(latest - m_rollWindowS);
    if (pastEnd) {
        completeCapture();
        return;
    }
    if (!m_showCapture)
        Q_EMIT dataAppended();
}

void Recorder::fire(double time)
{
    m_triggerTime = time;
    setState(State::Triggered);
    Q_EMIT triggered(time);
    // Ends the capture at triggerTime + post even when no further sample arrives.
    m_postTimer.wakeAt(m_clock, toNs(time + m_trigger.postTriggerS) + 1);
}

void Recorder::completeCapture()
{
    if (m_state != State::Triggered)
        return;
    m_postTimer.stop();
    const double from = m_triggerTime - m_trigger.preTriggerS;
    const double to = m_triggerTime + m_trigger.postTriggerS;
    for (Slot *slot : std::as_const(m_channels)) {
        slot->live.dropBefore(from);
        slot->live.dropAfter(to);
    }
    if (m_mode == Mode::Normal) {
        for (Slot *slot : std::as_const(m_channels)) {
            slot->capture = slot->live;
            slot->live.clear();
        }
        m_detector.reset();
        setState(State::Armed);
        Q_EMIT captureCompleted();
        Q_EMIT dataAppended();
        return;
    }
    stopSources();
    setState(State::Stopped);
    Q_EMIT captureCompleted();
    Q_EMIT dataAppended();
}

} // namespace db::scope
