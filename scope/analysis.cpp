#include "analysis.h"

#include <QCoreApplication>
#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include <unsupported/Eigen/FFT>

namespace db::scope::analysis {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr qint64 kMinSpectrumSamples = 8;
constexpr qint64 kMaxSpectrumPoints = qint64(1) << 22; // keeps a resampled FFT under ~100 MB
// A step's height is at least this share of the signal's peak-to-peak (an underdamped second
// order system with 70 % overshoot still passes; a sine gives at most 0.5).
constexpr double kStepShareOfSwing = 0.55;
// The mean of the last tenth of the range differs from that of the tenth before by at most
// this share of the step's height (a ramp over the whole range moves by about 10 %).
constexpr double kUnsettledShare = 0.04;

struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::scope::analysis)
};

double shown(const TraceBuffer &b, qint64 i, const ChannelInfo &info)
{
    return info.display(b.value(i));
}

// Index range [first, last) of the samples with t0 <= t <= t1.
std::pair<qint64, qint64> range(const TraceBuffer &b, double &t0, double &t1)
{
    if (t0 > t1)
        std::swap(t0, t1);
    return { b.lowerBound(t0), b.upperBound(t1) };
}

} // namespace

Statistics statistics(const TraceBuffer &buffer, double t0, double t1, const ChannelInfo &info)
{
    Statistics s;
    const auto [first, last] = range(buffer, t0, t1);
    s.dt = (std::isinf(t0) || std::isinf(t1)) && last > first
        ? buffer.time(last - 1) - buffer.time(first)
        : t1 - t0;
    s.inverseDt = s.dt == 0 ? std::numeric_limits<double>::infinity() : 1.0 / s.dt;
    s.count = std::max<qint64>(0, last - first);
    if (s.count == 0) {
        s.mean = s.rms = s.min = s.max = s.peakToPeak = s.stdDev = kNaN;
        return s;
    }
    // Welford's update keeps the variance accurate for large offsets (positions ~1e6 inc).
    double mean = 0, m2 = 0, sumSquares = 0;
    s.min = std::numeric_limits<double>::infinity();
    s.max = -s.min;
    qint64 n = 0;
    for (qint64 i = first; i < last; ++i) {
        const double v = shown(buffer, i, info);
        ++n;
        const double delta = v - mean;
        mean += delta / double(n);
        m2 += delta * (v - mean);
        sumSquares += v * v;
        s.min = std::min(s.min, v);
        s.max = std::max(s.max, v);
    }
    s.mean = mean;
    s.rms = std::sqrt(sumSquares / double(n));
    s.stdDev = std::sqrt(m2 / double(n));
    s.peakToPeak = s.max - s.min;
    return s;
}

double valueAt(const TraceBuffer &buffer, double t, const ChannelInfo &info)
{
    if (buffer.isEmpty() || t < buffer.firstTime() || t > buffer.lastTime())
        return kNaN;
    const qint64 i = buffer.lowerBound(t);
    if (buffer.time(i) == t || i == 0)
        return shown(buffer, i, info);
    if (buffer.startsGap(i))
        return shown(buffer, i - 1, info);
    const double ta = buffer.time(i - 1), tb = buffer.time(i);
    const double a = shown(buffer, i - 1, info), b = shown(buffer, i, info);
    return tb == ta ? b : a + (b - a) * (t - ta) / (tb - ta);
}

double Spectrum::peakFrequency() const
{
    if (amplitude.size() < 2)
        return 0;
    const auto it = std::max_element(amplitude.cbegin() + 1, amplitude.cend());
    return frequency[it - amplitude.cbegin()];
}

Result<Spectrum> spectrum(const TraceBuffer &buffer, double t0, double t1, const ChannelInfo &info,
                          double samplePeriodS)
{
    const auto [first, last] = range(buffer, t0, t1);
    const qint64 n = last - first;
    if (n < kMinSpectrumSamples)
        return Error(Error::Kind::InvalidArgument,
                     Tr::tr("a spectrum needs at least %1 samples in the range (has %2)")
                         .arg(kMinSpectrumSamples)
                         .arg(n));
    double period = samplePeriodS;
    if (period <= 0) {
        std::vector<double> spacing;
        spacing.reserve(size_t(n - 1));
        for (qint64 i = first + 1; i < last; ++i)
            spacing.push_back(buffer.time(i) - buffer.time(i - 1));
        std::nth_element(spacing.begin(), spacing.begin() + spacing.size() / 2, spacing.end());
        period = spacing[spacing.size() / 2];
    }
    const double tStart = buffer.time(first), tEnd = buffer.time(last - 1);
    if (!(period > 0) || tEnd <= tStart)
        return Error(Error::Kind::InvalidArgument,
                     Tr::tr("the samples in the range have no time spacing"));
    // The tolerance keeps a grid of exactly N periods from losing its last point to rounding.
    qint64 points = qint64(std::floor((tEnd - tStart) / period + 1e-6)) + 1;
    points = std::min(points, kMaxSpectrumPoints);
    points -= points % 2; // even length: bin N/2 is the Nyquist frequency
    if (points < kMinSpectrumSamples)
        return Error(Error::Kind::InvalidArgument, Tr::tr("the range is too short for a spectrum"));

    // Uniform resampling by linear interpolation, mean removal, Hann window.
    std::vector<double> x(static_cast<size_t>(points), 0.0);
    qint64 j = first;
    for (qint64 k = 0; k < points; ++k) {
        const double t = tStart + double(k) * period;
        while (j + 1 < last && buffer.time(j + 1) < t)
            ++j;
        const double ta = buffer.time(j);
        const double a = shown(buffer, j, info);
        if (j + 1 < last && buffer.time(j + 1) > ta) {
            const double b = shown(buffer, j + 1, info);
            x[size_t(k)] = a + (b - a) * std::clamp((t - ta) / (buffer.time(j + 1) - ta), 0.0, 1.0);
        } else {
            x[size_t(k)] = a;
        }
    }
    double mean = 0;
    for (double v : x)
        mean += v;
    mean /= double(points);
    double windowSum = 0;
    for (qint64 k = 0; k < points; ++k) {
        const double w = 0.5 - 0.5 * std::cos(2 * std::numbers::pi * double(k) / double(points));
        windowSum += w;
        x[size_t(k)] = (x[size_t(k)] - mean) * w;
    }
    Eigen::FFT<double> fft;
    std::vector<std::complex<double>> bins;
    fft.fwd(bins, x);

    Spectrum out;
    out.samplePeriodS = period;
    out.points = points;
    const qint64 half = points / 2;
    out.frequency.reserve(half + 1);
    out.amplitude.reserve(half + 1);
    // A sine of amplitude A gives |X[k]| = A * windowSum / 2; doubled for the one-sided
    // spectrum (except DC and Nyquist).
    for (qint64 k = 0; k <= half; ++k) {
        const double scale = (k == 0 || k == half) ? 1.0 : 2.0;
        out.frequency.append(double(k) / (double(points) * period));
        out.amplitude.append(scale * std::abs(bins[size_t(k)]) / windowSum);
    }
    return out;
}

Result<StepResponse> stepResponse(const TraceBuffer &buffer, double t0, double t1,
                                  const ChannelInfo &info, double settlingBand)
{
    // Plain variables, not a structured binding: the lambdas below capture them, which clang
    // before 16 refuses for bindings.
    const std::pair<qint64, qint64> bounds = range(buffer, t0, t1);
    const qint64 first = bounds.first;
    const qint64 last = bounds.second;
    const qint64 n = last - first;
    if (n < 3)
        return Error(
            Error::Kind::InvalidArgument,
            Tr::tr("a step response needs at least 3 samples in the range (has %1)").arg(n));
    const double start = std::isinf(t0) ? buffer.time(first) : t0;
    StepResponse r;
    r.initial = shown(buffer, first, info);
    const qint64 tail = std::max<qint64>(1, n / 20);
    double sum = 0;
    for (qint64 i = last - tail; i < last; ++i)
        sum += shown(buffer, i, info);
    r.final = sum / double(tail);
    const double height = r.final - r.initial;
    if (height == 0 || !std::isfinite(height))
        return Error(Error::Kind::InvalidArgument,
                     Tr::tr("not a step: the first and the final value are equal"));
    const double sign = height > 0 ? 1 : -1;

    // A step moves from one level to another and stays there. A signal that swings more than
    // it moves (a sine, noise) or is still moving at the end (a ramp that has not stopped) has
    // no rise time or overshoot that would mean anything.
    double lo = r.initial, hi = r.initial;
    for (qint64 i = first; i < last; ++i) {
        lo = std::min(lo, shown(buffer, i, info));
        hi = std::max(hi, shown(buffer, i, info));
    }
    if (std::abs(height) < kStepShareOfSwing * (hi - lo))
        return Error(Error::Kind::InvalidArgument,
                     Tr::tr("not a step: the signal swings more than it moves from its first "
                            "to its final value"));
    // Still moving at the end: the two halves of the last fifth differ in their mean (a mean,
    // so that noise and decayed ringing do not count).
    const qint64 tailStart = last - std::max<qint64>(4, n / 5);
    const qint64 tailMiddle = tailStart + (last - tailStart) / 2;
    double early = 0, late = 0;
    for (qint64 i = std::max(first, tailStart); i < tailMiddle; ++i)
        early += shown(buffer, i, info);
    for (qint64 i = tailMiddle; i < last; ++i)
        late += shown(buffer, i, info);
    early /= double(tailMiddle - std::max(first, tailStart));
    late /= double(last - tailMiddle);
    if (std::abs(late - early) > kUnsettledShare * std::abs(height))
        return Error(Error::Kind::InvalidArgument,
                     Tr::tr("not a step: the signal has not settled at the end of the range"));

    // Normalised progress p = (v - initial) / height: 0 at the start, 1 at the end.
    auto progress = [&](qint64 i) {
        return (shown(buffer, i, info) - r.initial) / height;
    };
    auto crossing = [&](double level) -> double {
        for (qint64 i = first + 1; i < last; ++i) {
            const double pa = progress(i - 1), pb = progress(i);
            if (pa < level && pb >= level) {
                const double ta = buffer.time(i - 1), tb = buffer.time(i);
                return ta + (tb - ta) * (level - pa) / (pb - pa);
            }
        }
        return kNaN;
    };
    const double t10 = crossing(0.1), t90 = crossing(0.9);
    if (std::isnan(t10) || std::isnan(t90))
        return Error(Error::Kind::InvalidArgument,
                     Tr::tr("not a step: the signal does not pass from 10 % to 90 % of the step in "
                            "the range"));
    r.riseTime = t90 - t10;

    qint64 peak = first;
    for (qint64 i = first; i < last; ++i) {
        if (sign * shown(buffer, i, info) > sign * shown(buffer, peak, info))
            peak = i;
    }
    r.peakValue = shown(buffer, peak, info);
    r.peakTime = buffer.time(peak) - start;
    r.overshootPercent = std::max(0.0, sign * (r.peakValue - r.final) / std::abs(height) * 100.0);

    r.settlingTime = 0;
    for (qint64 i = last - 1; i >= first; --i) {
        if (std::abs(progress(i) - 1.0) > settlingBand) {
            r.settlingTime = (i + 1 < last ? buffer.time(i + 1) : buffer.time(i)) - start;
            break;
        }
    }
    return r;
}

} // namespace db::scope::analysis
