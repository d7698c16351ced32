#pragma once

#include "core/result.h"
#include "ipvoter.h"
#include "levelslicer.h"
#include "messageparser.h"
#include "morsetypes.h"
#include "symbolizer.h"
#include "unitfit.h"

#include <QString>

#include <limits>
#include <map>
#include <span>
#include <tuple>
#include <vector>

namespace db::morse {

struct DecoderOptions
{
    UnitRange unitRange; // plausible dit lengths, seconds
    double minFitQuality = 0.6; // below: the blinking is not Morse
    double confident = IpVoter::kConfident;
    // Re-read each octet on the samples (framecheck.h). Off: the readings of the lengths alone
    // (for comparison in tests and benchmarks).
    bool checkFrames = true;
};

// A gap between two samples longer than this ends one recording and starts the next (a camera
// that stopped delivering frames, two recordings in one file): far longer than any Morse element
// (a word gap is 3.5 s at the slowest unit), and the levels, the sample period and the unit of
// the part before say nothing about the part after. Each part is read on its own; the readings
// of all parts vote for the IP.
constexpr double kMaxSampleGap = 10.0; // s

// Where the recording was cut (Decoder::gaps()).
struct SampleGap
{
    double after = 0.0; // time of the last sample before the gap, s
    double length = 0.0; // s
    std::size_t samples = 0; // samples fed before the gap (the gap follows sample number this)
};

enum class DecoderState {
    Searching, // no modulation found yet
    Acquiring, // LED found, not enough edges for the unit yet
    Decoding, // unit known, text growing, no confident IP yet
    Confident, // an IP address with confidence >= DecoderOptions::confident
    Idle, // LED was found, but has not changed for a while
};

struct DecoderEvent
{
    enum class Kind {
        LedFound, // two brightness levels found
        LedLost, // no edge for several seconds
        UnitFound, // first valid unit estimate (detail: "120.3 ms")
        MessageDecoded, // a complete "MC+IP...:" message (detail: its IP)
        IpConfident, // the voted IP reached the confidence threshold (detail: the IP)
    };
    Kind kind;
    double time = 0.0; // time of the last sample when the event was noticed
    QString detail;
};

struct DecodeResult
{
    QString text;
    std::vector<Element> timeline;
    std::vector<DecodedChar> chars;
    IpEstimate ip;
    double unit = 0.0; // s
    double duty = 0.0; // s added to marks
    double fitQuality = 0.0;
    Reason reason = Reason::None;
    double confidentAt = -1.0; // sample time at which the IP first became confident
};

// Streaming LED Morse decoder: samples -> LevelSlicer -> intervals -> fitUnit -> symbolize ->
// splitStretches -> parseStretch (one observation per message) -> checkFrames (the octets a
// reading is unsure of, on the samples: framecheck.h) -> IpVoter. feed() may be
// called with chunks of any size; after each call the text, timeline and IP reflect
// everything seen so far (the unit is re-estimated as data grows, so earlier characters can
// still change). Pure and synchronous; no Qt event loop.
class Decoder
{
public:
    explicit Decoder(DecoderOptions options = {});

    void feed(std::span<const Sample> samples);
    void feed(const Sample &sample) { feed(std::span<const Sample>(&sample, 1)); }
    // End of recording: the character in progress is completed.
    void finish();

    DecoderState state() const;
    // Decoded text: stretches between word gaps joined by ' '; a stretch that fits the message
    // grammar is shown as the sequence decoder read it, others character by character.
    const QString &text() const { return m_text; }
    // The character-by-character reading (one DecodedChar per code in chars()).
    const QString &rawText() const { return m_symbols.text; }
    const QString &pendingCode() const { return m_symbols.pendingCode; }
    const std::vector<Element> &timeline() const { return m_symbols.elements; }
    const std::vector<DecodedChar> &chars() const { return m_symbols.chars; }
    const IpEstimate &ip() const { return m_ip; }
    const UnitFit &unitFit() const { return m_fit; }
    const LevelSlicer &slicer() const { return m_slicer; }
    bool confident() const { return m_ip.confidence >= m_options.confident; }

    // Events since the last call, oldest first.
    std::vector<DecoderEvent> takeEvents();

    // Where the recording was cut at gaps longer than kMaxSampleGap (the first kMaxGapsKept),
    // and how many there were in all.
    const std::vector<SampleGap> &gaps() const { return m_gaps; }
    std::size_t gapCount() const { return m_gapCount; }
    // The cuts for the user ("the recording has a 1e+09 s gap in time after sample 36 (at
    // 3.60 s): read as 2 recordings"); empty without a cut.
    QString gapNote() const;

    // Why there is no confident IP (Reason::None when there is one). With a recording cut at
    // gaps: the reason of the part that came farthest.
    Reason reason() const;
    // reasonText(reason()), with the octets voted so far when no valid message was read
    // ("...; octets read so far: ?.?.7.42"), and gapNote() where the recording was cut.
    QString reasonMessage() const;
    // The reason as an Error (deviceCode = int(Reason)); Kind::None when confident.
    Error diagnosis() const;
    DecodeResult result() const;

    static constexpr std::size_t kMaxGapsKept = 3;

private:
    void update(bool final);
    // Completes the part before a gap and starts the next one from scratch; its readings,
    // text and reason are kept for the whole recording.
    void endPart(double gapLength);
    Reason partReason() const;
    void event(DecoderEvent::Kind kind, QString detail = {});
    StretchParse cachedParse(const StretchInput &stretch, ParseMode mode);
    // Re-reads each octet of the parse on the samples (framecheck.h): the value read and its
    // closest rivals, scored against every sample of the octet's region.
    void checkFrames(StretchParse &parse, const StretchInput &stretch) const;

    DecoderOptions m_options;
    LevelSlicer m_slicer;
    std::vector<Sample> m_samples; // the valid samples of the last kKeepSamples seconds
    // checkFrames(): log-likelihoods by region (from, to in microseconds) and text. An octet of
    // a stretch still arriving is checked once, not at every update; cleared with the model.
    mutable std::map<std::tuple<long long, long long, QString>, double> m_frameCache;
    UnitFit m_fit;
    Symbols m_symbols;
    QString m_text;
    IpEstimate m_ip;
    std::vector<DecoderEvent> m_events;
    std::size_t m_fittedAt = 0;
    std::size_t m_symbolizedKey = 0;
    double m_symbolizedUnit = 0.0;
    int m_completeSeen = 0;
    bool m_wasFound = false;
    bool m_wasIdle = false;
    bool m_closedMessage = false;
    double m_confidentAt = -1.0;
    std::map<std::tuple<double, std::size_t, bool, ParseMode>, StretchParse> m_cache; // by stretch
    ElementModel m_model;
    double m_modelUnit = 0.0;
    double m_modelDuty = 0.0;
    // The readings of the current part (at its last update), and those of the parts before the
    // last gap with their text and the farthest reason.
    std::vector<IpObservation> m_partReadings;
    std::vector<IpObservation> m_doneReadings;
    QString m_doneText;
    int m_doneComplete = 0;
    Reason m_doneReason = Reason::InvalidInput;
    std::vector<SampleGap> m_gaps;
    std::size_t m_gapCount = 0;
    std::size_t m_fed = 0;
    double m_lastTime = -std::numeric_limits<double>::infinity(); // of the last finite sample
};

// One-shot: the whole recording. An error (with the Reason in deviceCode) when no IP address
// could be voted at all; a result with ip.confidence below the threshold and
// reason == LowConfidence when the repetitions do not agree enough.
Result<DecodeResult> decodeRecording(std::span<const Sample> samples, DecoderOptions options = {});

} // namespace db::morse
