#pragma once

#include "core/result.h"
#include "morse/decode/morsetypes.h"

#include <QIODevice>
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
    QImage
        frame; // video: a frame with the LED on (at most kPreviewWidth wide and high); null for CSV
    QSize frameSize; // video: the frame size of the stream (the scale of `region`)
    double frameRate = 0.0; // video: frames per second
    QString source; // "csv" or "video (codec WxH)"
};

// CSV: one sample per line, "time_s,brightness" (',' ';' or tab; any brightness scale). An
// optional header line (a first line that is not numeric) is skipped; blank lines and lines
// starting with '#' are ignored. Any other unreadable line is an error naming the line, and so
// are times or brightness that are not finite, negative times, times that repeat or go back
// (rows out of order), lines longer than kMaxCsvLine and more than kMaxCsvSamples samples.
Result<Recording> readCsv(const QString &path);
// The same from any open device; `origin` names it in errors.
Result<Recording> readCsv(QIODevice &device, const QString &origin);
constexpr int kMaxCsvLine = 256; // characters
constexpr std::size_t kMaxCsvSamples = 10'000'000; // 160 MB; 2.7 h at 1 kHz

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
// readVideo() keeps the analysis frames of the whole video (the LED region is searched on all of
// them) up to this many bytes: 20 minutes at 30 fps of 16:9 frames. Longer videos are refused.
constexpr std::size_t kMaxVideoBytes = std::size_t(1) << 29;
constexpr std::size_t kMaxPreviews = 32; // preview frames kept to pick one with the LED on

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
