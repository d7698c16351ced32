// Corpus benchmark for the LED Morse decoder (not run by ctest).
//
//   morse_corpus [cases-per-condition=100] [seed=7]
//   (MORSE_ONLY=name,name runs only those conditions, a name with brackets also by its part
//   before them: MORSE_ONLY=all; MORSE_VERBOSE=1 lists the failures; MORSE_FRAMES=0 decodes
//   without the frame check)
//
// Prints, per condition: exact IP rate after the whole recording (3 message periods, random
// start inside a message), confident rate, confident-but-wrong count, and the time from the
// start of the first complete message to the first confident IP in message periods as sent
// (median, 95th percentile, max, share within 2; in brackets the share within 2 nominal
// periods, which jitter can make unreachable), plus exact rate per sample rate.
#include "morse/synth/corpus.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QTextStream>

#include <algorithm>
#include <cmath>
#include <map>

using namespace db::morse;

namespace {

std::vector<CorpusCondition> conditions()
{
    const double inf = std::numeric_limits<double>::infinity();
    const std::vector<double> rates = CorpusCondition().rates;
    return {
        { QStringLiteral("clean"), 0.0, inf, 0.0, 0.0, 0.0, 2.0 },
        { QStringLiteral("jitter15"), 0.15, inf, 0.0, 0.0, 0.0, 2.0 },
        { QStringLiteral("jitter30"), 0.30, inf, 0.0, 0.0, 0.0, 3.0 },
        { QStringLiteral("snr20"), 0.0, 20.0, 0.0, 0.0, 0.0, 2.0 },
        { QStringLiteral("snr6"), 0.0, 6.0, 0.0, 0.0, 0.0, 3.0 },
        { QStringLiteral("jitter30+snr6"), 0.30, 6.0, 0.0, 0.0, 0.0, 3.0 },
        { QStringLiteral("jitter30+snr6@60,1k"), 0.30, 6.0, 0.0, 0.0, 0.0, 3.0, { 60.0, 1000.0 } },
        { QStringLiteral("drift+autoexp"), 0.0, 20.0, 0.01, 0.3, 0.0, 2.0 },
        { QStringLiteral("drift+autoexp+6dB"), 0.0, 6.0, 0.01, 0.3, 0.0, 3.0 },
        { QStringLiteral("duty+-0.3"), 0.0, 20.0, 0.0, 0.0, 0.3, 3.0 },
        { QStringLiteral("all(j30,6dB,drift,duty.2)"), 0.30, 6.0, 0.01, 0.3, 0.2, 3.0 },
        { QStringLiteral("clean<2spu(1.2)"), 0.0, inf, 0.0, 0.0, 0.0, 1.2 },
        { QStringLiteral("j30+6dB<3spu(2)"), 0.30, 6.0, 0.0, 0.0, 0.0, 2.0 },
        // 6 dB under the amplitude definition 20 log10(A / sigma) is sigma = A / 2: 0 dB here.
        { QStringLiteral("j30+0dB(sigma=A/2)"), 0.30, 0.0, 0.0, 0.0, 0.0, 3.0 },
        // Messages back to back: a letter gap after ':' instead of a pause.
        { QStringLiteral("back-to-back"), 0.0, inf, 0.0, 0.0, 0.0, 2.0, rates, 3.0, 0.02 },
        { QStringLiteral("back-to-back+j30+6dB"), 0.30, 6.0, 0.0, 0.0, 0.0, 3.0, rates, 3.0, 0.02 },
    };
}

double quantile(std::vector<double> v, double q)
{
    if (v.empty())
        return -1.0;
    std::sort(v.begin(), v.end());
    return v[static_cast<std::size_t>(q * static_cast<double>(v.size() - 1))];
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    const QStringList args = app.arguments();
    const int count = args.size() > 1 ? args[1].toInt() : 100;
    const unsigned seed = args.size() > 2 ? args[2].toUInt() : 7u;
    QTextStream out(stdout);
    const bool verbose = qEnvironmentVariableIsSet("MORSE_VERBOSE");
    // MORSE_FRAMES=0: the lengths alone, without the check on the samples (DecoderOptions).
    DecoderOptions options;
    options.checkFrames = qEnvironmentVariable("MORSE_FRAMES") != QLatin1String("0");
    out << "condition                   n  exact%  conf%  wrongConf  reps-to-confident: median "
           "p95 max <=2% (nominal)  exact% per rate 15/25/30/60/1000   ms/case\n";
    // MORSE_ONLY=name1,name2 runs only those conditions.
    const QStringList only =
        qEnvironmentVariable("MORSE_ONLY").split(QLatin1Char(','), Qt::SkipEmptyParts);
    for (const CorpusCondition &cond : conditions()) {
        // A name with a bracket is also picked by its part before it ("all"): its own commas
        // would split it.
        const QString shortName = cond.name.section(QLatin1Char('('), 0, 0);
        if (!only.isEmpty() && !only.contains(cond.name) && !only.contains(shortName))
            continue;
        const std::vector<CorpusCase> corpus = makeCorpus(cond, count, seed);
        int exact = 0;
        int confident = 0;
        int wrong = 0;
        int within2 = 0;
        int within2Nominal = 0;
        std::vector<double> reps;
        std::map<int, std::pair<int, int>> perRate;
        QElapsedTimer timer;
        timer.start();
        // MORSE_CASE=i runs only case i of each condition (with
        // QT_LOGGING_RULES=drivebench.morse.debug=true: the decoder's trace).
        const int onlyCase = qEnvironmentVariableIsSet("MORSE_CASE")
            ? qEnvironmentVariableIntValue("MORSE_CASE")
            : -1;
        for (std::size_t k = 0; k < corpus.size(); ++k) {
            const CorpusCase &c = corpus[k];
            if (onlyCase >= 0 && int(k) != onlyCase)
                continue;
            const CaseOutcome o = runCase(c, cond.chunkSeconds, options);
            if (verbose
                && (!o.exact || o.repetitionsToConfident < 0.0 || o.repetitionsToConfident > 2.0))
                out << "  #" << k << " " << cond.name << " " << c.signal.sampleRate << " fps, unit "
                    << c.signal.unit * 1000 << " ms, exp " << c.signal.exposure << ": "
                    << ipText(c.ip, QLatin1Char('.')) << " -> " << o.decoded << " ["
                    << reasonText(o.reason) << "] reps " << o.repetitionsToConfident << " "
                    << o.text << "\n";
            exact += o.exact ? 1 : 0;
            confident += o.confident ? 1 : 0;
            wrong += o.wrongConfident ? 1 : 0;
            if (o.repetitionsToConfident >= 0.0) {
                reps.push_back(o.repetitionsToConfident);
                within2 += o.repetitionsToConfident <= 2.0 ? 1 : 0;
                within2Nominal += o.nominalRepetitionsToConfident <= 2.0 ? 1 : 0;
            }
            auto &r = perRate[static_cast<int>(c.signal.sampleRate)];
            r.first += o.exact ? 1 : 0;
            ++r.second;
        }
        const double n = corpus.size();
        out << qSetFieldWidth(26) << Qt::left << cond.name << qSetFieldWidth(0) << Qt::right
            << QStringLiteral("%1 %2 %3 %4   %5 %6 %7 %8 (%9)  ")
                   .arg(count, 3)
                   .arg(100.0 * exact / n, 7, 'f', 1)
                   .arg(100.0 * confident / n, 6, 'f', 1)
                   .arg(wrong, 6)
                   .arg(quantile(reps, 0.5), 6, 'f', 2)
                   .arg(quantile(reps, 0.95), 5, 'f', 2)
                   .arg(reps.empty() ? -1.0 : *std::max_element(reps.begin(), reps.end()), 5, 'f',
                        2)
                   .arg(100.0 * within2 / n, 5, 'f', 1)
                   .arg(100.0 * within2Nominal / n, 5, 'f', 1);
        for (const auto &[rate, r] : perRate)
            out << QStringLiteral(" %1").arg(100.0 * r.first / r.second, 5, 'f', 1);
        out << QStringLiteral("   %1\n").arg(double(timer.elapsed()) / n, 6, 'f', 1);
        out.flush();
    }
    return 0;
}
