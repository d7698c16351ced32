#include "messageparser.h"

#include "charscorer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <unordered_map>

namespace db::morse {
namespace {

using namespace detail;

// A digit whose best rival reading costs this much more (nats) gets the full vote weight.
constexpr double kClearMargin = 4.0;
constexpr double kMinWeight = 0.05;
// Salvage: nats per skipped mark, about what a mark and its gap 2.5 sigma off their nominal
// cost, so that a character is skipped only when no reading of the grammar explains it.
constexpr double kSkipCost = 3.0;

// Grammar states: P(j) expects prefix character j of "MC+IP"; O(k, n, v) is inside octet k
// after n digits of value v; U(k) is inside octet k whose first digits were before the
// recording (value unknown, never reported); End follows ':'.
constexpr int kPrefix = 5;
constexpr int kOctetBase = kPrefix;
constexpr int kUnknownBase = kOctetBase + 4 * 4 * 256;
constexpr int kEnd = kUnknownBase + 4;
constexpr int kStates = kEnd + 1;

constexpr int octetState(int k, int n, int v)
{
    return kOctetBase + (k * 4 + n) * 256 + v;
}

// The state after character c from state s, or -1.
int next(int s, int c)
{
    if (s < kPrefix)
        return c == s ? (s + 1 < kPrefix ? s + 1 : octetState(0, 0, 0)) : -1;
    const bool digit = c >= kDigit0 && c < kDigit0 + 10;
    if (s >= kUnknownBase && s < kEnd) {
        const int k = s - kUnknownBase;
        if (digit)
            return s;
        if (c == kPlus && k < 3)
            return octetState(k + 1, 0, 0);
        return c == kColon && k == 3 ? kEnd : -1;
    }
    if (s == kEnd)
        return -1;
    const int rel = s - kOctetBase;
    const int k = rel / 1024;
    const int n = (rel / 256) % 4;
    const int v = rel % 256;
    if (digit) {
        const int w = v * 10 + (c - kDigit0);
        return n < 3 && w <= 255 ? octetState(k, n + 1, w) : -1;
    }
    if (c == kPlus && n >= 1 && k < 3)
        return octetState(k + 1, 0, 0);
    return c == kColon && n >= 1 && k == 3 ? kEnd : -1;
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
    return codeLength(c) + (edit == 2 ? 1 : 0) - (edit == 1 ? 1 : 0);
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
    std::array<Costs, 3> charCost { Costs(n), Costs(n), Costs(n) };
    // The readings that fit at all, per start mark: the DP visits only these.
    struct Option
    {
        int ch;
        int edit;
        double cost;
    };
    std::vector<std::vector<Option>> options(n);
    for (std::size_t i = 0; i < n; ++i) {
        for (int c = 0; c < int(kChars.size()); ++c) {
            for (int e = 0; e < 3; ++e) {
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
    std::vector<std::unordered_map<int, Cell>> layer(n + 1);
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
                layer[at][kUnknownBase + k + kStates] = skip;
        }
    } else {
        // The first character may be cut: it is read inside an unknown octet or as a prefix
        // character, or skipped up to the first letter gap. Either way the position inside an
        // octet is unknown, so the first octet read is never reported.
        std::size_t skipped = 0;
        while (!in.firstComplete && skipped < in.gaps.size() && in.gaps[skipped] < 2.0)
            ++skipped;
        skipped += in.firstComplete ? 0 : 1;
        for (std::size_t at : { std::size_t(0), skipped }) {
            for (int st = 0; at < n && st < kPrefix; ++st)
                layer[at][st] = {};
            for (int k = 0; at < n && k < 4; ++k)
                layer[at][kUnknownBase + k + kStates] = {};
        }
    }
    for (std::size_t i = 0; i < n; ++i) {
        for (const auto &[st, cell] : layer[i]) {
            for (const auto &[ch, edit, cc] : options[i]) {
                const bool unanchored = st >= kStates;
                int t = next(unanchored ? st - kStates : st, ch);
                if (t < 0)
                    continue;
                t += unanchored && t != kEnd ? kStates : 0;
                auto [it, fresh] = layer[i + consumed(ch, edit)].try_emplace(t);
                if (fresh || cell.cost + cc < it->second.cost)
                    it->second = { cell.cost + cc, st, ch, edit };
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
        const Cell step = layer[i].at(s);
        if (step.ch < 0)
            break;
        i -= consumed(step.ch, step.edit);
        path.push_back({ i, step.prevState, step.ch, step.edit });
        s = step.prevState;
    }
    std::reverse(path.begin(), path.end());
    if (path.empty())
        return out;

    if (i > 0)
        out.text += QLatin1Char('?');
    double margin = kInf;
    std::vector<double> digitWeights; // of the octet being read
    for (const Taken &t : path) {
        double z = 0.0;
        scorer.character(t.at, t.ch, t.edit, &z);
        out.worstZ = std::max(out.worstZ, z);
        out.text += QLatin1Char(kChars[static_cast<std::size_t>(t.ch)]);
        const bool digit = t.ch >= kDigit0 && t.ch < kColon;
        // Octet states whose k is anchored: by a prefix character, or back from ':'.
        const int from = t.from % kStates;
        const bool known =
            from >= kOctetBase && from < kUnknownBase && (t.from < kStates || best == kEnd);
        if (digit && known) {
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
            digitWeights.push_back(
                std::clamp(ownMargin / kClearMargin, kMinWeight, IpVoter::kMaxWeight));
        }
        if ((t.ch == kPlus || t.ch == kColon) && known) {
            const int rel = from - kOctetBase;
            const auto k = static_cast<std::size_t>(rel / 1024);
            out.observation.octets[k] = rel % 256;
            out.observation.weight[k] =
                std::clamp(margin / kClearMargin, kMinWeight, IpVoter::kMaxWeight);
            if (digitWeights.size() <= 3) {
                std::copy(digitWeights.begin(), digitWeights.end(),
                          out.observation.digitWeight[k].begin());
                out.observation.digits[k] = int(digitWeights.size());
            }
        }
        if (t.ch == kPlus || t.ch == kColon || !known) {
            margin = kInf;
            digitWeights.clear();
        }
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
    out.observation.complete = std::all_of(
        out.observation.octets.begin(), out.observation.octets.end(), [](int v) { return v >= 0; });
    out.ok = true;
    return out;
}

} // namespace db::morse
