// Internal to protocols/morse (messageparser.cpp): the characters of the message grammar,
// their nominal ITU patterns and the cost of reading a character on measured lengths.
#pragma once

#include "messageparser.h"
#include "morsecode.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>
#include <vector>

namespace db::morse::detail {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kHuber = 2.0; // sigmas
constexpr double kEditCost = 6.0; // nats: a lost element is rarer than a 3-sigma deviation
// Readings of a character (Scorer::character): as sent, one element lost, one added, its first
// mark lost.
constexpr int kEdits = 4;

// The characters of the grammar: the prefix, the digits, the separator and the end mark.
constexpr std::array kChars { 'M', 'C', '+', 'I', 'P', '0', '1', '2',
                              '3', '4', '5', '6', '7', '8', '9', ':' };
constexpr int kPlus = 2;
constexpr int kDigit0 = 5;
constexpr int kColon = 15;

// ITU codes of kChars, looked up once.
inline const std::array<QString, kChars.size()> &codes()
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

inline const Patterns &patterns()
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

inline std::size_t codeLength(int c)
{
    return static_cast<std::size_t>(codes()[static_cast<std::size_t>(c)].size());
}

struct Scorer
{
    const StretchInput &in;
    const ElementModel &m;

    Scorer(const StretchInput &input, const ElementModel &model)
        : in(input)
        , m(model)
    {
        for (std::size_t n = 0; n < kNominals; ++n) {
            const double k = nominalAt(n);
            m_base2[n] = m.relJitter * m.relJitter * k * k + m.absSigma * m.absSigma;
        }
        const Spread base = spreadFor(0.0);
        // Most lengths of a clean signal have no edge noise: they share the model's spread.
        auto with = [&](double edge) {
            return edge > 0.0 ? spreadFor(edge) : base;
        };
        m_marks.reserve(in.marks.size());
        for (std::size_t i = 0; i < in.marks.size(); ++i)
            m_marks.push_back(with(in.markSigmaAt(i)));
        m_gaps.reserve(in.gaps.size());
        for (std::size_t i = 0; i < in.gaps.size(); ++i)
            m_gaps.push_back(with(in.gapSigmaAt(i)));
    }
    // Nominal lengths are odd whole units: 1 and 3, and 5 and 7 after a merge (3 + 1 + 3 at
    // most). Index n stands for 2n + 1 units.
    static constexpr std::size_t kNominals = 4;
    static constexpr double nominalAt(std::size_t n) { return 2.0 * static_cast<double>(n) + 1.0; }
    static std::size_t indexOf(double k)
    {
        return std::min(kNominals - 1, static_cast<std::size_t>(std::max(0.0, (k - 1.0) / 2.0)));
    }
    // Per nominal length: the spread of one measured length and ln of it relative to a dit's
    // spread without edge noise (so that costs are never negative).
    struct Spread
    {
        std::array<double, kNominals> sigma {};
        std::array<double, kNominals> logRatio {};
    };
    std::array<double, kNominals> m_base2 {}; // the model's variance per nominal length
    std::vector<Spread> m_marks; // per measured mark, with its edge noise
    std::vector<Spread> m_gaps;

    Spread spreadFor(double edge) const
    {
        Spread sp;
        for (std::size_t n = 0; n < kNominals; ++n) {
            const double var = m_base2[n] + edge * edge;
            sp.sigma[n] = std::sqrt(var);
            sp.logRatio[n] = 0.5 * std::log(var / m_base2[0]);
        }
        return sp;
    }
    // Negative log-likelihood of a length x (units) with nominal k and spread sp, offset so
    // that it is never negative; *z grows to |x - k| / s.
    double element(double x, double k, const Spread &sp, double *z) const
    {
        const std::size_t n = indexOf(k);
        const double e = std::abs(x - k) / sp.sigma[n];
        *z = std::max(*z, e);
        // Huber: quadratic near the nominal, linear in the tails, so that one element disturbed
        // by noise beyond the estimated spread does not outweigh the rest of the message.
        const double h = e < kHuber ? 0.5 * e * e : kHuber * (e - 0.5 * kHuber);
        return h + sp.logRatio[n];
    }
    // Cost of the nominal lengths `marks` (and gaps between them, then a letter gap) on the
    // measured marks from i; inf when they do not fit or exceed maxZ.
    // With pauseAfter (the character is ':'), the letter gap after it is the pause before the
    // next message, which may be longer than a letter gap at no cost.
    double pattern(std::size_t i, std::span<const double> marks, std::span<const double> gaps,
                   double *worstZ, bool pauseAfter = false) const
    {
        const std::size_t len = marks.size();
        if (len == 0 || i + len > in.marks.size())
            return kInf;
        double z = 0.0;
        double cost = 0.0;
        for (std::size_t j = 0; j < len && z <= m.maxZ; ++j) {
            cost += element(in.marks[i + j], marks[j], m_marks[i + j], &z);
            if (i + j >= in.gaps.size())
                continue;
            // A letter gap longer than its nominal may hold the first mark of the next
            // character, lost to noise (firstLost() refunds this charge), so it costs but
            // never rejects the reading.
            double unlimited = 0.0;
            const bool trailing = j + 1 == len && in.gaps[i + j] > gaps[j];
            const double x = trailing && pauseAfter ? gaps[j] : in.gaps[i + j];
            cost += element(x, gaps[j], m_gaps[i + j], trailing ? &unlimited : &z);
        }
        if (worstZ)
            *worstZ = z;
        return z > m.maxZ ? kInf : cost;
    }
    // Cost of character c on marks from i with one element added by noise (one mark more): a
    // dip that splits a mark, or a spike inside a gap (also the letter gap after the
    // character). The three measured lengths around it are read as the one nominal element.
    double inserted(std::size_t i, int c, double *worstZ) const
    {
        const Pattern &p = patterns()[static_cast<std::size_t>(c)][0].front();
        const std::size_t len = p.marks.size();
        if (i + len + 1 > in.marks.size())
            return kInf;
        // Measured elements from mark i: marks at even, gaps at odd positions.
        const std::size_t avail = 2 * (in.marks.size() - i) - 1;
        auto raw = [&](std::size_t e) {
            return e % 2 == 0 ? in.marks[i + e / 2] : in.gaps[i + e / 2];
        };
        auto spread = [&](std::size_t e) -> const Spread & {
            return e % 2 == 0 ? m_marks[i + e / 2] : m_gaps[i + e / 2];
        };
        double best = kInf;
        for (std::size_t q = 0; q < 2 * len && q + 2 < avail; ++q) {
            // The merged length keeps the outer edges of the three: the more uncertain one.
            const Spread &merged =
                spread(q).sigma[0] >= spread(q + 2).sigma[0] ? spread(q) : spread(q + 2);
            double z = 0.0;
            double cost = 0.0;
            for (std::size_t e = 0; e < 2 * len && z <= m.maxZ; ++e) {
                const std::size_t r = e < q ? e : e + 2;
                if (r >= avail)
                    break; // the letter gap after the stretch's last mark is not measured
                const double k = e % 2 == 0 ? p.marks[e / 2] : p.gaps[e / 2];
                double x = e == q ? raw(q) + raw(q + 1) + raw(q + 2) : raw(r);
                if (c == kColon && e + 1 == 2 * len)
                    x = std::min(x, k); // the pause after the message (pattern())
                cost += element(x, k, e == q ? merged : spread(r), &z);
            }
            if (z <= m.maxZ && cost < best) {
                best = cost;
                if (worstZ)
                    *worstZ = z;
            }
        }
        return best + kEditCost;
    }
    // Cost of character c on marks from i without its first mark: noise swallowed it, and the
    // letter gap before the character (gaps[i - 1], charged as 3 units by the character before)
    // grew by that mark and the gap after it. The difference for that gap is charged here.
    // Inside a stretch 'M' follows ':' only: the gap before it is a pause, charged up to a letter
    // gap (pattern()), and so the grown gap costs only when it is shorter than the lost part.
    double firstLost(std::size_t i, int c, double *worstZ) const
    {
        const Pattern &p = patterns()[static_cast<std::size_t>(c)][0].front();
        if (i == 0 || p.marks.size() < 2)
            return kInf;
        double z = 0.0;
        const double rest = pattern(i, std::span(p.marks).subspan(1), std::span(p.gaps).subspan(1),
                                    &z, c == kColon);
        if (rest == kInf)
            return kInf;
        double unused = 0.0;
        const Spread &sp = m_gaps[i - 1];
        const double grown = 3.0 + p.marks[0] + p.gaps[0];
        const double x = in.gaps[i - 1];
        const bool pause = kChars[static_cast<std::size_t>(c)] == 'M';
        const double before = element(pause ? std::min(x, 3.0) : x, 3.0, sp, &unused);
        const double after = element(pause ? std::min(x, grown) : x, grown, sp, &z);
        if (z > m.maxZ)
            return kInf;
        if (worstZ)
            *worstZ = z;
        return rest + after - before + kEditCost;
    }
    // Cost of character c on marks from i. edit 0: as sent. 1: the best reading with one
    // element lost (one mark less): a mark swallowed by noise (its gaps merge) or a gap filled
    // by noise (its marks merge). 2: one element added (inserted()). Edits cost kEditCost more.
    double character(std::size_t i, int c, int edit, double *worstZ) const
    {
        if (edit == 2)
            return inserted(i, c, worstZ);
        if (edit == 3)
            return firstLost(i, c, worstZ);
        const bool edited = edit == 1;
        double best = kInf;
        for (const Pattern &p : patterns()[static_cast<std::size_t>(c)][edited]) {
            double z = 0.0;
            const double cost = pattern(i, p.marks, p.gaps, &z, c == kColon);
            if (cost < best) {
                best = cost;
                if (worstZ)
                    *worstZ = z;
            }
        }
        return best + (edited ? kEditCost : 0.0);
    }
};

} // namespace db::morse::detail
