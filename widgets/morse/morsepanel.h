#pragma once

#include "core/result.h"
#include "morse/decode/decoder.h"

#include <QImage>
#include <QRect>
#include <QWidget>

#include <functional>
#include <memory>
#include <vector>

class QComboBox;
class QCustomPlot;
class QCPGraph;
class QLabel;
class QPlainTextEdit;
class QPushButton;
class QTimer;
class QToolButton;

namespace db::widgets {

class MorseLiveSource;

// What the panel plays: brightness samples, and for a video the LED region and a frame.
struct MorseSource
{
    std::vector<morse::Sample> samples;
    QRect region; // frame pixels; empty for CSV
    QImage frame; // null for CSV; may be scaled down from the video's frames
    int frameWidth = 0; // the video's frame width, the scale of `region`
    QString description; // "video (mpeg4 160x120), 25 fps"
};

// The LED Morse decoder panel: open a video or CSV, see the frame with the LED
// region, a live brightness plot with the decision threshold and the dit/dah timeline, the
// decoded text, and the IP with its confidence; "Connect" asks for a connection to that IP.
//
// Files are read through a loader that app/ injects (widgets know no video library). A loaded
// recording is played into a morse::Decoder at kPlaybackSpeed times real time on a timer (the
// plot replots at most kReplotHz); finishPlayback() decodes the rest at once.
//
// Live (morsepanel_live.cpp): a MorseLiveSource (a camera, injected by app/) feeds its samples
// straight into the decoder as they come; the plot shows the last 20 s, the frame view the
// camera's preview with the LED region (drag a rectangle on it to give the region, double-click
// to find it automatically again). Stopping keeps the result.
class MorsePanel : public QWidget
{
    Q_OBJECT
public:
    using Loader = std::function<Result<MorseSource>(const QString &path)>;
    static constexpr double kPlaybackSpeed = 8.0;
    static constexpr int kReplotHz = 20;

    explicit MorsePanel(QWidget *parent = nullptr);
    ~MorsePanel() override;

    void setLoader(Loader loader) { m_loader = std::move(loader); }
    // The camera input (not owned; nullptr: none in this build). Lists its devices at once.
    void setLiveSource(MorseLiveSource *source);
    MorseLiveSource *liveSource() const { return m_liveSource; }
    // Starts camera `index` of the live source with a new decoder; false with the reason shown.
    bool startLive(int index);
    void stopLive();
    bool live() const { return m_live; }
    static constexpr double kLiveKeep = 60.0; // s of brightness kept while live
    // Loads `path` through the loader and starts playback; false with the reason shown.
    bool openFile(const QString &path);
    void setSource(MorseSource source);
    void finishPlayback();
    bool playing() const;

    const morse::Decoder &decoder() const { return *m_decoder; }
    // What is shown: a loaded file, or while live the last kLiveKeep s of camera samples.
    const MorseSource &source() const { return m_source; }
    QString ipText() const; // "192.168.2.150" once complete, else empty
    QString statusText() const;
    QCustomPlot *plot() const { return m_plot; }

Q_SIGNALS:
    // "Connect" (refgo://IP) or its menu (canopen+slcan://IP?node=50).
    void connectRequested(const QString &uri);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    void chooseFile();
    void rebuildCameraList();
    void updateCameraControls();
    void liveSamples(const std::vector<morse::Sample> &samples);
    void livePreview(const QImage &image, const QRect &region);
    void liveStatus(const QString &text);
    void liveError(const QString &message);
    QPoint framePixel(const QPoint &labelPos) const;
    void step();
    void feedUntil(std::size_t end);
    void refresh();
    void updateFrame();

    Loader m_loader;
    MorseLiveSource *m_liveSource = nullptr;
    bool m_live = false;
    QString m_cameraName;
    QString m_error; // shown in the status line until the next start or open
    QPoint m_dragFrom { -1, -1 }; // frame pixels; x < 0: no drag
    MorseSource m_source;
    std::unique_ptr<morse::Decoder> m_decoder;
    std::size_t m_fed = 0;
    double m_playStart = 0.0; // recording time at playback start
    qint64 m_wallStart = 0;
    std::vector<double> m_thresholdT;
    std::vector<double> m_thresholdV;

    QTimer *m_timer;
    QPushButton *m_open;
    QComboBox *m_cameras;
    QPushButton *m_startCamera;
    QPushButton *m_stopCamera;
    QTimer *m_liveRefresh; // coalesces live refreshes to kReplotHz
    QLabel *m_sourceLabel;
    QLabel *m_frame;
    QCustomPlot *m_plot;
    QCPGraph *m_brightness;
    QCPGraph *m_threshold;
    QCPGraph *m_dits;
    QCPGraph *m_dahs;
    QPlainTextEdit *m_text;
    QLabel *m_ip;
    QLabel *m_status;
    QToolButton *m_connect;
};

} // namespace db::widgets
