// ScopePlot: the lanes (stacked axis rects sharing the time axis) and their graphs.
#include "scopeplot.h"

#include "scope/recorder.h"
#include "scopecursors.h"
#include "widgets/common/plot.h"

#include <set>

namespace db::widgets {

namespace {

const QColor kGridColor(225, 225, 225);
const QColor kAxisColor(90, 90, 90);

void styleAxis(QCPAxis *axis)
{
    axis->setBasePen(QPen(kAxisColor));
    axis->setTickPen(QPen(kAxisColor));
    axis->setSubTickPen(QPen(kAxisColor));
    axis->grid()->setPen(QPen(kGridColor, 1, Qt::SolidLine));
    axis->grid()->setZeroLinePen(QPen(QColor(190, 190, 190)));
    axis->setTickLabelColor(kAxisColor);
    axis->setLabelColor(QColor(50, 50, 50));
}

// Labels the time axis from an origin (the trigger instant) while its coordinates stay on the
// recorder's time base: ticks fall on round numbers counted from the origin.
class RelativeTimeTicker : public QCPAxisTicker
{
public:
    explicit RelativeTimeTicker(double origin)
        : m_origin(origin)
    { }

protected:
    QVector<double> createTickVector(double tickStep, const QCPRange &range) override
    {
        QVector<double> ticks = QCPAxisTicker::createTickVector(tickStep, range - m_origin);
        for (double &t : ticks)
            t += m_origin;
        return ticks;
    }
    QString getTickLabel(double tick, const QLocale &locale, QChar formatChar,
                         int precision) override
    {
        return QCPAxisTicker::getTickLabel(tick - m_origin, locale, formatChar, precision);
    }

private:
    double m_origin;
};

} // namespace

QString ScopePlot::laneLabel(int lane) const
{
    // The units of the lane's channels; their names are in the lane's legend.
    QStringList units;
    bool any = false;
    for (int i = 0; m_recorder && i < m_recorder->channelCount(); ++i) {
        const ScopeChannelStyle s = channelStyle(i);
        if (!s.visible || s.lane != lane)
            continue;
        any = true;
        const QString unit = m_recorder->channelInfo(i).unit;
        if (!unit.isEmpty() && !units.contains(unit))
            units.append(unit);
    }
    if (units.isEmpty())
        return any ? tr("raw") : QString();
    return units.join(QStringLiteral(", "));
}

void ScopePlot::rebuildLayout()
{
    // Everything is rebuilt: items and graphs first (they refer to the axes), then the lanes.
    m_plot->clearItems();
    m_plot->clearGraphs();
    m_plot->plotLayout()->clear();
    delete m_marginGroup;
    m_marginGroup = new QCPMarginGroup(m_plot);
    m_lanes.clear();
    m_origin = timeOrigin();
    const bool relative = m_recorder && std::isfinite(m_recorder->triggerTime());
    const int n = m_recorder ? m_recorder->channelCount() : 0;
    m_graphs.assign(size_t(n), nullptr);
    m_decimated.resize(size_t(n));
    m_points.resize(size_t(n));

    std::set<int> used;
    for (int i = 0; i < n; ++i) {
        const ScopeChannelStyle s = channelStyle(i);
        if (s.visible)
            used.insert(s.lane);
    }
    if (used.empty())
        used.insert(1);

    int row = 0;
    for (int number : used) {
        const bool top = row == 0;
        const bool bottom = row == int(used.size()) - 1;
        auto *rect = new QCPAxisRect(m_plot, true);
        m_plot->plotLayout()->addElement(row, 0, rect);
        rect->setMarginGroup(QCP::msLeft | QCP::msRight, m_marginGroup);
        rect->setAutoMargins(QCP::msLeft | QCP::msRight | (bottom ? QCP::msBottom : QCP::msNone));
        rect->setMargins(QMargins(0, top ? 22 : 6, 0, bottom ? 0 : 6));
        rect->setRangeDrag(Qt::Horizontal | Qt::Vertical);
        rect->setRangeZoom(Qt::Horizontal);
        rect->axis(QCPAxis::atTop)->setVisible(false);
        rect->axis(QCPAxis::atRight)->setVisible(true);
        rect->axis(QCPAxis::atRight)->setTicks(false);
        rect->axis(QCPAxis::atRight)->setTickLabels(false);
        rect->axis(QCPAxis::atRight)->setBasePen(QPen(kAxisColor));
        QCPAxis *x = rect->axis(QCPAxis::atBottom);
        QCPAxis *y = rect->axis(QCPAxis::atLeft);
        styleAxis(x);
        styleAxis(y);
        x->setTickLabels(bottom);
        x->setTicker(QSharedPointer<QCPAxisTicker>(new RelativeTimeTicker(m_origin)));
        if (bottom)
            x->setLabel(relative ? tr("time from the trigger (s)") : tr("time (s)"));
        y->setLabel(laneLabel(number));
        y->setNumberFormat(QStringLiteral("gb"));
        x->setRange(m_t0, m_t1);
        for (QCPAxis *axis : rect->axes())
            axis->grid()->setLayer(QStringLiteral("grid"));

        auto *legend = new QCPLegend;
        rect->insetLayout()->addElement(legend, Qt::AlignTop | Qt::AlignRight);
        legend->setLayer(QStringLiteral("legend"));
        legend->setBrush(QColor(255, 255, 255, 215));
        legend->setBorderPen(QPen(QColor(200, 200, 200)));
        QFont f = font();
        f.setPointSizeF(f.pointSizeF() * 0.9);
        legend->setFont(f);
        legend->setIconSize(18, 8);

        connect(x, qOverload<const QCPRange &>(&QCPAxis::rangeChanged), this,
                [this, rect] { onTimeRangeChanged(rect); });
        connect(y, qOverload<const QCPRange &>(&QCPAxis::rangeChanged), this, [this] {
            if (!m_settingRange)
                stopFollowing();
        });
        m_lanes.push_back({ number, rect, legend });
        m_plot->plotLayout()->setRowStretchFactor(row, 1.0);
        ++row;
    }

    for (int i = 0; i < n; ++i) {
        const ScopeChannelStyle s = channelStyle(i);
        if (!s.visible)
            continue;
        const auto lane = std::find_if(m_lanes.begin(), m_lanes.end(),
                                       [&s](const Lane &l) { return l.number == s.lane; });
        QCPGraph *g = m_plot->addGraph(lane->rect->axis(QCPAxis::atBottom),
                                       lane->rect->axis(QCPAxis::atLeft));
        const scope::ChannelInfo &info = m_recorder->channelInfo(i);
        const QString name = scopeChannelName(*m_recorder, i);
        g->setName(info.unit.isEmpty() ? name : QStringLiteral("%1 [%2]").arg(name, info.unit));
        g->setPen(QPen(s.color, 1.4));
        g->setAdaptiveSampling(false); // the data is decimated already
        g->addToLegend(lane->legend);
        m_graphs[size_t(i)] = g;
    }

    QList<QCPAxisRect *> rects;
    for (const Lane &lane : m_lanes)
        rects.append(lane.rect);
    m_cursors->attach(rects);
    m_layoutDirty = false;
    m_dirty = true;
}

} // namespace db::widgets
