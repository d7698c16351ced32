#include "scopeplot.h"

#include "scope/recorder.h"
#include "scopecursors.h"
#include "widgets/common/plot.h"

#include <QShortcut>
#include <QVBoxLayout>

#include <cmath>

namespace db::widgets {

namespace {

constexpr int kMinColumns = 200; // before the first layout (offscreen, hidden)
constexpr double kValueMargin = 0.08; // of the value span, above and below the data
constexpr qint64 kSmoothPixels = 3; // points at least this far apart on average: antialiased

} // namespace

QColor scopeChannelColor(int n)
{
    static const QColor kPalette[] = {
        QColor(31, 119, 180),  QColor(214, 39, 40), QColor(44, 160, 44),   QColor(255, 127, 14),
        QColor(148, 103, 189), QColor(140, 86, 75), QColor(227, 119, 194), QColor(23, 190, 207),
    };
    return kPalette[n % int(std::size(kPalette))];
}

ScopePlot::ScopePlot(QWidget *parent)
    : QWidget(parent)
    , m_plot(new QCustomPlot(this))
{
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_plot);
    m_plot->setObjectName(QStringLiteral("scopeCustomPlot"));
    m_plot->setMinimumSize(320, 200);
    m_plot->setFocusPolicy(Qt::ClickFocus);
    m_plot->setAutoAddPlottableToLegend(false);
    m_plot->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    m_plot->setNoAntialiasingOnDrag(true);
    m_plot->plotLayout()->clear(); // lanes are built in rebuildLayout()
    m_plot->plotLayout()->setRowSpacing(0);
    m_cursors = new ScopeCursors(m_plot, this);

    connect(m_plot, &QCustomPlot::mousePress, this, &ScopePlot::onMousePress);
    connect(m_plot, &QCustomPlot::mouseMove, m_cursors, &ScopeCursors::move);
    connect(m_plot, &QCustomPlot::mouseRelease, this, &ScopePlot::onMouseRelease);
    connect(m_plot, &QCustomPlot::mouseWheel, this, &ScopePlot::onWheel);
    connect(m_cursors, &ScopeCursors::moved, this, &ScopePlot::viewChanged);
    auto *shortcut = new QShortcut(QKeySequence(Qt::Key_A), this);
    shortcut->setContext(Qt::WidgetWithChildrenShortcut);
    connect(shortcut, &QShortcut::activated, this, &ScopePlot::autoscale);

    m_frameTimer.setInterval(1000 / kReplotHz);
    connect(&m_frameTimer, &QTimer::timeout, this, &ScopePlot::onFrame);
    rebuildLayout();
}

ScopePlot::~ScopePlot() = default;

void ScopePlot::setRecorder(scope::Recorder *recorder)
{
    if (m_recorder)
        m_recorder->disconnect(this);
    m_recorder = recorder;
    m_layoutDirty = true;
    m_following = true;
    markDirty();
    if (!recorder)
        return;
    connect(recorder, &scope::Recorder::dataAppended, this, &ScopePlot::markDirty);
    connect(recorder, &scope::Recorder::triggered, this, &ScopePlot::markDirty);
    connect(recorder, &scope::Recorder::channelsChanged, this, [this] {
        syncStyles();
        markDirty();
    });
    connect(recorder, &scope::Recorder::stateChanged, this, [this](scope::Recorder::State s) {
        if (s == scope::Recorder::State::Recording || s == scope::Recorder::State::Armed)
            m_following = true;
        markDirty();
    });
    syncStyles();
}

QString ScopePlot::styleKey(int channel) const
{
    // The id, numbered when the same object is recorded twice (e.g. from two devices).
    const QString id = m_recorder->channelInfo(channel).id;
    int occurrence = 0;
    for (int i = 0; i < channel; ++i)
        occurrence += m_recorder->channelInfo(i).id == id ? 1 : 0;
    return occurrence == 0 ? id : id + QLatin1Char('#') + QString::number(occurrence);
}

QString scopeChannelName(const scope::Recorder &recorder, int channel)
{
    const scope::ChannelInfo &info = recorder.channelInfo(channel);
    for (int i = 0; i < recorder.channelCount(); ++i) {
        if (recorder.channelInfo(i).device != info.device)
            return info.deviceLabel();
    }
    return info.displayLabel();
}

int ScopePlot::defaultLane(int channel) const
{
    // One value axis per unit: a new channel joins the lane of a channel with its unit, else
    // takes the first free lane (the last one when all are taken).
    const QString unit = m_recorder->channelInfo(channel).unit;
    QList<int> taken;
    for (int i = 0; i < m_recorder->channelCount(); ++i) {
        const auto it = m_styles.constFind(styleKey(i));
        if (i == channel || it == m_styles.cend())
            continue;
        if (m_recorder->channelInfo(i).unit == unit)
            return it->lane;
        taken.append(it->lane);
    }
    for (int lane = 1; lane <= kMaxLanes; ++lane) {
        if (!taken.contains(lane))
            return lane;
    }
    return kMaxLanes;
}

void ScopePlot::syncStyles()
{
    QStringList keys;
    const int n = m_recorder ? m_recorder->channelCount() : 0;
    for (int i = 0; i < n; ++i) {
        keys.append(styleKey(i));
        if (!m_styles.contains(keys.last()))
            m_styles.insert(keys.last(),
                            { scopeChannelColor(m_nextColor++), true, defaultLane(i) });
    }
    if (keys != m_layoutKeys) {
        m_layoutKeys = keys;
        m_layoutDirty = true;
        m_following = true; // new channels or a loaded recording: show all of it
    }
}

ScopeChannelStyle ScopePlot::channelStyle(int channel) const
{
    if (!m_recorder || channel < 0 || channel >= m_recorder->channelCount())
        return {};
    return m_styles.value(styleKey(channel));
}

void ScopePlot::setChannelStyle(int channel, const ScopeChannelStyle &style)
{
    if (!m_recorder || channel < 0 || channel >= m_recorder->channelCount())
        return;
    ScopeChannelStyle s = style;
    s.lane = std::clamp(s.lane, 1, kMaxLanes);
    m_styles.insert(styleKey(channel), s);
    m_layoutDirty = true;
    markDirty();
    Q_EMIT channelStyleChanged(channel);
}

QCPGraph *ScopePlot::graph(int channel) const
{
    return channel >= 0 && channel < int(m_graphs.size()) ? m_graphs[size_t(channel)] : nullptr;
}

QList<int> ScopePlot::lanes() const
{
    QList<int> result;
    for (const Lane &lane : m_lanes)
        result.append(lane.number);
    return result;
}

QCPAxisRect *ScopePlot::laneRect(int lane) const
{
    for (const Lane &l : m_lanes) {
        if (l.number == lane)
            return l.rect;
    }
    return nullptr;
}

double ScopePlot::timeOrigin() const
{
    const double t = m_recorder ? m_recorder->triggerTime() : NAN;
    return std::isfinite(t) ? t : 0.0;
}

double ScopePlot::timeLower() const
{
    return m_t0;
}

double ScopePlot::timeUpper() const
{
    return m_t1;
}

void ScopePlot::setTimeRange(double t0, double t1)
{
    if (!(t1 > t0) || !std::isfinite(t0) || !std::isfinite(t1))
        return;
    m_t0 = t0;
    m_t1 = t1;
    m_settingRange = true;
    for (const Lane &lane : m_lanes)
        lane.rect->axis(QCPAxis::atBottom)->setRange(t0, t1);
    m_settingRange = false;
    stopFollowing();
    updateData();
    m_plot->replot(QCustomPlot::rpQueuedReplot);
    Q_EMIT viewChanged();
}

void ScopePlot::autoscale()
{
    m_following = true;
    refreshNow();
}

void ScopePlot::stopFollowing()
{
    m_following = false;
}

void ScopePlot::markDirty()
{
    m_dirty = true;
}

void ScopePlot::onFrame()
{
    // Coalesced repaint: at most kReplotHz, only when something changed and someone can see it.
    if (m_dirty && isVisible())
        refreshNow();
}

void ScopePlot::showEvent(QShowEvent *event)
{
    QWidget::showEvent(event);
    m_frameTimer.start();
    markDirty();
}

void ScopePlot::hideEvent(QHideEvent *event)
{
    QWidget::hideEvent(event);
    m_frameTimer.stop();
}

void ScopePlot::refreshNow()
{
    if (timeOrigin() != m_origin)
        m_layoutDirty = true; // the time axis is labelled from another instant
    if (m_layoutDirty)
        rebuildLayout();
    if (m_following)
        fitTime();
    updateData();
    if (m_following)
        fitValues();
    m_dirty = false;
    m_plot->replot(QCustomPlot::rpQueuedReplot);
    Q_EMIT viewChanged();
}

void ScopePlot::fitTime()
{
    if (!m_recorder)
        return;
    double lo = INFINITY;
    double hi = -INFINITY;
    for (int i = 0; i < m_recorder->channelCount(); ++i) {
        const scope::TraceBuffer &b = m_recorder->buffer(i);
        if (b.isEmpty())
            continue;
        lo = std::min(lo, b.firstTime());
        hi = std::max(hi, b.lastTime());
    }
    if (!std::isfinite(lo))
        return;
    if (m_recorder->isRunning() && m_recorder->mode() == scope::Recorder::Mode::Roll)
        lo = hi - m_recorder->rollWindowS();
    if (hi - lo < 1e-6)
        hi = lo + 1.0;
    m_t0 = lo;
    m_t1 = hi;
    m_settingRange = true;
    for (const Lane &lane : m_lanes)
        lane.rect->axis(QCPAxis::atBottom)->setRange(lo, hi);
    m_settingRange = false;
}

void ScopePlot::fitValues()
{
    if (!m_recorder)
        return;
    for (const Lane &lane : m_lanes) {
        double lo = INFINITY;
        double hi = -INFINITY;
        for (int i = 0; i < int(m_graphs.size()); ++i) {
            if (!m_graphs[size_t(i)] || channelStyle(i).lane != lane.number)
                continue;
            const scope::TraceBuffer &b = m_recorder->buffer(i);
            const scope::TraceBuffer::Extent x = b.extent(b.lowerBound(m_t0), b.upperBound(m_t1));
            if (!x.valid)
                continue;
            const scope::ChannelInfo &info = m_recorder->channelInfo(i);
            const double a = info.display(x.min);
            const double c = info.display(x.max);
            lo = std::min({ lo, a, c });
            hi = std::max({ hi, a, c });
        }
        if (!std::isfinite(lo)) {
            lo = -1.0;
            hi = 1.0;
        }
        const double span = hi > lo ? hi - lo : std::abs(hi) * 0.1 + 1.0;
        // A band at the top for the lane's legend, so that it never hides the data.
        const double rectHeight = lane.rect->height();
        const double legendShare = rectHeight > 0 && lane.legend->itemCount() > 0
            ? std::clamp((lane.legend->outerRect().height() + 4.0) / rectHeight, 0.0, 0.4)
            : 0.0;
        const double full = span * (1.0 + 2.0 * kValueMargin);
        m_settingRange = true;
        lane.rect->axis(QCPAxis::atLeft)
            ->setRange(lo - span * kValueMargin,
                       hi + span * kValueMargin + full * legendShare / (1.0 - legendShare));
        m_settingRange = false;
    }
}

void ScopePlot::updateData()
{
    if (!m_recorder)
        return;
    for (int i = 0; i < int(m_graphs.size()) && i < m_recorder->channelCount(); ++i) {
        QCPGraph *g = m_graphs[size_t(i)];
        if (!g)
            continue;
        const scope::TraceBuffer &b = m_recorder->buffer(i);
        const int columns = std::max(g->keyAxis()->axisRect()->width(), kMinColumns);
        // Decimated into memory kept from the last frame: the graph's container lets go of
        // the points it shares with m_points[i] first, so refilling them allocates nothing.
        scope::DecimatedSeries &d = m_decimated[size_t(i)];
        scope::decimate(b, m_t0, m_t1, columns, d);
        const scope::ChannelInfo &info = m_recorder->channelInfo(i);
        g->data()->clear();
        QVector<QCPGraphData> &points = m_points[size_t(i)];
        points.resize(qsizetype(d.time.size()));
        for (size_t k = 0; k < d.time.size(); ++k)
            points[qsizetype(k)] = QCPGraphData(d.time[k], info.display(d.value[k]));
        g->data()->set(points, true);
        // Dense lines (min/max columns, or raw samples less than kSmoothPixels apart) gain
        // nothing from antialiasing or a wide pen but would cost most of the frame (the
        // stroker: 10 ms for 8 x 3000 raw points); sparse samples get the smooth pen.
        const bool smooth = !d.decimated && qint64(d.time.size()) * kSmoothPixels <= columns;
        QPen pen = g->pen();
        pen.setWidthF(smooth ? 1.4 : 1.0);
        g->setPen(pen);
        g->setAntialiased(smooth);
    }
    const scope::Trigger &trigger = m_recorder->trigger();
    const double t = m_recorder->triggerTime();
    const bool levelKind = trigger.kind != scope::Trigger::Kind::BitSet
        && trigger.kind != scope::Trigger::Kind::BitClear;
    QCPAxisRect *levelRect = trigger.isValid() && levelKind
            && trigger.channel < int(m_graphs.size()) && m_graphs[size_t(trigger.channel)]
        ? m_graphs[size_t(trigger.channel)]->keyAxis()->axisRect()
        : nullptr;
    m_cursors->setTrigger(t, trigger.level, levelRect);
}

void ScopePlot::onTimeRangeChanged(QCPAxisRect *source)
{
    if (m_settingRange)
        return;
    // A user zoom/pan on one lane: the others follow; QCustomPlot replots by itself.
    const QCPRange r = source->axis(QCPAxis::atBottom)->range();
    m_t0 = r.lower;
    m_t1 = r.upper;
    m_settingRange = true;
    for (const Lane &lane : m_lanes) {
        if (lane.rect != source)
            lane.rect->axis(QCPAxis::atBottom)->setRange(r);
    }
    m_settingRange = false;
    stopFollowing();
    updateData();
    Q_EMIT viewChanged();
}

void ScopePlot::onMousePress(QMouseEvent *event)
{
    const bool grabbed = m_cursors->press(event);
    m_plot->setInteraction(QCP::iRangeDrag, !grabbed);
    m_plot->setSelectionRectMode(
        !grabbed && (event->modifiers() & Qt::ShiftModifier) ? QCP::srmZoom : QCP::srmNone);
}

void ScopePlot::onMouseRelease()
{
    m_cursors->release();
    m_plot->setInteraction(QCP::iRangeDrag, true);
}

void ScopePlot::onWheel(QWheelEvent *event)
{
    const Qt::Orientation o =
        event->modifiers() & Qt::ControlModifier ? Qt::Vertical : Qt::Horizontal;
    for (const Lane &lane : m_lanes)
        lane.rect->setRangeZoom(o);
}

} // namespace db::widgets
