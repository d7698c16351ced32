#include "messageparser.h"

#include "morsecode.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <unordered_map>

namespace db::morse {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// A digit whose best rival reading costs this much more (nats) gets the full vote weight.
constexpr double kClearMargin = 4.0;
constexpr double kMinWeight = 0.05;
constexpr double kHuber = 2.0; // sigmas
constexpr double kEditCost = 6.0; // nats: a lost element is rarer than a 3-sigma deviation

// The characters of the grammar: the prefix, the digits, the separator and the end mark.
constexpr std::array kChars { 'M', 'C', '+', 'I', 'P', '0', '1', '2',
                              '3', '4', '5', '6', '7', '8', '9', ':' };
constexpr int kPlus = 2;
constexpr int kDigit0 = 5;
constexpr int kColon = 15;

// Grammar states: P(j) expects prefix character j of "MC+IP"; O(k, n, v) is inside octet k
// after n digits of value v; U(k) is inside octet k whose first digits were before the
// recording (value unknown, never reported); End follows ':'.
constexpr int kPrefix = 5;
constexpr int kOctetBase = kPrefix;
constexpr int kUnknownBase = kOctetBase + 4 * 4 * 256;
constexpr int kEnd = kUnknownBase + 4;
constexpr int kStates = kEnd + 1;

// ITU codes of kChars, looked up once.
const std::array<QString, kChars.size()> &codes()
{
    static const std::array<QString, kChars.size()> table = [] {
        std::array<QString, kChars.size()> t;
        for (std::size_t c = 0; c < kChars.size(); ++c)
            t[c] = codeFor(QLatin1Char(kChars[c]));
        return t;
    }();
    return table;
}

// Nominal lengths (units) of a character's marks and of the gaps after them.
struct Pattern
{
    std::vector<double> marks;
    std::vector<double> gaps;
};

// Per character: [0] the pattern as sent; [1] every pattern with one element lost.
using Patterns = std::array<std::array<std::vector<Pattern>, 2>, kChars.size()>;

const Patterns &patterns()
{
    static const Patterns table = [] {
        Patterns t;
        for (std::size_t c = 0; c < kChars.size(); ++c) {
            Pattern p;
            for (QChar e : codes()[c]) {
                p.marks.push_back(e == QLatin1Char('-') ? 3.0 : 1.0);
                p.gaps.push_back(1.0);
            }
            p.gaps.back() = 3.0;
            t[c][0].push_back(p);
            for (std::size_t j = 0; j + 1 < p.marks.size(); ++j) {
                const auto at = std::ptrdiff_t(j);
                Pattern merged = p; // a gap filled: marks j and j + 1 merge
                merged.marks[j] += p.gaps[j] + p.marks[j + 1];
                merged.marks.erase(merged.marks.begin() + at + 1);
                merged.gaps.erase(merged.gaps.begin() + at);
                t[c][1].push_back(merged);
                Pattern lost = p; // mark j + 1 swallowed: its gaps merge
                lost.gaps[j] += p.marks[j + 1] + p.gaps[j + 1];
                lost.marks.erase(lost.marks.begin() + at + 1);
                lost.gaps.erase(lost.gaps.begin() + at + 1);
                t[c][1].push_back(lost);
            }
        }
        return t;
    }();
    return table;
}

std::size_t codeLength(int c)
{
    return static_cast<std::size_t>(codes()[static_cast<std::size_t>(c)].size());
}

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

struct Scorer
{
    const StretchInput &in;
    const ElementModel &m;

    Scorer(const StretchInput &input, const ElementModel &model)
        : in(input)
        , m(model)
    {
        for (std::size_t k = 0; k < kSigmas; ++k) {
            const double kk = static_cast<double>(k);
            m_sigma[k] = std::sqrt(m.relJitter * m.relJitter * kk * kk + m.absSigma * m.absSigma);
        }
        for (std::size_t k = 0; k < kSigmas; ++k)
            m_logRatio[k] = std::log(m_sigma[k] / m_sigma[1]);
    }
    // Nominal lengths are whole units (1 + 3 + 3 at most after a merge).
    static constexpr std::size_t kSigmas = 12;
    std::array<double, kSigmas> m_sigma {};
    std::array<double, kSigmas> m_logRatio {};
    // Negative log-likelihood of a length x (units) with nominal k, offset so that it is never
    // negative (ln s relative to the dit's); *z grows to |x - k| / s.
    double element(double x, double k, double *z) const
    {
        const auto ki = std::min(kSigmas - 1, static_cast<std::size_t>(k));
        const double s = m_sigma[ki];
        const double e = std::abs(x - k) / s;
        *z = std::max(*z, e);
        // Huber: quadratic near the nominal, linear in the tails, so that one element disturbed
        // by noise beyond the estimated spread does not outweigh the rest of the message.
        const double h = e < kHuber ? 0.5 * e * e : kHuber * (e - 0.5 * kHuber);
        return h + m_logRatio[ki];
    }
    // Cost of the nominal lengths `marks` (and gaps between them, then a letter gap) on the
    // measured marks from i; inf when they do not fit or exceed maxZ.
    double pattern(std::size_t i, const std::vector<double> &marks, const std::vector<double> &gaps,
                   double *worstZ) const
    {
        const std::size_t len = marks.size();
        if (len == 0 || i + len > in.marks.size())
            return kInf;
        double z = 0.0;
        double cost = 0.0;
        for (std::size_t j = 0; j < len; ++j) {
            cost += element(in.marks[i + j], marks[j], &z);
            if (i + j < in.gaps.size())
                cost += element(in.gaps[i + j], gaps[j], &z);
        }
        if (worstZ)
            *worstZ = z;
        return z > m.maxZ ? kInf : cost;
    }
    // Cost of character c on marks from i. edited = false: as sent. edited = true: the best
    // reading with one element lost (one mark less): a mark swallowed by noise (its gaps merge)
    // or a gap filled by noise (its marks merge); kEditCost more.
    double character(std::size_t i, int c, bool edited, double *worstZ) const
    {
        double best = kInf;
        for (const Pattern &p : patterns()[static_cast<std::size_t>(c)][edited]) {
            double z = 0.0;
            const double cost = pattern(i, p.marks, p.gaps, &z);
            if (cost < best) {
                best = cost;
                if (worstZ)
                    *worstZ = z;
            }
        }
        return best + (edited ? kEditCost : 0.0);
    }
};

struct Cell
{
    double cost = 0.0;
    int prevState = -1;
    int ch = -1; // -1: a start state
    bool edited = false;
};

} // namespace

StretchParse parseStretch(const StretchInput &in, const ElementModel &model)
{
    StretchParse out;
    const std::size_t n = in.marks.size();
    if (n == 0 || in.gaps.size() + 1 != n)
        return out;
    const Scorer scorer(in, model);

    // Character costs per start mark, as sent and with one element lost.
    using Costs = std::vector<std::array<double, kChars.size()>>;
    std::array<Costs, 2> charCost { Costs(n), Costs(n) };
    for (std::size_t i = 0; i < n; ++i) {
        for (int c = 0; c < int(kChars.size()); ++c) {
            for (int e = 0; e < 2; ++e)
                charCost[std::size_t(e)][i][std::size_t(c)] = scorer.character(i, c, e, nullptr);
        }
    }

    // layer[i]: state -> best cost with marks [0, i) consumed, and how it was reached. Sparse:
    // of the ~4100 states only the few hundred consistent with the marks are ever reached.
    std::vector<std::unordered_map<int, Cell>> layer(n + 1);
    std::size_t skipped = 0;
    if (!in.openStart) {
        layer[0][0] = {};
    } else {
        // The first character may be cut: it is read inside an unknown octet or as a prefix
        // character, or skipped up to the first letter gap. Either way the position inside an
        // octet is unknown, so the first octet read is never reported.
        while (!in.firstComplete && skipped < in.gaps.size() && in.gaps[skipped] < 2.0)
            ++skipped;
        skipped += in.firstComplete ? 0 : 1;
        for (std::size_t at : { std::size_t(0), skipped }) {
            for (int st = 0; at < n && st < kPrefix; ++st)
                layer[at][st] = {};
            for (int k = 0; at < n && k < 4; ++k)
                layer[at][kUnknownBase + k] = {};
        }
    }
    for (std::size_t i = 0; i < n; ++i) {
        for (const auto &[st, cell] : layer[i]) {
            for (int c = 0; c < int(kChars.size()) * 2; ++c) {
                const bool edited = c >= int(kChars.size());
                const int ch = c % int(kChars.size());
                const double cc = charCost[edited][i][static_cast<std::size_t>(ch)];
                const int t = cc == kInf ? -1 : next(st, ch);
                if (t < 0)
                    continue;
                const std::size_t len = codeLength(ch) - (edited ? 1 : 0);
                auto [it, fresh] = layer[i + len].try_emplace(t);
                if (fresh || cell.cost + cc < it->second.cost)
                    it->second = { cell.cost + cc, st, ch, edited };
            }
        }
    }

    int best = -1;
    double bestCost = kInf;
    for (const auto &[st, cell] : layer[n]) {
        if ((in.openEnd || st == kEnd) && cell.cost < bestCost) {
            bestCost = cell.cost;
            best = st;
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
        bool edited;
    };
    std::vector<Taken> path;
    std::size_t i = n;
    int s = best;
    while (true) {
        const Cell step = layer[i].at(s);
        if (step.ch < 0)
            break;
        i -= codeLength(step.ch) - (step.edited ? 1 : 0);
        path.push_back({ i, step.prevState, step.ch, step.edited });
        s = step.prevState;
    }
    std::reverse(path.begin(), path.end());
    if (path.empty())
        return out;

    if (i > 0)
        out.text += QLatin1Char('?');
    double margin = kInf;
    for (const Taken &t : path) {
        double z = 0.0;
        scorer.character(t.at, t.ch, t.edited, &z);
        out.worstZ = std::max(out.worstZ, z);
        out.text += QLatin1Char(kChars[static_cast<std::size_t>(t.ch)]);
        const bool digit = t.ch >= kDigit0 && t.ch < kColon;
        const bool known = t.from >= kOctetBase && t.from < kUnknownBase;
        if (digit && known) {
            // Margin against the cheapest other reading of the same marks.
            const Costs &costs = charCost[t.edited];
            const double own = costs[t.at][static_cast<std::size_t>(t.ch)];
            for (int c = kPlus; c < kColon; ++c) {
                if (c != t.ch && (c == kPlus || c >= kDigit0))
                    margin = std::min(margin, costs[t.at][std::size_t(c)] - own);
            }
            if (t.edited)
                margin = std::min(margin, kClearMargin / 2.0); // a repaired digit: half a vote
        }
        if ((t.ch == kPlus || t.ch == kColon) && known) {
            const int rel = t.from - kOctetBase;
            const auto k = static_cast<std::size_t>(rel / 1024);
            out.observation.octets[k] = rel % 256;
            out.observation.weight[k] =
                std::clamp(margin / kClearMargin, kMinWeight, IpVoter::kMaxWeight);
        }
        if (t.ch == kPlus || t.ch == kColon || !known)
            margin = kInf;
    }
    out.observation.complete = std::all_of(
        out.observation.octets.begin(), out.observation.octets.end(), [](int v) { return v >= 0; });
    out.ok = true;
    return out;
}

} // namespace db::morse
