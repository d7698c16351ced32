#include "messageparser.h"

#include "charscorer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <unordered_map>

namespace db::morse {
namespace {

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
constexpr int kStates = kEnd + 1;
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

// The state after character c from state s, or -1.
int next(int s, int c)
{
    if (s < kPrefix)
        return c == s ? (s + 1 < kPrefix ? s + 1 : octetState(0, 0, 0)) : -1;
    const bool digit = c >= kDigit0 && c < kDigit0 + 10;
    if (s == kEnd)
        return -1;
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
double prior(int s, int c)
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
int step(int st, int c)
{
    const bool unanchored = st >= kStates;
    const int t = next(unanchored ? st - kStates : st, c);
    return t < 0 || !unanchored || t == kEnd ? t : t + kStates;
}

struct Cell
{
    double cost = 0.0;
    int prevState = -1;
    int ch = -1; // -1: a start state
    int edit = 0; // Scorer::character()
};

// Measured marks that character c takes with the given edit.
std::size_t consumed(int c, int edit)
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

// Soft evidence per octet (IpObservation::cost): for every octet k and value v, the cheapest
// parse of the whole stretch in which octet k is closed with value v, minus the cheapest parse
// overall. Forward costs are the DP's layers; a backward pass over the same (sparse) states
// gives the cheapest completion. An octet whose position is a guess (reached from a cut start)
// counts only on completions that reach ':', which anchor it.
std::array<std::map<int, double>, 4> octetCosts(const Layers &layer,
                                                const std::vector<std::vector<Option>> &options,
                                                bool openEnd, bool salvage, double bestCost)
{
    const std::size_t n = layer.size() - 1;
    std::vector<std::unordered_map<int, double>> back(n + 1); // any accepted end
    std::vector<std::unordered_map<int, double>> backEnd(n + 1); // ends after ':'
    for (std::size_t i = n + 1; i-- > 0;) {
        for (const auto &entry : layer[i]) {
            const int st = entry.first;
            double b = kInf;
            double be = kInf;
            if (salvage ? i >= 1 : i == n) {
                const double skip = kSkipCost * double(n - i);
                b = (openEnd || salvage || st == kEnd) ? skip : kInf;
                be = st == kEnd ? skip : kInf;
            }
            for (std::size_t o = 0; i < n && o < options[i].size(); ++o) {
                const Option &op = options[i][o];
                const int t = step(st, op.ch);
                if (t < 0)
                    continue;
                const std::size_t j = i + consumed(op.ch, op.edit);
                const auto it = back[j].find(t);
                if (it == back[j].end())
                    continue;
                const double cc = op.cost + prior(st, op.ch);
                b = std::min(b, cc + it->second);
                be = std::min(be, cc + backEnd[j].at(t));
            }
            back[i][st] = b;
            backEnd[i][st] = be;
        }
    }
    std::array<std::map<int, double>, 4> out;
    // Octets read from a cut start: per octet the cheapest parse that closes it after digits
    // cut in a character (consistent with every value), and per tail (digits, value) the
    // cheapest that closes it after those digits.
    std::array<double, 4> anyValue { kInf, kInf, kInf, kInf };
    std::array<std::map<std::pair<int, int>, double>, 4> tails;
    for (std::size_t i = 0; i < n; ++i) {
        for (const auto &[st, cell] : layer[i]) {
            const bool unanchored = st >= kStates;
            const auto [cut, k, digits, v] = partsOf(unanchored ? st - kStates : st);
            if (k < 0 || digits == 0)
                continue; // not inside an octet with at least one digit
            for (const Option &op : options[i]) {
                const int t = op.ch == kPlus || op.ch == kColon ? step(st, op.ch) : -1;
                if (t < 0)
                    continue;
                const std::size_t j = i + consumed(op.ch, op.edit);
                const auto &table = unanchored ? backEnd : back;
                const auto it = table[j].find(t);
                if (it == table[j].end() || it->second == kInf)
                    continue;
                const double delta = cell.cost + op.cost + it->second - bestCost;
                const auto ku = std::size_t(k);
                if (cut && digits == kCutDigits) {
                    anyValue[ku] = std::min(anyValue[ku], delta);
                    continue;
                }
                double &slot = cut ? tails[ku].try_emplace({ digits, v }, kInf).first->second
                                   : out[ku].try_emplace(v, kInf).first->second;
                slot = std::min(slot, delta);
            }
        }
    }
    // An octet's tail of d digits t fits the values that end in t and have at least d digits
    // ("05" fits 105 and 205, "93" fits 93 and 193).
    for (std::size_t k = 0; k < 4; ++k) {
        if (tails[k].empty())
            continue;
        for (int w = 0; w <= 255; ++w) {
            double cost = anyValue[k];
            for (const auto &[tail, delta] : tails[k]) {
                const int scale = tail.first == 1 ? 10 : 100;
                if (w % scale == tail.second && (w >= scale / 10 || tail.first == 1))
                    cost = std::min(cost, delta);
            }
            if (cost < kInf) {
                const auto [pos, fresh] = out[k].try_emplace(w, cost);
                if (!fresh)
                    pos->second = std::min(pos->second, cost);
            }
        }
    }
    return out;
}

} // namespace

StretchParse parseStretch(const StretchInput &in, const ElementModel &model, ParseMode mode)
{
    StretchParse out;
    const std::size_t n = in.marks.size();
    if (n == 0 || in.gaps.size() + 1 != n)
        return out;
    const Scorer scorer(in, model);

    // Character costs per start mark, as sent and with one element lost.
    using Costs = std::vector<std::array<double, kChars.size()>>;
    std::array<Costs, kEdits> charCost { Costs(n), Costs(n), Costs(n), Costs(n) };
    // The readings that fit at all, per start mark: the DP visits only these.
    std::vector<std::vector<Option>> options(n);
    for (std::size_t i = 0; i < n; ++i) {
        for (int c = 0; c < int(kChars.size()); ++c) {
            for (int e = 0; e < kEdits; ++e) {
                const double cost = scorer.character(i, c, e, nullptr);
                charCost[std::size_t(e)][i][std::size_t(c)] = cost;
                if (cost < kInf)
                    options[i].push_back({ c, e, cost });
            }
        }
    }

    // layer[i]: state -> best cost with marks [0, i) consumed, and how it was reached. Sparse:
    // of the ~4100 states only the few hundred consistent with the marks are ever reached.
    // States from kStates up are the same states without an anchor: reached from a cut start
    // inside an octet (U(k)), so that k is a guess until ':' confirms it.
    Layers layer(n + 1);
    const bool salvage = mode == ParseMode::Salvage;
    if (!in.openStart && !salvage) {
        layer[0][0] = {};
    } else if (salvage) {
        // Any mark may start the reading (the hard letter gaps may be the damage); the marks
        // before it are skipped.
        for (std::size_t at = 0; at < n; ++at) {
            const Cell skip { kSkipCost * double(at), -1, -1, 0 };
            for (int st = 0; st < kPrefix; ++st)
                layer[at][st] = skip;
            for (int k = 0; k < 4; ++k)
                layer[at][unknownState(k, kCutDigits, 0) + kStates] = skip;
        }
    } else {
        // The first character may be cut: it is read inside an unknown octet or as a prefix
        // character, or skipped up to the first letter gap. Either way the position inside an
        // octet is unknown, and so is the first octet's value: the digits read may be its tail.
        // Only three digits from the first complete character are certainly all of it.
        std::size_t skipped = 0;
        while (!in.firstComplete && skipped < in.gaps.size() && in.gaps[skipped] < 2.0)
            ++skipped;
        skipped += in.firstComplete ? 0 : 1;
        for (std::size_t at : { std::size_t(0), skipped }) {
            const int digits = at == skipped ? 0 : kCutDigits;
            for (int st = 0; at < n && st < kPrefix; ++st)
                layer[at][st] = {};
            for (int k = 0; at < n && k < 4; ++k)
                layer[at][unknownState(k, digits, 0) + kStates] = {};
        }
    }
    for (std::size_t i = 0; i < n; ++i) {
        // Beam: states far costlier than the best one on the same marks are dropped. Start
        // states (salvage, cut start) stay, so that a reading may still begin there.
        double least = kInf;
        for (const auto &entry : layer[i])
            least = std::min(least, entry.second.cost);
        std::erase_if(layer[i], [least](const auto &entry) {
            return entry.second.ch >= 0 && entry.second.cost > least + kBeam;
        });
        for (const auto &[st, cell] : layer[i]) {
            for (const auto &[ch, edit, cc] : options[i]) {
                if (edit == 3 && cell.ch < 0)
                    continue; // a start: no letter gap before it was charged
                const int t = step(st, ch);
                if (t < 0)
                    continue;
                auto [it, fresh] = layer[i + consumed(ch, edit)].try_emplace(t);
                const double cost = cc + prior(st, ch);
                if (fresh || cell.cost + cost < it->second.cost)
                    it->second = { cell.cost + cost, st, ch, edit };
            }
        }
    }

    int best = -1;
    double bestCost = kInf;
    std::size_t end = n;
    for (std::size_t at = salvage ? 1 : n; at <= n; ++at) {
        const double skip = kSkipCost * double(n - at); // salvage: the marks after `at`
        for (const auto &[st, cell] : layer[at]) {
            if ((in.openEnd || salvage || st == kEnd) && cell.ch >= 0
                && cell.cost + skip < bestCost) {
                bestCost = cell.cost + skip;
                best = st;
                end = at;
            }
        }
    }
    if (best < 0)
        return out;

    // Backtrace: characters with their start marks and states.
    struct Taken
    {
        std::size_t at;
        int from;
        int ch;
        int edit;
    };
    std::vector<Taken> path;
    std::size_t i = end;
    int s = best;
    while (true) {
        const Cell back = layer[i].at(s);
        if (back.ch < 0)
            break;
        i -= consumed(back.ch, back.edit);
        path.push_back({ i, back.prevState, back.ch, back.edit });
        s = back.prevState;
    }
    std::reverse(path.begin(), path.end());
    if (path.empty())
        return out;

    out.cost = bestCost;
    if (i > 0)
        out.text += QLatin1Char('?');
    double margin = kInf;
    int tailOctet = -1; // the octet closed after a cut start with only its last digits read
    for (const Taken &t : path) {
        double z = 0.0;
        scorer.character(t.at, t.ch, t.edit, &z);
        out.worstZ = std::max(out.worstZ, z);
        out.text += QLatin1Char(kChars[static_cast<std::size_t>(t.ch)]);
        const bool digit = t.ch >= kDigit0 && t.ch < kColon;
        // Octet states whose k is anchored: by a prefix character, or back from ':'.
        const OctetParts from = partsOf(t.from % kStates);
        const bool known = from.k >= 0 && !from.cut && (t.from < kStates || best == kEnd);
        // Digits after a cut count towards the margin: a third one makes them an octet.
        const bool tail = from.cut && from.n < kCutDigits && best == kEnd;
        if (digit && (known || tail)) {
            // Margin against the cheapest other reading of the same marks.
            const Costs &costs = charCost[std::size_t(t.edit)];
            const double own = costs[t.at][static_cast<std::size_t>(t.ch)];
            double ownMargin = kInf;
            for (int c = kPlus; c < kColon; ++c) {
                if (c != t.ch && (c == kPlus || c >= kDigit0))
                    ownMargin = std::min(ownMargin, costs[t.at][std::size_t(c)] - own);
            }
            if (t.edit != 0) // a repaired digit: half a vote
                ownMargin = std::min(ownMargin, kClearMargin / 2.0);
            margin = std::min(margin, ownMargin);
        }
        if ((t.ch == kPlus || t.ch == kColon) && tail && from.n > 0)
            tailOctet = from.k;
        if ((t.ch == kPlus || t.ch == kColon) && known) {
            const auto k = static_cast<std::size_t>(from.k);
            out.observation.octets[k] = from.v;
            out.observation.weight[k] =
                std::clamp(margin / kClearMargin, kMinWeight, IpVoter::kMaxWeight);
        }
        if (t.ch == kPlus || t.ch == kColon || !(known || tail))
            margin = kInf;
    }
    if (end < n)
        out.text += QLatin1Char('?');
    // A salvaged reading counts only with at least two octets, so that status text such as
    // "ERR+5:" (movingcap.md 2.2: the LED sends other text too) is never read as an address
    // (and keeps its character-by-character text).
    const auto read = std::count_if(out.observation.octets.begin(), out.observation.octets.end(),
                                    [](int v) { return v >= 0; });
    if (salvage && read < 2)
        return {};
    // The octet still arriving at the end of an open stretch: its digits so far are a prefix of
    // its value ("20" fits 20 and 200-209). Each end state inside that octet gives a prefix.
    std::map<int, double> prefix;
    int open = -1;
    const OctetParts last = partsOf(best); // k < 0 for the unanchored copy
    if (in.openEnd && !salvage && last.k >= 0 && !last.cut && last.n >= 1) {
        open = last.k;
        for (const auto &[st, cell] : layer[end]) {
            const auto [cut, k, digits, value] = partsOf(st);
            if (k != open || cut || digits == 0)
                continue;
            if (digits > 1 && value < (digits == 2 ? 10 : 100))
                continue; // a leading zero: no plain decimal value starts so
            for (int w = 0; w <= 255; ++w) {
                const int length = w >= 100 ? 3 : (w >= 10 ? 2 : 1);
                if (length >= digits
                    && w / (length - digits == 2 ? 100 : (length - digits == 1 ? 10 : 1))
                        == value) {
                    const auto [it, fresh] = prefix.try_emplace(w, cell.cost - bestCost);
                    it->second = std::min(it->second, cell.cost - bestCost);
                }
            }
        }
    }
    const bool anyOctet = open >= 0 || tailOctet >= 0
        || std::any_of(out.observation.octets.begin(), out.observation.octets.end(),
                       [](int v) { return v >= 0; });
    const auto soft = anyOctet ? octetCosts(layer, options, in.openEnd, salvage, bestCost)
                               : std::array<std::map<int, double>, 4> {};
    for (std::size_t k = 0; k < 4; ++k) {
        const bool isOpen = int(k) == open;
        const bool isTail = int(k) == tailOctet;
        if (out.observation.octets[k] < 0 && !isOpen && !isTail)
            continue;
        for (const auto &[value, nats] : soft[k]) {
            if (nats < kSoftRange)
                out.observation.cost[k][value] = std::max(0.0, nats);
        }
        if (isTail)
            continue; // costs only: the values that end in the digits read cost least
        if (!isOpen) {
            out.observation.cost[k][out.observation.octets[k]] = 0.0;
            continue;
        }
        for (const auto &[value, nats] : prefix) {
            const auto [it, fresh] = out.observation.cost[k].try_emplace(value, nats);
            it->second = std::max(0.0, std::min(it->second, nats));
        }
    }
    out.observation.complete = std::all_of(
        out.observation.octets.begin(), out.observation.octets.end(), [](int v) { return v >= 0; });
    out.ok = true;
    return out;
}

} // namespace db::morse
