#pragma once

#include "widgets/morse/morselivesource.h"

#include <QCameraDevice>
#include <QList>
#include <QSize>

class QMediaDevices;

namespace db::morseio {
class CameraSource;
}

namespace db::gui {

// The Morse panel's live input over Qt Multimedia: widgets::MorseLiveSource around
// morseio::CameraSource. Lists QMediaDevices::videoInputs() (kept current), maps preview pixels
// to frame pixels for a drawn region, and forwards samples, previews, status and errors.
class CameraLiveSource : public widgets::MorseLiveSource
{
    Q_OBJECT
public:
    explicit CameraLiveSource(QObject *parent = nullptr);
    ~CameraLiveSource() override;

    QStringList devices() const override;
    bool start(int index) override;
    void stop() override;
    bool isActive() const override;
    void setRegion(const QRect &previewRegion) override;

private:
    void refreshDevices();

    morseio::CameraSource *m_camera;
    QMediaDevices *m_mediaDevices;
    QList<QCameraDevice> m_devices;
    QSize m_previewSize; // of the last preview image
};

} // namespace db::gui
