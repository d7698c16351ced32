#include "symbolizer.h"

#include "morsecode.h"

#include <cmath>
#include <queue>

namespace db::morse {
namespace {

// An unknown code is read as the nearest known one with the same number of elements when that
// costs at most one element at the dit/dah boundary (ln(sqrt 3)^2 ~ 0.3) more.
constexpr double kMaxCorrection = 0.3;

double unitsOf(const Interval &iv, const UnitFit &fit)
{
    return (iv.duration + (iv.on ? -fit.duty : fit.duty)) / fit.unit;
}

// Merges intervals shorter than the glitch limit into both neighbours, shortest first: a noise
// dip inside a mark is healed before the two halves of the mark could look like glitches
// themselves, and a noise spike inside a gap disappears. The first and last interval stay.
std::vector<Interval> deglitch(const std::vector<Interval> &in, const UnitFit &fit, double glitch)
{
    const std::size_t n = in.size();
    std::vector<Interval> iv = in;
    std::vector<std::size_t> prev(n);
    std::vector<std::size_t> next(n);
    std::vector<bool> alive(n, true);
    using Entry = std::pair<double, std::size_t>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
    for (std::size_t i = 0; i < n; ++i) {
        prev[i] = i - 1; // wraps for i == 0; never used there
        next[i] = i + 1;
        if (i > 0 && i + 1 < n && unitsOf(iv[i], fit) < glitch)
            queue.push({ unitsOf(iv[i], fit), i });
    }
    while (!queue.empty()) {
        const auto [units, i] = queue.top();
        queue.pop();
        const std::size_t q = next[i];
        if (!alive[i] || units != unitsOf(iv[i], fit) || q >= n - 1)
            continue; // stale entry, or the neighbour is the open (last) interval
        const std::size_t p = prev[i];
        iv[p].duration += iv[i].duration + iv[q].duration;
        alive[i] = alive[q] = false;
        next[p] = next[q];
        if (next[q] < n)
            prev[next[q]] = p;
    }
    std::vector<Interval> out;
    out.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
        if (alive[i])
            out.push_back(iv[i]);
    }
    return out;
}

} // namespace

ElementKind classify(bool on, double units, const Thresholds &t)
{
    if (on)
        return units < t.dah ? ElementKind::Dit
                             : (units < t.longMark ? ElementKind::Dah : ElementKind::LongMark);
    return units < t.letterGap
        ? ElementKind::IntraGap
        : (units < t.wordGap ? ElementKind::LetterGap : ElementKind::WordGap);
}

Symbols symbolize(const std::vector<Interval> &closed, const Interval &open, const UnitFit &fit,
                  bool final, const Thresholds &t)
{
    Symbols out;
    if (!fit.valid)
        return out;
    std::vector<Interval> all = closed;
    all.push_back(open);
    all = deglitch(all, fit, t.glitch);

    bool uncertain = true; // first character may have lost its first elements
    QString code;
    std::vector<double> markUnits;
    double charStart = 0.0;
    double charEnd = 0.0;
    auto flush = [&] {
        if (code.isEmpty())
            return;
        QChar ch = charFor(code);
        if (ch.isNull() && !code.contains(QLatin1Char('L')))
            ch = nearestChar(markUnits, kMaxCorrection);
        if (ch.isNull() || uncertain)
            ch = QLatin1Char('?');
        uncertain = false;
        out.chars.push_back({ ch, code, charStart, charEnd });
        out.text += ch;
        code.clear();
        markUnits.clear();
    };

    for (std::size_t i = 0; i < all.size(); ++i) {
        const Interval &iv = all[i];
        const bool inProgress = i + 1 == all.size() && !final;
        const double units = unitsOf(iv, fit);
        const ElementKind kind = classify(iv.on, units, t);
        const double endSigma = i + 1 < all.size() ? all[i + 1].startSigma : 0.0;
        const double edgeSigma =
            std::sqrt(iv.startSigma * iv.startSigma + endSigma * endSigma) / fit.unit;
        if (!inProgress || !iv.on)
            out.elements.push_back({ kind, iv.start, iv.duration, units, edgeSigma });
        if (iv.on) {
            if (inProgress)
                break;
            if (code.isEmpty())
                charStart = iv.start;
            code += kind == ElementKind::Dit
                ? QLatin1Char('.')
                : (kind == ElementKind::Dah ? QLatin1Char('-') : QLatin1Char('L'));
            charEnd = iv.start + iv.duration;
            markUnits.push_back(units);
            continue;
        }
        if (kind == ElementKind::IntraGap) {
            if (inProgress)
                break;
            continue;
        }
        if (code.isEmpty() && i == 0)
            uncertain = false; // recording began in a letter gap or longer
        flush();
        if (kind == ElementKind::WordGap && !out.text.isEmpty()
            && !out.text.endsWith(QLatin1Char(' '))) {
            out.chars.push_back({ QLatin1Char(' '), QString(), iv.start, iv.start + iv.duration });
            out.text += QLatin1Char(' ');
        }
    }
    if (final)
        flush();
    out.pendingCode = code;
    return out;
}

} // namespace db::morse
