// Plot frame time of the scope: decimation + QCustomPlot replot, offscreen, for
// 8 channels x 1e6 samples and 1 channel x 1e7 samples, full view and zoomed (a panning 1 %
// window, so every frame decimates anew). Prints ms per frame and fps; target >= 30 fps.
//
//   QT_QPA_PLATFORM=offscreen build/bench/scope/scope_plot_bench [frames]
#include "scope/recorder.h"
#include "widgets/scope/scopeplot.h"

#include <qcustomplot.h>

#include <QApplication>
#include <QElapsedTimer>

#include <cmath>
#include <cstdio>

using namespace db;

namespace {

// Channels that look like a drive: a position ramp with noise, a current with steps and
// noise, a sine; deterministic.
scope::Recording makeRecording(int channels, qint64 samples)
{
    scope::Recording rec;
    rec.device = QStringLiteral("bench://");
    quint32 seed = 12345;
    for (int c = 0; c < channels; ++c) {
        scope::RecordedChannel ch;
        ch.info.id = QStringLiteral("%1:0").arg(0x6064 + c, 4, 16, QLatin1Char('0'));
        ch.info.name = QStringLiteral("channel %1").arg(c);
        ch.buffer.setCapacity(samples);
        for (qint64 i = 0; i < samples; ++i) {
            seed = seed * 1664525u + 1013904223u;
            const double noise = double(seed >> 16) / 65536.0 - 0.5;
            const double t = double(i) * 1e-4;
            const double v = c % 3 == 0 ? 1000.0 * t + 5 * noise
                : c % 3 == 1            ? (std::fmod(t, 2.0) < 1.0 ? 800.0 : -300.0) + 40 * noise
                                        : 100.0 * std::sin(2 * M_PI * 3.0 * t) + noise;
            ch.buffer.append(t, v);
        }
        rec.channels.append(ch);
    }
    return rec;
}

struct Figures
{
    double firstMs = 0;
    double frameMs = 0;
    double decimationMs = 0; // of frameMs: decimation and data hand-over, without drawing
};

Figures measure(widgets::ScopePlot &plot, int frames, bool zoomed)
{
    QCustomPlot *qcp = plot.customPlot();
    QElapsedTimer timer;
    timer.start();
    plot.autoscale(); // first frame: builds the min/max pyramids
    qcp->replot(QCustomPlot::rpImmediateRefresh);
    Figures f;
    f.firstMs = double(timer.nsecsElapsed()) * 1e-6;
    const double t0 = plot.timeLower();
    const double span = plot.timeUpper() - t0;
    timer.restart();
    qint64 decimationNs = 0;
    for (int i = 0; i < frames; ++i) {
        QElapsedTimer part;
        part.start();
        if (zoomed) {
            const double lo = t0 + span * 0.9 * double(i) / frames;
            plot.setTimeRange(lo, lo + span * 0.01);
        } else {
            plot.autoscale(); // a full refresh: fit, decimate, hand over
        }
        decimationNs += part.nsecsElapsed();
        qcp->replot(QCustomPlot::rpImmediateRefresh);
    }
    f.frameMs = double(timer.nsecsElapsed()) * 1e-6 / frames;
    f.decimationMs = double(decimationNs) * 1e-6 / frames;
    return f;
}

void run(const char *name, int channels, qint64 samples, int frames)
{
    scope::Recorder recorder;
    QElapsedTimer timer;
    timer.start();
    recorder.load(makeRecording(channels, samples));
    std::printf("%s: %d channel(s) x %lld samples made in %.0f ms\n", name, channels,
                static_cast<long long>(samples), double(timer.nsecsElapsed()) * 1e-6);
    widgets::ScopePlot plot;
    plot.resize(1600, 900);
    plot.show();
    plot.setRecorder(&recorder);
    for (bool zoomed : { false, true }) {
        const Figures f = measure(plot, frames, zoomed);
        std::printf("%-8s %-6s first frame %6.1f ms | frame %6.2f ms = %6.1f fps "
                    "(decimation %5.2f ms)\n",
                    name, zoomed ? "zoomed" : "full", f.firstMs, f.frameMs, 1000.0 / f.frameMs,
                    f.decimationMs);
    }
}

} // namespace

int main(int argc, char *argv[])
{
    QApplication app(argc, argv);
    const int frames = argc > 1 ? std::max(1, std::atoi(argv[1])) : 60;
    std::printf("scope_plot_bench: %d frames each, plot 1600 x 900 px, platform %s\n", frames,
                qPrintable(QGuiApplication::platformName()));
    run("8 x 1e6", 8, 1'000'000, frames);
    run("1 x 1e7", 1, 10'000'000, frames);
    return 0;
}
