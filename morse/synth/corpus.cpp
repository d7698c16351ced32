#include "corpus.h"

#include <QStringList>

#include <cmath>
#include <random>

namespace db::morse {

QString ipText(const std::array<int, 4> &ip, QChar separator)
{
    QStringList parts;
    for (int o : ip)
        parts << QString::number(o);
    return parts.join(separator);
}

std::vector<CorpusCase> makeCorpus(const CorpusCondition &cond, int count, unsigned seed)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> uni(0.0, 1.0);
    std::vector<CorpusCase> out;
    for (int i = 0; i < count; ++i) {
        CorpusCase c;
        SignalOptions &s = c.signal;
        s.sampleRate = cond.rates[static_cast<std::size_t>(i) % cond.rates.size()];
        const double minUnit = std::max(0.06, cond.minSamplesPerUnit / s.sampleRate);
        s.unit = minUnit * std::pow(0.4 / minUnit, uni(rng)); // log-uniform up to 400 ms
        s.exposure = s.sampleRate > 100.0 ? 1.0 : uni(rng);
        for (int &o : c.ip) {
            const double r = uni(rng); // mix of 1-, 2- and 3-digit octets
            o = r < 0.2 ? int(uni(rng) * 10)
                        : (r < 0.4 ? 10 + int(uni(rng) * 90) : 100 + int(uni(rng) * 156));
        }
        s.text = QStringLiteral("MC+IP") + ipText(c.ip, QLatin1Char('+')) + QLatin1Char(':');
        s.jitter = cond.jitter;
        s.snrDb = cond.snrDb;
        s.ambient = 2.0 * uni(rng);
        s.amplitude = 0.1 + 100.0 * uni(rng); // any brightness scale
        s.drift = cond.drift * (uni(rng) < 0.5 ? -1.0 : 1.0);
        s.gainDrift = cond.gainDrift;
        s.dutyError = cond.dutyError * (uni(rng) < 0.5 ? -1.0 : 1.0);
        s.startOffset = uni(rng);
        s.repetitions = 3;
        const double drawn = 7.0 + 7.0 * uni(rng); // drawn always: the same cases either way
        s.repeatGap = cond.repeatGap > 0.0 ? cond.repeatGap : drawn;
        s.seed = static_cast<unsigned>(rng());
        out.push_back(c);
    }
    return out;
}

namespace {

// Message periods between starts[0] and t, each period with its own (jittered) length.
double periodsSent(const std::vector<double> &starts, double t)
{
    for (std::size_t k = 0; k + 1 < starts.size(); ++k) {
        if (t < starts[k + 1])
            return double(k) + std::max(0.0, t - starts[k]) / (starts[k + 1] - starts[k]);
    }
    return double(starts.size()); // not reached: the recording ends before the last start
}

} // namespace

CaseOutcome runCase(const CorpusCase &c, double chunkSeconds, DecoderOptions options)
{
    const Signal sig = generateSignal(c.signal);
    Decoder decoder(options);
    CaseOutcome out;
    const QString truth = ipText(c.ip, QLatin1Char('.'));
    std::size_t begin = 0;
    while (begin < sig.samples.size()) {
        std::size_t end = begin;
        const double until = sig.samples[begin].t + chunkSeconds;
        while (end < sig.samples.size() && sig.samples[end].t < until)
            ++end;
        decoder.feed(std::span<const Sample>(sig.samples.data() + begin, end - begin));
        begin = end;
        if (decoder.confident()) {
            if (decoder.ip().toString() != truth)
                out.wrongConfident = true;
            if (out.repetitionsToConfident < 0.0) {
                const double t = decoder.slicer().lastTime();
                out.nominalRepetitionsToConfident =
                    (t - sig.messageStarts.front()) / sig.messagePeriod;
                out.repetitionsToConfident = periodsSent(sig.messageStarts, t);
            }
        }
    }
    decoder.finish();
    out.decoded = decoder.ip().toString();
    out.text = decoder.text();
    out.exact = out.decoded == truth;
    out.confident = decoder.confident();
    out.reason = decoder.reason();
    return out;
}

} // namespace db::morse
