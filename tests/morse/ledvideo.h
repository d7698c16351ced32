#pragma once

// Renders a video of a simulated LED for the Morse tests: a bright round blob that blinks with
// a generated Morse signal (protocols/morse signalgenerator, exposure blur and frame times
// included) on a textured, noisy grey background. Deterministic per seed.
#include "morse/signalgenerator.h"
#include "morse/videowriter.h"

#include <QPoint>
#include <QString>

#include <algorithm>
#include <cmath>
#include <vector>

namespace morsetest {

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

inline db::Result<void> renderLedVideo(const QString &path, db::morse::SignalOptions signal,
                                       const LedScene &scene = {})
{
    signal.amplitude = 1.0;
    signal.ambient = 0.0;
    signal.drift = 0.0;
    signal.gainDrift = 0.0;
    signal.snrDb = std::numeric_limits<double>::infinity(); // noise comes from the pixels
    const db::morse::Signal sig = db::morse::generateSignal(signal);
    const int fps = static_cast<int>(std::lround(signal.sampleRate));
    unsigned state = signal.seed * 2654435761u + 1u;
    auto gauss = [&state] { // uniform, sigma 1 (cheap; the decoder only sees region means)
        state = state * 1664525u + 1013904223u;
        return (double(state >> 8) / double(1u << 24) - 0.5) * std::sqrt(12.0);
    };
    // Background texture and LED coverage per pixel, computed once.
    std::vector<double> base(std::size_t(scene.width * scene.height));
    std::vector<double> cover(base.size());
    for (int y = 0; y < scene.height; ++y) {
        for (int x = 0; x < scene.width; ++x) {
            const double dx = x - scene.led.x();
            const double dy = y - scene.led.y();
            const double r = std::sqrt(dx * dx + dy * dy);
            const auto i = std::size_t(y * scene.width + x);
            base[i] = scene.background + 25.0 * std::sin(x * 0.09) * std::cos(y * 0.07);
            cover[i] = std::clamp(scene.radius + 1.0 - r, 0.0, 1.0) * scene.ledOn;
        }
    }
    return db::morseio::writeGreyVideo(
        path, scene.width, scene.height, fps, static_cast<int>(sig.samples.size()),
        [&](int f, unsigned char *grey) {
            const double on =
                scene.ledVisible ? std::clamp(sig.samples[std::size_t(f)].value, 0.0, 1.0) : 0.0;
            for (std::size_t i = 0; i < base.size(); ++i) {
                const double v = base[i] + cover[i] * on + scene.noise * gauss();
                grey[i] = static_cast<unsigned char>(std::clamp(v, 0.0, 255.0));
            }
        });
}

} // namespace morsetest
