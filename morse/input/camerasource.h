#pragma once

#include "ledtracker.h"
#include "morse/decode/morsetypes.h"

#include <QCameraDevice>
#include <QElapsedTimer>
#include <QImage>
#include <QList>
#include <QObject>
#include <QPointer>
#include <QRect>
#include <QSize>
#include <QVideoFrame>

#include <optional>
#include <vector>

class QCamera;
class QMediaCaptureSession;
class QTimer;
class QVideoSink;

namespace db::morseio {

// Live LED input for the Morse decoder: a QCamera runs into a QMediaCaptureSession
// whose QVideoSink hands every frame to consumeFrame(); frames become small grey analysis frames
// (analysisSize(), the same area scaling as readVideo) and LiveLedTracker finds the LED and
// turns each frame into a brightness sample.
//
// Frames need not come from a camera: videoSink() or consumeFrame() accept any QVideoFrame (the
// tests push synthetic ones). All signals are emitted on this object's thread; frames from the
// backend's streaming thread arrive queued.
//
// Sample times are seconds since the first frame of the session: the frames' start times when
// the first frame has one, else a monotonic clock (frames without a start time later in a
// start-time session fall back to the monotonic clock, aligned at the first frame).
class CameraSource : public QObject
{
    Q_OBJECT
public:
    static constexpr double kPreviewHz = 4.0; // preview images per second of frame time
    static constexpr int kPreviewWidth = 320; // px
    static constexpr int kFirstFrameTimeoutMs = 6000; // a started camera must deliver by then
    static constexpr int kBadFramesForError = 30; // consecutive unreadable frames

    explicit CameraSource(QObject *parent = nullptr);
    ~CameraSource() override;

    // The cameras Qt Multimedia lists (empty without a camera or without a media backend).
    static QList<QCameraDevice> devices();

    // Starts `device`; a new session (tracker and clock restart). False, with errorOccurred(),
    // for a null device; camera errors later come through errorOccurred() and stop the camera.
    bool start(const QCameraDevice &device);
    // Stops the camera (idempotent). The tracker keeps its state until the next start().
    void stop();
    bool isActive() const;

    // The sink the capture session renders into; frames set on it are consumed.
    QVideoSink *videoSink() const { return m_sink; }

    // The LED region in frame pixels (nullopt: found automatically). Applies to the next frame;
    // a region outside the frame is refused, with the reason in statusChanged(), and the LED is
    // searched for instead.
    void setRegion(std::optional<QRect> frameRegion);
    QRect region() const; // frame pixels; empty while searching
    QSize frameSize() const { return m_frameSize; }
    LiveLedTracker::State state() const { return m_tracker.state(); }
    // Restarts the session: tracker, clock, counters (start() does this).
    void reset();

public Q_SLOTS:
    // The cameras the system has now (QMediaDevices::videoInputs() after videoInputsChanged,
    // watched by the owner): a running camera that is not among them fails as disconnected.
    void checkDevices(const QList<QCameraDevice> &now);
    // Reads one frame. Invalid frames (the sink sends one when the camera stops) are ignored;
    // unmappable or malformed frames are skipped and reported after kBadFramesForError in a row.
    void consumeFrame(const QVideoFrame &frame);

Q_SIGNALS:
    // Brightness samples (mean grey level in the region), strictly increasing times.
    void samplesReady(const std::vector<db::morse::Sample> &samples);
    // A downscaled frame (kPreviewWidth wide at most) at <= kPreviewHz, and the LED region in
    // the image's pixels (empty while searching).
    void previewReady(const QImage &image, const QRect &region);
    // "Searching for the blinking LED…", "LED found at …", "LED lost …".
    void statusChanged(const QString &text);
    // A message naming the cause: no camera, camera busy or not permitted, no frames, ...
    void errorOccurred(const QString &message);

private:
    double frameTime(const QVideoFrame &frame);
    std::vector<unsigned char> analysisFrame(const QVideoFrame &frame, QImage *image);
    void applyUserRegion();
    void fail(const QString &message);

    QVideoSink *m_sink;
    QMediaCaptureSession *m_session = nullptr; // created at the first start()
    QPointer<QCamera> m_camera;
    QCameraDevice m_device;
    QTimer *m_firstFrame;
    LiveLedTracker m_tracker;
    std::optional<LiveLedTracker::State> m_reported; // last state told by statusChanged()
    std::optional<QRect> m_userRegion; // frame pixels
    QSize m_frameSize;
    QElapsedTimer m_clock;
    bool m_started = false; // a frame was seen in this session
    bool m_streamTime = false; // sample times from the frames' start times
    double m_origin = 0.0; // s: the first frame's time
    double m_lastPreview = -1.0;
    int m_badFrames = 0;
    bool m_badReported = false;
};

} // namespace db::morseio
