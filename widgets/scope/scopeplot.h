#pragma once

#include "scope/decimation.h"
#include "scope/recorder.h"

#include <QColor>
#include <QHash>
#include <QPointer>
#include <QTimer>
#include <QWidget>

#include <vector>

class QCustomPlot;
class QCPAxisRect;
class QCPGraph;
class QCPGraphData;
class QCPLegend;
class QCPMarginGroup;
class QMouseEvent;
class QWheelEvent;

namespace db::widgets {

class ScopeCursors;

// How one channel is drawn (the recorder keeps what it is and its display scaling).
struct ScopeChannelStyle
{
    QColor color;
    bool visible = true;
    int lane = 1; // 1..ScopePlot::kMaxLanes: channels with the same lane share a value axis
};

// The scope's plot: the channels of a Recorder as lines over one time axis, in up to kMaxLanes
// stacked lanes (axis rects) with their own value axis, A/B cursors, trigger markers.
//
// Drawing contract:
// - Data is min/max decimated (scope/decimation.h) to the visible time range and the lane's
//   width in pixels, so the cost of a frame depends on the pixels, not on the recording length.
// - Repaint is coalesced: dataAppended()/channelsChanged() only mark the view dirty; a kReplotHz
//   timer refreshes and calls replot(rpQueuedReplot) when dirty AND visible. A hidden plot never
//   replots and its timer stops; it catches up when shown.
// - Following: while the recorder runs (and after autoscale()), the view tracks the data
//   (Run/Single/Normal: the whole buffer; Roll: the roll window) and scales the value axes. Any
//   zoom or pan by the user stops following until autoscale().
//
// Mouse: wheel zooms time (Ctrl+wheel: the lane's value axis), drag pans, Shift+drag zooms into
// a rectangle, dragging a cursor line moves it; key A autoscales.
class ScopePlot : public QWidget
{
    Q_OBJECT
public:
    static constexpr int kReplotHz = 30;
    static constexpr int kMaxLanes = 4;

    explicit ScopePlot(QWidget *parent = nullptr);
    ~ScopePlot() override;

    // Not owned; the plot follows its channels and data. nullptr detaches.
    void setRecorder(scope::Recorder *recorder);
    scope::Recorder *recorder() const { return m_recorder; }
    QCustomPlot *customPlot() const { return m_plot; }
    ScopeCursors *cursors() const { return m_cursors; }

    // Style of recorder channel `channel` (styles follow a channel's id across re-ordering).
    ScopeChannelStyle channelStyle(int channel) const;
    void setChannelStyle(int channel, const ScopeChannelStyle &style);
    // The graph drawing recorder channel `channel` (nullptr when hidden or out of range).
    QCPGraph *graph(int channel) const;
    // Lanes in use (in display order) and the axis rect of a lane number.
    QList<int> lanes() const;
    QCPAxisRect *laneRect(int lane) const;

    // The time the time axis counts from: the trigger instant of a triggered recording (so
    // the pre-trigger is negative), else 0 (the recording's start). Times in this class's API
    // stay on the recorder's time base; only what people read is shifted.
    double timeOrigin() const;

    double timeLower() const;
    double timeUpper() const;
    // Shows [t0, t1] and stops following.
    void setTimeRange(double t0, double t1);
    // Fits time to the recording and every lane's value axis to its visible data; follows the
    // data while the recorder runs.
    void autoscale();
    bool isFollowing() const { return m_following; }

    // Refreshes the decimated data now (tests, export); replot() follows at the next frame.
    void refreshNow();
    // Whether the frame timer runs: only while the plot is shown (a hidden plot costs no
    // wake-ups at all).
    bool isRefreshing() const { return m_frameTimer.isActive(); }

Q_SIGNALS:
    // The time range or the drawn data changed (measurements may need an update).
    void viewChanged();
    void channelStyleChanged(int channel);

protected:
    void showEvent(QShowEvent *event) override;
    void hideEvent(QHideEvent *event) override;

private:
    struct Lane
    {
        int number = 1;
        QCPAxisRect *rect = nullptr;
        QCPLegend *legend = nullptr;
    };

    void markDirty();
    void onFrame();
    void rebuildLayout();
    void updateData();
    void fitTime();
    void fitValues();
    void onTimeRangeChanged(QCPAxisRect *source);
    void onMousePress(QMouseEvent *event);
    void onMouseRelease();
    void onWheel(QWheelEvent *event);
    void stopFollowing();
    void syncStyles();
    QString styleKey(int channel) const;
    QString laneLabel(int lane) const;
    int defaultLane(int channel) const;

    QCustomPlot *m_plot = nullptr;
    ScopeCursors *m_cursors = nullptr;
    QPointer<scope::Recorder> m_recorder;
    QCPMarginGroup *m_marginGroup = nullptr;
    double m_origin = 0.0; // timeOrigin() when the time axes were last labelled
    double m_t0 = 0.0; // the shared time range
    double m_t1 = 1.0;
    QTimer m_frameTimer;
    bool m_dirty = true;
    bool m_layoutDirty = true;
    bool m_following = true;
    bool m_settingRange = false;
    std::vector<Lane> m_lanes;
    std::vector<QCPGraph *> m_graphs; // per recorder channel; nullptr when hidden
    std::vector<scope::DecimatedSeries> m_decimated; // per recorder channel, reused each frame
    std::vector<QVector<QCPGraphData>> m_points; // per recorder channel, shared with the graph
    QHash<QString, ScopeChannelStyle> m_styles;
    QStringList m_layoutKeys; // channel keys of the current layout, to detect re-ordering
    int m_nextColor = 0;
};

// The colour of the n-th channel (a palette that stays apart on white).
QColor scopeChannelColor(int n);
// How people see recorder channel `channel` named: with its device in front when the channels
// come from more than one device ("ACTIVE Cube ACU 127.0.0.1: 210 Actual frequency"), else
// without ("210 Actual frequency").
QString scopeChannelName(const scope::Recorder &recorder, int channel);

} // namespace db::widgets
