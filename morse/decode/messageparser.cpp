#include "messageparser.h"

#include "messageparser_p.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <unordered_map>
namespace db::morse {
namespace {

using namespace grammar;

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
