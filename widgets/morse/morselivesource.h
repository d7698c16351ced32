#pragma once

#include "morse/decode/morsetypes.h"

#include <QImage>
#include <QObject>
#include <QRect>
#include <QStringList>

#include <vector>

namespace db::widgets {

// A live brightness source for the Morse panel: a camera, injected by app/ (widgets know no
// Qt Multimedia), or a fake in tests. The panel does not own it.
//
// Contract: samples() carries strictly increasing times (seconds) within one start(); it stays
// silent while the LED is searched. preview() comes at a low rate (<= 5 Hz) with the LED region
// in the image's own pixels (empty while searching). After error() the source has stopped.
class MorseLiveSource : public QObject
{
    Q_OBJECT
public:
    using QObject::QObject;

    // Names for the camera list, in start() index order; empty when there is no camera.
    virtual QStringList devices() const = 0;
    // Starts device `index`; false, after emitting error(), when it cannot.
    virtual bool start(int index) = 0;
    virtual void stop() = 0;
    virtual bool isActive() const = 0;
    // The LED region in the pixels of the last preview image; an empty rect: find it again
    // automatically.
    virtual void setRegion(const QRect &previewRegion) = 0;

Q_SIGNALS:
    void samples(const std::vector<db::morse::Sample> &samples);
    void preview(const QImage &image, const QRect &region);
    void status(const QString &text); // what the source is doing ("Searching for the LED…")
    void error(const QString &message); // names the cause; the source has stopped
    void devicesChanged(); // devices() changed (camera plugged in or out)
};

} // namespace db::widgets
