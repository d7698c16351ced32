// The soft evidence of a parse: for every octet and value, the cost of the cheapest reading of
// the stretch with that value (the backward pass over the parser's layers).

#include "messageparser_p.h"

#include <algorithm>
#include <limits>

namespace db::morse::grammar {

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

} // namespace db::morse::grammar
