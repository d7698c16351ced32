#include "framecheck.h"

#include "morsecode.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace db::morse {
namespace {

constexpr double kNegInf = -std::numeric_limits<double>::infinity();
constexpr double kHuber = 2.0; // sigmas, as the sequence decoder
constexpr double kMaxZ = 5.0; // lengths farther from their nominal are not considered
constexpr double kMinSpread = 0.05; // units
constexpr std::size_t kMinSamples = 8;
constexpr double kNegligible = 40.0; // nats below a window's largest term
// A window sum taken relative to a larger term than its own largest: below this, too few
// significant digits may be left (about 645 nats down), so the window is summed exactly.
constexpr double kSmallestSum = 1e-280;
constexpr double kFreeDark = 6.0;
constexpr double kSlopeSigmas = 3.0; // a level's slope counts from this many standard errors //
                                     // units of dark at either end of a region, at most

double medianOf(std::vector<double> v)
{
    if (v.empty())
        return 0.0;
    auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
    std::nth_element(v.begin(), mid, v.end());
    return *mid;
}

struct Part
{
    bool on = false;
    double units = -1.0; // nominal; < 0: dark of any length (the region's ends)
};

// Dark of any length, the nominal elements of `text`, dark of any length; empty when a character
// has no code.
std::vector<Part> elementsOf(const QString &text)
{
    if (text.isEmpty()
        || std::any_of(text.begin(), text.end(), [](QChar c) { return codeFor(c).isEmpty(); }))
        return {};
    std::vector<Part> out { { false, -1.0 } };
    const std::vector<double> units = messageElements(text, -1.0); // the last gap: free dark
    for (std::size_t i = 0; i < units.size(); ++i)
        out.push_back({ i % 2 == 0, units[i] });
    return out;
}

} // namespace

std::span<const Sample> samplesBetween(std::span<const Sample> samples, double from, double to)
{
    const auto begin = std::lower_bound(samples.begin(), samples.end(), from,
                                        [](const Sample &s, double t) { return s.t < t; });
    const auto end = std::upper_bound(begin, samples.end(), to,
                                      [](double t, const Sample &s) { return t < s.t; });
    return { begin, end };
}

bool estimateLevels(std::span<const Sample> samples, RegionModel *model)
{
    if (samples.size() < kMinSamples)
        return false;
    std::vector<double> sorted;
    sorted.reserve(samples.size());
    for (const Sample &s : samples)
        sorted.push_back(s.value);
    std::sort(sorted.begin(), sorted.end());
    const double p10 = sorted[sorted.size() / 10];
    const double p90 = sorted[sorted.size() - 1 - sorted.size() / 10];
    RegionModel &m = *model;
    m.low = m.high = (p10 + p90) / 2.0;
    m.lowSlope = m.highSlope = 0.0;
    // First the medians below and above the middle; then twice a straight line through each
    // group, with the samples grouped by the middle of the lines (drift and auto exposure move
    // both levels by several noise sigmas over a region of ten seconds).
    for (int pass = 0; pass < 3; ++pass) {
        std::array<std::vector<double>, 2> values;
        std::array<double, 2> n {}, st {}, sx {}, stt {}, stx {}, sxx {};
        for (const Sample &s : samples) {
            const double dt = s.t - m.from;
            const std::size_t g =
                s.value < m.levelAt(dt, false) / 2.0 + m.levelAt(dt, true) / 2.0 ? 0 : 1;
            values[g].push_back(s.value);
            n[g] += 1.0;
            st[g] += dt;
            sx[g] += s.value;
            stt[g] += dt * dt;
            stx[g] += dt * s.value;
            sxx[g] += s.value * s.value;
        }
        if (values[0].size() < 2 || values[1].size() < 2)
            return false;
        for (std::size_t g = 0; g < 2; ++g) {
            double &level = g == 0 ? m.low : m.high;
            double &slope = g == 0 ? m.lowSlope : m.highSlope;
            const double var = stt[g] - st[g] * st[g] / n[g];
            const double cov = stx[g] - st[g] * sx[g] / n[g];
            const double fit = var > 0.0 ? cov / var : 0.0;
            // The slope counts where it is kSlopeSigmas standard errors: a line through a few
            // noisy samples is otherwise worse than their median.
            const double residual = std::max(0.0, sxx[g] - sx[g] * sx[g] / n[g] - fit * cov)
                / std::max(1.0, n[g] - 2.0);
            if (pass == 0 || n[g] < 3.0 || var <= 0.0
                || std::abs(fit) < kSlopeSigmas * std::sqrt(residual / var)) {
                level = medianOf(values[g]);
                slope = 0.0;
            } else {
                slope = fit;
                level = (sx[g] - slope * st[g]) / n[g];
            }
        }
    }
    // Noise: the median distance from the nearer level. Not from successive differences: at
    // three frames per dit, half of them are steps.
    std::vector<double> r;
    r.reserve(samples.size());
    for (const Sample &s : samples) {
        const double dt = s.t - m.from;
        r.push_back(std::min(std::abs(s.value - m.levelAt(dt, false)),
                             std::abs(s.value - m.levelAt(dt, true))));
    }
    m.sigma = 1.4826 * medianOf(r);
    const double contrast = m.high - m.low;
    m.sigma = std::max(m.sigma, 0.02 * contrast);
    return contrast > 0.0;
}

double regionLogLikelihood(std::span<const Sample> all, const RegionModel &m, const QString &text)
{
    const std::vector<Part> elements = elementsOf(text);
    const std::span<const Sample> s = samplesBetween(all, m.from, m.to);
    if (elements.empty() || s.size() < 2 || m.unit <= 0.0 || m.sigma <= 0.0 || m.to <= m.from)
        return kNegInf;
    // Per state, prefix sums of each sample's log-likelihood.
    const std::size_t n = s.size();
    std::vector<double> dark(n + 1, 0.0);
    std::vector<double> lit(n + 1, 0.0);
    const double norm = -std::log(m.sigma) - 0.5 * std::log(2.0 * std::numbers::pi);
    for (std::size_t j = 0; j < n; ++j) {
        const double dt = s[j].t - m.from;
        const double zl = (s[j].value - m.levelAt(dt, false)) / m.sigma;
        const double zh = (s[j].value - m.levelAt(dt, true)) / m.sigma;
        dark[j + 1] = dark[j] + norm - 0.5 * zl * zl;
        lit[j + 1] = lit[j] + norm - 0.5 * zh * zh;
    }
    const double period = (s.back().t - s.front().t) / double(n - 1);
    // One grid point per sample period: between two samples, an edge's position changes only
    // the length's prior, not the samples' likelihood. No finer than a 16th of a unit (a
    // photodiode at 1 kHz: the lengths' spread is far wider), no coarser than a third.
    const double h = std::clamp(period, m.unit / 16.0, m.unit / 3.0);
    const double cells = std::ceil((m.to - m.from) / h);
    // Per element: the lengths considered (grid steps) and the probability of each, Huber
    // around the nominal length and normalised over the grid cells, so that readings with more
    // or fewer elements, or with dahs (wider spread) instead of dits, compare fairly. The dark at
    // either end is half a letter gap: any length up to kFreeDark units, the same for every text.
    struct Steps
    {
        std::size_t shortest = 0;
        std::size_t longest = 0;
        std::vector<double> p; // by length - shortest
    };
    const std::size_t freeSteps = static_cast<std::size_t>(std::ceil(kFreeDark * m.unit / h));
    std::vector<Steps> steps(elements.size());
    for (std::size_t i = 0; i < elements.size(); ++i) {
        const Part &e = elements[i];
        Steps &st = steps[i];
        if (e.units < 0.0) {
            st.longest = freeSteps;
            st.p.assign(freeSteps + 1, 1.0);
            continue;
        }
        const double spread = std::hypot(m.relJitter * e.units, kMinSpread);
        const double offset = e.on ? m.duty : -m.duty;
        const double lo = (e.units - kMaxZ * spread) * m.unit + offset;
        const double hi = (e.units + kMaxZ * spread) * m.unit + offset;
        st.shortest = std::max<std::size_t>(1, static_cast<std::size_t>(std::max(0.0, lo / h)));
        st.longest = std::max(st.shortest, static_cast<std::size_t>(std::ceil(hi / h)));
        double sum = 0.0;
        for (std::size_t d = st.shortest; d <= st.longest; ++d) {
            const double z = std::abs((double(d) * h - offset) / m.unit - e.units) / spread;
            st.p.push_back(std::exp(-(z < kHuber ? 0.5 * z * z : kHuber * (z - 0.5 * kHuber))));
            sum += st.p.back();
        }
        for (double &p : st.p)
            p /= sum;
    }
    // Where element i may begin: early enough for the shortest elements after it, late enough
    // for the longest ones to reach the end.
    std::vector<std::size_t> minRest(elements.size() + 1, 0);
    std::vector<std::size_t> maxRest(elements.size() + 1, 0);
    for (std::size_t i = elements.size(); i-- > 0;) {
        minRest[i] = minRest[i + 1] + steps[i].shortest;
        maxRest[i] = maxRest[i + 1] + steps[i].longest;
    }
    // A region longer than the longest reading of the text cannot hold it. Checked before the
    // grid is allocated: the region's length comes from the recording (a gap of hours in the
    // samples), the grid's bound from the text.
    if (!(cells <= double(maxRest[0])))
        return kNegInf;
    const auto grid = static_cast<std::size_t>(cells);
    // first[g]: the first sample at or after grid point g.
    std::vector<std::size_t> first(grid + 2);
    for (std::size_t g = 0, j = 0; g <= grid + 1; ++g) {
        const double t = m.from + double(g) * h;
        while (j < n && s[j].t < t)
            ++j;
        first[g] = j;
    }
    // Forward algorithm: alpha[g] = ln p(element i begins at grid point g, the samples before
    // it), summed over all edge positions. The samples of an element from a to b contribute
    // prefix[b] - prefix[a], so next[b] = prefix[b] + ln sum_a exp(alpha[a] - prefix[a]) p(b - a),
    // summed in linear scale relative to the largest term of each window (the terms span
    // thousands of nats on a clean signal).
    std::vector<double> alpha(grid + 1, kNegInf);
    std::vector<double> next(grid + 1, kNegInf);
    std::vector<double> beta(grid + 1, kNegInf);
    std::vector<double> scaled(grid + 1, 0.0);
    std::vector<double> blockTop;
    std::vector<double> blockRatio;
    alpha[0] = 0.0;
    for (std::size_t i = 0; i < elements.size(); ++i) {
        const Part &e = elements[i];
        const Steps &st = steps[i];
        const std::vector<double> &prefix = e.on ? lit : dark;
        const std::size_t lastStart = grid >= minRest[i] ? grid - minRest[i] : 0;
        const std::size_t firstStart = grid > maxRest[i] ? grid - maxRest[i] : 0;
        std::fill(beta.begin(), beta.end(), kNegInf);
        for (std::size_t a = firstStart; a <= lastStart; ++a) {
            if (alpha[a] != kNegInf)
                beta[a] = alpha[a] - prefix[first[a]];
        }
        // ln sum over the starts a in [lo, hi] of exp(beta[a]) weight(a).
        auto windowSum = [&](std::size_t lo, std::size_t hi, auto weight) {
            double top = kNegInf;
            for (std::size_t a = lo; a <= hi; ++a)
                top = std::max(top, beta[a]);
            if (top == kNegInf)
                return kNegInf;
            double sum = 0.0;
            for (std::size_t a = lo; a <= hi; ++a) {
                if (beta[a] > top - kNegligible)
                    sum += std::exp(beta[a] - top) * weight(a);
            }
            return sum > 0.0 ? top + std::log(sum) : kNegInf;
        };
        if (i + 1 == elements.size()) {
            // The dark at the end: from wherever the last mark ended to the end of the region
            // (any length up to kFreeDark units, each with the same weight).
            const std::size_t lo = std::max(firstStart, grid > freeSteps ? grid - freeSteps : 0);
            const double l = windowSum(lo, lastStart, [](std::size_t) { return 1.0; });
            return l == kNegInf ? kNegInf : prefix[first[grid + 1]] + l;
        }
        // The starts in blocks as wide as a window: each block's largest term and every term's
        // exponential relative to it, taken once per start. A window (two blocks at most) then
        // sums products relative to the larger block top, with one exponential per block;
        // windows whose terms all lie too far below that top to be represented take the exact
        // sum above.
        const std::size_t width = st.longest - st.shortest + 1;
        blockTop.assign((lastStart - firstStart) / width + 1, kNegInf);
        for (std::size_t a = firstStart; a <= lastStart; ++a) {
            double &top = blockTop[(a - firstStart) / width];
            top = std::max(top, beta[a]);
        }
        for (std::size_t a = firstStart; a <= lastStart; ++a) {
            const double top = blockTop[(a - firstStart) / width];
            scaled[a] = beta[a] == kNegInf ? 0.0 : std::exp(beta[a] - top);
        }
        // Two neighbouring blocks: the lower top relative to the higher one.
        blockRatio.resize(blockTop.size());
        for (std::size_t k = 0; k + 1 < blockTop.size(); ++k) {
            const double low = std::min(blockTop[k], blockTop[k + 1]);
            const double high = std::max(blockTop[k], blockTop[k + 1]);
            blockRatio[k] = low == kNegInf ? 0.0 : std::exp(low - high);
        }
        std::fill(next.begin(), next.end(), kNegInf);
        const std::size_t bLast = std::min(grid, lastStart + st.longest);
        for (std::size_t b = firstStart + st.shortest; b <= bLast; ++b) {
            const std::size_t lo =
                b > st.longest ? std::max(firstStart, b - st.longest) : firstStart;
            const std::size_t hi = std::min(lastStart, b - st.shortest);
            if (lo > hi)
                continue;
            const std::size_t k1 = (lo - firstStart) / width;
            const std::size_t k2 = (hi - firstStart) / width;
            const double top = std::max(blockTop[k1], blockTop[k2]);
            if (top == kNegInf)
                continue;
            const std::size_t offset = b - st.shortest; // st.p[offset - a]: start a's weight
            double sum = 0.0;
            for (std::size_t k = k1; k <= k2; ++k) {
                if (blockTop[k] == kNegInf)
                    continue;
                const std::size_t from = std::max(lo, firstStart + k * width);
                const std::size_t to = std::min(hi, firstStart + (k + 1) * width - 1);
                // Four running sums: one chain of additions waits for each previous one.
                std::array<double, 4> part {};
                std::size_t a = from;
                for (; a + 3 <= to; a += 4) {
                    for (std::size_t j = 0; j < 4; ++j)
                        part[j] += scaled[a + j] * st.p[offset - a - j];
                }
                for (; a <= to; ++a)
                    part[0] += scaled[a] * st.p[offset - a];
                const double factor = blockTop[k] == top ? 1.0 : blockRatio[k1];
                sum += (part[0] + part[1] + part[2] + part[3]) * factor;
            }
            const double l = sum > kSmallestSum
                ? top + std::log(sum)
                : windowSum(lo, hi, [&](std::size_t a) { return st.p[b - a - st.shortest]; });
            if (l != kNegInf)
                next[b] = prefix[first[b]] + l;
        }
        std::swap(alpha, next);
    }
    return kNegInf; // not reached: the last element returns
}

} // namespace db::morse
