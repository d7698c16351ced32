// Timeline -> stretches between word gaps, and the element model, for messageparser.
#include "messageparser.h"
#include "morsecode.h"
#include "symbolizer.h"

#include <algorithm>
#include <cmath>

namespace db::morse {
namespace {

// A mark shorter than this (units) between two gaps of at least a letter gap that make a word
// gap with it is a noise spike in the pause between two messages, not a character: the
// message grammar has no character of one dit, and a dit 30 % short is 0.7 units.
constexpr double kSpike = 0.6;

bool isGap(const Element &e)
{
    return e.kind == ElementKind::IntraGap || e.kind == ElementKind::LetterGap
        || e.kind == ElementKind::WordGap;
}

// Whether timeline[i] is such a spike; the gap after it is closed (not the one in progress).
bool isSpike(const std::vector<Element> &timeline, std::size_t i)
{
    const Thresholds t;
    if (i == 0 || i + 2 >= timeline.size() || timeline[i].kind != ElementKind::Dit
        || timeline[i].units >= kSpike)
        return false;
    const Element &before = timeline[i - 1];
    const Element &after = timeline[i + 1];
    return isGap(before) && isGap(after) && before.units >= t.letterGap
        && after.units >= t.letterGap
        && before.units + timeline[i].units + after.units >= t.wordGap;
}

// Marks after which a stretch is closed at the next message boundary: messages sent back to back
// run together into one stretch, up to the whole recording, and every update parses the open
// stretch anew. About four messages (60-110 marks each).
constexpr std::size_t kLongStretch = 400;

// Whether the last character of `s` (its marks after the last letter gap) reads ':' hard.
bool endsInColon(const StretchInput &s)
{
    const Thresholds t;
    QString code;
    for (std::size_t i = s.marks.size(); i-- > 0;) {
        code.prepend(s.marks[i] >= t.dah ? QLatin1Char('-') : QLatin1Char('.'));
        if (i == 0 || s.gaps[i - 1] >= t.letterGap)
            break;
    }
    return code == codeFor(QLatin1Char(':'));
}

} // namespace

std::vector<StretchInput> splitStretches(const std::vector<Element> &timeline)
{
    std::vector<StretchInput> out;
    StretchInput cur;
    cur.openStart = true;
    bool endsInLetterGap = false;
    auto close = [&](bool open) {
        if (open && !endsInLetterGap) {
            // Keep complete characters only.
            std::size_t g = cur.gaps.size();
            while (g > 0 && cur.gaps[g - 1] < 2.0)
                --g;
            cur.marks.resize(g);
            cur.gaps.resize(g > 0 ? g - 1 : 0);
            cur.markSigma.resize(cur.marks.size());
            cur.gapSigma.resize(cur.gaps.size());
            cur.markTimes.resize(cur.marks.size());
        }
        // A stretch closed by a long mark ends in the gap before it: no gap follows its last
        // mark (before, such a stretch failed parseStretch()'s size check and was never read).
        if (!cur.marks.empty() && cur.gaps.size() >= cur.marks.size()) {
            cur.gaps.resize(cur.marks.size() - 1);
            cur.gapSigma.resize(std::min(cur.gapSigma.size(), cur.gaps.size()));
        }
        cur.openEnd = open;
        if (!cur.marks.empty())
            out.push_back(cur);
        cur = {};
        endsInLetterGap = false;
    };
    for (std::size_t i = 0; i < timeline.size(); ++i) {
        const Element &e = timeline[i];
        const bool last = i + 1 == timeline.size();
        if (isSpike(timeline, i)) {
            // The pause between two messages: the stretch ends at the gap before the spike,
            // and the spike and the gap after it are skipped.
            const Element &after = timeline[i + 1];
            const double pause = timeline[i - 1].units + e.units + after.units;
            if (!cur.marks.empty()) {
                if (cur.gaps.size() == cur.marks.size()) { // the gap before, as a letter gap
                    cur.gaps.pop_back();
                    cur.gapSigma.pop_back();
                }
                cur.gapAfter = pause;
                cur.gapAfterSigma = after.edgeSigma;
                close(false);
            } else if (!out.empty() && timeline[i - 1].kind == ElementKind::WordGap) {
                out.back().gapAfter = pause;
                out.back().gapAfterSigma = after.edgeSigma;
            }
            ++i;
            continue;
        }
        switch (e.kind) {
        case ElementKind::LongMark:
            close(false);
            break;
        case ElementKind::Dit:
        case ElementKind::Dah:
            if (cur.marks.empty())
                cur.start = e.start;
            if (cur.marks.size() > cur.gaps.size()) {
                cur.gaps.push_back(1.0); // cannot happen after symbolize(); keeps sizes paired
                cur.gapSigma.push_back(0.0);
            }
            cur.marks.push_back(e.units);
            cur.markSigma.push_back(e.edgeSigma);
            cur.markTimes.push_back(e.start);
            endsInLetterGap = false;
            break;
        case ElementKind::WordGap:
            cur.gapAfter = e.units;
            cur.gapAfterSigma = e.edgeSigma;
            close(false);
            break;
        case ElementKind::IntraGap:
        case ElementKind::LetterGap:
            if (i == 0) {
                cur.firstComplete = e.kind == ElementKind::LetterGap;
                break;
            }
            if (last) {
                endsInLetterGap = e.kind == ElementKind::LetterGap;
                break;
            }
            if (e.kind == ElementKind::LetterGap && cur.marks.size() >= kLongStretch
                && cur.gaps.size() + 1 == cur.marks.size() && endsInColon(cur)) {
                // A long stretch ends after a message: the letter gap read as its pause.
                cur.gapAfter = e.units;
                cur.gapAfterSigma = e.edgeSigma;
                close(false);
                break;
            }
            if (!cur.marks.empty()) {
                cur.gaps.push_back(e.units);
                cur.gapSigma.push_back(e.edgeSigma);
            }
            break;
        }
    }
    close(true);
    return out;
}

StretchInput joinStretches(const StretchInput &a, const StretchInput &b)
{
    StretchInput out = a;
    out.gaps.push_back(a.gapAfter);
    out.marks.insert(out.marks.end(), b.marks.begin(), b.marks.end());
    out.gaps.insert(out.gaps.end(), b.gaps.begin(), b.gaps.end());
    // Sigmas missing in either part (StretchInput allows that) are 0.
    out.markSigma.resize(a.marks.size());
    out.markSigma.insert(out.markSigma.end(), b.markSigma.begin(), b.markSigma.end());
    out.markSigma.resize(out.marks.size());
    out.gapSigma.resize(a.gaps.size());
    out.gapSigma.push_back(a.gapAfterSigma);
    out.gapSigma.insert(out.gapSigma.end(), b.gapSigma.begin(), b.gapSigma.end());
    out.gapSigma.resize(out.gaps.size());
    if (a.markTimes.size() == a.marks.size() && b.markTimes.size() == b.marks.size())
        out.markTimes.insert(out.markTimes.end(), b.markTimes.begin(), b.markTimes.end());
    else
        out.markTimes.clear();
    out.openEnd = b.openEnd;
    out.gapAfter = b.gapAfter;
    out.gapAfterSigma = b.gapAfterSigma;
    return out;
}

ElementModel estimateModel(const std::vector<Element> &timeline, double samplePeriodUnits)
{
    std::vector<double> r;
    for (const Element &e : timeline) {
        const bool one = e.kind == ElementKind::Dit || e.kind == ElementKind::IntraGap;
        const bool three = e.kind == ElementKind::Dah || e.kind == ElementKind::LetterGap;
        if ((one || three) && e.units > 0.0)
            r.push_back(std::abs(std::log(e.units / (one ? 1.0 : 3.0))));
    }
    ElementModel m;
    m.absSigma = std::max(0.05, 0.4 * samplePeriodUnits);
    if (r.size() >= 8) {
        auto mid = r.begin() + static_cast<std::ptrdiff_t>(r.size() / 2);
        std::nth_element(r.begin(), mid, r.end());
        const double spread = 1.4826 * *mid;
        m.relJitter = std::clamp(
            std::sqrt(std::max(0.0, spread * spread - m.absSigma * m.absSigma)), 0.04, 0.3);
    }
    return m;
}

} // namespace db::morse
