#pragma once

#include "ipvoter.h"
#include "morsetypes.h"

#include <QString>

#include <array>

#include <utility>
#include <vector>

namespace db::morse {

// Sequence decoder for one stretch of Morse between word gaps, with the known grammar of the
// MovingCap message (movingcap.md section 2.2):
//
//     "MC+IP" octet "+" octet "+" octet "+" octet ":"     octet = 1-3 digits, value 0..255
//
// repeated: the manual gives no pause between repetitions, so the next message may follow ':'
// after a letter gap in the same stretch. The gap after ':' costs as a letter gap when it is
// longer (a pause of any length), as a too-short letter gap when it is shorter.
//
// Instead of deciding every mark (dit/dah) and every gap (element/letter gap) on its own and
// then looking the codes up, a dynamic programme over the marks finds the character sequence of
// the grammar whose nominal timing (ITU, section 2.4) explains all measured lengths best. Two
// kinds of error that hard decisions cannot undo are corrected this way: a letter gap read as
// an element gap (two characters merge into an unknown code) and the reverse (one character
// splits in two), and an element near the dit/dah boundary whose reading makes an invalid
// character or octet.
//
// Cost model: a measured length x (units, duty-corrected) of nominal k costs
// rho((x - k) / s_k) + ln s_k with s_k^2 = (relJitter k)^2 + absSigma^2 + e^2 (jitter is
// proportional to the length, frame quantisation is not; e is the length's own uncertainty from
// noise at its two edges, Element::edgeSigma) and rho the Huber function (quadratic up to 2
// sigma, linear beyond: noise makes heavier tails than the estimate).
struct ElementModel
{
    double relJitter = 0.15; // relative sigma of every length
    double absSigma = 0.15; // units: quantisation and edge noise
    double maxZ = 8.0; // a parse that needs an element this far from its nominal is rejected
};

struct StretchInput
{
    double start = 0.0; // s, start of the first mark (identifies the stretch while streaming)
    std::vector<double> marks; // units
    std::vector<double> gaps; // units; gaps[i] follows marks[i]; size() == marks.size() - 1
    // Uncertainty (units) of each length from noise at its edges (Element::edgeSigma); empty or
    // shorter than marks / gaps: 0.
    std::vector<double> markSigma;
    std::vector<double> gapSigma;
    bool openStart = false; // the recording began inside this stretch
    bool openEnd = false; // the stretch is still arriving
    bool firstComplete = false; // with openStart: the first mark begins a character
    std::vector<double> markTimes; // s, start of each mark (framecheck.h); may be empty
    double gapAfter = 0.0; // units of the word gap that closed the stretch; 0: none (long mark)
    double gapAfterSigma = 0.0;
    double markSigmaAt(std::size_t i) const { return i < markSigma.size() ? markSigma[i] : 0.0; }
    double gapSigmaAt(std::size_t i) const { return i < gapSigma.size() ? gapSigma[i] : 0.0; }
};

// How much of a stretch the grammar must explain.
enum class ParseMode {
    // Every mark, from "MC+IP" (or, with openStart, from the cut) to ':' (or, with openEnd,
    // to the last complete character).
    Strict,
    // Salvage for a stretch that Strict rejects (noise corrupted a character beyond one lost
    // element, or other text follows a message): the parse may skip whole characters at the
    // start and at the end at kSkipCost per mark, and leave a message unfinished to start
    // reading again at any later mark (kSkipCost more). Octets are still reported only where
    // their position in the message is anchored: counted from a prefix character ("IP" read)
    // or back from ':'.
    Salvage,
};

// Where an octet of a message was read: its `digits` digits are marks [firstMark,
// separatorMark), the separator ('+' or ':') begins at separatorMark. -1: not read whole.
struct OctetSpan
{
    long firstMark = -1;
    long separatorMark = -1;
    int digits = 0;
};
using OctetSpans = std::array<OctetSpan, 4>;

struct StretchParse
{
    bool ok = false; // the grammar explains the stretch within ElementModel::maxZ
    QString text; // decoded characters; '?' for a truncated first character or skipped marks
    // One per message read in this stretch, in order: its octets read completely (weights:
    // margins) and their soft costs. Never empty when ok.
    std::vector<IpObservation> observations;
    std::vector<OctetSpans> spans; // per observation
    double worstZ = 0.0;
    double cost = 0.0; // nats: how well the reading explains the lengths (less is better)
};

// Salvage: nats per skipped mark, about what a mark and its gap 2.5 sigma off their nominal
// cost, so that a character is skipped only when no reading of the grammar explains it.
constexpr double kSkipCost = 3.0;

// Splits a classified timeline (symbolize()) into stretches at word gaps and long marks. The
// first stretch is open at the start unless the recording began in a word gap; the last one is
// open at the end unless a word gap follows it, and then ends at its last complete character
// (the last gap of at least two units), because the character in progress may still grow.
std::vector<StretchInput> splitStretches(const std::vector<Element> &timeline);

// Robust estimate of the element model from a classified timeline: the relative spread of the
// marks and gaps around their nominal lengths, and the sample period in units.
ElementModel estimateModel(const std::vector<Element> &timeline, double samplePeriodUnits);

// Parses one stretch. Per message, octets whose digits were all seen get a weight margin / 4 nats,
// in [0.05, IpVoter::kMaxWeight], where margin is the least cost difference between a digit and its
// nearest rival reading (another digit or '+') on the same marks: small when an element was
// close to the dit/dah boundary. A digit repaired by a lost-element edit counts half. An octet
// whose position in the message is not anchored (read after a cut start, in a stretch that does
// not reach ':') is not reported.
StretchParse parseStretch(const StretchInput &in, const ElementModel &model,
                          ParseMode mode = ParseMode::Strict);

// `a` followed by `b` as one stretch, the word gap between them (a.gapAfter) read as an
// ordinary gap. A word gap never occurs inside a message; one that does is noise (a mark lost
// between two gaps, which then merge), so a closed stretch the grammar rejects is re-read
// joined with the next one. Requires a.gapAfter > 0.
StretchInput joinStretches(const StretchInput &a, const StretchInput &b);

} // namespace db::morse
