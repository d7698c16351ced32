#pragma once

#include "morse/decode/morsetypes.h"
#include "morseinput.h"

#include <QRect>
#include <QSize>

#include <deque>
#include <limits>
#include <optional>
#include <vector>

namespace db::morseio {

// Finds the LED in a live stream of small grey frames (analysis pixels, see analysisSize()) and
// turns every frame into a brightness sample: the live counterpart of readVideo(). Pure, no
// Qt Multimedia; CameraSource feeds it.
//
// Contract: frames come in time order (a frame not later than the previous one is ignored); a
// change of frame size starts over. While no region is known, the last kWindow seconds of frames
// are kept and findLedRegion() runs on them once the window is full and then every kRetry
// seconds. When it finds the LED, the buffered frames come out as samples at once (the decoder
// also gets the seconds spent searching), then one sample per frame. An automatic region whose
// brightness has not moved by kDeadFraction of its on/off step for kDeadAfter seconds (LED out
// of view, camera moved) is dropped and the search starts again. A user region is never dropped.
class LiveLedTracker
{
public:
    enum class State {
        Searching, // no region yet: no samples
        Tracking, // a region: one sample per frame
        Lost, // an automatic region went dead; searching again
    };

    static constexpr double kWindow = 3.0; // s of frames findLedRegion() looks at
    static constexpr double kRetry = 2.0; // s between searches while no region is known
    // A dark stretch of the LED is at most the gap between repetitions (10 units, 5 s at the
    // slowest 500 ms unit the decoder accepts): a region that stays flat three times longer
    // has lost the LED.
    static constexpr double kDeadAfter = 15.0;
    static constexpr double kDeadFraction = 0.2;
    static constexpr std::size_t kMaxFrames = 300; // memory bound at high frame rates

    // Feeds one frame (width * height bytes, row-major) taken at `t` seconds. Returns the samples
    // this frame releases: none while searching, the whole window when the LED is found, else one.
    std::vector<morse::Sample> push(double t, std::vector<unsigned char> frame, QSize size);

    // A region in analysis pixels chosen by the user (nullopt: automatic). Takes effect at once.
    void setUserRegion(std::optional<QRect> region);
    void reset();

    State state() const { return m_state; }
    QRect region() const { return m_region; } // analysis pixels; empty while searching
    bool userRegion() const { return m_user.has_value(); }

private:
    void search(double now, std::vector<morse::Sample> &out);
    void watch(const morse::Sample &s);

    // The last kWindow seconds of frames, as findLedRegion() takes them (no copy per search),
    // and their times.
    GreyFrames m_window;
    std::deque<double> m_times;
    std::deque<morse::Sample> m_recent; // tracking: the last kDeadAfter seconds of samples
    std::optional<QRect> m_user;
    QRect m_region;
    QSize m_size;
    State m_state = State::Searching;
    static constexpr double kNever = -std::numeric_limits<double>::infinity();
    double m_lastT = kNever;
    double m_lastSampleT = kNever;
    double m_lastSearch = kNever;
    double m_step = 0.0; // on/off step of the region when found (grey levels)
};

} // namespace db::morseio
