// Frame time of the scope plot (decimation from the buffers' min/max summary + QCustomPlot
// replot), offscreen at 1600 x 900 px, and the cost of appending samples while recording.
//
// For each case (8 x 1e6, 8 x 1e7, 1 x 1e7 samples):
// - full: autoscale() every frame (fit, decimate, hand over, replot), as while following;
// - zoomed: a 1 % window panning across the first tenth of the recording;
// - zoomed-bare: a bare QCustomPlot holding the same samples (the panned tenth), the same
//   window each frame and only setRange + replot (its own adaptive sampling, 1 px pen without
//   antialiasing like the scope's decimated lines): what the scope's zoomed frame is held to.
// Each frame is timed on the wall clock and in CPU time of the thread (the machine may be busy
// with other work; CPU time is what the frame costs).
//
// append: a source delivers 8 channels at 2.5 kHz each (20 kHz in total), one signal per
// sample as the polling source does, for --append-seconds; the process's CPU use is measured
// with the source alone, with the recorder appending (buffers and summary), and with a shown
// plot following the data at its 30 Hz frame rate.
//
//   QT_QPA_PLATFORM=offscreen build/bench/scope/scope_plot_bench [frames] [--cases 8x1e6,...]
//                                                               [--append-seconds S] [--rt]
#include "scope/decimation.h"
#include "scope/recorder.h"
#include "scope/tracesource.h"
#include "widgets/common/plot.h"
#include "widgets/scope/scopeplot.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QTimer>

#include <sched.h>
#include <sys/resource.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <memory>
#include <vector>

using namespace db;

namespace {

double threadCpuMs()
{
    timespec ts {};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) * 1e3 + double(ts.tv_nsec) * 1e-6;
}

double processCpuMs()
{
    rusage ru {};
    getrusage(RUSAGE_SELF, &ru);
    const auto ms = [](const timeval &tv) {
        return double(tv.tv_sec) * 1e3 + tv.tv_usec * 1e-3;
    };
    return ms(ru.ru_utime) + ms(ru.ru_stime);
}

// A value of channel c at sample i that looks like a drive: a position ramp with noise, a
// current with steps and noise, a sine; deterministic and cheap.
double driveValue(int c, qint64 i, quint32 &seed)
{
    seed = seed * 1664525u + 1013904223u;
    const double noise = double(seed >> 16) / 65536.0 - 0.5;
    const double t = double(i) * 1e-4;
    switch (c % 3) {
    case 0:
        return 1000.0 * t + 5 * noise;
    case 1:
        return ((i / 10000) % 2 == 0 ? 800.0 : -300.0) + 40 * noise;
    default:
        return 100.0 * std::sin(2 * M_PI * 3.0 * t) + noise;
    }
}

scope::Recording makeRecording(int channels, qint64 samples)
{
    scope::Recording rec;
    rec.device = QStringLiteral("bench://");
    quint32 seed = 12345;
    for (int c = 0; c < channels; ++c) {
        scope::RecordedChannel ch;
        ch.info.id = QStringLiteral("%1:0").arg(0x6064 + c, 4, 16, QLatin1Char('0'));
        ch.info.name = QStringLiteral("channel %1").arg(c);
        rec.channels.append(std::move(ch));
        scope::TraceBuffer &buffer = rec.channels.last().buffer;
        buffer.setCapacity(samples);
        for (qint64 i = 0; i < samples; ++i)
            buffer.append(double(i) * 1e-4, driveValue(c, i, seed));
    }
    return rec;
}

struct Frames
{
    double wallMs = 0; // per frame
    double cpuMs = 0;
    double decimationMs = 0; // of cpuMs: fit, decimation and hand-over, without drawing
    double decimateMs = 0; // of decimationMs: scope::decimate() alone
};

void print(const char *name, const char *view, const Frames &f)
{
    std::printf("%-8s %-11s frame %7.2f ms = %7.1f fps | CPU %7.2f ms = %7.1f fps"
                " | decimation %6.2f ms (decimate() %5.2f ms)\n",
                name, view, f.wallMs, 1000.0 / f.wallMs, f.cpuMs, 1000.0 / f.cpuMs, f.decimationMs,
                f.decimateMs);
    std::fflush(stdout);
}

// The window of zoomed frame i: 1 % of the span, panning across its first tenth.
QCPRange zoomWindow(double t0, double span, int i, int frames)
{
    const double lo = t0 + span * 0.09 * double(i) / frames;
    return { lo, lo + span * 0.01 };
}

Frames measure(widgets::ScopePlot &plot, int frames, bool zoomed, double t0, double span)
{
    QCustomPlot *qcp = plot.customPlot();
    Frames f;
    QElapsedTimer wall;
    wall.start();
    const double cpu0 = threadCpuMs();
    for (int i = 0; i < frames; ++i) {
        const double d0 = threadCpuMs();
        if (zoomed) {
            const QCPRange r = zoomWindow(t0, span, i, frames);
            plot.setTimeRange(r.lower, r.upper);
        } else {
            plot.autoscale(); // a full refresh: fit, decimate, hand over
        }
        f.decimationMs += threadCpuMs() - d0;
        qcp->replot(QCustomPlot::rpImmediateRefresh);
    }
    f.wallMs = double(wall.nsecsElapsed()) * 1e-6 / frames;
    f.cpuMs = (threadCpuMs() - cpu0) / frames;
    f.decimationMs /= frames;
    // The same frames' decimate() calls alone, at the plot's width in columns.
    scope::Recorder *recorder = plot.recorder();
    const int columns = plot.graph(0)->keyAxis()->axisRect()->width();
    const double d0 = threadCpuMs();
    for (int i = 0; i < frames; ++i) {
        const QCPRange r = zoomed ? zoomWindow(t0, span, i, frames) : QCPRange(t0, t0 + span);
        for (int c = 0; c < recorder->channelCount(); ++c)
            scope::decimate(recorder->buffer(c), r.lower, r.upper, columns);
    }
    f.decimateMs = (threadCpuMs() - d0) / frames;
    return f;
}

using BarePoints = std::vector<QVector<QCPGraphData>>;

// The samples of every channel up to t, as QCustomPlot data.
BarePoints barePoints(const scope::Recording &rec, double t)
{
    BarePoints all;
    for (const scope::RecordedChannel &c : rec.channels) {
        const scope::TraceBuffer &b = c.buffer;
        QVector<QCPGraphData> points(b.upperBound(t));
        for (qsizetype i = 0; i < points.size(); ++i)
            points[i] = QCPGraphData(b.time(i), b.value(i));
        all.push_back(std::move(points));
    }
    return all;
}

Frames measureBare(const BarePoints &data, int frames, double t0, double span)
{
    QCustomPlot qcp;
    qcp.resize(1600, 900);
    qcp.show();
    for (const QVector<QCPGraphData> &points : data) {
        QCPGraph *g = qcp.addGraph();
        g->data()->set(points, true);
        g->setPen(QPen(Qt::blue, 1.0));
        g->setAntialiased(false);
    }
    qcp.xAxis->setRange(zoomWindow(t0, span, 0, frames));
    qcp.rescaleAxes();
    qcp.replot(QCustomPlot::rpImmediateRefresh);
    Frames f;
    QElapsedTimer wall;
    wall.start();
    const double cpu0 = threadCpuMs();
    for (int i = 0; i < frames; ++i) {
        qcp.xAxis->setRange(zoomWindow(t0, span, i, frames));
        qcp.replot(QCustomPlot::rpImmediateRefresh);
    }
    f.wallMs = double(wall.nsecsElapsed()) * 1e-6 / frames;
    f.cpuMs = (threadCpuMs() - cpu0) / frames;
    return f;
}

void runCase(const char *name, int channels, qint64 samples, int frames)
{
    QElapsedTimer timer;
    timer.start();
    scope::Recording rec = makeRecording(channels, samples);
    std::printf("%s: %d channel(s) x %lld samples made in %.0f ms\n", name, channels,
                static_cast<long long>(samples), double(timer.nsecsElapsed()) * 1e-6);
    const double t0 = rec.startTime();
    const double span = rec.endTime() - t0;
    const BarePoints bare = barePoints(rec, t0 + span * 0.1); // the panned tenth
    {
        scope::Recorder recorder;
        recorder.load(std::move(rec));
        widgets::ScopePlot plot;
        plot.resize(1600, 900);
        plot.show();
        plot.setRecorder(&recorder);
        plot.autoscale();
        plot.customPlot()->replot(QCustomPlot::rpImmediateRefresh);
        print(name, "full", measure(plot, frames, false, t0, span));
        print(name, "zoomed", measure(plot, frames, true, t0, span));
    }
    print(name, "zoomed-bare", measureBare(bare, frames, t0, span));
}

// Delivers `channels` channels at `rateHz` each in real time, one samplesReady per sample.
class BenchSource : public scope::TraceSource
{
public:
    BenchSource(int channels, double rateHz)
        : m_channels(channels)
        , m_rateHz(rateHz)
    {
        m_timer.setTimerType(Qt::PreciseTimer);
        m_timer.setInterval(1);
        QObject::connect(&m_timer, &QTimer::timeout, this, [this] { tick(); });
    }
    QList<scope::ChannelInfo> channels() const override
    {
        QList<scope::ChannelInfo> list;
        for (int c = 0; c < m_channels; ++c) {
            scope::ChannelInfo info;
            info.id = QStringLiteral("%1:0").arg(0x6064 + c, 4, 16, QLatin1Char('0'));
            info.name = QStringLiteral("channel %1").arg(c);
            list.append(info);
        }
        return list;
    }
    bool isRunning() const override { return m_timer.isActive(); }
    void start(const QElapsedTimer &timeBase) override
    {
        m_timeBase = timeBase;
        m_sent = 0;
        m_timer.start();
    }
    void stop() override { m_timer.stop(); }
    qint64 sent() const { return m_sent * m_channels; }

private:
    void tick()
    {
        const double now = double(m_timeBase.nsecsElapsed()) * 1e-9;
        const qint64 due = qint64(now * m_rateHz);
        for (; m_sent < due; ++m_sent) {
            for (int c = 0; c < m_channels; ++c)
                Q_EMIT samplesReady(c, { { now, driveValue(c, m_sent, m_seed) } });
        }
    }

    int m_channels;
    double m_rateHz;
    QTimer m_timer;
    QElapsedTimer m_timeBase;
    qint64 m_sent = 0;
    quint32 m_seed = 1;
};

// Percent of one core the process uses while the source runs for `seconds`.
double appendCpu(double seconds, bool record, bool plot)
{
    BenchSource source(8, 2500.0);
    scope::Recorder recorder;
    std::unique_ptr<widgets::ScopePlot> view;
    if (record)
        recorder.addSource(&source);
    if (plot) {
        view = std::make_unique<widgets::ScopePlot>();
        view->resize(1600, 900);
        view->setRecorder(&recorder);
        view->show();
    }
    QElapsedTimer timeBase;
    timeBase.start();
    if (record)
        recorder.start();
    else
        source.start(timeBase);
    QElapsedTimer wall;
    wall.start();
    const double cpu0 = processCpuMs();
    QEventLoop loop;
    QTimer::singleShot(int(seconds * 1000), &loop, &QEventLoop::quit);
    loop.exec();
    const double cpu = processCpuMs() - cpu0;
    const double wallMs = double(wall.nsecsElapsed()) * 1e-6;
    if (record)
        recorder.stop();
    else
        source.stop();
    if (record && recorder.channelCount() == 8 && recorder.buffer(0).size() < source.sent() / 16)
        std::printf("append: the recorder kept only %lld samples per channel\n",
                    static_cast<long long>(recorder.buffer(0).size()));
    return 100.0 * cpu / wallMs;
}

} // namespace

int main(int argc, char *argv[])
{
    QApplication app(argc, argv);
    int frames = 60;
    QStringList cases = { QStringLiteral("8x1e6"), QStringLiteral("8x1e7"),
                          QStringLiteral("1x1e7") };
    double appendSeconds = 5;
    bool realTime = false;
    const QStringList args = app.arguments().mid(1);
    for (int i = 0; i < args.size(); ++i) {
        if (args[i] == QLatin1String("--cases") && i + 1 < args.size())
            cases = args[++i].split(QLatin1Char(','), Qt::SkipEmptyParts);
        else if (args[i] == QLatin1String("--append-seconds") && i + 1 < args.size())
            appendSeconds = args[++i].toDouble();
        else if (args[i] == QLatin1String("--rt"))
            realTime = true;
        else if (args[i].toInt() > 0)
            frames = args[i].toInt();
        else {
            std::fprintf(stderr,
                         "usage: scope_plot_bench [frames] [--cases 8x1e6,8x1e7,1x1e7]"
                         " [--append-seconds S] [--rt]\n");
            return 2;
        }
    }
    if (realTime) {
        // On a machine busy with other work, real-time priority (as root) makes the wall-clock
        // figures stand in for an idle machine's.
        sched_param param {};
        param.sched_priority = 20;
        if (sched_setscheduler(0, SCHED_FIFO, &param) != 0)
            std::fprintf(stderr, "scope_plot_bench: --rt: %s (needs root)\n", strerror(errno));
    }
    std::printf("scope_plot_bench: %d frames each, plot 1600 x 900 px, platform %s\n", frames,
                qPrintable(QGuiApplication::platformName()));
    for (const QString &c : cases) {
        const QStringList parts = c.split(QLatin1Char('x'));
        const int channels = parts.value(0).toInt();
        const qint64 samples = qint64(parts.value(1).toDouble());
        if (parts.size() != 2 || channels < 1 || samples < 2) {
            std::fprintf(stderr, "scope_plot_bench: bad case %s (CHANNELSxSAMPLES)\n",
                         qPrintable(c));
            return 2;
        }
        const QByteArray name = QStringLiteral("%1 x %2").arg(channels).arg(parts[1]).toUtf8();
        runCase(name.constData(), channels, samples, frames);
    }
    if (appendSeconds > 0) {
        const double alone = appendCpu(appendSeconds, false, false);
        const double recorded = appendCpu(appendSeconds, true, false);
        const double plotted = appendCpu(appendSeconds, true, true);
        std::printf("append 8 x 2.5 kHz for %.0f s\n", appendSeconds);
        std::printf("append: source alone %.1f %% of a core\n", alone);
        std::printf("append: recorded %.1f %% of a core\n", recorded);
        std::printf("append: cost of recording %.1f %% of a core\n", recorded - alone);
        std::printf("append: recorded, plot following %.1f %% of a core\n", plotted);
    }
    return 0;
}
