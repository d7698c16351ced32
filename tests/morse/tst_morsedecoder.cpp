// The decoder on generated signals: the spec example (movingcap.md 2.2), streaming partial
// results and events, and the reasons given when nothing can be decoded.
#include "morse/decode/decoder.h"
#include "morse/decode/levelslicer.h"
#include "morse/decode/messageparser.h"
#include "morse/decode/morsecode.h"
#include "morse/synth/corpus.h"
#include "morse/synth/signalgenerator.h"

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

    // A gap in time far longer than any Morse element (a camera that stalled, two recordings in
    // one file) cuts the recording: each part is read on its own (the levels and the sample
    // period of one say nothing about the other), the readings of both vote, and the cut is
    // named. Fed in chunks, as the GUI and a camera do.
    void gapInTimeCutsTheRecording()
    {
        SignalOptions o = specSignal(30.0, 0.1);
        o.repetitions = 2;
        const std::vector<Sample> part = generateSignal(o).samples;
        const auto joined = [&part](std::size_t size, double gap) {
            std::vector<Sample> out(part.begin(), part.begin() + std::ptrdiff_t(size));
            for (std::size_t i = 0; i < size; ++i)
                out.push_back({ part[i].t + part[size - 1].t + gap, part[i].value });
            return out;
        };
        const std::vector<Sample> samples = joined(part.size(), 1e8);
        Decoder decoder;
        for (std::size_t i = 0; i < samples.size(); i += 7)
            decoder.feed(
                std::span(samples).subspan(i, std::min<std::size_t>(7, samples.size() - i)));
        decoder.finish();
        QCOMPARE(decoder.ip().toString(), QStringLiteral("192.168.2.150"));
        QVERIFY(decoder.confident());
        const QStringList parts = decoder.text().split(QStringLiteral(" | "));
        QCOMPARE(parts.size(), 2);
        QVERIFY2(parts[0].contains(QLatin1String("MC+IP192+168+2+150:"))
                     && parts[1].contains(QLatin1String("MC+IP192+168+2+150:")),
                 qPrintable(decoder.text()));

        // Too short on either side: the reason, and the cut that made the parts short.
        Decoder shortParts;
        shortParts.feed(joined(36, 1e9));
        shortParts.finish();
        QVERIFY(!shortParts.confident());
        const QString message = shortParts.diagnosis().message();
        QVERIFY2(message.contains(QStringLiteral("the recording has a 1e+09 s gap in time after "
                                                 "sample 36 (at %1 s): read as 2 recordings")
                                      .arg(part[35].t, 0, 'f', 2)),
                 qPrintable(message));

        // A gap of a few seconds is dark LED, not a cut: back-to-back recording as one.
        Decoder pause;
        pause.feed(joined(part.size(), 5.0));
        pause.finish();
        QVERIFY(!pause.text().contains(QLatin1Char('|')));
        QVERIFY(!pause.reasonMessage().contains(QLatin1String("gap")));
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
