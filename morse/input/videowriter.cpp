#include "videowriter.h"

#include <QFile>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
}

#include <QCoreApplication>
#include <cstring>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::morse)
};
} // namespace

namespace db::morseio {
namespace {

constexpr int kQuantiser = 4; // fixed MPEG-4 quantiser: small files, blob edges stay sharp

Error fail(const QString &what)
{
    return Error(Error::Kind::Io, Tr::tr("video writer: %1").arg(what));
}

} // namespace

Result<void> writeGreyVideo(const QString &path, int width, int height, int fps, int frames,
                            const std::function<void(int, unsigned char *)> &draw)
{
    const QByteArray name = QFile::encodeName(path);
    AVFormatContext *fmt = nullptr;
    if (avformat_alloc_output_context2(&fmt, nullptr, nullptr, name.constData()) < 0 || !fmt)
        return fail(QStringLiteral("no container for %1").arg(path));
    const AVCodec *codec = avcodec_find_encoder(AV_CODEC_ID_MPEG4);
    AVCodecContext *enc = codec ? avcodec_alloc_context3(codec) : nullptr;
    AVStream *stream = avformat_new_stream(fmt, nullptr);
    AVFrame *frame = av_frame_alloc();
    AVPacket *packet = av_packet_alloc();
    auto cleanup = [&] {
        av_packet_free(&packet);
        av_frame_free(&frame);
        avcodec_free_context(&enc);
        if (fmt && !(fmt->oformat->flags & AVFMT_NOFILE))
            avio_closep(&fmt->pb);
        avformat_free_context(fmt);
    };
    if (!enc || !stream || !frame || !packet) {
        cleanup();
        return fail(QStringLiteral("no MPEG-4 encoder"));
    }
    enc->width = width;
    enc->height = height;
    enc->pix_fmt = AV_PIX_FMT_YUV420P;
    enc->time_base = AVRational { 1, fps };
    enc->framerate = AVRational { fps, 1 };
    enc->gop_size = fps;
    enc->flags |= AV_CODEC_FLAG_QSCALE;
    enc->global_quality = FF_QP2LAMBDA * kQuantiser;
    if (fmt->oformat->flags & AVFMT_GLOBALHEADER)
        enc->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    if (avcodec_open2(enc, codec, nullptr) < 0) {
        cleanup();
        return fail(QStringLiteral("cannot open the MPEG-4 encoder"));
    }
    avcodec_parameters_from_context(stream->codecpar, enc);
    stream->time_base = enc->time_base;
    if (!(fmt->oformat->flags & AVFMT_NOFILE)
        && avio_open(&fmt->pb, name.constData(), AVIO_FLAG_WRITE) < 0) {
        cleanup();
        return fail(QStringLiteral("cannot write %1").arg(path));
    }
    if (avformat_write_header(fmt, nullptr) < 0) {
        cleanup();
        return fail(QStringLiteral("cannot write the header"));
    }
    frame->format = enc->pix_fmt;
    frame->width = width;
    frame->height = height;
    av_frame_get_buffer(frame, 0);
    std::vector<unsigned char> grey(std::size_t(width * height));
    bool ok = true;
    auto pump = [&](AVFrame *f) {
        if (avcodec_send_frame(enc, f) < 0)
            ok = false;
        while (avcodec_receive_packet(enc, packet) == 0) {
            av_packet_rescale_ts(packet, enc->time_base, stream->time_base);
            packet->stream_index = stream->index;
            if (av_interleaved_write_frame(fmt, packet) < 0)
                ok = false;
        }
    };
    for (int i = 0; i < frames && ok; ++i) {
        av_frame_make_writable(frame);
        draw(i, grey.data());
        for (int y = 0; y < height; ++y)
            std::memcpy(frame->data[0] + y * frame->linesize[0], grey.data() + y * width,
                        std::size_t(width));
        for (int p = 1; p < 3; ++p) {
            for (int y = 0; y < height / 2; ++y)
                std::memset(frame->data[p] + y * frame->linesize[p], 128, std::size_t(width / 2));
        }
        frame->pts = i;
        pump(frame);
    }
    pump(nullptr);
    av_write_trailer(fmt);
    cleanup();
    if (!ok)
        return fail(QStringLiteral("encoding failed"));
    return {};
}

} // namespace db::morseio
