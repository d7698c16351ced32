#include "signalgenerator.h"

#include "morse/decode/morsecode.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace db::morse {
namespace {

constexpr double kGainPeriod = 23.0; // s; slow auto-exposure swing, not a multiple of a message

struct OnSpan
{
    double start;
    double end;
};

double onFraction(const std::vector<OnSpan> &spans, double a, double b)
{
    auto it = std::upper_bound(spans.begin(), spans.end(), a,
                               [](double v, const OnSpan &s) { return v < s.end; });
    double on = 0.0;
    for (; it != spans.end() && it->start < b; ++it)
        on += std::min(b, it->end) - std::max(a, it->start);
    return b > a ? on / (b - a) : 0.0;
}

} // namespace

double messageUnits(const QString &text, double repeatGap)
{
    double sum = 0.0;
    for (double u : messageElements(text, repeatGap))
        sum += u;
    return sum;
}

Signal generateSignal(const SignalOptions &o)
{
    Signal out;
    const std::vector<double> nominal = messageElements(o.text, o.repeatGap);
    if (nominal.empty() || o.unit <= 0.0 || o.sampleRate <= 0.0 || o.repetitions <= 0)
        return out;

    std::mt19937 rng(o.seed);
    std::uniform_real_distribution<double> jitter(-o.jitter, o.jitter);

    // The LED timeline: repetitions + 2 messages so that any start offset is covered.
    std::vector<OnSpan> spans;
    std::vector<double> messageStarts;
    double t = 0.0;
    for (int rep = 0; rep < o.repetitions + 2; ++rep) {
        messageStarts.push_back(t);
        for (std::size_t i = 0; i < nominal.size(); ++i) {
            const bool mark = i % 2 == 0;
            double d = nominal[i] * (1.0 + (o.jitter > 0.0 ? jitter(rng) : 0.0));
            d += (mark ? o.dutyError : -o.dutyError);
            d = std::max(0.05, d) * o.unit;
            if (mark)
                spans.push_back({ t, t + d });
            t += d;
        }
    }

    out.messagePeriod = messageUnits(o.text, o.repeatGap) * o.unit;
    const double offset = std::clamp(o.startOffset, 0.0, 0.999);
    const double t0 = offset * (messageStarts[1] - messageStarts[0]);
    messageStarts.push_back(t);
    for (std::size_t r = offset > 0.0 ? 1 : 0; r < messageStarts.size(); ++r)
        out.messageStarts.push_back(messageStarts[r] - t0);

    const double sigma =
        std::isfinite(o.snrDb) ? o.amplitude / (2.0 * std::pow(10.0, o.snrDb / 20.0)) : 0.0;
    out.noiseSigma = sigma;
    std::normal_distribution<double> noise(0.0, 1.0);

    const double frame = 1.0 / o.sampleRate;
    const double window = std::clamp(o.exposure, 0.0, 1.0) * frame;
    const auto count = static_cast<std::size_t>(o.repetitions * out.messagePeriod / frame);
    out.samples.reserve(count);
    for (std::size_t k = 0; k < count; ++k) {
        const double ts = static_cast<double>(k) * frame;
        const double led = t0 + ts;
        double on = 0.0;
        if (window > 0.0) {
            on = onFraction(spans, led - window, led);
        } else {
            on = onFraction(spans, led, led + 1e-9);
        }
        const double gain = 1.0 + o.gainDrift * std::sin(2.0 * std::numbers::pi * ts / kGainPeriod);
        double v = gain * (o.amplitude * (o.ambient + o.drift * ts) + o.amplitude * on);
        if (sigma > 0.0)
            v += sigma * noise(rng);
        out.samples.push_back({ ts, v });
    }
    return out;
}

} // namespace db::morse
