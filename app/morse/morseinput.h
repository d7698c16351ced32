#pragma once

#include "core/result.h"
#include "morse/morsetypes.h"

#include <QImage>
#include <QRect>
#include <QSize>
#include <QString>

#include <optional>
#include <vector>

namespace db::morseio {

// Brightness samples for protocols/morse from files: a CSV of samples or a video of the LED.
// Blocking; a two-minute 30 fps video takes about a second. Pure readers: no widgets.

struct Recording
{
    std::vector<morse::Sample> samples;
    QRect region; // video: the LED region in frame pixels; empty for CSV
    QImage frame; // video: a frame with the LED on (at most kPreviewWidth wide); null for CSV
    QSize frameSize; // video: the frame size of the stream (the scale of `region`)
    double frameRate = 0.0; // video: frames per second
    QString source; // "csv" or "video (codec WxH)"
};

// CSV: one sample per line, "time_s,brightness" (',' ';' or tab; any brightness scale). An
// optional header line (a first line that is not numeric) is skipped; blank lines and lines
// starting with '#' are ignored. Any other unreadable line is an error naming the line.
Result<Recording> readCsv(const QString &path);

// Video (any container/codec libavformat/libavcodec read): frames are converted to grey,
// scaled down to kAnalysisWidth and the LED region is the one with the strongest on/off
// modulation (findLedRegion), unless `region` (frame pixels) is given. The brightness of a
// frame is the mean grey level inside the region; times come from the stream's timestamps.
Result<Recording> readVideo(const QString &path, std::optional<QRect> region = std::nullopt);

// By extension: .csv/.txt/.tsv as CSV, everything else as video.
Result<Recording> readRecording(const QString &path, std::optional<QRect> region = std::nullopt);

// Parses "x,y,w,h".
std::optional<QRect> parseRegion(const QString &text);

constexpr int kAnalysisWidth = 160;
constexpr int kPreviewWidth = 640;

// A stack of small grey frames, row-major, width * height bytes each.
struct GreyFrames
{
    int width = 0;
    int height = 0;
    std::vector<std::vector<unsigned char>> frames;
};

// The region with the strongest on/off modulation: per pixel, the temporal variance minus half
// the variance of frame-to-frame differences (white noise adds equally to both, so it cancels;
// a blinking LED changes rarely between frames and keeps most of its variance). The region is
// the bounding box of the connected pixels scoring above half the best score around the best
// pixel, grown by one pixel. Empty when no pixel is modulated above the noise.
QRect findLedRegion(const GreyFrames &frames);

// The analysis frame size for frames of `frame` size: at most kAnalysisWidth wide, same aspect.
QSize analysisSize(QSize frame);
// How the luma of a camera frame lies in its first plane: 8-bit grey (also plane 0 of planar
// YUV), or packed 4:2:2 with luma in every other byte (Y U Y V, or U Y V Y).
enum class LumaLayout { Planar, Yuyv, Uyvy };
// Scales the luma of one frame (`stride` bytes per row) to a grey frame of `to` with the area
// filter readVideo uses for video frames (libswscale). Empty when a size is not positive or the
// stride too short.
std::vector<unsigned char> scaleGrey(const unsigned char *data, QSize size, int stride, QSize to,
                                     LumaLayout layout = LumaLayout::Planar);
// Mean grey level inside `region` (analysis pixels, inside the frame) of one analysis frame.
double regionMean(const std::vector<unsigned char> &frame, int width, const QRect &region);
// A region in frame pixels to analysis pixels (clipped to the frame; empty when outside it),
// and back (the frame pixels an analysis region covers).
QRect toAnalysisRegion(const QRect &frameRegion, QSize frame, QSize analysis);
QRect toFrameRegion(const QRect &analysisRegion, QSize frame, QSize analysis);

} // namespace db::morseio
