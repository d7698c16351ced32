#pragma once

// The message grammar of the sequence decoder, shared by parseStretch() (messageparser.cpp) and
// the soft octet costs of its backward pass (messageparser_costs.cpp). Private to protocols/morse.

#include "charscorer.h"
#include "messageparser.h"

#include <array>
#include <cmath>
#include <map>
#include <unordered_map>
#include <vector>

namespace db::morse::grammar {

using namespace detail;

using namespace detail;

// A digit whose best rival reading costs this much more (nats) gets the full vote weight.
constexpr double kClearMargin = 4.0;
constexpr double kMinWeight = 0.05;
// Soft octet costs beyond this (nats) are not kept: the voter caps each reading lower.
constexpr double kSoftRange = 2.0 * IpVoter::kMaxWeight * IpVoter::kNatsPerWeight;
// Beam: a partial parse costlier by this much (nats) than the best one over the same marks is
// not followed. It lies above kSoftRange, the most the voter uses. With strong timing jitter the
// element model is wide and, without the beam, ~1300 octet states survived every mark (500 ms
// per corpus case instead of 110). It also drops contrived parses that become cheapest only at
// the end: a noisy "5+179+10+170" read as "089+110+100+070" (bench j30+6dB<3spu, seed 7).
constexpr double kBeam = 15.0;

// Grammar states: P(j) expects prefix character j of "MC+IP"; O(k, n, v) is inside octet k
// after n digits of value v; U(k, n, v) is inside octet k read from a cut start: the n < 3
// digits v seen since the first complete character may be the octet's tail, so its value is
// unknown, unless a third digit shows that they were all of it (then O(k, 3, v)); U(k, 3) is
// inside an octet cut in the middle of a character (any digits, never a value); End follows ':'.
constexpr int kPrefix = 5;
constexpr int kOctetBase = kPrefix;
constexpr int kUnknownBase = kOctetBase + 4 * 4 * 256;
constexpr int kEnd = kUnknownBase + 4 * 4 * 256;
// R(j): P(j) of a message read after a restart (Salvage), which may not end the parse before
// its first octet (see kRestartCost).
constexpr int kRestartBase = kEnd + 1;
constexpr int kStates = kRestartBase + kPrefix;
constexpr int kCutDigits = 3; // U(k, kCutDigits): digits after a cut inside a character

constexpr int octetState(int k, int n, int v)
{
    return kOctetBase + (k * 4 + n) * 256 + v;
}

constexpr int unknownState(int k, int n, int v)
{
    return kUnknownBase + (k * 4 + n) * 256 + v;
}

// The parts of O(k, n, v) or U(k, n, v) (one layout from either base; s of the anchored copy).
// Other states have k == -1.
struct OctetParts
{
    bool cut = false; // U
    int k = -1;
    int n = 0;
    int v = 0;
};

constexpr OctetParts partsOf(int s)
{
    if (s < kOctetBase || s >= kEnd)
        return {};
    const bool cut = s >= kUnknownBase;
    const int rel = s - (cut ? kUnknownBase : kOctetBase);
    return { cut, rel / 1024, rel / 256 % 4, rel % 256 };
}

// The state after character c from state s, or -1. After ':' the next message may follow in
// the same stretch (the pause between them read as a letter gap).
inline int next(int s, int c)
{
    if (s >= kRestartBase) {
        const int t = next(s - kRestartBase, c);
        return t >= 0 && t < kPrefix ? t + kRestartBase : t;
    }
    if (s == kEnd)
        s = 0;
    if (s < kPrefix)
        return c == s ? (s + 1 < kPrefix ? s + 1 : octetState(0, 0, 0)) : -1;
    const bool digit = c >= kDigit0 && c < kDigit0 + 10;
    const auto [cut, k, n, v] = partsOf(s);
    if (cut) {
        if (digit && n == kCutDigits)
            return s;
        if (digit) {
            const int w = v * 10 + (c - kDigit0);
            if (n < 2)
                return unknownState(k, n + 1, w);
            return w <= 255 ? octetState(k, 3, w) : -1; // three digits: a whole octet
        }
        if (c == kPlus && k < 3)
            return octetState(k + 1, 0, 0);
        return c == kColon && k == 3 ? kEnd : -1;
    }
    if (digit) {
        const int w = v * 10 + (c - kDigit0);
        return n < 3 && w <= 255 ? octetState(k, n + 1, w) : -1;
    }
    if (c == kPlus && n >= 1 && k < 3)
        return octetState(k + 1, 0, 0);
    return c == kColon && n >= 1 && k == 3 ? kEnd : -1;
}

// The drive sends octets in plain decimal ("MC+IP192+168+2+150:"), so a digit after a leading
// zero is an unlikely reading. It stays possible (a firmware that pads would still decode) at
// this cost in nats, which settles readings such as "020" against "120" or "20".
constexpr double kLeadingZeroCost = 3.0;

// Prior cost of character c in state s (either copy), beyond how well it fits the marks.
inline double prior(int s, int c)
{
    const OctetParts o = partsOf(s % kStates);
    if (o.k < 0 || c < kDigit0 || c >= kDigit0 + 10)
        return 0.0;
    if (o.cut) // after a cut, "05" may be the tail of 105; only a third digit shows the zero
        return o.n == 2 && o.v < 10 ? kLeadingZeroCost : 0.0;
    return o.n >= 1 && o.v == 0 ? kLeadingZeroCost : 0.0;
}

// next() for a state of either copy: from kStates up, the states reached from a cut start
// without an anchor; their successors stay unanchored until ':' anchors them.
inline int step(int st, int c)
{
    const bool unanchored = st >= kStates;
    const int t = next(unanchored ? st - kStates : st, c);
    return t < 0 || !unanchored || t == kEnd ? t : t + kStates;
}

struct Cell
{
    double cost = 0.0;
    int prevState = -1; // a start: the state of the message left at `from` (restart), or -1
    int ch = -1; // -1: a start state
    int edit = 0; // Scorer::character()
    std::size_t from = 0; // a restart: the mark at which the message before was left
};

// Salvage: nats to leave a message unfinished and start reading the next one at a later mark
// (the marks between cost kSkipCost each), so that a message is given up only where no
// reading of the grammar explains its damaged part.
// - The next reading starts with "MC+IP" (state R(0)): its octets are counted from the prefix,
//   and the two parts of one message (say, with an octet too few) cannot be read as the start
//   and the end of two. A shorter anchor is not enough: restarting at 'P', noise that made
//   "+96+191" look like "P96+191" read 96 as the first octet (bench drift + 6 dB, seed 7).
// - A message may be left only after its prefix (canLeave()), and one read after a restart
//   may not end the parse inside its prefix (the R states), nor set the beam: otherwise stray
//   marks read as "MC+" cost less than skipped, and the beam dropped better readings for them.
constexpr double kRestartCost = 2.0 * kSkipCost;

inline bool canLeave(int st)
{
    return st == kEnd || partsOf(st % kStates).k >= 0;
}

inline bool isRestartPrefix(int st)
{
    return st >= kRestartBase && st < kStates;
}

// The states the reading of a stretch may start in at any mark (Salvage): a prefix character,
// or digits cut inside an octet whose position is unknown until ':' anchors it.
inline constexpr auto kStarts = [] {
    std::array<int, kPrefix + 4> s {};
    for (int j = 0; j < kPrefix; ++j)
        s[std::size_t(j)] = j;
    for (int k = 0; k < 4; ++k)
        s[std::size_t(kPrefix + k)] = unknownState(k, kCutDigits, 0) + kStates;
    return s;
}();

// Measured marks that character c takes with the given edit.
inline std::size_t consumed(int c, int edit)
{
    return codeLength(c) + (edit == 2 ? 1 : 0) - (edit == 1 || edit == 3 ? 1 : 0);
}

struct Option
{
    int ch;
    int edit;
    double cost;
};
using Layers = std::vector<std::unordered_map<int, Cell>>;
using OctetCosts = std::array<std::map<int, double>, 4>;
// Per message of the best parse and octet k: the mark at which that parse closed octet k (or,
// for the octet still arriving, the end of the stretch); -1 where it did not read octet k.
using Closings = std::vector<std::array<long, 4>>;

// The message of the best parse that a closing of octet k at mark i belongs to (see the .cpp).
int messageAt(const Closings &closings, std::size_t k, std::size_t i);
std::vector<OctetCosts> octetCosts(const Layers &layer,
                                   const std::vector<std::vector<Option>> &options, bool openEnd,
                                   bool salvage, double bestCost, const Closings &closings);
std::map<int, double> openOctetCosts(const std::unordered_map<int, Cell> &endLayer, int open,
                                     double bestCost);

} // namespace db::morse::grammar
