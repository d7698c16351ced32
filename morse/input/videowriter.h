#pragma once

#include "core/result.h"

#include <QString>

#include <functional>

namespace db::morseio {

// Writes a small MPEG-4 Part 2 video with libavcodec (the encoder every FFmpeg build has), for
// tests and demos that need a real video file of a simulated LED. `draw(frame, grey)` fills the
// grey (luma) plane of each frame, width * height bytes, row-major; chroma is neutral.
// Blocking.
Result<void> writeGreyVideo(const QString &path, int width, int height, int fps, int frames,
                            const std::function<void(int, unsigned char *)> &draw);

} // namespace db::morseio
