#pragma once

#include "morsetypes.h"

#include <deque>
#include <vector>

namespace db::morse {

// Brightness samples -> on/off intervals with sub-sample edge times.
//
// 1. A boxcar of kSmoothTime (12 ms, well under the shortest dit) averages fast sample streams
//    (1 kHz photodiodes); camera frames pass through unchanged. Edges are delayed equally.
// 2. Searching: the LED counts as found when the last kWindow seconds are bimodal: the medians
//    of the samples below and above the middle of the 5th/95th percentiles differ by more than
//    kMinContrast noise sigmas (noise from the median of successive differences, so it ignores
//    the steps) and the signal crosses the middle at least twice.
// 3. Tracking: decision-directed levels. `low` follows the mean of samples that are clearly
//    off, the contrast `high - low` that of clearly-on samples minus `low` (time constant
//    kLevelTau), so ambient light, drift and auto exposure move the threshold
//    (low + high) / 2 with them, also through long dark gaps. Where the contrast is at least
//    8 noise sigmas, both levels also follow a common slope (alpha-beta tracker), so that a
//    ramp of ambient light does not leave them behind. Every 50 ms, two parallel lines are also
//    fitted to the clearly-off and clearly-on samples of the last kWindow seconds; where their
//    common slope is significant (4 standard errors), they give the levels instead, so that a
//    ramp or an auto-exposure swing is followed without lag in noise too. A hysteresis of
//    kHysteresis * (high - low) decides the state; the edge time is the linear interpolation of the
//    threshold crossing between two samples, and its standard deviation from noise
//    (Interval::startSigma) is the noise sigma over the step between them per second, at most a
//    sample period: the parser trusts a steep edge more than one between two noisy samples near
//    the threshold. An interval shorter than one sample period is noise
//    and merged into the one before, unless one of its samples lies more than kKeepSigmas noise
//    sigmas beyond the threshold (a real element cut short by the frame grid, e.g. a dit of 1.3
//    frame periods).
// 4. Watchdog: with no edge for kQuiet seconds the window is checked again; if it is bimodal
//    the levels were lost (exposure jump) and are set anew, otherwise the LED is idle.
//
// Not thread-safe; feed samples in time order.
class LevelSlicer
{
public:
    void feed(const Sample &sample);

    // Closed intervals, in time order. The first one is truncated.
    const std::vector<Interval> &intervals() const { return m_intervals; }
    // The interval still open at the last sample (duration up to lastTime()).
    Interval openInterval() const;

    bool found() const { return m_found; } // modulation seen at least once
    bool idle() const { return m_idle; } // found, but no edge for kQuiet seconds
    double lastTime() const { return m_lastT; }
    double low() const { return m_low; }
    double high() const { return m_high; }
    double noise() const { return m_noise; } // sigma of the smoothed signal
    double samplePeriod() const { return m_period; } // mean, s
    int invalidSamples() const { return m_invalid; }
    int validSamples() const { return m_valid; }

private:
    struct Point
    {
        double t;
        double x; // smoothed
        double raw; // for the noise estimate
    };
    void process(const Point &p);
    bool bimodal(double *low, double *high);
    void edge(double t, double sigma);
    // Two parallel lines through the clearly-off and clearly-on samples of the window; sets the
    // levels and the slope from them and returns true where the slope is significant.
    bool fitLines(double now);
    // Standard deviation (s) from noise of a threshold crossing interpolated between two
    // samples `dt` apart.
    double crossingSigma(double before, double after, double dt) const;

    std::deque<Sample> m_smooth;
    double m_smoothSum = 0.0;
    double m_smoothTSum = 0.0;
    std::deque<Point> m_window;

    std::vector<Interval> m_intervals;
    // How far the farthest sample of the last closed interval (and of the open one) lay beyond
    // the threshold, in the interval's direction.
    double m_lastPeak = 0.0;
    double m_openPeak = 0.0;
    double m_lastFit = -1e300;
    bool m_fitted = false; // the levels come from fitLines() until the next fit
    bool m_found = false;
    bool m_tracking = false;
    bool m_idle = false;
    bool m_on = false;
    bool m_firstOpen = true;
    double m_openStart = 0.0;
    double m_openSigma = 0.0; // startSigma of the open interval
    double m_lastEdge = 0.0;
    double m_lastCheck = -1e300;
    double m_low = 0.0;
    double m_high = 0.0;
    double m_slope = 0.0; // common drift of both levels, per second
    double m_noise = 0.0;
    double m_prevT = 0.0;
    double m_prevX = 0.0;
    double m_cross = -1e300; // time of the last threshold crossing
    double m_crossSigma = 0.0; // its standard deviation from noise, s
    double m_lastT = -1e300;
    double m_rawPrev = 0.0;
    double m_period = 0.0; // mean sample period
    int m_invalid = 0;
    int m_valid = 0;
};

} // namespace db::morse
