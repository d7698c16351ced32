#pragma once

#include "morse/decode/morsetypes.h"

#include <QString>

#include <limits>
#include <vector>

namespace db::morse {

// Synthetic LED brightness for tests, benchmarks and the video renderer.
//
// Model: the LED sends `text` with ITU timing (movingcap.md section 2.4) and repeats it after
// `repeatGap` units of darkness. A camera frame at time t integrates the LED over
// [t - exposure / sampleRate, t] (exposure 0: point sample). Brightness =
// gain(t) * (ambient + drift * t + amplitude * onFraction) + noise.
//
// SNR definition: ratio of the AC power of the on/off wave (amplitude^2 / 4, a 50 % duty square
// wave of step `amplitude`) to the noise power sigma^2 of each sample:
//     snrDb = 10 log10(amplitude^2 / (4 sigma^2)),  so 6 dB is sigma = amplitude / 4,
//     20 dB is sigma = amplitude / 20. Noise is white and Gaussian per sample.
struct SignalOptions
{
    QString text = QStringLiteral("MC+IP192+168+2+150:");
    double unit = 0.12; // dit length, seconds (assumption: the drive's is unknown)
    double sampleRate = 30.0; // samples (frames) per second
    double exposure = 0.5; // fraction of the frame period the sensor integrates, 0..1
    double jitter = 0.0; // every mark and gap scaled by 1 + U(-jitter, +jitter)
    double snrDb = std::numeric_limits<double>::infinity();
    double amplitude = 1.0; // brightness step on - off
    double ambient = 0.3; // off level, multiples of amplitude
    double drift = 0.0; // ambient change per second, multiples of amplitude
    double gainDrift = 0.0; // auto exposure: gain swings by +-gainDrift (sine, 23 s period)
    double dutyError = 0.0; // marks longer by this many units, following gaps shorter
    double startOffset = 0.0; // recording starts this fraction of a period into a message, [0,1)
    int repetitions = 3; // recording length in message periods
    double repeatGap = 10.0; // darkness between repetitions, units
    unsigned seed = 1;
};

struct Signal
{
    std::vector<Sample> samples;
    double messagePeriod = 0.0; // seconds, nominal (message + repeat gap)
    // Recording times at which the messages from the first complete one on actually start (with
    // jitter), one more than fit in the recording; messageStarts[0]: the first complete message.
    std::vector<double> messageStarts;
    double noiseSigma = 0.0;
};

Signal generateSignal(const SignalOptions &options);

// Nominal length of `text` plus the repeat gap, in units (ITU timing).
double messageUnits(const QString &text, double repeatGap);

} // namespace db::morse
