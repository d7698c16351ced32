#pragma once

#include "morsetypes.h"

#include <QString>

#include <span>

namespace db::morse {

// Frame-level check of a reading. The sequence decoder (messageparser.h) reads the lengths
// between threshold crossings. A noisy frame next to an edge moves a crossing by a whole frame,
// which at 3 frames per dit turns a dah of 2.2 units (30 % jitter) into one of 1.8: the lengths
// then fit the wrong digit better, and two messages disagree. The samples themselves say more:
// this check scores a reading of a region against every sample in it.
//
// Model: the region begins and ends in dark of any length; between them, the characters of
// `text` with ITU timing. Each element's length is Gaussian-Huber around its nominal (relative
// spread relJitter, as ElementModel) after the duty correction; each sample is Gaussian around the
// level of the LED state at its time (point sampling: a frame that saw part of an edge fits
// either state, at a cost). The likelihood sums over all edge positions on a grid of a sample
// period (within a 16th and a third of a unit; forward algorithm), so that no single crossing
// decides.
struct RegionModel
{
    double from = 0.0; // s: the region, dark at both ends
    double to = 0.0;
    double unit = 0.0; // s
    double duty = 0.0; // s added to every mark (UnitFit::duty)
    double relJitter = 0.15;
    double low = 0.0; // brightness of the dark LED at `from`
    double high = 1.0; // of the lit LED
    double lowSlope = 0.0; // per second: drift and auto exposure
    double highSlope = 0.0;
    double sigma = 0.1; // noise of one sample
    double levelAt(double sinceFrom, bool lit) const
    {
        return lit ? high + highSlope * sinceFrom : low + lowSlope * sinceFrom;
    }
};

// The samples (in time order) with from <= t <= to.
std::span<const Sample> samplesBetween(std::span<const Sample> samples, double from, double to);

// Sets the levels (a straight line each, through the samples below and above their middle) and
// the noise (the median distance from the nearer level) from `samples`; model->from is the
// lines' origin. False when there are too few samples or no contrast.
bool estimateLevels(std::span<const Sample> samples, RegionModel *model);

// ln p(the samples between from and to | dark, `text`, dark); -inf when the text cannot fit.
// Readings of the same region compare by this value: the difference is a log-likelihood ratio.
double regionLogLikelihood(std::span<const Sample> samples, const RegionModel &model,
                           const QString &text);

} // namespace db::morse
