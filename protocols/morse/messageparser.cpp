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
int next(int s, int c)
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

bool canLeave(int st)
{
    return st == kEnd || partsOf(st % kStates).k >= 0;
}

bool isRestartPrefix(int st)
{
    return st >= kRestartBase && st < kStates;
}

// The states the reading of a stretch may start in at any mark (Salvage): a prefix character,
// or digits cut inside an octet whose position is unknown until ':' anchors it.
constexpr auto kStarts = [] {
    std::array<int, kPrefix + 4> s {};
    for (int j = 0; j < kPrefix; ++j)
        s[std::size_t(j)] = j;
    for (int k = 0; k < 4; ++k)
        s[std::size_t(kPrefix + k)] = unknownState(k, kCutDigits, 0) + kStates;
    return s;
}();

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
using OctetCosts = std::array<std::map<int, double>, 4>;
// Per message of the best parse and octet k: the mark at which that parse closed octet k (or,
// for the octet still arriving, the end of the stretch); -1 where it did not read octet k.
using Closings = std::vector<std::array<long, 4>>;

// The message of the best parse that a closing of octet k at mark i belongs to: the one whose
// own closing of octet k is nearest (another parse may place it a few marks apart). -1: none.
int messageAt(const Closings &closings, std::size_t k, std::size_t i)
{
    int best = -1;
    long distance = 0;
    for (std::size_t m = 0; m < closings.size(); ++m) {
        const long at = closings[m][k];
        const long d = std::abs(at - long(i));
        if (at >= 0 && (best < 0 || d < distance)) {
            best = int(m);
            distance = d;
        }
    }
    return best;
}

// Soft evidence per message and octet (IpObservation::cost): for every octet k and value v, the
// cheapest parse of the whole stretch in which octet k is closed with value v, minus the
// cheapest parse overall. Forward costs are the DP's layers; a backward pass over the same
// (sparse) states gives the cheapest completion. An octet whose position is a guess (reached
// from a cut start) counts only on completions in which ':' anchors it.
std::vector<OctetCosts> octetCosts(const Layers &layer,
                                   const std::vector<std::vector<Option>> &options, bool openEnd,
                                   bool salvage, double bestCost, const Closings &closings)
{
    const std::size_t n = layer.size() - 1;
    std::vector<std::unordered_map<int, double>> back(n + 1); // any accepted end
    // For unanchored states: completions through ':' (anchored states: as `back`).
    std::vector<std::unordered_map<int, double>> backEnd(n + 1);
    double restart = kInf; // Salvage: the cheapest completion from a restart at or after i
    for (std::size_t i = n + 1; i-- > 0;) {
        if (i < n)
            restart += kSkipCost;
        for (const auto &entry : layer[i]) {
            const int st = entry.first;
            const bool unanchored = st >= kStates;
            double b = kInf;
            double be = kInf;
            if (salvage ? i >= 1 : i == n)
                b = (openEnd || salvage || st == kEnd) && !isRestartPrefix(st)
                    ? kSkipCost * double(n - i)
                    : kInf;
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
                if (unanchored)
                    be = std::min(be, cc + backEnd[j].at(t));
            }
            back[i][st] = b;
            backEnd[i][st] = be;
        }
        if (salvage) {
            const auto it = back[i].find(kRestartBase);
            if (it != back[i].end())
                restart = std::min(restart, it->second);
            for (auto &[st, b] : back[i]) {
                if (canLeave(st))
                    b = std::min(b, kRestartCost + restart);
            }
        }
        for (const auto &[st, b] : back[i]) {
            if (st < kStates)
                backEnd[i][st] = b;
        }
    }
    std::vector<OctetCosts> out(closings.size());
    // Octets read from a cut start: per message and octet the cheapest parse that closes it
    // after digits cut in a character (consistent with every value), and per tail (digits,
    // value) the cheapest that closes it after those digits.
    std::vector<std::array<double, 4>> anyValue(closings.size(), { kInf, kInf, kInf, kInf });
    std::vector<std::array<std::map<std::pair<int, int>, double>, 4>> tails(closings.size());
    for (std::size_t i = 0; i < n; ++i) {
        for (const auto &[st, cell] : layer[i]) {
            const bool unanchored = st >= kStates;
            const auto [cut, k, digits, v] = partsOf(unanchored ? st - kStates : st);
            if (k < 0 || digits == 0)
                continue; // not inside an octet with at least one digit
            const auto ku = std::size_t(k);
            const int m = messageAt(closings, ku, i);
            if (m < 0)
                continue;
            const auto mu = std::size_t(m);
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
                if (cut && digits == kCutDigits) {
                    anyValue[mu][ku] = std::min(anyValue[mu][ku], delta);
                    continue;
                }
                double &slot = cut ? tails[mu][ku].try_emplace({ digits, v }, kInf).first->second
                                   : out[mu][ku].try_emplace(v, kInf).first->second;
                slot = std::min(slot, delta);
            }
        }
    }
    // An octet's tail of d digits t fits the values that end in t and have at least d digits
    // ("05" fits 105 and 205, "93" fits 93 and 193).
    for (std::size_t m = 0; m < closings.size(); ++m) {
        for (std::size_t k = 0; k < 4; ++k) {
            if (tails[m][k].empty())
                continue;
            for (int w = 0; w <= 255; ++w) {
                double cost = anyValue[m][k];
                for (const auto &[tail, delta] : tails[m][k]) {
                    const int scale = tail.first == 1 ? 10 : 100;
                    if (w % scale == tail.second && (w >= scale / 10 || tail.first == 1))
                        cost = std::min(cost, delta);
                }
                if (cost < kInf) {
                    const auto [pos, fresh] = out[m][k].try_emplace(w, cost);
                    if (!fresh)
                        pos->second = std::min(pos->second, cost);
                }
            }
        }
    }
    return out;
}

// The octet still arriving at the end of an open stretch: its digits so far are a prefix of
// its value ("20" fits 20 and 200-209). Each end state inside octet k gives such a prefix.
std::map<int, double> openOctetCosts(const std::unordered_map<int, Cell> &endLayer, int open,
                                     double bestCost)
{
    std::map<int, double> prefix;
    for (const auto &[st, cell] : endLayer) {
        const auto [cut, k, digits, value] = partsOf(st);
        if (k != open || cut || digits == 0)
            continue;
        if (digits > 1 && value < (digits == 2 ? 10 : 100))
            continue; // a leading zero: no plain decimal value starts so
        for (int w = 0; w <= 255; ++w) {
            const int length = w >= 100 ? 3 : (w >= 10 ? 2 : 1);
            if (length >= digits
                && w / (length - digits == 2 ? 100 : (length - digits == 1 ? 10 : 1)) == value) {
                const auto [it, fresh] = prefix.try_emplace(w, cell.cost - bestCost);
                it->second = std::min(it->second, cell.cost - bestCost);
            }
        }
    }
    return prefix;
}

// A character of the best parse, from its start mark and state; ch == -1 marks a restart.
struct Taken
{
    std::size_t at;
    int from;
    int ch;
    int edit;
};

// A message of the best parse: path[begin, end); `colon` when it reached its ':' (which
// anchors octets read after a cut start).
struct Message
{
    std::size_t begin;
    std::size_t end;
    bool colon;
};

struct MessageReading
{
    IpObservation observation; // octets read completely, weights from their margins
    std::array<long, 4> closed { -1, -1, -1, -1 }; // Closings
    int tailOctet = -1; // closed after a cut start with only its last digits read
    OctetSpans spans;
};

using CharCosts = std::array<std::vector<std::array<double, kChars.size()>>, kEdits>;

MessageReading readMessage(const std::vector<Taken> &path, const Message &msg,
                           const CharCosts &charCost)
{
    MessageReading r;
    double margin = kInf;
    long firstDigit = -1; // path index of the octet's first digit
    for (std::size_t p = msg.begin; p < msg.end; ++p) {
        const Taken &t = path[p];
        const bool digit = t.ch >= kDigit0 && t.ch < kColon;
        const bool closes = t.ch == kPlus || t.ch == kColon;
        if (digit && firstDigit < 0)
            firstDigit = long(p);
        if (!digit && !closes)
            firstDigit = -1;
        // Octet states whose k is anchored: by a prefix character, or back from ':'.
        const OctetParts from = partsOf(t.from % kStates);
        const bool known = from.k >= 0 && !from.cut && (t.from < kStates || msg.colon);
        // Digits after a cut count towards the margin: a third one makes them an octet.
        const bool tail = from.cut && from.n < kCutDigits && msg.colon;
        if (digit && (known || tail)) {
            // Margin against the cheapest other reading of the same marks.
            const auto &costs = charCost[std::size_t(t.edit)][t.at];
            const double own = costs[static_cast<std::size_t>(t.ch)];
            double ownMargin = kInf;
            for (int c = kPlus; c < kColon; ++c) {
                if (c != t.ch && (c == kPlus || c >= kDigit0))
                    ownMargin = std::min(ownMargin, costs[std::size_t(c)] - own);
            }
            if (t.edit != 0) // a repaired digit: half a vote
                ownMargin = std::min(ownMargin, kClearMargin / 2.0);
            margin = std::min(margin, ownMargin);
        }
        if (closes && tail && from.n > 0) {
            r.tailOctet = from.k;
            r.closed[std::size_t(from.k)] = long(t.at);
        }
        if (closes && known) {
            const auto k = static_cast<std::size_t>(from.k);
            r.observation.octets[k] = from.v;
            r.observation.weight[k] =
                std::clamp(margin / kClearMargin, kMinWeight, IpVoter::kMaxWeight);
            r.closed[k] = long(t.at);
            if (firstDigit >= 0)
                r.spans[k] = { long(path[std::size_t(firstDigit)].at), long(t.at),
                               int(long(p) - firstDigit) };
        }
        if (closes)
            firstDigit = -1;
        if (closes || !(known || tail))
            margin = kInf;
    }
    return r;
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
    CharCosts charCost;
    for (auto &costs : charCost)
        costs.resize(n);
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
    } else if (!salvage) {
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
    // Salvage: the cheapest restart at mark i after a message left unfinished at or before i
    // (the marks since skipped), and where that message was left.
    double restartCost = kInf;
    int restartFrom = -1;
    std::size_t restartAt = 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (salvage) {
            // Any mark may start the reading (the hard letter gaps may be the damage), the marks
            // before it skipped; and a message may follow a damaged one in the same stretch.
            restartCost += kSkipCost;
            for (const auto &[st, cell] : layer[i]) {
                if (canLeave(st) && cell.cost + kRestartCost < restartCost) {
                    restartCost = cell.cost + kRestartCost;
                    restartFrom = st;
                    restartAt = i;
                }
            }
            const double skip = kSkipCost * double(i);
            for (int st : kStarts) {
                const auto [it, fresh] = layer[i].try_emplace(st);
                if (fresh || skip < it->second.cost)
                    it->second = { skip, -1, -1, 0, 0 };
            }
            if (restartCost < kInf)
                layer[i][kRestartBase] = { restartCost, restartFrom, -1, 0, restartAt };
        }
        // Beam: states far costlier than the best one on the same marks are dropped. Start
        // states (salvage, cut start) stay, so that a reading may still begin there.
        double least = kInf;
        for (const auto &[st, cell] : layer[i]) {
            if (!isRestartPrefix(st)) // may not end the parse: no measure of the best
                least = std::min(least, cell.cost);
        }
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
            if ((in.openEnd || salvage || st == kEnd) && cell.ch >= 0 && !isRestartPrefix(st)
                && cell.cost + skip < bestCost) {
                bestCost = cell.cost + skip;
                best = st;
                end = at;
            }
        }
    }
    if (best < 0)
        return out;

    // Backtrace: characters with their start marks and states; ch == -1 marks a restart
    // (Salvage: the message before was left unfinished).
    std::vector<Taken> path;
    std::size_t i = end;
    int s = best;
    while (true) {
        const Cell back = layer[i].at(s);
        if (back.ch < 0 && back.prevState < 0)
            break;
        if (back.ch < 0) {
            path.push_back({ i, -1, -1, 0 });
            i = back.from;
            s = back.prevState;
            continue;
        }
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
    // The messages read: path ranges, split where ':' is followed by the next 'M' and at
    // restarts.
    std::vector<Message> messages;
    std::size_t first = 0;
    for (std::size_t p = 0; p <= path.size(); ++p) {
        const bool restart = p < path.size() && path[p].ch < 0;
        if (p < path.size() && !restart && path[p].from != kEnd)
            continue;
        if (p > first)
            messages.push_back({ first, p, path[p - 1].ch == kColon });
        first = restart ? p + 1 : p;
    }
    for (const Taken &t : path) {
        if (t.ch < 0) {
            out.text += QLatin1Char('?');
            continue;
        }
        double z = 0.0;
        scorer.character(t.at, t.ch, t.edit, &z);
        out.worstZ = std::max(out.worstZ, z);
        out.text += QLatin1Char(kChars[static_cast<std::size_t>(t.ch)]);
    }
    if (end < n)
        out.text += QLatin1Char('?');

    // Per message: its octets with their weights, where each was closed, and the octet whose
    // tail only was read after a cut start (its value is not known, only which values fit).
    std::vector<MessageReading> readings;
    for (const Message &msg : messages) {
        MessageReading r = readMessage(path, msg, charCost);
        const IpObservation &obs = r.observation;
        // A salvaged reading counts only with at least two octets, so that status text such as
        // "ERR+5:" (movingcap.md 2.2: the LED sends other text too) is never read as an
        // address.
        const auto read =
            std::count_if(obs.octets.begin(), obs.octets.end(), [](int v) { return v >= 0; });
        if (salvage && read < 2)
            continue;
        readings.push_back(std::move(r));
    }
    if (readings.empty()) // a salvaged stretch keeps its character-by-character text
        return {};
    // The octet still arriving at the end of an open stretch, in the last message.
    int open = -1;
    const OctetParts last = partsOf(best); // k < 0 for the unanchored copy
    const bool lastIsOpen = messages.back().end == path.size() && !messages.back().colon;
    if (in.openEnd && !salvage && lastIsOpen && last.k >= 0 && !last.cut && last.n >= 1) {
        open = last.k;
        readings.back().closed[std::size_t(open)] = long(end);
    }
    Closings closings;
    bool anyOctet = false; // read, a tail read, or still arriving: each has its closing
    for (const MessageReading &r : readings) {
        closings.push_back(r.closed);
        anyOctet = anyOctet
            || std::any_of(r.closed.begin(), r.closed.end(), [](long at) { return at >= 0; });
    }
    const auto soft = anyOctet ? octetCosts(layer, options, in.openEnd, salvage, bestCost, closings)
                               : std::vector<OctetCosts>(readings.size());
    const std::map<int, double> prefix =
        open >= 0 ? openOctetCosts(layer[end], open, bestCost) : std::map<int, double> {};
    for (std::size_t m = 0; m < readings.size(); ++m) {
        IpObservation &obs = readings[m].observation;
        for (std::size_t k = 0; k < 4; ++k) {
            const bool isOpen = m + 1 == readings.size() && int(k) == open;
            const bool isTail = int(k) == readings[m].tailOctet;
            if (obs.octets[k] < 0 && !isOpen && !isTail)
                continue;
            for (const auto &[value, nats] : soft[m][k]) {
                if (nats < kSoftRange)
                    obs.cost[k][value] = std::max(0.0, nats);
            }
            if (isTail)
                continue; // costs only: the values that end in the digits read cost least
            if (!isOpen) {
                obs.cost[k][obs.octets[k]] = 0.0;
                continue;
            }
            for (const auto &[value, nats] : prefix) {
                const auto [it, fresh] = obs.cost[k].try_emplace(value, nats);
                it->second = std::max(0.0, std::min(it->second, nats));
            }
        }
        obs.complete =
            std::all_of(obs.octets.begin(), obs.octets.end(), [](int v) { return v >= 0; });
        out.observations.push_back(std::move(obs));
        out.spans.push_back(readings[m].spans);
    }
    out.ok = true;
    return out;
}

} // namespace db::morse
