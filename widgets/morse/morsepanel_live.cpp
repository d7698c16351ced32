// MorsePanel, live input: the camera list and buttons, samples straight into the decoder, the
// preview with the LED region, and the region drawn with the mouse.
#include "morselivesource.h"
#include "morsepanel.h"
#include "widgets/common/plot.h"

#include <QComboBox>
#include <QLabel>
#include <QMouseEvent>
#include <QPushButton>
#include <QTimer>

#include <algorithm>

namespace db::widgets {

void MorsePanel::setLiveSource(MorseLiveSource *source)
{
    if (m_liveSource) {
        stopLive();
        disconnect(m_liveSource, nullptr, this, nullptr);
    }
    m_liveSource = source;
    if (m_liveSource) {
        connect(m_liveSource, &MorseLiveSource::samples, this, &MorsePanel::liveSamples);
        connect(m_liveSource, &MorseLiveSource::preview, this, &MorsePanel::livePreview);
        connect(m_liveSource, &MorseLiveSource::status, this, &MorsePanel::liveStatus);
        connect(m_liveSource, &MorseLiveSource::error, this, &MorsePanel::liveError);
        connect(m_liveSource, &MorseLiveSource::devicesChanged, this,
                &MorsePanel::rebuildCameraList);
        connect(m_liveSource, &QObject::destroyed, this, [this] {
            m_liveSource = nullptr;
            m_live = false;
        });
    }
    rebuildCameraList();
}

void MorsePanel::rebuildCameraList()
{
    const QString current = m_cameras->currentText();
    const QStringList names = m_liveSource ? m_liveSource->devices() : QStringList();
    m_cameras->clear();
    m_cameras->addItems(names);
    if (const int i = m_cameras->findText(current); i >= 0)
        m_cameras->setCurrentIndex(i);
    const QString why = !m_liveSource ? tr("No camera input in this build")
        : names.isEmpty()             ? tr("No camera found (Qt Multimedia lists none)")
                                      : QString();
    m_cameras->setPlaceholderText(why);
    const QString hint = why.isEmpty()
        ? tr("Film the green STATUS LED: it is found automatically, or drag a rectangle around "
             "it on the frame")
        : why;
    m_cameras->setToolTip(hint);
    m_startCamera->setToolTip(hint);
    updateCameraControls();
}

void MorsePanel::updateCameraControls()
{
    const bool have = m_liveSource && m_cameras->count() > 0;
    m_cameras->setEnabled(have && !m_live);
    m_startCamera->setEnabled(have && !m_live);
    m_stopCamera->setEnabled(m_live);
    m_stopCamera->setVisible(m_live || have);
}

bool MorsePanel::startLive(int index)
{
    if (!m_liveSource || index < 0 || index >= m_cameras->count()) {
        m_error = m_liveSource ? tr("No camera found (Qt Multimedia lists none)")
                               : tr("No camera input in this build");
        refresh();
        return false;
    }
    const QString name = m_cameras->itemText(index);
    setSource(MorseSource { {}, {}, {}, 0, tr("Camera \"%1\"").arg(name) }); // new decoder
    m_cameraName = name;
    m_live = true; // before start(): a synchronous error() must find the panel live
    updateCameraControls();
    const bool started = m_liveSource->start(index);
    if (!started)
        m_live = false;
    updateCameraControls();
    refresh();
    return started;
}

void MorsePanel::stopLive()
{
    if (!m_live)
        return;
    m_live = false; // first: stop() may report through error()
    if (m_liveSource)
        m_liveSource->stop();
    m_liveRefresh->stop();
    m_decoder->finish();
    m_sourceLabel->setText(tr("Camera \"%1\" (stopped)").arg(m_cameraName));
    updateCameraControls();
    refresh();
}

void MorsePanel::liveSamples(const std::vector<morse::Sample> &samples)
{
    if (!m_live || samples.empty())
        return;
    m_source.samples.insert(m_source.samples.end(), samples.begin(), samples.end());
    feedUntil(m_source.samples.size());
    // Bounded: the decoder keeps its own history; the panel's samples and the plot only the
    // last kLiveKeep s (a camera left running for hours must not grow the panel).
    const double cutoff = samples.back().t - kLiveKeep;
    const auto old = std::lower_bound(m_source.samples.begin(), m_source.samples.end(), cutoff,
                                      [](const morse::Sample &s, double t) { return s.t < t; });
    m_fed -= static_cast<std::size_t>(std::distance(m_source.samples.begin(), old));
    m_source.samples.erase(m_source.samples.begin(), old);
    m_brightness->data()->removeBefore(cutoff);
    const auto keep = std::lower_bound(m_thresholdT.begin(), m_thresholdT.end(), cutoff);
    const auto drop = std::distance(m_thresholdT.begin(), keep);
    m_thresholdT.erase(m_thresholdT.begin(), keep);
    m_thresholdV.erase(m_thresholdV.begin(), m_thresholdV.begin() + drop);
    if (!m_liveRefresh->isActive())
        m_liveRefresh->start();
}

void MorsePanel::livePreview(const QImage &image, const QRect &region)
{
    if (!m_live)
        return;
    m_source.frame = image;
    m_source.region = region;
    m_source.frameWidth = image.width();
    updateFrame();
}

void MorsePanel::liveStatus(const QString &text)
{
    if (m_live)
        m_sourceLabel->setText(tr("Camera \"%1\": %2").arg(m_cameraName, text));
}

void MorsePanel::liveError(const QString &message)
{
    m_error = message;
    if (m_live)
        stopLive(); // the source has stopped already; stop() again does nothing
    else
        refresh();
}

QPoint MorsePanel::framePixel(const QPoint &labelPos) const
{
    // The pixmap is the preview scaled to the label's pixmap width, centred in the label.
    const QPixmap shown = m_frame->pixmap();
    if (shown.isNull() || m_source.frame.isNull())
        return { -1, -1 };
    const QRect cr = m_frame->contentsRect();
    const QPoint origin(cr.x() + (cr.width() - shown.width()) / 2,
                        cr.y() + (cr.height() - shown.height()) / 2);
    const double s = double(m_source.frame.width()) / double(shown.width());
    const QPoint p((labelPos - origin) * s);
    return QRect(QPoint(0, 0), m_source.frame.size()).contains(p) ? p : QPoint(-1, -1);
}

bool MorsePanel::eventFilter(QObject *watched, QEvent *event)
{
    if (watched != m_frame || !m_live || !m_liveSource)
        return QWidget::eventFilter(watched, event);
    switch (event->type()) {
    case QEvent::MouseButtonPress:
        m_dragFrom = framePixel(static_cast<QMouseEvent *>(event)->position().toPoint());
        return true;
    case QEvent::MouseButtonRelease: {
        const QPoint to = framePixel(static_cast<QMouseEvent *>(event)->position().toPoint());
        const QRect r = QRect(m_dragFrom, to).normalized();
        if (m_dragFrom.x() >= 0 && to.x() >= 0 && r.width() >= 2 && r.height() >= 2)
            m_liveSource->setRegion(r);
        m_dragFrom = { -1, -1 };
        return true;
    }
    case QEvent::MouseButtonDblClick:
        m_liveSource->setRegion(QRect()); // automatic again
        return true;
    default:
        return QWidget::eventFilter(watched, event);
    }
}

} // namespace db::widgets
