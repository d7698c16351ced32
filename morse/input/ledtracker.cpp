#include "ledtracker.h"

#include "morseinput.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace db::morseio {
namespace {
constexpr double kMinSpreadSigmas = 8.0;
constexpr double kMinSigma = 0.25; // grey levels: 8-bit quantisation of a region mean

// On short windows findLedRegion() also picks the luckiest noise pixel of a static scene, so a
// found region must really switch: the spread of its brightness (10th to 90th percentile) must
// stand kMinSpreadSigmas above its frame-to-frame noise. The noise comes from the quietest
// quarter of the frame differences (P25 of |N(0, s)| is 0.3186 s): a blinking LED changes
// between few frames, so its transitions do not count as noise.
bool switches(std::vector<double> v)
{
    if (v.size() < 8)
        return false;
    std::vector<double> d;
    d.reserve(v.size() - 1);
    for (std::size_t i = 1; i < v.size(); ++i)
        d.push_back(std::abs(v[i] - v[i - 1]));
    const auto q = d.begin() + std::ptrdiff_t(d.size() / 4);
    std::nth_element(d.begin(), q, d.end());
    const double sigma = std::max(kMinSigma, *q / 0.3186 / std::sqrt(2.0));
    std::sort(v.begin(), v.end());
    const double spread = v[v.size() * 9 / 10] - v[v.size() / 10];
    return spread >= kMinSpreadSigmas * sigma;
}
} // namespace

void LiveLedTracker::reset()
{
    m_window = {};
    m_times.clear();
    m_recent.clear();
    m_region = {};
    m_size = {};
    m_state = State::Searching;
    m_lastT = kNever;
    m_lastSampleT = kNever;
    m_lastSearch = kNever;
    m_step = 0.0; // the user region (m_user) is applied again once push() knows the frame size
}

void LiveLedTracker::setUserRegion(std::optional<QRect> region)
{
    m_user = region;
    m_recent.clear();
    if (m_user && !m_size.isEmpty()) {
        m_region = *m_user & QRect(QPoint(0, 0), m_size);
        m_state = m_region.isEmpty() ? State::Searching : State::Tracking;
    } else {
        m_region = {};
        m_state = State::Searching;
        m_lastSearch = kNever; // search the current window at the next frame
    }
}

std::vector<morse::Sample> LiveLedTracker::push(double t, std::vector<unsigned char> frame,
                                                QSize size)
{
    std::vector<morse::Sample> out;
    if (size.isEmpty() || frame.size() != std::size_t(size.width() * size.height())
        || !std::isfinite(t))
        return out;
    if (size != m_size) {
        reset();
        m_size = size;
        m_window.width = size.width();
        m_window.height = size.height();
        if (m_user)
            setUserRegion(m_user);
    }
    if (t <= m_lastT)
        return out;
    m_lastT = t;
    m_window.frames.push_back(std::move(frame));
    m_times.push_back(t);
    while (m_times.size() > kMaxFrames || t - m_times.front() > kWindow) {
        m_times.pop_front();
        m_window.frames.erase(m_window.frames.begin()); // moves the frames' handles only
    }
    if (m_state == State::Tracking) {
        const morse::Sample s { t, regionMean(m_window.frames.back(), m_size.width(), m_region) };
        out.push_back(s);
        m_lastSampleT = t;
        if (!m_user)
            watch(s);
        return out;
    }
    search(t, out);
    return out;
}

void LiveLedTracker::search(double now, std::vector<morse::Sample> &out)
{
    const std::size_t n = m_times.size();
    if (n < 8 || now - m_lastSearch < kRetry)
        return;
    // Full window: the buffered frames plus one frame period span kWindow.
    const double span = m_times.back() - m_times.front();
    if (n < kMaxFrames && span + span / double(n - 1) < kWindow)
        return;
    m_lastSearch = now;
    const QRect r = findLedRegion(m_window);
    if (r.isEmpty())
        return;
    std::vector<double> values;
    values.reserve(n);
    for (const std::vector<unsigned char> &f : m_window.frames)
        values.push_back(regionMean(f, m_size.width(), r));
    if (!switches(values))
        return;
    m_region = r;
    m_state = State::Tracking;
    m_recent.clear();
    const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
    m_step = *hi - *lo;
    for (std::size_t i = 0; i < n; ++i) {
        if (m_times[i] > m_lastSampleT) { // after a loss: never repeat a time already sent
            out.push_back({ m_times[i], values[i] });
            m_recent.push_back(out.back());
        }
    }
    m_lastSampleT = m_times.back();
}

void LiveLedTracker::watch(const morse::Sample &s)
{
    m_recent.push_back(s);
    while (m_recent.size() > 2 && s.t - m_recent[1].t >= kDeadAfter)
        m_recent.pop_front();
    if (s.t - m_recent.front().t < kDeadAfter)
        return;
    const auto [lo, hi] = std::minmax_element(
        m_recent.begin(), m_recent.end(),
        [](const morse::Sample &a, const morse::Sample &b) { return a.value < b.value; });
    if (hi->value - lo->value >= kDeadFraction * m_step)
        return;
    m_region = {};
    m_recent.clear();
    m_state = State::Lost;
    m_lastSearch = kNever;
}

} // namespace db::morseio
