#pragma once

#include "morsetypes.h"

#include <vector>

namespace db::morse {

// The Morse unit (dit length) and duty offset that best explain a run of intervals.
//
// Marks last 1 or 3 units, gaps 1, 3 or 7+ units. For every candidate unit u on a log grid
// (2 % steps) the cost is the sum over intervals of min_k ln(d / (k u))^2, capped at
// ln(1.8)^2 so glitches and the free-length pauses between repetitions cannot dominate; gaps
// longer than 5 u are word or repeat gaps and cost nothing. Sub-multiples lose because dahs
// and letter gaps no longer fit, multiples because dits no longer fit. The best grid point is
// refined by least squares on the assigned multiples, with a duty offset: marks are k u + duty,
// gaps k u - duty (exposure, camera gamma and LED drivers stretch or shrink the on-time).
struct UnitFit
{
    bool valid = false;
    double unit = 0.0; // seconds
    double duty = 0.0; // seconds added to every mark and taken from every gap
    double quality = 0.0; // fraction of fitted intervals within 45 % of their multiple
    int used = 0; // intervals that took part
};

struct UnitRange
{
    double min = 0.04; // s
    double max = 0.5; // s
};

UnitFit fitUnit(const std::vector<Interval> &intervals, UnitRange range = {});

} // namespace db::morse
