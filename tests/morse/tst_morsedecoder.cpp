// The decoder on generated signals: the spec example (movingcap.md 2.2), streaming partial
// results and events, and the reasons given when nothing can be decoded.
#include "morse/corpus.h"
#include "morse/decoder.h"
#include "morse/levelslicer.h"
#include "morse/messageparser.h"
#include "morse/morsecode.h"
#include "morse/signalgenerator.h"

#include <QTest>

#include <cmath>
#include <map>
#include <numbers>
#include <numeric>
#include <random>

using namespace db::morse;

namespace {

SignalOptions specSignal(double rate, double unit)
{
    SignalOptions o; // text defaults to the spec example "MC+IP192+168+2+150:"
    o.sampleRate = rate;
    o.unit = unit;
    o.startOffset = 0.37;
    return o;
}

// A stretch with the nominal ITU lengths of `text` (units), closed at both ends.
StretchInput nominalStretch(const QString &text)
{
    StretchInput s;
    for (QChar c : text) {
        for (QChar e : codeFor(c)) {
            s.marks.push_back(e == QLatin1Char('-') ? 3.0 : 1.0);
            s.gaps.push_back(1.0);
        }
        s.gaps.back() = 3.0;
    }
    s.gaps.pop_back();
    return s;
}

// The first mark of character `index` of `text` in nominalStretch(text).
std::size_t markOf(const QString &text, int index)
{
    std::size_t at = 0;
    for (int i = 0; i < index; ++i)
        at += static_cast<std::size_t>(codeFor(text[i]).size());
    return at;
}

const std::array<int, 4> kSpecIp { 192, 168, 2, 150 };

// Empty when `samples` decode to the spec example's address, confident, with the whole message
// read at least `times` times after a word gap; otherwise what is wrong.
QString specDecodeProblem(const std::vector<Sample> &samples, int times)
{
    Decoder decoder;
    decoder.feed(samples);
    decoder.finish();
    const QString text = decoder.text();
    if (text.count(QLatin1String("MC+IP192+168+2+150:")) < times)
        return QStringLiteral("text: ") + text;
    if (decoder.ip().toString() != QLatin1String("192.168.2.150") || !decoder.confident())
        return QStringLiteral("ip: %1 (%2)")
            .arg(decoder.ip().toString())
            .arg(decoder.ip().confidence);
    return {};
}

void addElement(std::vector<Element> &timeline, ElementKind kind, double units)
{
    const double t = timeline.empty() ? 0.0 : timeline.back().start + timeline.back().duration;
    timeline.push_back({ kind, t, units * 0.1, units, 0.0 });
}

// A classified timeline (symbolize()) with the lengths of `s`, 0.1 s per unit, after a word gap.
std::vector<Element> timelineOf(const StretchInput &s)
{
    std::vector<Element> timeline;
    addElement(timeline, ElementKind::WordGap, 10.0);
    for (std::size_t i = 0; i < s.marks.size(); ++i) {
        addElement(timeline, s.marks[i] > 2.0 ? ElementKind::Dah : ElementKind::Dit, s.marks[i]);
        if (i < s.gaps.size())
            addElement(timeline, s.gaps[i] > 2.0 ? ElementKind::LetterGap : ElementKind::IntraGap,
                       s.gaps[i]);
    }
    return timeline;
}

Reason reasonOf(const std::vector<Sample> &samples)
{
    const auto r = decodeRecording(samples);
    return r.ok() ? r->reason : static_cast<Reason>(r.error().deviceCode());
}

} // namespace

class TstMorseDecoder : public QObject
{
    Q_OBJECT

private slots:
    void specExample_data()
    {
        QTest::addColumn<double>("rate");
        QTest::addColumn<double>("unit");
        QTest::newRow("15 fps, 200 ms") << 15.0 << 0.2;
        QTest::newRow("25 fps, 120 ms") << 25.0 << 0.12;
        QTest::newRow("30 fps, 100 ms") << 30.0 << 0.1;
        QTest::newRow("60 fps, 60 ms") << 60.0 << 0.06;
        QTest::newRow("1 kHz, 400 ms") << 1000.0 << 0.4;
    }
    void specExample()
    {
        QFETCH(double, rate);
        QFETCH(double, unit);
        const Signal sig = generateSignal(specSignal(rate, unit));
        const auto result = decodeRecording(sig.samples);
        QVERIFY2(result.ok(), qPrintable(result.error().toString()));
        QCOMPARE(result->ip.toString(), QStringLiteral("192.168.2.150"));
        QVERIFY(result->ip.confidence >= IpVoter::kConfident);
        QCOMPARE(result->reason, Reason::None);
        QVERIFY2(result->text.contains(QLatin1String("MC+IP192+168+2+150:")),
                 qPrintable(result->text));
        QVERIFY(std::abs(result->unit - unit) < 0.05 * unit);
        QVERIFY(!result->timeline.empty());
    }

    void streamingGivesPartialResults()
    {
        const Signal sig = generateSignal(specSignal(30.0, 0.1));
        Decoder decoder;
        QCOMPARE(decoder.state(), DecoderState::Searching);
        std::vector<DecoderEvent::Kind> kinds;
        QString previousText;
        bool textGrew = false;
        double messageAt = -1.0;
        for (std::size_t i = 0; i < sig.samples.size(); i += 15) {
            const std::size_t n = std::min<std::size_t>(15, sig.samples.size() - i);
            decoder.feed(std::span<const Sample>(sig.samples.data() + i, n));
            textGrew = textGrew
                || (decoder.text().size() > previousText.size() && !previousText.isEmpty());
            previousText = decoder.text();
            for (const DecoderEvent &e : decoder.takeEvents()) {
                kinds.push_back(e.kind);
                if (e.kind == DecoderEvent::Kind::MessageDecoded && messageAt < 0.0) {
                    messageAt = e.time;
                    QCOMPARE(e.detail, QStringLiteral("192.168.2.150"));
                    // One message seen: the IP is known but not yet confident.
                    QCOMPARE(decoder.state(), DecoderState::Decoding);
                    QCOMPARE(decoder.reason(), Reason::LowConfidence);
                }
            }
        }
        QVERIFY(textGrew);
        QVERIFY(messageAt > 0.0);
        QCOMPARE(decoder.state(), DecoderState::Confident);
        QCOMPARE(kinds.front(), DecoderEvent::Kind::LedFound);
        QVERIFY(std::count(kinds.begin(), kinds.end(), DecoderEvent::Kind::UnitFound) == 1);
        QVERIFY(std::count(kinds.begin(), kinds.end(), DecoderEvent::Kind::IpConfident) == 1);
        QVERIFY(std::abs(decoder.unitFit().unit - 0.1) < 0.005);
    }

    // Ambient light rising by 0.3 contrasts per second (a lamp warming up, the sun on a
    // window): the levels follow the ramp without lagging behind it, so the threshold stays in
    // the middle of the two levels, and the message decodes.
    void levelsFollowARamp()
    {
        SignalOptions o = specSignal(25.0, 0.3);
        o.snrDb = 30.0;
        o.drift = 0.3;
        const Signal sig = generateSignal(o);
        LevelSlicer slicer;
        double worst = 0.0;
        for (const Sample &s : sig.samples) {
            slicer.feed(s);
            const double trueLow = o.amplitude * (o.ambient + o.drift * s.t);
            if (s.t > 10.0) // after the levels have settled
                worst = std::max(worst, std::abs(slicer.low() - trueLow) / o.amplitude);
        }
        // Without the slope the off level lags by up to 0.3 contrasts (tau 0.8 s, frozen for
        // a dah); the threshold would then sit 0.15 contrasts off the middle.
        QVERIFY2(worst < 0.12, qPrintable(QStringLiteral("off level off by %1").arg(worst)));
        const auto r = decodeRecording(sig.samples);
        QVERIFY2(r.ok(), qPrintable(r.ok() ? QString() : r.error().message()));
        QCOMPARE(r->ip.octets, kSpecIp);
        QVERIFY(r->ip.confidence >= IpVoter::kConfident);
    }

    // Auto exposure swinging the gain by +-30 % on an ambient of 1.5 contrasts, plus drift, in
    // noise at 6 dB, at 25 fps: the off level moves by up to 0.15 contrasts per second. The
    // recursive tracker alone lags behind (its slope is not used in such noise); the line fit
    // over the last 4 s follows it. The threshold error is measured against the generator's levels.
    void levelsFollowAutoExposureInNoise()
    {
        SignalOptions o = specSignal(25.0, 0.15);
        o.snrDb = 6.0;
        o.ambient = 1.5;
        o.drift = 0.01;
        o.gainDrift = 0.3;
        o.repetitions = 4;
        o.seed = 11;
        const Signal sig = generateSignal(o);
        LevelSlicer slicer;
        double sum = 0.0;
        int n = 0;
        for (const Sample &s : sig.samples) {
            slicer.feed(s);
            if (s.t < 8.0)
                continue; // acquisition and settling
            const double gain = 1.0 + o.gainDrift * std::sin(2.0 * std::numbers::pi * s.t / 23.0);
            const double low = gain * o.amplitude * (o.ambient + o.drift * s.t);
            const double high = low + gain * o.amplitude;
            const double err = ((slicer.low() + slicer.high()) - (low + high)) / 2.0 / (high - low);
            sum += err * err;
            ++n;
        }
        const double rms = std::sqrt(sum / n);
        qInfo("threshold error %.3f contrasts rms", rms);
        // 0.16 measured; 0.54 without the line fit.
        QVERIFY2(rms < 0.25,
                 qPrintable(QStringLiteral("threshold off by %1 contrasts (rms)").arg(rms)));
    }

    // A frame period shorter than an element: at 15 fps a dit of 1.3 frame periods can leave one
    // frame, whose threshold crossings are less than a period apart. On a clean signal that
    // interval is real and kept; in noise, a frame just beyond the threshold is a noise spike
    // and merged, one far beyond it (more than 3 noise sigmas) is kept.
    void subFramePieceKeptWhenClear_data()
    {
        QTest::addColumn<double>("sigma"); // noise, in contrasts
        QTest::addColumn<double>("spike"); // the single frame, in contrasts above the off level
        QTest::addColumn<bool>("kept");
        QTest::newRow("clean") << 0.0 << 0.9 << true;
        QTest::newRow("noise, 1.5 sigmas beyond") << 0.1 << 0.65 << false;
        QTest::newRow("noise, 4.5 sigmas beyond") << 0.1 << 0.95 << true;
    }
    void subFramePieceKeptWhenClear()
    {
        QFETCH(double, sigma);
        QFETCH(double, spike);
        QFETCH(bool, kept);
        const double period = 1.0 / 15.0;
        std::mt19937 rng(3);
        std::normal_distribution<double> noise(0.0, sigma > 0.0 ? sigma : 1.0);
        LevelSlicer slicer;
        double spikeAt = 0.0;
        for (int k = 0; k < 150; ++k) {
            // 4 s of 4 frames on, 4 off (acquisition), then 8 frames off with one spike, then
            // the square wave again.
            double v = 0.0;
            if (k < 60 || k >= 72)
                v = (k / 4) % 2 == 0 ? 1.0 : 0.0;
            if (k == 66) {
                v = spike;
                spikeAt = k * period;
            }
            slicer.feed({ k * period, v + (sigma > 0.0 && k != 66 ? noise(rng) : 0.0) });
        }
        QVERIFY(slicer.found());
        QVERIFY2(std::abs(slicer.noise() - sigma) < 0.3 * sigma + 1e-6,
                 qPrintable(QString::number(slicer.noise())));
        bool found = false;
        for (const Interval &iv : slicer.intervals()) {
            if (iv.on && iv.start > spikeAt - period && iv.start < spikeAt) {
                found = true;
                QVERIFY2(iv.duration < period, qPrintable(QString::number(iv.duration / period)));
            }
        }
        QCOMPARE(found, kept);
    }

    // Every edge carries the uncertainty of its crossing: none on a clean signal; in noise a
    // steep step between two frames far from the threshold is placed more precisely than a step
    // that a frame half on (exposure across the edge) splits in two.
    void edgeSigmaFollowsTheStep()
    {
        const double period = 1.0 / 25.0;
        for (const double sigma : { 0.0, 0.08 }) {
            std::mt19937 rng(5);
            std::normal_distribution<double> noise(0.0, 1.0);
            LevelSlicer slicer;
            for (int k = 0; k < 400; ++k) {
                // 5 frames on, 5 off; every second rising edge has a frame half on before it.
                const int phase = k % 20;
                double v = phase < 5 || (phase >= 10 && phase < 15) ? 1.0 : 0.0;
                if (phase == 9)
                    v = 0.5;
                slicer.feed({ k * period, v + sigma * noise(rng) });
            }
            std::vector<double> steep;
            std::vector<double> split;
            for (const Interval &iv : slicer.intervals()) {
                if (iv.truncated || iv.start < 4.0)
                    continue;
                if (!iv.on)
                    steep.push_back(iv.startSigma / period);
                else
                    (std::abs(std::fmod(iv.start / period, 20.0) - 10.0) < 5.0 ? split : steep)
                        .push_back(iv.startSigma / period);
            }
            QVERIFY(steep.size() > 20 && split.size() > 5);
            const double steepMean =
                std::accumulate(steep.begin(), steep.end(), 0.0) / steep.size();
            const double splitMean =
                std::accumulate(split.begin(), split.end(), 0.0) / split.size();
            if (sigma == 0.0) {
                QCOMPARE(steepMean, 0.0);
                QCOMPARE(splitMean, 0.0);
                continue;
            }
            // sigma / step: about 0.08 of a period for a full step, twice that for half a step.
            QVERIFY2(steepMean > 0.04 && steepMean < 0.15, qPrintable(QString::number(steepMean)));
            QVERIFY2(splitMean > 1.5 * steepMean, qPrintable(QString::number(splitMean)));
        }
    }

    // A mark measured at 1.9 units is a dah by the model alone ("-...." is '6'), but when its
    // edges are uncertain by a whole unit, dit and dah explain it about equally: the rival '5'
    // comes within half a nat instead of several.
    void uncertainEdgeMakesTheReadingSoft()
    {
        const QString text = QStringLiteral("MC+IP192+168+2+160:");
        StretchInput s = nominalStretch(text);
        const std::size_t at = markOf(text, 16); // the '6'
        s.marks[at] = 1.9;
        const StretchParse sharp = parseStretch(s, ElementModel());
        QVERIFY(sharp.ok);
        QCOMPARE(sharp.observations.at(0).octets[3], 160);
        QVERIFY2(sharp.observations.at(0).cost[3].at(150) > 2.0,
                 qPrintable(QString::number(sharp.observations.at(0).cost[3].at(150))));
        s.markSigma.assign(s.marks.size(), 0.0);
        s.markSigma[at] = 1.0;
        const StretchParse soft = parseStretch(s, ElementModel());
        QVERIFY(soft.ok);
        const auto &cost = soft.observations.at(0).cost[3];
        const int other = soft.observations.at(0).octets[3] == 160 ? 150 : 160;
        QVERIFY(soft.observations.at(0).octets[3] == 160
                || soft.observations.at(0).octets[3] == 150);
        QVERIFY2(cost.at(other) < 0.5, qPrintable(QString::number(cost.at(other))));
    }

    void invalidInput()
    {
        QCOMPARE(reasonOf({}), Reason::InvalidInput);
        const double nan = std::nan("");
        QCOMPARE(reasonOf({ { 0.0, nan }, { 0.1, nan }, { 0.2, nan } }), Reason::InvalidInput);
        QCOMPARE(reasonOf({ { 1.0, 0.0 }, { 0.5, 1.0 }, { 0.2, 0.0 } }), Reason::InvalidInput);
        const auto r = decodeRecording({});
        QVERIFY(!r.ok());
        QCOMPARE(r.error().kind(), db::Error::Kind::InvalidArgument);
    }

    void noModulation_data()
    {
        QTest::addColumn<double>("sigma");
        QTest::newRow("constant") << 0.0;
        QTest::newRow("noise only") << 0.5;
    }
    void noModulation()
    {
        QFETCH(double, sigma);
        std::vector<Sample> samples;
        unsigned state = 12345u;
        for (int i = 0; i < 30 * 60; ++i) {
            state = state * 1664525u + 1013904223u; // deterministic noise
            const double u = (state >> 8) / double(1u << 24) - 0.5;
            samples.push_back({ i / 30.0, 100.0 + sigma * u * 3.46 });
        }
        QCOMPARE(reasonOf(samples), Reason::NoModulation);
        const auto r = decodeRecording(samples);
        QVERIFY(!r.ok());
        QVERIFY(r.error().message().contains(QLatin1String("modulation")));
    }

    void blinkingButNotMorse()
    {
        // A 1 Hz heartbeat: all marks and gaps equal, 500 ms: no dah, unit outside the range.
        std::vector<Sample> samples;
        for (int i = 0; i < 30 * 60; ++i)
            samples.push_back({ i / 30.0, (i / 15) % 2 ? 200.0 : 20.0 });
        const Reason r = reasonOf(samples);
        QVERIFY2(r == Reason::NotMorse || r == Reason::NoValidIp, qPrintable(reasonText(r)));
    }

    void tooShort()
    {
        SignalOptions o = specSignal(30.0, 0.12);
        o.startOffset = 0.0;
        Signal sig = generateSignal(o);
        sig.samples.resize(static_cast<std::size_t>(0.5 * sig.messagePeriod * 30.0));
        QCOMPARE(reasonOf(sig.samples), Reason::TooShort);
    }

    // The reason names the octets voted so far, if any: "?.1.2.3" when the first octet is out
    // of range, "?.?.7.42" when only the end of the message could be read (its start is text
    // the grammar does not know).
    void messageWithoutValidIp_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("partial"); // expected in the message; empty: no octets
        QTest::newRow("octet 300") << "MC+IP300+1+2+3:"
                                   << "octets read so far: ?.1.2.3";
        QTest::newRow("three octets") << "MC+IP10+1+2:" << QString();
        QTest::newRow("status only") << "ST+OK:" << QString();
        QTest::newRow("last octets only") << "ST+7+42:"
                                          << "octets read so far: ?.?.7.42";
    }
    void messageWithoutValidIp()
    {
        QFETCH(QString, text);
        QFETCH(QString, partial);
        SignalOptions o = specSignal(60.0, 0.08);
        o.text = text;
        o.repetitions = 4;
        const Signal sig = generateSignal(o);
        QCOMPARE(reasonOf(sig.samples), Reason::NoValidIp);
        const QString message = decodeRecording(sig.samples).error().message();
        if (partial.isEmpty())
            QVERIFY2(!message.contains(QLatin1String("octets read")), qPrintable(message));
        else
            QVERIFY2(message.contains(partial), qPrintable(message));
    }

    // Noise that corrupts a character beyond one edit: Strict rejects the stretch, Salvage
    // skips the damaged header and still reads all four octets (anchored by the 'P').
    void salvageSkipsDamagedHeader()
    {
        const QString text = QStringLiteral("MC+IP192+168+2+150:");
        StretchInput s = nominalStretch(text);
        s.marks[markOf(text, 3)] = 9.0; // 'I': a mark far longer than any nominal
        const ElementModel model;
        QVERIFY(!parseStretch(s, model).ok);
        const StretchParse p = parseStretch(s, model, ParseMode::Salvage);
        QVERIFY(p.ok);
        QCOMPARE(p.observations.at(0).octets, kSpecIp);
        QVERIFY2(p.text.endsWith(QLatin1String("P192+168+2+150:")), qPrintable(p.text));
    }

    // Status text (movingcap.md 2.2: the LED sends other text too) never salvages into octets.
    void salvageIgnoresStatusText()
    {
        const StretchInput s = nominalStretch(QStringLiteral("ERR+5:"));
        QVERIFY(!parseStretch(s, ElementModel()).ok);
        QVERIFY(!parseStretch(s, ElementModel(), ParseMode::Salvage).ok);
    }

    // The last dit of '6' lost: its gaps merge into 5.5 units, a word gap inside the message.
    // The two halves are read as one stretch again.
    void joinAcrossSpuriousWordGap()
    {
        const QString text = QStringLiteral("MC+IP192+168+2+150:");
        const StretchInput full = nominalStretch(text);
        const std::size_t lost = markOf(text, 11) - 1; // last mark of the '6' in 168
        StretchInput a;
        a.marks.assign(full.marks.begin(), full.marks.begin() + std::ptrdiff_t(lost));
        a.gaps.assign(full.gaps.begin(), full.gaps.begin() + std::ptrdiff_t(lost - 1));
        a.gapAfter = 5.5;
        StretchInput b;
        b.marks.assign(full.marks.begin() + std::ptrdiff_t(lost + 1), full.marks.end());
        b.gaps.assign(full.gaps.begin() + std::ptrdiff_t(lost + 1), full.gaps.end());
        const ElementModel model;
        QVERIFY(!parseStretch(a, model).ok);
        const StretchParse p = parseStretch(joinStretches(a, b), model);
        QVERIFY(p.ok);
        QCOMPARE(p.observations.at(0).octets, kSpecIp);
        QVERIFY(p.observations.at(0).weight[1] <= 0.5); // the repaired octet counts half at most
    }

    // The first dah of the '2' in 192 measured at 1.75 units, close to the dit/dah boundary of
    // the default model ("...--" is '3'):
    // the soft costs (IpObservation::cost) name 193 as a close rival, other values as far off,
    // and a leading zero ("092" would need the '1' read as '0') as unlikely.
    void softCostsNameTheRival()
    {
        const QString text = QStringLiteral("MC+IP192+168+2+150:");
        StretchInput s = nominalStretch(text);
        s.marks[markOf(text, 7) + 2] = 1.75;
        const StretchParse p = parseStretch(s, ElementModel());
        QVERIFY(p.ok);
        const auto &cost = p.observations.at(0).cost[0];
        QCOMPARE(cost.at(p.observations.at(0).octets[0]), 0.0);
        QVERIFY(cost.count(193) == 1);
        QVERIFY2(cost.at(193) < 2.0, qPrintable(QString::number(cost.at(193))));
        QVERIFY(cost.count(182) == 0 || cost.at(182) > 6.0);
        QVERIFY(cost.count(92) == 0 || cost.at(92) > 6.0);
        // The clean octets have no close rival.
        for (const auto &[value, nats] : p.observations.at(0).cost[1])
            QVERIFY(value == 168 || nats > 3.0);
    }

    // A noise dip splits the first dah of the '9' in 192: read as one mark with an edit.
    void insertedElementIsRepaired()
    {
        const QString text = QStringLiteral("MC+IP192+168+2+150:");
        StretchInput s = nominalStretch(text);
        const std::size_t at = markOf(text, 6);
        s.marks[at] = 1.2;
        s.marks.insert(s.marks.begin() + std::ptrdiff_t(at) + 1, 1.2);
        s.gaps.insert(s.gaps.begin() + std::ptrdiff_t(at), 0.6);
        const StretchParse p = parseStretch(s, ElementModel());
        QVERIFY(p.ok);
        QCOMPARE(p.observations.at(0).octets, kSpecIp);
        QVERIFY(p.observations.at(0).weight[0] <= 0.5);
    }

    // Noise swallows the first dit of the '5' in 150: the letter gap before it grows by that dit
    // and the gap after it (3 + 1 + 1 units), and "...." is left. Read as '5' with its first
    // mark lost, every length fits its nominal, so 150 leads clearly; without that reading '5'
    // needed a 5-unit letter gap and a 1-unit gap read as 3, and 140 came within 3 nats.
    // With tight timing (a drive without jitter, noise only) the grown gap lies 11 sigmas from
    // a letter gap: the character before must not be rejected for it.
    void lostFirstMarkIsRepaired_data()
    {
        QTest::addColumn<double>("relJitter");
        QTest::addColumn<double>("absSigma");
        QTest::newRow("default model") << ElementModel().relJitter << ElementModel().absSigma;
        QTest::newRow("tight timing") << 0.04 << 0.13;
    }
    void lostFirstMarkIsRepaired()
    {
        QFETCH(double, relJitter);
        QFETCH(double, absSigma);
        ElementModel model;
        model.relJitter = relJitter;
        model.absSigma = absSigma;
        const QString text = QStringLiteral("MC+IP192+168+2+150:");
        StretchInput s = nominalStretch(text);
        const std::size_t at = markOf(text, 16);
        QCOMPARE(s.gaps[at - 1], 3.0);
        s.gaps[at - 1] = 5.0;
        s.marks.erase(s.marks.begin() + std::ptrdiff_t(at));
        s.gaps.erase(s.gaps.begin() + std::ptrdiff_t(at));
        const StretchParse p = parseStretch(s, model);
        QVERIFY(p.ok);
        QCOMPARE(p.text, text);
        QCOMPARE(p.observations.at(0).octets, kSpecIp);
        const std::map<int, double> &cost = p.observations.at(0).cost[3];
        QCOMPARE(cost.at(150), 0.0);
        QVERIFY2(!cost.contains(140) || cost.at(140) > 5.0,
                 qPrintable(QString::number(cost.contains(140) ? cost.at(140) : -1.0)));
        QVERIFY(p.observations.at(0).weight[3] <= 0.5); // a repaired digit: half a vote
    }

    // Cut at both ends ("4+34+" of some message): which octet "34" is, is unknown.
    void unanchoredOctetsAreNotReported()
    {
        StretchInput s = nominalStretch(QStringLiteral("4+34+"));
        s.openStart = true;
        s.firstComplete = true;
        s.openEnd = true;
        const StretchParse p = parseStretch(s, ElementModel());
        QVERIFY(p.ok);
        QCOMPARE(p.observations.at(0).octets, (std::array<int, 4> { -1, -1, -1, -1 }));
    }

    // Noise fills the gap between the two dahs of the 'M' in the first two messages: a mark of
    // 7 units. It stays in the message (read as 'M' with one element lost) instead of closing
    // it as a long mark, which cut "C+IP..." off from the 'M' (and, at the end of a message,
    // the ':' from the rest).
    void mergedDahsStayInTheMessage()
    {
        SignalOptions o = specSignal(30.0, 0.1);
        o.startOffset = 0.95; // in the repeat gap: the first two messages are complete
        Signal sig = generateSignal(o);
        const double on = o.amplitude * (o.ambient + 1.0);
        for (std::size_t m = 0; m < 2; ++m) {
            const double gapStart = sig.messageStarts[m] + 3.0 * o.unit;
            for (Sample &s : sig.samples) {
                if (s.t > gapStart - 0.01 && s.t < gapStart + o.unit + 0.01)
                    s.value = on;
            }
        }
        Decoder decoder;
        decoder.feed(sig.samples);
        decoder.finish();
        const QString text = decoder.text();
        QVERIFY2(text.count(QLatin1String("MC+IP192+168+2+150:")) >= 2, qPrintable(text));
        QVERIFY2(!text.contains(QLatin1Char('?')), qPrintable(text));
        QCOMPARE(decoder.ip().toString(), QStringLiteral("192.168.2.150"));
        QVERIFY(decoder.confident());
    }

    // The pause between two messages is not specified (movingcap.md 2.2). Shorter than a word
    // gap (4.4 units; 7 units with 30 % jitter are 4.9), or none at all (a drive that loops its
    // message: only a letter gap after ':'), it reads as a letter gap and the messages run
    // together into one stretch, up to the whole recording. The grammar reads the next message
    // after ':'. Before, a 4.4-unit pause needed a special cut, and back to back no address
    // was read at all.
    void pauseBetweenMessages_data()
    {
        QTest::addColumn<double>("pause"); // units
        QTest::newRow("4.4 units") << 4.4;
        QTest::newRow("back to back") << 3.0;
    }
    void pauseBetweenMessages()
    {
        QFETCH(double, pause);
        SignalOptions o = specSignal(30.0, 0.12);
        o.repeatGap = pause;
        o.repetitions = 4;
        const QString problem = specDecodeProblem(generateSignal(o).samples, 3);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
    }

    // Bench case (jitter 30 % + 6 dB at 2 samples per unit, seed 43, case 42): noise breaks the
    // ':' of one message, and three of its marks (read 'S') stand alone between two word gaps, a
    // stretch that the grammar rejects. Joined to the next message (as if the word gap were
    // noise inside a message) they were read into it: "MC+IP173+61+84+71:" for 73. The message
    // alone explains its lengths better than the join does with the three marks skipped, so
    // the join is not taken.
    void strayMarksAreNotJoinedToTheNextMessage()
    {
        const CorpusCondition c { QStringLiteral("j30+6dB<3spu"), 0.3, 6.0, 0.0, 0.0, 0.0, 2.0 };
        const CaseOutcome o = runCase(makeCorpus(c, 43, 43).back());
        QVERIFY2(!o.text.contains(QLatin1String("IP173")), qPrintable(o.text));
        QVERIFY2(o.exact, qPrintable(o.decoded));
    }

    // Noise lights the LED for half a unit in the middle of every pause: two gaps of about 3.3
    // units, each a letter gap, with a mark too short for any character of the message between
    // them. It is a spike in a word gap; before, it ran the messages together (read as 'E').
    void spikeInThePause()
    {
        SignalOptions o = specSignal(1000.0, 0.1);
        o.repeatGap = 7.0;
        o.repetitions = 4;
        Signal sig = generateSignal(o);
        const double on = o.amplitude * (o.ambient + 1.0);
        for (std::size_t m = 1; m < sig.messageStarts.size(); ++m) {
            const double middle = sig.messageStarts[m] - 3.5 * o.unit;
            for (Sample &s : sig.samples) {
                if (std::abs(s.t - middle) < 0.25 * o.unit)
                    s.value = on;
            }
        }
        const QString problem = specDecodeProblem(sig.samples, 3);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
    }

    // The recording began in the 'P' of "IP": the first complete character is the '1' of 119.
    // Octets have at most three digits, so three after the cut are the whole octet and it is
    // read; two ("19") may be the end of 119 or 219, so no value is read, but the values that
    // do not end in 19 cost more (the evidence of the tail).
    void digitsAfterACut()
    {
        auto cut = [](const QString &text) {
            StretchInput s = nominalStretch(text);
            s.marks.insert(s.marks.begin(), 1.0); // the last dit of 'P'
            s.gaps.insert(s.gaps.begin(), 3.0);
            s.openStart = true;
            return s;
        };
        const StretchParse whole = parseStretch(cut(QStringLiteral("119+222+156+176:")), {});
        QVERIFY(whole.ok);
        QCOMPARE(whole.observations.at(0).octets, (std::array<int, 4> { 119, 222, 156, 176 }));

        const StretchParse tail = parseStretch(cut(QStringLiteral("19+222+156+176:")), {});
        QVERIFY(tail.ok);
        QCOMPARE(tail.observations.at(0).octets, (std::array<int, 4> { -1, 222, 156, 176 }));
        const std::map<int, double> &cost = tail.observations.at(0).cost[0];
        for (int v : { 19, 119, 219 })
            QVERIFY2(cost.contains(v) && cost.at(v) == 0.0, qPrintable(QString::number(v)));
        for (int v : { 18, 118, 9, 29 })
            QVERIFY2(!cost.contains(v) || cost.at(v) > 2.0, qPrintable(QString::number(v)));
    }

    // A long mark (the LED steady on, or a slicer glitch) closes the stretch before it. The gap
    // between its last character and the long mark is not part of the stretch: with it, the
    // stretch failed parseStretch()'s size check and its message was never read.
    void stretchClosedByALongMark()
    {
        const StretchInput nominal = nominalStretch(QStringLiteral("MC+IP10+0+7+42:"));
        std::vector<Element> timeline = timelineOf(nominal);
        addElement(timeline, ElementKind::LetterGap, 3.0);
        addElement(timeline, ElementKind::LongMark, 12.0);
        addElement(timeline, ElementKind::WordGap, 10.0);
        const std::vector<StretchInput> stretches = splitStretches(timeline);
        QCOMPARE(stretches.size(), std::size_t(1));
        QCOMPARE(stretches[0].marks.size(), nominal.marks.size());
        QCOMPARE(stretches[0].gaps.size(), nominal.gaps.size());
        const StretchParse p = parseStretch(stretches[0], ElementModel());
        QVERIFY(p.ok);
        QCOMPARE(p.observations.at(0).octets, (std::array<int, 4> { 10, 0, 7, 42 }));
    }

    // Messages back to back run together into one stretch, up to the whole recording, which
    // every update would parse anew. After 400 marks the stretch ends at the next ':' (read
    // hard), the letter gap after it read as the pause; every message is still read.
    void longStretchEndsAfterAMessage()
    {
        const QString message = QStringLiteral("MC+IP192+168+2+150:");
        QString text;
        for (int m = 0; m < 10; ++m)
            text += message;
        std::vector<Element> timeline = timelineOf(nominalStretch(text));
        addElement(timeline, ElementKind::WordGap, 10.0);
        const std::vector<StretchInput> stretches = splitStretches(timeline);
        QVERIFY(stretches.size() >= 2);
        int complete = 0;
        for (const StretchInput &s : stretches) {
            QVERIFY(s.marks.size() < 400 + 2 * nominalStretch(message).marks.size());
            const StretchParse p = parseStretch(s, ElementModel());
            QVERIFY2(p.ok && p.text.startsWith(QLatin1String("MC+IP")), qPrintable(p.text));
            for (const IpObservation &obs : p.observations)
                complete += obs.octets == kSpecIp && obs.complete ? 1 : 0;
        }
        QCOMPARE(complete, 10);
    }

    // Back to back (pauseBetweenMessages) with noise: one damaged message must not stop the reading
    // of the others in the stretch (Salvage leaves it and restarts at the next "MC+IP"), and no
    // mis-cut may agree with itself into a confident wrong address (a split at any letter gap did
    // that). Streamed in chunks, the address is checked at every step.
    void backToBackMessagesInNoise()
    {
        const std::array<int, 4> ip { 10, 0, 7, 42 };
        int right = 0;
        for (unsigned seed = 1; seed <= 6; ++seed) {
            SignalOptions o = specSignal(30.0, 0.12);
            o.text = QStringLiteral("MC+IP10+0+7+42:");
            o.repeatGap = 3.0;
            o.repetitions = 4;
            o.snrDb = 6.0;
            o.jitter = 0.3;
            o.seed = seed;
            o.startOffset = 0.15 * seed;
            const Signal sig = generateSignal(o);
            Decoder decoder;
            for (std::size_t at = 0; at < sig.samples.size(); at += 8) {
                const std::size_t count = std::min<std::size_t>(8, sig.samples.size() - at);
                decoder.feed(std::span<const Sample>(sig.samples.data() + at, count));
                QVERIFY2(!decoder.confident() || decoder.ip().octets == ip,
                         qPrintable(decoder.ip().toString() + QStringLiteral(" from ")
                                    + decoder.text()));
            }
            decoder.finish();
            right += decoder.confident() && decoder.ip().octets == ip ? 1 : 0;
        }
        QCOMPARE(right, 6);
    }

    // Two messages in one stretch are two observations, each with its own soft costs: the '2' of
    // 42 is unclear in the second message only (its first dah 1.75 units: "...--" is '3').
    void twoMessagesInOneStretch()
    {
        const QString message = QStringLiteral("MC+IP10+0+7+42:");
        const QString text = message + message;
        StretchInput s = nominalStretch(text);
        s.marks[markOf(text, int(message.size()) + 13) + 2] = 1.75;
        const StretchParse p = parseStretch(s, ElementModel());
        QVERIFY(p.ok);
        QCOMPARE(p.text, text);
        QCOMPARE(p.observations.size(), std::size_t(2));
        for (const IpObservation &obs : p.observations) {
            QCOMPARE(obs.octets, (std::array<int, 4> { 10, 0, 7, 42 }));
            QVERIFY(obs.complete);
        }
        const auto &first = p.observations[0].cost[3];
        const auto &second = p.observations[1].cost[3];
        QVERIFY2(!first.contains(43) || first.at(43) > 4.0,
                 qPrintable(QString::number(first.contains(43) ? first.at(43) : -1.0)));
        QVERIFY2(second.contains(43) && second.at(43) < 2.0,
                 qPrintable(QString::number(second.contains(43) ? second.at(43) : -1.0)));
    }

    // The gap after ':' is the pause before the next message: longer than a letter gap, it
    // costs no more than one (a longer pause is no worse a reading).
    void pauseAfterTheMessageCostsNothing()
    {
        const QString message = QStringLiteral("MC+IP10+0+7+42:");
        StretchInput s = nominalStretch(message + message);
        const std::size_t colonEnd = markOf(message + message, int(message.size())) - 1;
        QCOMPARE(s.gaps[colonEnd], 3.0);
        const StretchParse tight = parseStretch(s, ElementModel());
        s.gaps[colonEnd] = 4.4;
        const StretchParse pause = parseStretch(s, ElementModel());
        QVERIFY(tight.ok && pause.ok);
        QCOMPARE(pause.cost, tight.cost);
        QCOMPARE(pause.observations.size(), std::size_t(2));
    }

    // Noise ruins the middle one of three messages in a stretch (a mark of 9 units in its "IP"):
    // Salvage reads the first, leaves the second after the octets it can anchor, and restarts
    // at the third "MC+IP". Every octet reported is right.
    void salvageRestartsAfterADamagedMessage()
    {
        const QString message = QStringLiteral("MC+IP10+0+7+42:");
        const QString text = message + message + message;
        StretchInput s = nominalStretch(text);
        s.marks[markOf(text, int(message.size()) + 8)] = 9.0; // the '0' of the second message
        const ElementModel model;
        QVERIFY(!parseStretch(s, model).ok);
        const StretchParse p = parseStretch(s, model, ParseMode::Salvage);
        QVERIFY(p.ok);
        const std::array<int, 4> ip { 10, 0, 7, 42 };
        int complete = 0;
        for (const IpObservation &obs : p.observations) {
            complete += obs.complete ? 1 : 0;
            for (std::size_t k = 0; k < 4; ++k)
                QVERIFY2(obs.octets[k] < 0 || obs.octets[k] == ip[k], qPrintable(p.text));
        }
        QVERIFY2(complete == 2, qPrintable(p.text));
    }

    void otherTextIsTolerated()
    {
        SignalOptions o = specSignal(30.0, 0.1);
        o.text = QStringLiteral("ST+OK: MC+IP10+0+0+7: ERR+5:");
        const auto r = decodeRecording(generateSignal(o).samples);
        QVERIFY2(r.ok(), qPrintable(r.error().toString()));
        QCOMPARE(r->ip.toString(), QStringLiteral("10.0.0.7"));
        QCOMPARE(r->reason, Reason::None);
    }
};

QTEST_GUILESS_MAIN(TstMorseDecoder)
#include "tst_morsedecoder.moc"
