// The frame-level check of a reading (framecheck.h) on samples rendered here: a dah whose first
// frame noise darkened, which the lengths between threshold crossings read as a dit.
#include "morse/decode/framecheck.h"
#include "morse/decode/levelslicer.h"
#include "morse/decode/morsecode.h"

#include <QTest>

#include <cmath>
#include <random>

using namespace db::morse;

namespace {

constexpr double kUnit = 0.2; // s
constexpr double kRate = 15.0; // camera frames per second: 3 per unit
constexpr double kLow = 10.0;
constexpr double kHigh = 50.0;

struct Rendered
{
    std::vector<Sample> samples;
    RegionModel region; // from, to and unit set; the levels are estimated
};

// `text` between 1.5 units of dark on either side, point-sampled; marks' and gaps' lengths in
// units from `lengths` where given (else nominal). `darken`: the first frame of mark number
// `darken` lies `depth` of the contrast below the lit level. Gaussian noise of `sigma`.
Rendered render(const QString &text, const std::map<std::size_t, double> &lengths, int darken,
                double depth, double sigma, unsigned seed)
{
    std::vector<std::pair<bool, double>> parts { { false, 1.5 } };
    const std::vector<double> units = messageElements(text, 1.5);
    for (std::size_t i = 0; i < units.size(); ++i)
        parts.push_back({ i % 2 == 0, units[i] });
    for (const auto &[at, units] : lengths)
        parts[at].second = units;
    std::vector<std::tuple<double, double, bool>> spans; // start, end, lit
    double t = 0.0;
    for (const auto &[on, units] : parts) {
        spans.emplace_back(t, t + units * kUnit, on);
        t += units * kUnit;
    }
    std::mt19937 rng(seed);
    std::normal_distribution<double> noise(0.0, sigma);
    Rendered r;
    int mark = -1;
    double darkenedAt = -1.0;
    for (const auto &[start, end, on] : spans) {
        if (on && ++mark == darken)
            darkenedAt = std::ceil(start * kRate) / kRate;
    }
    for (double s = 0.0; s < t; s += 1.0 / kRate) {
        bool on = false;
        for (const auto &[start, end, lit] : spans) {
            if (s >= start && s < end)
                on = lit;
        }
        double v = on ? kHigh : kLow;
        if (std::abs(s - darkenedAt) < 1e-9)
            v = kHigh - depth * (kHigh - kLow);
        r.samples.push_back({ s, v + noise(rng) });
    }
    r.region.from = 0.0;
    r.region.to = t;
    r.region.unit = kUnit;
    r.region.relJitter = 0.17;
    return r;
}

// The length in units of mark `index` as the level slicer measures it.
double slicedMark(const std::vector<Sample> &samples, std::size_t index)
{
    // Three times in a row: the slicer needs a few seconds to find the levels.
    const double length = samples.back().t + 1.0 / kRate;
    LevelSlicer slicer;
    for (int pass = 0; pass < 3; ++pass) {
        for (const Sample &s : samples)
            slicer.feed({ s.t + pass * length, s.value });
    }
    std::vector<double> marks;
    for (const Interval &iv : slicer.intervals()) {
        if (iv.on && iv.start > 2.0 * length)
            marks.push_back(iv.duration / kUnit);
    }
    return index < marks.size() ? marks[index] : -1.0;
}

} // namespace

class TstFrameCheck : public QObject
{
    Q_OBJECT

private slots:
    void estimatesLevelsAndNoise()
    {
        const Rendered r = render(QStringLiteral("MC"), {}, -1, 0.0, 4.0, 1);
        RegionModel m = r.region;
        QVERIFY(estimateLevels(r.samples, &m));
        QVERIFY2(std::abs(m.low - kLow) < 2.0, qPrintable(QString::number(m.low)));
        QVERIFY2(std::abs(m.high - kHigh) < 2.0, qPrintable(QString::number(m.high)));
        QVERIFY2(m.sigma > 3.0 && m.sigma < 5.5, qPrintable(QString::number(m.sigma)));
    }

    // '1' (.----) whose first dah is 27 % short (2.2 units) and whose first frame noise pulled
    // below the threshold: the slicer measures that mark under 2 units in some seeds (a
    // dit: '2', ..---), the samples fit '1' better in every one. And a clean '2' stays '2'. Noise
    // 10 (a quarter of the contrast: 6 dB), eight seeds.
    void readsTheDigitThatWasSent()
    {
        int cutToADit = 0;
        for (unsigned seed = 1; seed <= 8; ++seed) {
            // parts: 0 dark, 1 dit, 2 gap, 3 dah. The dark before puts the dah's first frame
            // at its start: undarkened, the slicer measures 2.18 units.
            const Rendered one =
                render(QStringLiteral("1"), { { 0, 1.3 }, { 3, 2.2 } }, 1, 0.65, 10.0, seed);
            cutToADit += slicedMark(one.samples, 1) < 2.0 ? 1 : 0;
            RegionModel m = one.region;
            QVERIFY(estimateLevels(one.samples, &m));
            const double asOne = regionLogLikelihood(one.samples, m, QStringLiteral("1"));
            const double asTwo = regionLogLikelihood(one.samples, m, QStringLiteral("2"));
            QVERIFY2(
                asOne > asTwo + 1.0,
                qPrintable(
                    QStringLiteral("seed %1: '1' %2, '2' %3").arg(seed).arg(asOne).arg(asTwo)));

            const Rendered two = render(QStringLiteral("2"), {}, -1, 0.0, 10.0, seed);
            m = two.region;
            QVERIFY(estimateLevels(two.samples, &m));
            QVERIFY(regionLogLikelihood(two.samples, m, QStringLiteral("2"))
                    > regionLogLikelihood(two.samples, m, QStringLiteral("1")) + 1.0);
        }
        // The scenario: in some seeds (2 of 8), the lengths alone read that dah as a dit.
        QVERIFY2(cutToADit >= 2, qPrintable(QString::number(cutToADit)));
    }

    // Readings with more or fewer characters than were sent lose clearly: the grid cells'
    // probabilities are normalised, so element counts do not bias the comparison.
    void countsCharactersFairly()
    {
        const Rendered r = render(QStringLiteral("15"), {}, -1, 0.0, 10.0, 3);
        RegionModel m = r.region;
        QVERIFY(estimateLevels(r.samples, &m));
        const double sent = regionLogLikelihood(r.samples, m, QStringLiteral("15"));
        for (const QString &other : { QStringLiteral("1"), QStringLiteral("5"),
                                      QStringLiteral("115"), QStringLiteral("155") }) {
            QVERIFY2(sent > regionLogLikelihood(r.samples, m, other) + 5.0, qPrintable(other));
        }
    }

    void rejectsWhatCannotFit()
    {
        const Rendered r = render(QStringLiteral("5"), {}, -1, 0.0, 10.0, 4);
        RegionModel m = r.region;
        QVERIFY(estimateLevels(r.samples, &m));
        QVERIFY(std::isinf(regionLogLikelihood(r.samples, m, QStringLiteral("#"))));
        QVERIFY(std::isinf(regionLogLikelihood({}, m, QStringLiteral("5"))));
        RegionModel reversed = m;
        std::swap(reversed.from, reversed.to);
        QVERIFY(std::isinf(regionLogLikelihood(r.samples, reversed, QStringLiteral("5"))));
        // Far more marks than the region holds.
        QVERIFY(std::isinf(regionLogLikelihood(r.samples, m, QStringLiteral("00000"))));
        // A region far longer than the text: a gap in time of hours between the samples at its
        // ends. Nothing is allocated for the length of the gap.
        for (const double gap : { 1e9, 1e8, 1e7 }) {
            std::vector<Sample> apart = r.samples;
            for (const Sample &s : r.samples)
                apart.push_back({ s.t + r.region.to + gap, s.value });
            RegionModel wide = m;
            wide.to = apart.back().t;
            QVERIFY(std::isinf(regionLogLikelihood(apart, wide, QStringLiteral("5"))));
        }
        // Levels: too few samples, or no contrast.
        RegionModel none;
        QVERIFY(!estimateLevels(std::span(r.samples).first(4), &none));
        const std::vector<Sample> flat(50, Sample { 0.0, 7.0 });
        QVERIFY(!estimateLevels(flat, &none));
    }
};

QTEST_GUILESS_MAIN(TstFrameCheck)
#include "tst_framecheck.moc"
