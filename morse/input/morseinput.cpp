#include "morseinput.h"

#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>
#include <QTextStream>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libswscale/swscale.h>
}

#include <QCoreApplication>
#include <algorithm>
#include <cmath>
#include <memory>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::morse)
};
} // namespace

namespace db::morseio {
namespace {

Error ioError(const QString &message)
{
    return Error(Error::Kind::Io, message);
}

QString avText(int code)
{
    char buf[AV_ERROR_MAX_STRING_SIZE] = {};
    av_strerror(code, buf, sizeof buf);
    return QString::fromUtf8(buf);
}

// RAII for the libav objects of one decode.
struct AvFormat
{
    AVFormatContext *p = nullptr;
    ~AvFormat() { avformat_close_input(&p); }
};
struct AvCodec
{
    AVCodecContext *p = nullptr;
    ~AvCodec() { avcodec_free_context(&p); }
};
struct AvFrame
{
    AVFrame *p = av_frame_alloc();
    ~AvFrame() { av_frame_free(&p); }
};
struct AvPacket
{
    AVPacket *p = av_packet_alloc();
    ~AvPacket() { av_packet_free(&p); }
};
struct Sws
{
    SwsContext *p = nullptr;
    ~Sws() { sws_freeContext(p); }
};

// One decoded frame, converted to grey at two sizes: small for the analysis, preview for the
// panel (only kept for the frame where the region is brightest).
struct Decoded
{
    double t;
    std::vector<unsigned char> small;
};

} // namespace

std::optional<QRect> parseRegion(const QString &text)
{
    const QStringList p = text.split(QLatin1Char(','));
    if (p.size() != 4)
        return std::nullopt;
    int v[4];
    for (int i = 0; i < 4; ++i) {
        bool ok = false;
        v[i] = p[i].trimmed().toInt(&ok);
        if (!ok || v[i] < 0)
            return std::nullopt;
    }
    if (v[2] == 0 || v[3] == 0)
        return std::nullopt;
    return QRect(v[0], v[1], v[2], v[3]);
}

Result<Recording> readCsv(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return ioError(Tr::tr("cannot open %1: %2").arg(path, file.errorString()));
    Result<Recording> rec = readCsv(file, path);
    if (file.error() != QFileDevice::NoError)
        return ioError(Tr::tr("%1: %2").arg(path, file.errorString()));
    return rec;
}

Result<Recording> readCsv(QIODevice &file, const QString &path)
{
    Recording rec;
    rec.source = QStringLiteral("csv");
    static const QRegularExpression sep(QStringLiteral("[,;\\t]"));
    auto invalid = [&path](int line, const QString &what) {
        return Error(Error::Kind::InvalidArgument,
                     Tr::tr("%1:%2: %3").arg(path).arg(line).arg(what));
    };
    auto seconds = [](double t) {
        return QString::number(t, 'g', 10);
    };
    int line = 0;
    bool first = true;
    while (!file.atEnd()) {
        // One byte more than a line may have, so that a longer one is noticed, not split.
        const QByteArray raw = file.readLine(kMaxCsvLine + 2);
        ++line;
        if (raw.size() > kMaxCsvLine && !raw.endsWith('\n') && !file.atEnd())
            return invalid(line, Tr::tr("line longer than %1 characters").arg(kMaxCsvLine));
        const QString text = QString::fromUtf8(raw).trimmed();
        if (text.isEmpty() || text.startsWith(QLatin1Char('#')))
            continue;
        const QStringList f = text.split(sep);
        bool okT = false;
        bool okV = false;
        const double t = f.size() >= 2 ? f[0].trimmed().toDouble(&okT) : 0.0;
        const double v = f.size() >= 2 ? f[1].trimmed().toDouble(&okV) : 0.0;
        if (!okT || !okV) {
            if (first) { // header
                first = false;
                continue;
            }
            return invalid(
                line,
                QStringLiteral("expected \"time_s,brightness\", got \"%1\"").arg(text.left(60)));
        }
        first = false;
        // The decoder needs strictly increasing, finite times: a row out of order (rows sorted
        // wrongly, two recordings appended) or a clock that stepped back makes the file
        // ambiguous, so it is refused with the row rather than read in part.
        if (!std::isfinite(t))
            return invalid(
                line, QStringLiteral("time \"%1\" is not a finite number").arg(f[0].trimmed()));
        if (!std::isfinite(v))
            return invalid(
                line,
                QStringLiteral("brightness \"%1\" is not a finite number").arg(f[1].trimmed()));
        if (t < 0.0)
            return invalid(line, Tr::tr("time %1 s is negative").arg(seconds(t)));
        if (!rec.samples.empty() && t == rec.samples.back().t)
            return invalid(line,
                           Tr::tr("time %1 s repeats the previous row's time").arg(seconds(t)));
        if (!rec.samples.empty() && t < rec.samples.back().t)
            return invalid(line,
                           Tr::tr("time %1 s is before the previous row's %2 s "
                                  "(rows must be in time order)")
                               .arg(seconds(t), seconds(rec.samples.back().t)));
        if (rec.samples.size() >= kMaxCsvSamples)
            return invalid(line,
                           Tr::tr("more than %1 samples: cut the recording").arg(kMaxCsvSamples));
        rec.samples.push_back({ t, v });
    }
    if (rec.samples.empty())
        return Error(Error::Kind::InvalidArgument, Tr::tr("%1: no samples").arg(path));
    return rec;
}

QRect findLedRegion(const GreyFrames &g)
{
    const auto n = g.frames.size();
    const auto px = static_cast<std::size_t>(g.width * g.height);
    if (n < 8 || px == 0)
        return {};
    std::vector<double> sum(px), sum2(px), dsum2(px);
    for (std::size_t f = 0; f < n; ++f) {
        const auto &fr = g.frames[f];
        for (std::size_t i = 0; i < px; ++i) {
            const double x = fr[i];
            sum[i] += x;
            sum2[i] += x * x;
            if (f > 0) {
                const double d = x - g.frames[f - 1][i];
                dsum2[i] += d * d;
            }
        }
    }
    std::vector<double> score(px);
    std::size_t best = 0;
    for (std::size_t i = 0; i < px; ++i) {
        const double mean = sum[i] / double(n);
        const double var = sum2[i] / double(n) - mean * mean;
        score[i] = var - 0.5 * dsum2[i] / double(n - 1);
        if (score[i] > score[best])
            best = i;
    }
    // Modulated at all: the LED's on/off step must stand well above the frame-to-frame noise.
    const double noise = 0.5 * dsum2[best] / double(n - 1);
    if (score[best] < 1.0 || score[best] < 0.5 * noise)
        return {};
    // Flood fill from the best pixel over pixels above half its score.
    const double limit = 0.5 * score[best];
    std::vector<char> seen(px, 0);
    std::vector<std::size_t> stack { best };
    seen[best] = 1;
    int x0 = g.width, y0 = g.height, x1 = -1, y1 = -1;
    while (!stack.empty()) {
        const std::size_t i = stack.back();
        stack.pop_back();
        const int x = int(i % std::size_t(g.width));
        const int y = int(i / std::size_t(g.width));
        x0 = std::min(x0, x);
        y0 = std::min(y0, y);
        x1 = std::max(x1, x);
        y1 = std::max(y1, y);
        const int nb[4][2] = { { 1, 0 }, { -1, 0 }, { 0, 1 }, { 0, -1 } };
        for (const auto &d : nb) {
            const int nx = x + d[0];
            const int ny = y + d[1];
            if (nx < 0 || ny < 0 || nx >= g.width || ny >= g.height)
                continue;
            const auto j = std::size_t(ny * g.width + nx);
            if (!seen[j] && score[j] >= limit) {
                seen[j] = 1;
                stack.push_back(j);
            }
        }
    }
    return QRect(QPoint(x0, y0), QPoint(x1, y1)).adjusted(-1, -1, 1, 1)
        & QRect(0, 0, g.width, g.height);
}

QSize analysisSize(QSize frame)
{
    if (frame.width() <= 0 || frame.height() <= 0)
        return {};
    const int sw = std::min(frame.width(), kAnalysisWidth);
    return QSize(sw, std::max(1, frame.height() * sw / frame.width()));
}

namespace {

// One picture of `format` (planes and their strides) scaled to a grey frame of `to` with the
// area filter; `sws` caches the context for frames of the same size and format.
std::vector<unsigned char> toGrey(Sws &sws, AVPixelFormat format, const uint8_t *const planes[],
                                  const int strides[], QSize size, QSize to)
{
    sws.p =
        sws_getCachedContext(sws.p, size.width(), size.height(), format, to.width(), to.height(),
                             AV_PIX_FMT_GRAY8, SWS_AREA, nullptr, nullptr, nullptr);
    if (!sws.p)
        return {};
    std::vector<unsigned char> out(std::size_t(to.width() * to.height()));
    uint8_t *dst[1] = { out.data() };
    const int dstStride[1] = { to.width() };
    sws_scale(sws.p, planes, strides, 0, size.height(), dst, dstStride);
    return out;
}

} // namespace

std::vector<unsigned char> scaleGrey(const unsigned char *data, QSize size, int stride, QSize to,
                                     LumaLayout layout)
{
    const bool packed = layout != LumaLayout::Planar;
    if (!data || size.isEmpty() || to.isEmpty() || stride < (packed ? 2 : 1) * size.width())
        return {};
    const AVPixelFormat format = layout == LumaLayout::Yuyv ? AV_PIX_FMT_YUYV422
        : layout == LumaLayout::Uyvy                        ? AV_PIX_FMT_UYVY422
                                                            : AV_PIX_FMT_GRAY8;
    thread_local Sws sws; // cached per thread: the camera scales every frame at the same size
    const uint8_t *planes[1] = { data };
    const int strides[1] = { stride };
    return toGrey(sws, format, planes, strides, size, to);
}

double regionMean(const std::vector<unsigned char> &frame, int width, const QRect &region)
{
    double s = 0.0;
    for (int y = region.top(); y <= region.bottom(); ++y) {
        for (int x = region.left(); x <= region.right(); ++x)
            s += frame[std::size_t(y * width + x)];
    }
    return s / double(std::max(1, region.width() * region.height()));
}

QRect toAnalysisRegion(const QRect &frameRegion, QSize frame, QSize analysis)
{
    const int w = frame.width();
    const int h = frame.height();
    const int sw = analysis.width();
    const int sh = analysis.height();
    const QRect fr = QRect(QPoint(0, 0), frame) & frameRegion;
    if (fr.isEmpty() || analysis.isEmpty())
        return {};
    return QRect(QPoint(fr.left() * sw / w, fr.top() * sh / h),
                 QPoint(std::max(fr.left() * sw / w, (fr.right() * sw) / w),
                        std::max(fr.top() * sh / h, (fr.bottom() * sh) / h)));
}

QRect toFrameRegion(const QRect &r, QSize frame, QSize analysis)
{
    if (r.isEmpty() || analysis.isEmpty())
        return {};
    const int w = frame.width();
    const int h = frame.height();
    const int sw = analysis.width();
    const int sh = analysis.height();
    return QRect(QPoint(r.left() * w / sw, r.top() * h / sh),
                 QPoint(((r.right() + 1) * w) / sw - 1, ((r.bottom() + 1) * h) / sh - 1));
}

Result<Recording> readVideo(const QString &path, std::optional<QRect> userRegion)
{
    if (!QFileInfo::exists(path))
        return ioError(Tr::tr("%1: no such file").arg(path));
    AvFormat fmt;
    const QByteArray name = QFile::encodeName(path);
    if (const int rc = avformat_open_input(&fmt.p, name.constData(), nullptr, nullptr); rc < 0)
        return ioError(Tr::tr("%1: not a readable video (%2)").arg(path, avText(rc)));
    if (avformat_find_stream_info(fmt.p, nullptr) < 0)
        return ioError(Tr::tr("%1: no stream information").arg(path));
    const AVCodec *codec = nullptr;
    const int si = av_find_best_stream(fmt.p, AVMEDIA_TYPE_VIDEO, -1, -1, &codec, 0);
    if (si < 0 || !codec)
        return ioError(Tr::tr("%1: no decodable video stream").arg(path));
    AVStream *stream = fmt.p->streams[si];
    AvCodec dec;
    dec.p = avcodec_alloc_context3(codec);
    avcodec_parameters_to_context(dec.p, stream->codecpar);
    if (avcodec_open2(dec.p, codec, nullptr) < 0)
        return ioError(Tr::tr("%1: cannot open the %2 decoder").arg(path, codec->name));
    const int w = dec.p->width;
    const int h = dec.p->height;
    if (w <= 0 || h <= 0)
        return ioError(Tr::tr("%1: video without a frame size").arg(path));
    const QSize analysis = analysisSize(QSize(w, h));
    const int sw = analysis.width();
    const int sh = analysis.height();
    // The preview at most kPreviewWidth wide and high (a tall frame is scaled to fit).
    int pw = std::min(w, kPreviewWidth);
    int ph = std::max(1, int(qint64(h) * pw / w));
    if (ph > kPreviewWidth) {
        ph = kPreviewWidth;
        pw = std::max(1, int(qint64(w) * ph / h));
    }

    GreyFrames grey { sw, sh, {} };
    std::vector<double> times;
    // Every previewEvery-th frame, to pick an "on" frame later: at most kMaxPreviews (every
    // other one is dropped and the step doubled when they are full).
    std::vector<QImage> previews;
    std::size_t previewEvery = 8;
    const std::size_t frameBytes = std::size_t(sw) * std::size_t(sh);
    bool tooLong = false;
    AvFrame frame;
    AvPacket packet;
    Sws small;
    Sws preview;
    const double tb = av_q2d(stream->time_base);
    auto take = [&](AVFrame *f) {
        if ((grey.frames.size() + 1) * frameBytes > kMaxVideoBytes) {
            tooLong = true;
            return;
        }
        std::vector<unsigned char> g = toGrey(small, AVPixelFormat(f->format), f->data, f->linesize,
                                              QSize(f->width, f->height), analysis);
        if (g.size() != frameBytes)
            return; // a frame libswscale cannot convert
        const int64_t pts = f->best_effort_timestamp;
        double t = pts != AV_NOPTS_VALUE ? double(pts) * tb : 0.0;
        if (pts == AV_NOPTS_VALUE || (!times.empty() && t <= times.back()))
            t = times.empty() ? 0.0
                              : times.back() + 1.0 / std::max(1.0, av_q2d(stream->r_frame_rate));
        times.push_back(t);
        grey.frames.push_back(std::move(g));
        if ((grey.frames.size() - 1) % previewEvery == 0) {
            if (previews.size() == kMaxPreviews) {
                for (std::size_t i = 0; i < kMaxPreviews / 2; ++i)
                    previews[i] = previews[2 * i];
                previews.resize(kMaxPreviews / 2);
                previewEvery *= 2;
                if ((grey.frames.size() - 1) % previewEvery != 0)
                    return;
            }
            preview.p =
                sws_getCachedContext(preview.p, f->width, f->height, AVPixelFormat(f->format), pw,
                                     ph, AV_PIX_FMT_RGB32, SWS_BILINEAR, nullptr, nullptr, nullptr);
            QImage img(pw, ph, QImage::Format_RGB32);
            uint8_t *pd[1] = { img.bits() };
            const int ps[1] = { int(img.bytesPerLine()) };
            sws_scale(preview.p, f->data, f->linesize, 0, f->height, pd, ps);
            previews.push_back(img);
        }
    };
    auto drain = [&] {
        while (avcodec_receive_frame(dec.p, frame.p) == 0)
            take(frame.p);
    };
    while (!tooLong && av_read_frame(fmt.p, packet.p) >= 0) {
        if (packet.p->stream_index == si && avcodec_send_packet(dec.p, packet.p) == 0)
            drain();
        av_packet_unref(packet.p);
    }
    avcodec_send_packet(dec.p, nullptr);
    drain();
    if (tooLong)
        return ioError(Tr::tr("%1: longer than %2 frames of %3x%4 pixels (%5 MB) at once: "
                              "cut the video")
                           .arg(path)
                           .arg(grey.frames.size())
                           .arg(sw)
                           .arg(sh)
                           .arg(kMaxVideoBytes >> 20));
    if (grey.frames.size() < 2)
        return ioError(Tr::tr("%1: no frames decoded").arg(path));

    Recording rec;
    rec.frameSize = QSize(w, h);
    rec.frameRate =
        times.size() > 1 ? double(times.size() - 1) / (times.back() - times.front()) : 0.0;
    rec.source = QStringLiteral("video (%1 %2x%3)").arg(QLatin1String(codec->name)).arg(w).arg(h);
    // Region in analysis pixels.
    QRect r;
    if (userRegion) {
        r = toAnalysisRegion(*userRegion, rec.frameSize, analysis);
        if (r.isEmpty())
            return Error(Error::Kind::InvalidArgument,
                         Tr::tr("region outside the %1x%2 frame").arg(w).arg(h));
    } else {
        r = findLedRegion(grey);
    }
    rec.region = toFrameRegion(r, rec.frameSize, analysis);
    const QRect use = r.isEmpty() ? QRect(0, 0, sw, sh) : r;
    double brightest = -1.0;
    for (std::size_t f = 0; f < grey.frames.size(); ++f) {
        const double v = regionMean(grey.frames[f], sw, use);
        rec.samples.push_back({ times[f], v });
        if (f % previewEvery == 0 && f / previewEvery < previews.size() && v > brightest) {
            brightest = v;
            rec.frame = previews[f / previewEvery];
        }
    }
    return rec;
}

Result<Recording> readRecording(const QString &path, std::optional<QRect> region)
{
    const QString ext = QFileInfo(path).suffix().toLower();
    if (ext == QLatin1String("csv") || ext == QLatin1String("txt") || ext == QLatin1String("tsv"))
        return readCsv(path);
    return readVideo(path, region);
}

} // namespace db::morseio
