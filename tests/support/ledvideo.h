#pragma once

// Renders a video of a simulated LED for the Morse tests: a bright round blob that blinks with
// a generated Morse signal (morse/synth signal generator, exposure blur and frame times
// included) on a textured, noisy grey background. Deterministic per seed.
#include "morse/input/videowriter.h"
#include "morse/synth/signalgenerator.h"

#include <QPoint>
#include <QString>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace morsetest {

// The signal the LED tests blink: `text` at `rate` samples (frames) per second, a 100 ms dit
// with 10 % jitter, three repetitions starting `startOffset` into the message.
inline db::morse::SignalOptions ledSignal(const QString &text, double rate, unsigned seed,
                                          double startOffset = 0.6)
{
    db::morse::SignalOptions o;
    o.text = text;
    o.sampleRate = rate;
    o.unit = 0.1;
    o.startOffset = startOffset;
    o.jitter = 0.1;
    o.repetitions = 3;
    o.seed = seed;
    return o;
}

struct LedScene
{
    int width = 160;
    int height = 120;
    QPoint led { 112, 38 };
    int radius = 5;
    double noise = 6.0; // grey levels, per pixel and frame
    double background = 70.0;
    double ledOn = 160.0; // added to the background at full on
    bool ledVisible = true;
};

// The scene's frames one at a time (for videos and for frames pushed into a live source):
// frame f of the generated signal as width * height grey bytes. Draw frames in order: the
// pixel noise is one deterministic sequence.
class LedRenderer
{
public:
    LedRenderer(db::morse::SignalOptions signal, const LedScene &scene = {})
        : m_scene(scene)
    {
        signal.amplitude = 1.0;
        signal.ambient = 0.0;
        signal.drift = 0.0;
        signal.gainDrift = 0.0;
        signal.snrDb = std::numeric_limits<double>::infinity(); // noise comes from the pixels
        m_signal = db::morse::generateSignal(signal);
        m_fps = static_cast<int>(std::lround(signal.sampleRate));
        m_state = signal.seed * 2654435761u + 1u;
        // Background texture and LED coverage per pixel, computed once.
        m_base.resize(std::size_t(scene.width * scene.height));
        m_cover.resize(m_base.size());
        for (int y = 0; y < scene.height; ++y) {
            for (int x = 0; x < scene.width; ++x) {
                const double dx = x - scene.led.x();
                const double dy = y - scene.led.y();
                const double r = std::sqrt(dx * dx + dy * dy);
                const auto i = std::size_t(y * scene.width + x);
                m_base[i] = scene.background + 25.0 * std::sin(x * 0.09) * std::cos(y * 0.07);
                m_cover[i] = std::clamp(scene.radius + 1.0 - r, 0.0, 1.0) * scene.ledOn;
            }
        }
    }

    const db::morse::Signal &signal() const { return m_signal; }
    int fps() const { return m_fps; }
    int frames() const { return static_cast<int>(m_signal.samples.size()); }

    // Pixel noise: uniform, sigma 1 (cheap; the decoder only sees region means). The loop calls
    // no function, so that it stays fast where test code is compiled without optimisation (and
    // instrumented, in the sanitizer build): this is most of the Morse video tests' time.
    void draw(int f, unsigned char *grey)
    {
        const double on =
            m_scene.ledVisible ? std::clamp(m_signal.samples[std::size_t(f)].value, 0.0, 1.0) : 0.0;
        const double *base = m_base.data();
        const double *cover = m_cover.data();
        const std::size_t n = m_base.size();
        const double noise = m_scene.noise;
        const double spread = std::sqrt(12.0);
        unsigned state = m_state;
        for (std::size_t i = 0; i < n; ++i) {
            state = state * 1664525u + 1013904223u;
            const double gauss = (double(state >> 8) / double(1u << 24) - 0.5) * spread;
            const double v = base[i] + cover[i] * on + noise * gauss;
            grey[i] = static_cast<unsigned char>(v < 0.0 ? 0.0 : (v > 255.0 ? 255.0 : v));
        }
        m_state = state;
    }

private:
    LedScene m_scene;
    db::morse::Signal m_signal;
    int m_fps = 0;
    unsigned m_state = 0;
    std::vector<double> m_base;
    std::vector<double> m_cover;
};

inline db::Result<void> renderLedVideo(const QString &path, db::morse::SignalOptions signal,
                                       const LedScene &scene = {})
{
    LedRenderer renderer(std::move(signal), scene);
    return db::morseio::writeGreyVideo(path, scene.width, scene.height, renderer.fps(),
                                       renderer.frames(),
                                       [&](int f, unsigned char *grey) { renderer.draw(f, grey); });
}

} // namespace morsetest
