#include "cameralivesource.h"

#include "morse/input/camerasource.h"
#include "morse/input/morseinput.h"

#include <QMediaDevices>

namespace db::gui {

CameraLiveSource::CameraLiveSource(QObject *parent)
    : widgets::MorseLiveSource(parent)
    , m_camera(new morseio::CameraSource(this))
    , m_mediaDevices(new QMediaDevices(this))
{
    connect(m_camera, &morseio::CameraSource::samplesReady, this,
            &widgets::MorseLiveSource::samples);
    connect(m_camera, &morseio::CameraSource::previewReady, this,
            [this](const QImage &image, const QRect &region) {
                m_previewSize = image.size();
                Q_EMIT preview(image, region);
            });
    connect(m_camera, &morseio::CameraSource::statusChanged, this,
            &widgets::MorseLiveSource::status);
    connect(m_camera, &morseio::CameraSource::errorOccurred, this,
            &widgets::MorseLiveSource::error);
    connect(m_mediaDevices, &QMediaDevices::videoInputsChanged, this,
            &CameraLiveSource::refreshDevices);
    m_devices = morseio::CameraSource::devices();
}

CameraLiveSource::~CameraLiveSource() = default;

void CameraLiveSource::refreshDevices()
{
    m_devices = morseio::CameraSource::devices();
    m_camera->checkDevices(m_devices); // a running camera unplugged: its error first
    Q_EMIT devicesChanged();
}

QStringList CameraLiveSource::devices() const
{
    QStringList names;
    for (const QCameraDevice &d : m_devices)
        names << d.description();
    return names;
}

bool CameraLiveSource::start(int index)
{
    m_previewSize = {};
    return m_camera->start(m_devices.value(index)); // out of range: a null device, an error
}

void CameraLiveSource::stop()
{
    m_camera->stop();
}

bool CameraLiveSource::isActive() const
{
    return m_camera->isActive();
}

void CameraLiveSource::setRegion(const QRect &previewRegion)
{
    const QSize frame = m_camera->frameSize();
    if (previewRegion.isEmpty() || m_previewSize.isEmpty() || frame.isEmpty()) {
        m_camera->setRegion(std::nullopt);
        return;
    }
    // The preview is the frame scaled down, aspect kept, as the analysis frames are.
    m_camera->setRegion(morseio::toFrameRegion(previewRegion, frame, m_previewSize));
}

} // namespace db::gui
