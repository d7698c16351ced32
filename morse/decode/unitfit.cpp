#include "unitfit.h"

#include <algorithm>
#include <cmath>

namespace db::morse {
namespace {

constexpr double kGridStep = 1.02;
constexpr double kWordGap = 5.0; // units; longer gaps are not fitted
constexpr double kCapRatio = 1.8; // cost cap: an interval this far off counts as an outlier
constexpr double kGoodRatio = 1.45;
constexpr int kMinIntervals = 12;

// Nearest multiple (1 or 3 for marks, 1 or 3 for gaps) in log distance; 0 for long gaps.
int multiple(const Interval &iv, double d, double u)
{
    const double r = d / u;
    if (!iv.on && r > kWordGap)
        return 0;
    return r < std::sqrt(3.0) ? 1 : 3;
}

// Grid cost with duty 0, on precomputed logarithms (this is the hot loop of the decoder).
double cost(const std::vector<double> &logD, const std::vector<bool> &on, double logU)
{
    const double cap = std::log(kCapRatio) * std::log(kCapRatio);
    const double log3 = std::log(3.0);
    const double logWord = std::log(kWordGap);
    double sum = 0.0;
    for (std::size_t i = 0; i < logD.size(); ++i) {
        const double r = logD[i] - logU; // ln(d / u)
        if (!on[i] && r > logWord)
            continue;
        const double e = r < log3 / 2.0 ? r : r - log3;
        sum += std::min(cap, e * e);
    }
    return sum;
}

} // namespace

UnitFit fitUnit(const std::vector<Interval> &all, UnitRange range)
{
    UnitFit fit;
    std::vector<Interval> ivs;
    ivs.reserve(all.size());
    int marks = 0;
    for (const Interval &iv : all) {
        if (!iv.truncated && iv.duration > 0.0) {
            ivs.push_back(iv);
            marks += iv.on ? 1 : 0;
        }
    }
    if (static_cast<int>(ivs.size()) < kMinIntervals || marks < kMinIntervals / 3)
        return fit;

    std::vector<double> logD;
    std::vector<bool> on;
    for (const Interval &iv : ivs) {
        logD.push_back(std::log(iv.duration));
        on.push_back(iv.on);
    }
    double bestU = range.min;
    double bestCost = 1e300;
    for (double u = range.min; u <= range.max; u *= kGridStep) {
        const double c = cost(logD, on, std::log(u));
        if (c < bestCost) {
            bestCost = c;
            bestU = u;
        }
    }

    // Least squares for unit and duty on the assigned multiples, weights 1/k^2 (jitter is
    // proportional to the length): marks d = k u + duty, gaps d = k u - duty.
    double u = bestU;
    double duty = 0.0;
    for (int iter = 0; iter < 3; ++iter) {
        double a11 = 0, a12 = 0, a22 = 0, b1 = 0, b2 = 0;
        for (const Interval &iv : ivs) {
            const double d = iv.duration;
            const double dc = d + (iv.on ? -duty : duty);
            const int k = multiple(iv, dc, u);
            if (k == 0 || std::abs(std::log(dc / (k * u))) > std::log(kCapRatio))
                continue;
            const double s = iv.on ? 1.0 : -1.0;
            const double w = 1.0 / (k * k);
            a11 += w * k * k;
            a12 += w * k * s;
            a22 += w;
            b1 += w * k * d;
            b2 += w * s * d;
        }
        const double det = a11 * a22 - a12 * a12;
        if (det <= 1e-12)
            break;
        u = (b1 * a22 - b2 * a12) / det;
        duty = std::clamp((a11 * b2 - a12 * b1) / det, -0.5 * u, 0.5 * u);
    }
    if (!(u > 0.0))
        return fit;

    int used = 0;
    int good = 0;
    for (const Interval &iv : ivs) {
        const double d = iv.duration + (iv.on ? -duty : duty);
        const int k = multiple(iv, d, u);
        if (k == 0)
            continue;
        ++used;
        good += std::abs(std::log(std::max(d, 1e-6) / (k * u))) < std::log(kGoodRatio) ? 1 : 0;
    }
    fit.unit = u;
    fit.duty = duty;
    fit.used = used;
    fit.quality = used > 0 ? static_cast<double>(good) / used : 0.0;
    fit.valid = u >= range.min * 0.9 && u <= range.max * 1.1;
    return fit;
}

} // namespace db::morse
