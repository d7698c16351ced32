#include "decoder.h"

#include <QLoggingCategory>
#include <QStringList>

#include <algorithm>

Q_LOGGING_CATEGORY(lcMorse, "drivebench.morse", QtInfoMsg)

namespace db::morse {
namespace {

constexpr std::size_t kFitWindow = 400; // intervals used for the unit estimate
constexpr std::size_t kMinIntervals = 12; // before that, no unit estimate is tried
constexpr std::size_t kRefitEvery = 24; // new intervals between estimates
constexpr int kLongTextChars = 40; // this much text without ':' is not "too short"

} // namespace

QString reasonText(Reason reason)
{
    switch (reason) {
    case Reason::None:
        return QStringLiteral("IP address decoded");
    case Reason::InvalidInput:
        return QStringLiteral("no usable samples (empty, not finite or time not increasing)");
    case Reason::NoModulation:
        return QStringLiteral("no modulation: the brightness never shows two distinct levels "
                              "(LED not in view, covered or not blinking)");
    case Reason::NotMorse:
        return QStringLiteral("the LED blinks, but not with Morse timing of 40-500 ms per unit");
    case Reason::TooShort:
        return QStringLiteral("recording too short: not one complete message yet");
    case Reason::NoValidIp:
        return QStringLiteral("Morse text without a valid \"MC+IPa+b+c+d:\" message");
    case Reason::LowConfidence:
        return QStringLiteral("IP address seen, but the repetitions do not agree enough yet");
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
    for (const Sample &s : samples)
        m_slicer.feed(s);
    update(false);
}

void Decoder::finish()
{
    update(true);
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

    IpVoter voter;
    int complete = 0;
    for (const IpObservation &obs : parseIpObservations(m_symbols.text)) {
        voter.add(obs);
        if (obs.complete && ++complete > m_completeSeen) {
            IpEstimate one;
            one.octets = obs.octets;
            event(DecoderEvent::Kind::MessageDecoded, one.toString());
        }
    }
    m_completeSeen = std::max(m_completeSeen, complete);
    m_ip = voter.observations() > 0 ? voter.estimate() : IpEstimate {};

    const qsizetype colon = m_symbols.text.indexOf(QLatin1Char(':'));
    m_closedMessage = colon >= 0 && m_symbols.text.indexOf(QLatin1Char(':'), colon + 1) >= 0;

    if (confident() && m_confidentAt < 0.0) {
        m_confidentAt = m_slicer.lastTime();
        event(DecoderEvent::Kind::IpConfident, m_ip.toString());
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
    if (messageSeen || m_symbols.text.size() >= kLongTextChars)
        return Reason::NoValidIp;
    return Reason::TooShort;
}

Error Decoder::diagnosis() const
{
    const Reason r = reason();
    if (r == Reason::None)
        return {};
    QString message = reasonText(r);
    if (r == Reason::NoValidIp || r == Reason::LowConfidence)
        message += QStringLiteral(" (text: \"%1\")").arg(m_symbols.text.right(80));
    return Error(r == Reason::InvalidInput ? Error::Kind::InvalidArgument : Error::Kind::Malformed,
                 message, static_cast<quint32>(r));
}

DecodeResult Decoder::result() const
{
    DecodeResult r;
    r.text = m_symbols.text;
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
