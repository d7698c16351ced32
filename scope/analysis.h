#pragma once
// Measurements on recorded channels (Eigen): statistics, spectrum, step-response figures.
// Pure functions on a TraceBuffer and a time range; values are DISPLAYED values
// (raw * scale + offset) when a ChannelInfo is given, raw values otherwise.
#include "channel.h"
#include "core/result.h"
#include "tracebuffer.h"
#include <QList>
#include <limits>

namespace db::scope::analysis {

constexpr double kAll = std::numeric_limits<double>::infinity();

// Statistics of the samples with t0 <= t <= t1 (e.g. between cursors A and B; pass t0 > t1 in
// any order, they are sorted). dt = t1 - t0 of the range as given (the cursor distance),
// inverseDt = 1 / dt (inf when dt == 0). With no samples in range: count 0 and NaN figures.
struct Statistics
{
    qint64 count = 0;
    double mean = 0;
    double rms = 0;
    double min = 0;
    double max = 0;
    double peakToPeak = 0;
    double stdDev = 0;
    double dt = 0;
    double inverseDt = 0;
};
Statistics statistics(const TraceBuffer &buffer, double t0 = -kAll, double t1 = kAll,
                      const ChannelInfo &info = {});

// The value at time t, linear between neighbouring samples (not across a gap: then the
// earlier sample's value); NaN outside the recorded range.
double valueAt(const TraceBuffer &buffer, double t, const ChannelInfo &info = {});

// One-sided amplitude spectrum: the samples in [t0, t1] are resampled to a uniform grid (linear
// interpolation, period = the median sample spacing, or `samplePeriodS` when > 0), the mean is
// removed, a Hann window applied, FFT (Eigen), amplitudes corrected for the window so a sine of
// amplitude A shows a peak of ~A. frequency[k] = k / (N * period), k = 0..N/2.
struct Spectrum
{
    QList<double> frequency; // Hz
    QList<double> amplitude; // display units
    double samplePeriodS = 0;
    qint64 points = 0; // N after resampling
    // Frequency of the largest amplitude above DC (0 when empty).
    double peakFrequency() const;
};
// InvalidArgument when fewer than 8 samples are in range or the spacing is 0.
Result<Spectrum> spectrum(const TraceBuffer &buffer, double t0 = -kAll, double t1 = kAll,
                          const ChannelInfo &info = {}, double samplePeriodS = 0);

// Step-response figures of the samples in [t0, t1]; the step starts at t0 (or the first sample)
// from the initial value (first sample) to the final value (mean of the last 5 % of the range,
// at least one sample).
// - riseTime: time from 10 % to 90 % of the step (linearly interpolated crossings).
// - overshootPercent: (extreme beyond final - final) / |final - initial| * 100, >= 0.
// - settlingTime: from t0 to the last time the signal is outside +-settlingBand (2 %) of the
//   step height around the final value (0 when it never leaves the band).
struct StepResponse
{
    double initial = 0;
    double final = 0;
    double riseTime = 0;
    double overshootPercent = 0;
    double peakValue = 0;
    double peakTime = 0;
    double settlingTime = 0;
};
// InvalidArgument when fewer than 3 samples are in range, or, with a message starting "not a
// step:", when the signal is not one: |final - initial| is 0 or less than about half the
// signal's peak-to-peak (a sine, noise), the last tenth of the range still varies by more than
// a quarter of the step (not settled), or the 90 % level is never reached.
Result<StepResponse> stepResponse(const TraceBuffer &buffer, double t0 = -kAll, double t1 = kAll,
                                  const ChannelInfo &info = {}, double settlingBand = 0.02);

} // namespace db::scope::analysis
