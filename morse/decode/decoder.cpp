#include "decoder.h"

#include "framecheck.h"
#include "messageparser.h"
#include "morsecode.h"

#include <QCoreApplication>
#include <QLoggingCategory>
#include <QStringList>

#include <algorithm>
#include <cmath>
#include <limits>

Q_LOGGING_CATEGORY(lcMorse, "drivebench.morse", QtInfoMsg)

namespace db::morse {

namespace {

struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::morse)
};

constexpr std::size_t kFitWindow = 400; // intervals used for the unit estimate
constexpr std::size_t kMinIntervals = 12; // before that, no unit estimate is tried
constexpr std::size_t kRefitEvery = 24; // new intervals between estimates
constexpr double kReparse = 0.01; // relative unit change that makes recent stretches parse anew
constexpr int kLongTextChars = 40; // this much text without ':' is not "too short"
constexpr std::size_t kMaxJoins = 2; // spurious word gaps re-read inside one message
// Seconds: stretches that began longer ago keep their parse when the element model changes, so
// that a camera running for hours does not re-read its whole history at every refit (30 min of
// messages: 190 ms for such an update). Longer than a recording of three messages at the
// slowest unit (about 4 minutes), whose first messages are read again until the unit is known.
constexpr double kReparseSeconds = 600.0;
// Samples kept for checkFrames(): those of every stretch that may still be parsed.
constexpr double kKeepSamples = kReparseSeconds + 120.0;
// And at most twice this many of them (32 MB): a source of more than 2.9 kHz keeps less time.
constexpr std::size_t kMaxKeptSamples = std::size_t(1) << 21;
// checkFrames(): the value read and up to kRivals others whose soft cost is below kCheckRange
// nats (the voter uses up to IpVoter::kMaxWeight * kNatsPerWeight = 6).
constexpr std::size_t kRivals = 3;
constexpr double kCheckRange = 8.0;

// Character-by-character reading of a stretch the grammar rejected (other text, status).
QString hardText(const StretchInput &s)
{
    QString text;
    QString code;
    for (std::size_t i = 0; i < s.marks.size(); ++i) {
        code += s.marks[i] < 2.0 ? QLatin1Char('.') : QLatin1Char('-');
        if (i + 1 == s.marks.size() || s.gaps[i] >= 2.0) {
            const QChar c = charFor(code);
            text += c.isNull() || (text.isEmpty() && s.openStart) ? QLatin1Char('?') : c;
            code.clear();
        }
    }
    return text;
}

// A reading for the debug log: per octet the value, its weight and the soft costs below 6 nats.
QString readingText(const IpObservation &obs)
{
    QStringList octets;
    for (std::size_t k = 0; k < 4; ++k) {
        QStringList costs;
        for (const auto &[value, nats] : obs.cost[k]) {
            if (nats < 6.0)
                costs << QStringLiteral("%1:%2").arg(value).arg(nats, 0, 'f', 1);
        }
        octets << QStringLiteral("%1 w%2 {%3}")
                      .arg(obs.octets[k])
                      .arg(obs.weight[k], 0, 'f', 2)
                      .arg(costs.join(QLatin1Char(' ')));
    }
    return (obs.complete ? QStringLiteral("complete: ") : QStringLiteral("partial: "))
        + octets.join(QStringLiteral(" | "));
}

} // namespace

QString reasonText(Reason reason)
{
    switch (reason) {
    case Reason::None:
        return Tr::tr("IP address decoded");
    case Reason::InvalidInput:
        return Tr::tr("no usable samples (empty, not finite or time not increasing)");
    case Reason::NoModulation:
        return Tr::tr("no modulation: the brightness never shows two distinct levels "
                      "(LED not in view, covered or not blinking)");
    case Reason::NotMorse:
        return Tr::tr("the LED blinks, but not with Morse timing of 40-500 ms per unit");
    case Reason::TooShort:
        return Tr::tr("recording too short: not one complete message yet");
    case Reason::NoValidIp:
        return Tr::tr("Morse text without a valid \"MC+IPa+b+c+d:\" message");
    case Reason::LowConfidence:
        return Tr::tr("IP address seen, but the repetitions do not agree enough yet");
    }
    return {};
}

QString IpEstimate::toString() const
{
    QStringList parts;
    for (int o : octets)
        parts << (o >= 0 ? QString::number(o) : QStringLiteral("?"));
    return parts.join(QLatin1Char('.'));
}

Decoder::Decoder(DecoderOptions options)
    : m_options(options)
{ }

void Decoder::feed(std::span<const Sample> samples)
{
    for (const Sample &s : samples) {
        const bool valid = std::isfinite(s.t) && std::isfinite(s.value);
        if (valid && std::isfinite(m_lastTime) && s.t - m_lastTime > kMaxSampleGap)
            endPart(s.t - m_lastTime);
        ++m_fed;
        m_slicer.feed(s);
        if (valid && (m_samples.empty() || s.t > m_samples.back().t)) {
            m_samples.push_back(s);
            m_lastTime = s.t;
            if (m_samples.size() >= 2 * kMaxKeptSamples)
                m_samples.erase(m_samples.begin(),
                                m_samples.begin() + std::ptrdiff_t(kMaxKeptSamples));
        }
    }
    // Drop the old samples in blocks (amortised): at most twice the window is kept.
    if (!m_samples.empty()) {
        const std::size_t old =
            samplesBetween(m_samples, m_samples.back().t - kKeepSamples, m_samples.back().t).data()
            - m_samples.data();
        if (old > m_samples.size() - old)
            m_samples.erase(m_samples.begin(), m_samples.begin() + std::ptrdiff_t(old));
    }
    update(false);
}

void Decoder::finish()
{
    update(true);
}

void Decoder::endPart(double gapLength)
{
    update(true);
    const auto rank = [](Reason r) {
        return r == Reason::None ? 100 : int(r);
    };
    if (rank(partReason()) > rank(m_doneReason))
        m_doneReason = partReason();
    m_doneReadings.insert(m_doneReadings.end(), m_partReadings.begin(), m_partReadings.end());
    m_doneText = m_text;
    m_doneComplete = m_completeSeen;
    if (m_gaps.size() < kMaxGapsKept)
        m_gaps.push_back({ m_lastTime, gapLength, m_fed });
    ++m_gapCount;
    qCDebug(lcMorse) << "gap of" << gapLength << "s after" << m_lastTime << ": new recording";
    m_slicer = {};
    m_samples.clear();
    m_frameCache.clear();
    m_fit = {};
    m_symbols = {};
    m_fittedAt = 0;
    m_symbolizedKey = 0;
    m_symbolizedUnit = 0.0;
    m_wasFound = false;
    m_wasIdle = false;
    m_cache.clear();
    m_model = {};
    m_modelUnit = 0.0;
    m_modelDuty = 0.0;
    m_partReadings.clear();
}

QString Decoder::gapNote() const
{
    if (m_gapCount == 0)
        return {};
    QStringList where;
    for (const SampleGap &g : m_gaps) {
        where << Tr::tr("a %1 s gap in time after sample %2 (at %3 s)")
                     .arg(g.length, 0, 'g', 3)
                     .arg(g.samples)
                     .arg(g.after, 0, 'f', 2);
    }
    if (m_gapCount > m_gaps.size())
        where << Tr::tr("%1 more").arg(m_gapCount - m_gaps.size());
    return Tr::tr("the recording has %1: read as %2 recordings")
        .arg(where.join(QStringLiteral(", ")))
        .arg(m_gapCount + 1);
}

void Decoder::event(DecoderEvent::Kind kind, QString detail)
{
    qCDebug(lcMorse) << "event" << int(kind) << m_slicer.lastTime() << detail;
    m_events.push_back({ kind, m_slicer.lastTime(), std::move(detail) });
}

void Decoder::update(bool final)
{
    if (m_slicer.found() && !m_wasFound)
        event(DecoderEvent::Kind::LedFound);
    m_wasFound = m_slicer.found();
    if (m_slicer.idle() && !m_wasIdle)
        event(DecoderEvent::Kind::LedLost);
    m_wasIdle = m_slicer.idle();

    const std::vector<Interval> &ivs = m_slicer.intervals();
    if (ivs.size() >= kMinIntervals
        && (ivs.size() >= m_fittedAt + kRefitEvery || !m_fit.valid
            || (final && ivs.size() != m_fittedAt))) {
        const bool had = m_fit.valid;
        const auto from = ivs.size() > kFitWindow ? ivs.end() - kFitWindow : ivs.begin();
        m_fit = fitUnit(std::vector<Interval>(from, ivs.end()), m_options.unitRange);
        m_fittedAt = ivs.size();
        if (m_fit.valid && !had)
            event(DecoderEvent::Kind::UnitFound,
                  QStringLiteral("%1 ms").arg(m_fit.unit * 1000.0, 0, 'f', 1));
    }
    if (!m_fit.valid || m_fit.quality < m_options.minFitQuality) {
        m_symbols = {};
        m_text = m_doneText;
        m_partReadings.clear();
        return;
    }

    // Re-decode only when an interval closed, the unit changed, or the gap in progress
    // crossed a classification threshold (letter or word gap).
    const Interval open = m_slicer.openInterval();
    const double openUnits = open.duration / m_fit.unit;
    const int openClass = open.on ? 0 : (openUnits < 2.0 ? 1 : (openUnits < 5.0 ? 2 : 3));
    const std::size_t key = ivs.size() * 4 + static_cast<std::size_t>(openClass);
    if (!final && key == m_symbolizedKey && m_fit.unit == m_symbolizedUnit)
        return;
    m_symbolizedKey = key;
    m_symbolizedUnit = m_fit.unit;
    m_symbols = symbolize(ivs, open, m_fit, final);

    // Sequence decoding per stretch between word gaps (messageparser.h); stretches that the
    // grammar does not explain keep their character-by-character reading.
    if (std::abs(m_fit.unit - m_modelUnit) > kReparse * m_fit.unit
        || std::abs(m_fit.duty - m_modelDuty) > kReparse * m_fit.unit) {
        // Parsed stretches are kept while the unit moves by less than kReparse.
        m_model = estimateModel(m_symbols.elements, m_slicer.samplePeriod() / m_fit.unit);
        m_modelUnit = m_fit.unit;
        m_modelDuty = m_fit.duty;
        const double keep = m_slicer.lastTime() - kReparseSeconds;
        std::erase_if(m_cache,
                      [keep](const auto &entry) { return std::get<0>(entry.first) >= keep; });
        m_frameCache.clear();
    }
    IpVoter voter;
    for (const IpObservation &obs : m_doneReadings)
        voter.add(obs);
    m_partReadings.clear();
    int complete = m_doneComplete;
    QString corrected;
    const std::vector<StretchInput> stretches = splitStretches(m_symbols.elements);
    for (std::size_t i = 0; i < stretches.size(); ++i) {
        StretchInput stretch = stretches[i];
        StretchParse parse = cachedParse(stretch, ParseMode::Strict);
        // A stretch the grammar rejects: first the word gap after it may be noise inside
        // the message (re-read joined with what follows), then its damaged characters are
        // skipped (ParseMode::Salvage). The joined reading must explain the lengths
        // better than the stretch skipped and the ones after it read on their own: a noise
        // spike between two messages is a stretch of one mark that the grammar rejects, and
        // joined to the next message it makes a contrived reading of that message.
        StretchInput joined = stretch;
        double separate = kSkipCost * double(stretch.marks.size());
        for (std::size_t j = i + 1; !parse.ok && !joined.openEnd && joined.gapAfter > 0.0
             && j < stretches.size() && j <= i + kMaxJoins;
             ++j) {
            joined = joinStretches(joined, stretches[j]);
            const StretchParse alone = cachedParse(stretches[j], ParseMode::Strict);
            separate += alone.ok ? alone.cost : kSkipCost * double(stretches[j].marks.size());
            const StretchParse p = cachedParse(joined, ParseMode::Strict);
            if (p.ok && p.cost < separate) {
                stretch = joined;
                parse = p;
                i = j;
            }
        }
        if (!parse.ok)
            parse = cachedParse(stretch, ParseMode::Salvage);
        qCDebug(lcMorse) << "stretch" << stretch.start << stretch.marks.size() << "ok" << parse.ok
                         << parse.text;
        if (!corrected.isEmpty())
            corrected += QLatin1Char(' ');
        corrected += parse.ok ? parse.text : hardText(stretch);
        for (const IpObservation &obs : parse.observations) {
            if (std::none_of(obs.octets.begin(), obs.octets.end(), [](int v) { return v >= 0; })
                && std::all_of(obs.cost.begin(), obs.cost.end(),
                               [](const auto &c) { return c.empty(); }))
                continue;
            qCDebug(lcMorse).noquote() << "  reading" << readingText(obs);
            voter.add(obs);
            m_partReadings.push_back(obs);
            if (obs.complete && ++complete > m_completeSeen) {
                IpEstimate one;
                one.octets = obs.octets;
                event(DecoderEvent::Kind::MessageDecoded, one.toString());
            }
        }
    }
    m_completeSeen = std::max(m_completeSeen, complete);
    m_ip = voter.observations() > 0 ? voter.estimate() : IpEstimate {};
    qCDebug(lcMorse) << "ip" << m_slicer.lastTime() << m_ip.toString() << m_ip.confidence;
    // The parts of a recording cut at gaps are told apart by '|'.
    m_text = m_doneText.isEmpty() || corrected.isEmpty()
        ? m_doneText + corrected
        : m_doneText + QStringLiteral(" | ") + corrected;

    const qsizetype colon = m_text.indexOf(QLatin1Char(':'));
    m_closedMessage = colon >= 0 && m_text.indexOf(QLatin1Char(':'), colon + 1) >= 0;

    if (confident() && m_confidentAt < 0.0) {
        m_confidentAt = m_slicer.lastTime();
        event(DecoderEvent::Kind::IpConfident, m_ip.toString());
    }
}

StretchParse Decoder::cachedParse(const StretchInput &stretch, ParseMode mode)
{
    // Closed stretches do not change until the model does (then the recent ones are parsed
    // again).
    const auto key = std::make_tuple(stretch.start, stretch.marks.size(), stretch.openEnd, mode);
    const auto it = m_cache.find(key);
    if (it != m_cache.end())
        return it->second;
    if (stretch.openEnd) {
        // A stretch still arriving (alone or joined) has grown: its shorter parses are never
        // asked for again.
        std::erase_if(m_cache, [&stretch](const auto &entry) {
            const auto &[start, marks, open, parsedAs] = entry.first;
            return open && start == stretch.start && marks < stretch.marks.size();
        });
    }
    StretchParse parse = parseStretch(stretch, m_model, mode);
    if (m_options.checkFrames)
        checkFrames(parse, stretch);
    return m_cache[key] = parse;
}

void Decoder::checkFrames(StretchParse &parse, const StretchInput &in) const
{
    if (m_modelUnit <= 0.0 || in.markTimes.size() != in.marks.size() || m_samples.size() < 2
        || parse.spans.size() != parse.observations.size())
        return;
    // The unit of the element model: it changes only when the parses are renewed, so that the
    // regions (and m_frameCache) stay the same while a stretch grows.
    const double unit = m_modelUnit;
    const double duty = m_modelDuty;
    auto gapMiddle = [&](long i) {
        const auto g = static_cast<std::size_t>(i);
        return in.markTimes[g] + in.marks[g] * unit + duty + (in.gaps[g] * unit - duty) / 2.0;
    };
    for (std::size_t m = 0; m < parse.observations.size(); ++m) {
        IpObservation &obs = parse.observations[m];
        for (std::size_t k = 0; k < 4; ++k) {
            const OctetSpan &span = parse.spans[m][k];
            if (obs.octets[k] < 0 || span.firstMark < 1 || span.separatorMark < 1
                || span.separatorMark > long(in.gaps.size()))
                continue;
            RegionModel region;
            region.from = gapMiddle(span.firstMark - 1);
            region.to = gapMiddle(span.separatorMark - 1);
            region.unit = unit;
            region.duty = duty;
            region.relJitter = m_model.relJitter;
            const std::span<const Sample> samples =
                samplesBetween(m_samples, region.from - unit, region.to + unit);
            if (region.to <= region.from || !estimateLevels(samples, &region))
                continue;
            // The value read and its cheapest rivals.
            std::vector<std::pair<double, int>> rivals;
            for (const auto &[value, nats] : obs.cost[k]) {
                if (value != obs.octets[k] && nats < kCheckRange)
                    rivals.emplace_back(nats, value);
            }
            if (rivals.empty())
                continue; // the lengths leave no doubt
            std::sort(rivals.begin(), rivals.end());
            rivals.resize(std::min(rivals.size(), kRivals));
            std::vector<int> values { obs.octets[k] };
            for (const auto &r : rivals)
                values.push_back(r.second);
            // Each value with as many digits as were read, leading zeros too ("076"), where it
            // has no more.
            std::vector<double> ll;
            for (int v : values) {
                QString t = QString::number(v);
                while (t.size() < span.digits)
                    t.prepend(QLatin1Char('0'));
                const auto key = std::make_tuple(std::llround(region.from * 1e6),
                                                 std::llround(region.to * 1e6), t);
                auto it = m_frameCache.find(key);
                if (it == m_frameCache.end())
                    it = m_frameCache.emplace(key, regionLogLikelihood(samples, region, t)).first;
                ll.push_back(it->second);
            }
            const auto best = std::size_t(std::max_element(ll.begin(), ll.end()) - ll.begin());
            if (!std::isfinite(ll[best]))
                continue;
            // Where the samples confirm the value read, they add to the lengths' evidence (the
            // more decisive of the two counts). Where they prefer another value, the reading
            // reads both: it no longer vouches for either, and the other messages decide. The
            // samples never overrule the lengths outright: where drift, auto exposure or a duty
            // error bend the model, their margins can be large and wrong.
            if (best == 0) {
                for (std::size_t c = 1; c < values.size(); ++c) {
                    double &cost = obs.cost[k][values[c]];
                    cost = std::max(cost, ll[0] - ll[c]);
                }
            } else {
                qCDebug(lcMorse) << "frames prefer octet" << k << "=" << values[best] << "to"
                                 << values[0] << "by" << (ll[best] - ll[0]) << "nats, region"
                                 << region.from << region.to;
                obs.cost[k][values[best]] = 0.0;
            }
        }
    }
}

DecoderState Decoder::state() const
{
    if (!m_slicer.found())
        return DecoderState::Searching;
    if (confident())
        return DecoderState::Confident;
    if (m_slicer.idle())
        return DecoderState::Idle;
    if (!m_fit.valid)
        return DecoderState::Acquiring;
    return DecoderState::Decoding;
}

std::vector<DecoderEvent> Decoder::takeEvents()
{
    return std::exchange(m_events, {});
}

Reason Decoder::reason() const
{
    const Reason part = partReason();
    if (m_gapCount == 0 || part == Reason::None)
        return part;
    if (m_doneReason == Reason::None)
        return Reason::LowConfidence; // a part was confident alone, the later ones disagree
    return std::max(part, m_doneReason, [](Reason a, Reason b) { return int(a) < int(b); });
}

Reason Decoder::partReason() const
{
    if (m_slicer.validSamples() < 2)
        return Reason::InvalidInput;
    if (!m_slicer.found())
        return Reason::NoModulation;
    if (!m_fit.valid)
        return m_slicer.intervals().size() < kMinIntervals ? Reason::TooShort : Reason::NotMorse;
    if (m_fit.quality < m_options.minFitQuality)
        return Reason::NotMorse;
    if (confident())
        return Reason::None;
    const bool messageSeen = m_closedMessage || m_completeSeen > 0;
    if (m_ip.complete() && messageSeen)
        return Reason::LowConfidence;
    if (messageSeen || m_text.size() >= kLongTextChars)
        return Reason::NoValidIp;
    return Reason::TooShort;
}

QString Decoder::reasonMessage() const
{
    const Reason r = reason();
    QString message = reasonText(r);
    // Octets voted so far tell the user that the drive was read in part (noise or a poor view
    // damaged every message), not that it sends something else.
    if (r == Reason::NoValidIp && m_ip.anyOctet())
        message += Tr::tr("; octets read so far: %1").arg(m_ip.toString());
    if (m_gapCount > 0)
        message += QStringLiteral("; ") + gapNote();
    return message;
}

Error Decoder::diagnosis() const
{
    const Reason r = reason();
    if (r == Reason::None)
        return {};
    QString message = reasonMessage();
    if (r == Reason::NoValidIp || r == Reason::LowConfidence)
        message += QStringLiteral(" (text: \"%1\")").arg(m_text.right(80));
    return Error(r == Reason::InvalidInput ? Error::Kind::InvalidArgument : Error::Kind::Malformed,
                 message, static_cast<quint32>(r));
}

DecodeResult Decoder::result() const
{
    DecodeResult r;
    r.text = m_text;
    r.timeline = m_symbols.elements;
    r.chars = m_symbols.chars;
    r.ip = m_ip;
    r.unit = m_fit.valid ? m_fit.unit : 0.0;
    r.duty = m_fit.duty;
    r.fitQuality = m_fit.quality;
    r.reason = reason();
    r.confidentAt = m_confidentAt;
    return r;
}

Result<DecodeResult> decodeRecording(std::span<const Sample> samples, DecoderOptions options)
{
    Decoder decoder(options);
    decoder.feed(samples);
    decoder.finish();
    if (!decoder.ip().complete())
        return decoder.diagnosis();
    return decoder.result();
}

} // namespace db::morse
