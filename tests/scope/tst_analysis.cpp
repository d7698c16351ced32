// Level 1: analysis against synthetic signals with known answers: a sine's spectrum peak and
// amplitude, a second-order step's overshoot/rise/settling, statistics between cursors.
#include "scope/analysis.h"

#include <QtTest>
#include <cmath>
#include <numbers>

using namespace db;
using namespace db::scope;

namespace {

TraceBuffer sine(double frequency, double amplitude, double rate, double seconds, double jitter = 0)
{
    TraceBuffer b;
    const int n = int(seconds * rate);
    quint32 state = 12345;
    for (int i = 0; i < n; ++i) {
        state = state * 1664525u + 1013904223u;
        const double dt = jitter * (double(state >> 8) / double(1 << 24) - 0.5) / rate;
        const double t = i / rate + dt;
        b.append(t, 100 + amplitude * std::sin(2 * std::numbers::pi * frequency * t));
    }
    return b;
}

// Unit step response of wn^2 / (s^2 + 2 zeta wn s + wn^2), underdamped.
double secondOrder(double t, double zeta, double wn)
{
    const double wd = wn * std::sqrt(1 - zeta * zeta);
    const double phi = std::acos(zeta);
    return 1 - std::exp(-zeta * wn * t) / std::sqrt(1 - zeta * zeta) * std::sin(wd * t + phi);
}

} // namespace

class TstAnalysis : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void sineSpectrumPeak()
    {
        const TraceBuffer b = sine(50, 3, 1000, 2);
        const auto s = analysis::spectrum(b);
        QVERIFY2(s.ok(), qPrintable(s.error().toString()));
        QCOMPARE(s->points, 2000); // 2 s at 1 kHz
        QVERIFY(std::abs(s->peakFrequency() - 50) <= 0.5);
        const double peak = *std::max_element(s->amplitude.cbegin() + 1, s->amplitude.cend());
        QVERIFY2(std::abs(peak - 3) < 0.1, qPrintable(QString::number(peak)));
        QVERIFY(s->amplitude[0] < 0.01); // mean removed
        QCOMPARE(s->frequency.last(), 500.0);
    }
    void jitteredSamplesAreResampled()
    {
        // Polled samples do not arrive on a grid: the spectrum still finds the sine.
        const TraceBuffer b = sine(12, 1, 200, 5, 0.3);
        const auto s = analysis::spectrum(b);
        QVERIFY(s.ok());
        QVERIFY(std::abs(s->peakFrequency() - 12) <= 0.3);
    }
    void spectrumOfARange()
    {
        TraceBuffer b;
        for (int i = 0; i < 4000; ++i) {
            const double t = i / 1000.0;
            const double f = t < 2 ? 20 : 80;
            b.append(t, std::sin(2 * std::numbers::pi * f * t));
        }
        const auto early = analysis::spectrum(b, 0.1, 1.9);
        const auto late = analysis::spectrum(b, 2.1, 3.9);
        QVERIFY(early.ok() && late.ok());
        QVERIFY(std::abs(early->peakFrequency() - 20) <= 1);
        QVERIFY(std::abs(late->peakFrequency() - 80) <= 1);
    }
    void spectrumNeedsSamples()
    {
        TraceBuffer b;
        b.append(0, 1);
        b.append(1, 2);
        const auto s = analysis::spectrum(b);
        QCOMPARE(s.error().kind(), Error::Kind::InvalidArgument);
    }

    void secondOrderStep()
    {
        const double zeta = 0.3, wn = 2 * std::numbers::pi * 5;
        TraceBuffer b;
        for (int i = 0; i < 200; ++i) // 0.2 s at rest before the step
            b.append(i * 1e-3 - 0.2, 10);
        for (int i = 0; i <= 3000; ++i) {
            const double t = i * 1e-4 * 10; // 0..3 s, 1 ms
            b.append(t, 10 + 100 * secondOrder(t, zeta, wn));
        }
        const auto r = analysis::stepResponse(b, 0, 3);
        QVERIFY2(r.ok(), qPrintable(r.error().toString()));
        const double overshoot =
            100 * std::exp(-zeta * std::numbers::pi / std::sqrt(1 - zeta * zeta));
        QVERIFY2(std::abs(r->overshootPercent - overshoot) < 0.2,
                 qPrintable(QString::number(r->overshootPercent)));
        const double peakTime = std::numbers::pi / (wn * std::sqrt(1 - zeta * zeta));
        QVERIFY(std::abs(r->peakTime - peakTime) < 2e-3);
        QVERIFY(std::abs(r->initial - 10) < 1e-9);
        QVERIFY(std::abs(r->final - 110) < 0.1);
        // Rise time 10-90 %: compare with a fine numeric search on the model.
        double t10 = 0, t90 = 0;
        for (double t = 0; t < 1; t += 1e-6) {
            if (!t10 && secondOrder(t, zeta, wn) >= 0.1)
                t10 = t;
            if (!t90 && secondOrder(t, zeta, wn) >= 0.9) {
                t90 = t;
                break;
            }
        }
        QVERIFY(std::abs(r->riseTime - (t90 - t10)) < 1e-3);
        // Settling to 2 %: the envelope estimate 4 / (zeta wn) bounds it from above.
        QVERIFY(r->settlingTime > 0.5 * 4 / (zeta * wn));
        QVERIFY(r->settlingTime < 4 / (zeta * wn));
        QVERIFY(std::abs(secondOrder(r->settlingTime + 0.002, zeta, wn) - 1) <= 0.0205);
    }
    void fallingStepAndNoStep()
    {
        TraceBuffer b;
        for (int i = 0; i < 100; ++i)
            b.append(i * 0.01, i < 10 ? 50 : (i < 12 ? 30 : 0));
        const auto r = analysis::stepResponse(b);
        QVERIFY(r.ok());
        QCOMPARE(r->overshootPercent, 0.0);
        QCOMPARE(r->final, 0.0);
        TraceBuffer flat;
        for (int i = 0; i < 10; ++i)
            flat.append(i, 5);
        QCOMPARE(analysis::stepResponse(flat).error().kind(), Error::Kind::InvalidArgument);
    }
    void notAStep()
    {
        // A sine, noise and a signal still rising at the end get "not a step" instead of a
        // rise time and an overshoot; a lightly damped step (70 % overshoot) is still one.
        const auto notAStep = [](const TraceBuffer &b) {
            const auto r = analysis::stepResponse(b);
            return !r.ok() && r.error().message().startsWith(QLatin1String("not a step:"));
        };
        QVERIFY(notAStep(sine(3, 10, 1000, 1.3)));
        TraceBuffer noise;
        quint32 state = 7;
        for (int i = 0; i < 1000; ++i) {
            state = state * 1664525u + 1013904223u;
            noise.append(i * 1e-3, 50 + double(state >> 20) / 4096.0);
        }
        QVERIFY(notAStep(noise));
        TraceBuffer rising;
        for (int i = 0; i < 1000; ++i)
            rising.append(i * 1e-3, i < 100 ? 0.0 : (i - 100) * (i - 100) * 1e-3);
        QVERIFY(notAStep(rising));
        TraceBuffer flat;
        for (int i = 0; i < 10; ++i)
            flat.append(i, 5);
        QVERIFY(notAStep(flat));
        TraceBuffer ringing;
        for (int i = 0; i <= 3000; ++i)
            ringing.append(i * 1e-3, 100 * secondOrder(i * 1e-3, 0.11, 2 * std::numbers::pi * 5));
        const auto r = analysis::stepResponse(ringing);
        QVERIFY2(r.ok(), qPrintable(r.error().toString()));
        QVERIFY(r->overshootPercent > 69);
    }

    void statisticsBetweenCursors()
    {
        TraceBuffer b;
        for (int i = 0; i < 100; ++i)
            b.append(i * 0.01, (i % 2) ? 3 : -1); // square wave -1/3
        ChannelInfo info;
        info.scale = 2;
        info.offset = 1; // displayed -1 / 7
        const auto s = analysis::statistics(b, 0.5, 0.1, info); // cursors in any order
        QCOMPARE(s.count, 41);
        QCOMPARE(s.min, -1.0);
        QCOMPARE(s.max, 7.0);
        QCOMPARE(s.peakToPeak, 8.0);
        QVERIFY(std::abs(s.mean - (21 * -1 + 20 * 7) / 41.0) < 1e-12);
        QVERIFY(std::abs(s.rms - std::sqrt((21 * 1 + 20 * 49) / 41.0)) < 1e-12);
        QVERIFY(std::abs(s.dt - 0.4) < 1e-12);
        QVERIFY(std::abs(s.inverseDt - 2.5) < 1e-9);
        const auto none = analysis::statistics(b, 5, 6);
        QCOMPARE(none.count, 0);
        QVERIFY(std::isnan(none.mean));
    }
    void valueAtInterpolatesButNotAcrossGaps()
    {
        TraceBuffer b;
        b.append(0, 0);
        b.append(1, 10);
        b.markLost(1);
        b.append(3, 30);
        QCOMPARE(analysis::valueAt(b, 0.5), 5.0);
        QCOMPARE(analysis::valueAt(b, 2.0), 10.0);
        QVERIFY(std::isnan(analysis::valueAt(b, 4.0)));
    }
};

QTEST_GUILESS_MAIN(TstAnalysis)
#include "tst_analysis.moc"
