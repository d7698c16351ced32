#include "camerasource.h"

#include "morseinput.h"

#include <QCamera>
#include <QMediaCaptureSession>
#include <QMediaDevices>
#include <QTimer>
#include <QVideoSink>

#include <cmath>
#include <limits>

namespace db::morseio {
namespace {

// The camera mode to ask for: the highest frame rate up to 60 fps (the decoder wants short
// frames for sub-dit timing), then the size nearest 640 px wide (the analysis is 160 px wide;
// more pixels only cost), then uncompressed over JPEG (no decode per frame).
QCameraFormat pickFormat(const QCameraDevice &device)
{
    QCameraFormat best;
    double bestScore = -std::numeric_limits<double>::infinity();
    for (const QCameraFormat &f : device.videoFormats()) {
        const double fps = std::min(60.0, double(f.maxFrameRate()));
        const double score = fps * 100.0 - std::abs(f.resolution().width() - 640) / 10.0
            - (f.pixelFormat() == QVideoFrameFormat::Format_Jpeg ? 5.0 : 0.0);
        if (score > bestScore) {
            bestScore = score;
            best = f;
        }
    }
    return best;
}

} // namespace

CameraSource::CameraSource(QObject *parent)
    : QObject(parent)
    , m_sink(new QVideoSink(this))
    , m_firstFrame(new QTimer(this))
{
    // Auto connection: queued when the backend delivers on its streaming thread.
    connect(m_sink, &QVideoSink::videoFrameChanged, this, &CameraSource::consumeFrame);
    m_firstFrame->setSingleShot(true);
    m_firstFrame->setInterval(kFirstFrameTimeoutMs);
    connect(m_firstFrame, &QTimer::timeout, this, [this] {
        fail(tr("Camera \"%1\" delivers no frames after %2 s (in use by another program, or no "
                "permission for its device?)")
                 .arg(m_device.description())
                 .arg(kFirstFrameTimeoutMs / 1000));
    });
}

CameraSource::~CameraSource()
{
    stop();
}

QList<QCameraDevice> CameraSource::devices()
{
    return QMediaDevices::videoInputs();
}

bool CameraSource::start(const QCameraDevice &device)
{
    stop();
    reset();
    if (device.isNull()) {
        fail(tr("No camera found (Qt Multimedia lists none)"));
        return false;
    }
    if (!m_session) {
        m_session = new QMediaCaptureSession(this);
        m_session->setVideoSink(m_sink);
    }
    m_device = device;
    auto *camera = new QCamera(device, this);
    m_camera = camera;
    connect(
        camera, &QCamera::errorOccurred, this, [this, camera](QCamera::Error, const QString &text) {
            if (camera != m_camera)
                return; // a late error of a camera already stopped
            fail(tr("Camera \"%1\": %2")
                     .arg(m_device.description(),
                          text.isEmpty() ? tr("cannot be opened (busy or no permission?)") : text));
        });
    if (const QCameraFormat format = pickFormat(device); !format.isNull())
        camera->setCameraFormat(format);
    m_session->setCamera(camera);
    camera->start();
    if (!m_camera) // failed synchronously; errorOccurred() was emitted
        return false;
    m_firstFrame->start();
    Q_EMIT statusChanged(tr("Starting camera \"%1\"…").arg(device.description()));
    return true;
}

void CameraSource::stop()
{
    m_firstFrame->stop();
    if (QCamera *camera = m_camera) {
        m_camera = nullptr;
        camera->stop();
        if (m_session)
            m_session->setCamera(nullptr);
        camera->deleteLater(); // stop() may run inside the camera's own errorOccurred()
    }
}

bool CameraSource::isActive() const
{
    return m_camera != nullptr;
}

void CameraSource::reset()
{
    m_tracker.reset();
    m_reported.reset();
    m_frameSize = {};
    m_started = false;
    m_streamTime = false;
    m_origin = 0.0;
    m_lastPreview = -1.0;
    m_badFrames = 0;
    m_badReported = false;
    applyUserRegion();
}

void CameraSource::setRegion(std::optional<QRect> frameRegion)
{
    m_userRegion = frameRegion;
    applyUserRegion();
}

QRect CameraSource::region() const
{
    return toFrameRegion(m_tracker.region(), m_frameSize, analysisSize(m_frameSize));
}

void CameraSource::applyUserRegion()
{
    if (!m_userRegion) {
        m_tracker.setUserRegion(std::nullopt);
        return;
    }
    if (m_frameSize.isEmpty())
        return; // at the first frame
    const QRect r = toAnalysisRegion(*m_userRegion, m_frameSize, analysisSize(m_frameSize));
    if (!r.isEmpty()) {
        m_tracker.setUserRegion(r);
        return;
    }
    // Not an error: the camera keeps running and the LED is searched for. The reason stays in
    // the status until the search reports something new.
    const QString reason = tr("Region %1,%2 %3x%4 lies outside the %5x%6 camera frame; "
                              "searching for the blinking LED automatically")
                               .arg(m_userRegion->x())
                               .arg(m_userRegion->y())
                               .arg(m_userRegion->width())
                               .arg(m_userRegion->height())
                               .arg(m_frameSize.width())
                               .arg(m_frameSize.height());
    m_userRegion.reset();
    m_tracker.setUserRegion(std::nullopt);
    m_reported = m_tracker.state();
    Q_EMIT statusChanged(reason);
}

void CameraSource::fail(const QString &message)
{
    stop();
    Q_EMIT errorOccurred(message);
}

void CameraSource::checkDevices(const QList<QCameraDevice> &now)
{
    if (m_camera && !now.contains(m_device))
        fail(tr("Camera \"%1\" was disconnected").arg(m_device.description()));
}

double CameraSource::frameTime(const QVideoFrame &frame)
{
    const qint64 us = frame.startTime(); // -1 when the backend gave none
    if (!m_started) {
        m_started = true;
        m_clock.start();
        m_streamTime = us >= 0;
        m_origin = m_streamTime ? double(us) / 1e6 : 0.0;
        return 0.0;
    }
    if (m_streamTime && us >= 0)
        return double(us) / 1e6 - m_origin;
    return double(m_clock.nsecsElapsed()) / 1e9;
}

std::vector<unsigned char> CameraSource::analysisFrame(const QVideoFrame &in, QImage *image)
{
    QVideoFrame f = in; // shallow copy: map() needs a non-const frame
    const QSize size = f.size();
    if (size.isEmpty())
        return {};
    std::optional<LumaLayout> layout;
    switch (f.pixelFormat()) {
    case QVideoFrameFormat::Format_Y8:
    case QVideoFrameFormat::Format_YUV420P:
    case QVideoFrameFormat::Format_YUV422P:
    case QVideoFrameFormat::Format_YV12:
    case QVideoFrameFormat::Format_NV12:
    case QVideoFrameFormat::Format_NV21:
    case QVideoFrameFormat::Format_IMC1:
    case QVideoFrameFormat::Format_IMC2:
    case QVideoFrameFormat::Format_IMC3:
    case QVideoFrameFormat::Format_IMC4: // plane 0 is 8-bit luma: no colour conversion
        layout = LumaLayout::Planar;
        break;
    case QVideoFrameFormat::Format_YUYV:
        layout = LumaLayout::Yuyv;
        break;
    case QVideoFrameFormat::Format_UYVY:
        layout = LumaLayout::Uyvy;
        break;
    default:
        break;
    }
    if (!layout) { // RGB, JPEG, 16-bit: Qt converts
        *image = f.toImage();
        if (image->isNull())
            return {};
        const QImage g = image->convertToFormat(QImage::Format_Grayscale8);
        return scaleGrey(g.constBits(), g.size(), int(g.bytesPerLine()), analysisSize(g.size()));
    }
    if (!f.map(QVideoFrame::ReadOnly))
        return {};
    const int stride = f.bytesPerLine(0);
    std::vector<unsigned char> out;
    if (f.bits(0) && qint64(stride) * size.height() <= f.mappedBytes(0))
        out = scaleGrey(f.bits(0), size, stride, analysisSize(size), *layout);
    f.unmap();
    return out;
}

void CameraSource::consumeFrame(const QVideoFrame &frame)
{
    if (!frame.isValid())
        return;
    m_firstFrame->stop();
    QImage image;
    std::vector<unsigned char> grey = analysisFrame(frame, &image);
    if (grey.empty()) {
        if (++m_badFrames >= kBadFramesForError && !m_badReported) {
            m_badReported = true;
            fail(tr("Camera frames cannot be read (pixel format %1, %2x%3)")
                     .arg(QVideoFrameFormat::pixelFormatToString(frame.pixelFormat()))
                     .arg(frame.width())
                     .arg(frame.height()));
        }
        return;
    }
    m_badFrames = 0;
    const QSize size = image.isNull() ? frame.size() : image.size();
    if (size != m_frameSize) {
        m_frameSize = size;
        applyUserRegion();
    }
    const double t = frameTime(frame);
    const bool previewDue = m_lastPreview < 0.0 || t - m_lastPreview >= 1.0 / kPreviewHz;
    const QSize analysis = analysisSize(size);
    std::vector<unsigned char> greyPreview;
    if (previewDue) {
        m_lastPreview = t;
        if (image.isNull())
            image = frame.toImage();
        if (image.isNull())
            greyPreview = grey;
    }
    const std::vector<morse::Sample> samples = m_tracker.push(t, std::move(grey), analysis);
    if (m_reported != m_tracker.state()) {
        m_reported = m_tracker.state();
        const QRect r = region();
        switch (*m_reported) {
        case LiveLedTracker::State::Searching:
            Q_EMIT statusChanged(tr("Searching for the blinking LED…"));
            break;
        case LiveLedTracker::State::Tracking:
            Q_EMIT statusChanged(
                tr("LED at %1,%2 (%3x%4 px)%5")
                    .arg(r.x())
                    .arg(r.y())
                    .arg(r.width())
                    .arg(r.height())
                    .arg(m_tracker.userRegion() ? tr(", your region") : QString()));
            break;
        case LiveLedTracker::State::Lost:
            Q_EMIT statusChanged(tr("LED lost (no blinking for %1 s): searching again…")
                                     .arg(LiveLedTracker::kDeadAfter, 0, 'f', 0));
            break;
        }
    }
    if (!samples.empty())
        Q_EMIT samplesReady(samples);
    if (previewDue) {
        if (image.isNull()) // no Qt conversion for this format: the grey analysis frame
            image = QImage(greyPreview.data(), analysis.width(), analysis.height(),
                           analysis.width(), QImage::Format_Grayscale8)
                        .copy();
        if (image.width() > kPreviewWidth)
            image = image.scaledToWidth(kPreviewWidth, Qt::SmoothTransformation);
        image = image.convertToFormat(QImage::Format_RGB32);
        Q_EMIT previewReady(image, toFrameRegion(m_tracker.region(), image.size(), analysis));
    }
}

} // namespace db::morseio
