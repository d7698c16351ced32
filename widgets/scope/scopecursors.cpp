#include "scopecursors.h"

#include "widgets/common/plot.h"

#include <cmath>

namespace db::widgets {

namespace {

const QColor kCursorColor(60, 60, 60);
const QColor kTriggerColor(200, 30, 30);

QCPItemStraightLine *verticalLine(QCustomPlot *plot, QCPAxisRect *rect, const QPen &pen)
{
    auto *line = new QCPItemStraightLine(plot);
    line->setClipAxisRect(rect);
    for (QCPItemPosition *p : { line->point1, line->point2 })
        p->setAxes(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
    line->setPen(pen);
    line->setSelectable(false);
    return line;
}

QCPItemText *topLabel(QCustomPlot *plot, QCPAxisRect *rect, const QString &text,
                      const QColor &color)
{
    auto *label = new QCPItemText(plot);
    label->setClipToAxisRect(false);
    label->position->setTypeX(QCPItemPosition::ptPlotCoords);
    label->position->setTypeY(QCPItemPosition::ptAxisRectRatio);
    label->position->setAxes(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
    label->position->setAxisRect(rect);
    label->setPositionAlignment(Qt::AlignHCenter | Qt::AlignBottom);
    label->setText(text);
    label->setColor(Qt::white);
    label->setBrush(color);
    label->setPadding(QMargins(4, 1, 4, 1));
    QFont f = plot->font();
    f.setBold(true);
    label->setFont(f);
    label->setSelectable(false);
    return label;
}

void placeVertical(QCPItemStraightLine *line, double t, bool visible)
{
    if (!line)
        return;
    line->setVisible(visible);
    line->point1->setCoords(t, 0.0);
    line->point2->setCoords(t, 1.0);
}

void placeLabel(QCPItemText *label, double t, bool visible)
{
    if (!label)
        return;
    label->setVisible(visible);
    label->position->setCoords(t, 0.0);
}

} // namespace

ScopeCursors::ScopeCursors(QCustomPlot *plot, QObject *parent)
    : QObject(parent)
    , m_plot(plot)
{ }

void ScopeCursors::setEnabled(bool enabled)
{
    m_enabled = enabled;
    update();
}

void ScopeCursors::setPositions(double a, double b)
{
    if (!std::isfinite(a) || !std::isfinite(b))
        return;
    const bool changed = a != m_a || b != m_b;
    m_a = a;
    m_b = b;
    update();
    if (changed)
        Q_EMIT moved(m_a, m_b);
}

void ScopeCursors::placeWithin(double t0, double t1)
{
    const auto inside = [t0, t1](double t) {
        return t >= t0 && t <= t1;
    };
    if (!inside(m_a) || !inside(m_b))
        setPositions(t0 + (t1 - t0) * 0.25, t0 + (t1 - t0) * 0.75);
}

void ScopeCursors::setTrigger(double time, double level, QCPAxisRect *levelRect)
{
    m_triggerTime = time;
    m_triggerLevel = level;
    m_levelRect = levelRect;
    if (m_level) {
        m_plot->removeItem(m_level);
        m_level = nullptr;
    }
    if (levelRect && std::isfinite(level) && std::isfinite(time)) {
        m_level = new QCPItemStraightLine(m_plot);
        m_level->setClipAxisRect(levelRect);
        for (QCPItemPosition *p : { m_level->point1, m_level->point2 })
            p->setAxes(levelRect->axis(QCPAxis::atBottom), levelRect->axis(QCPAxis::atLeft));
        m_level->setPen(QPen(kTriggerColor, 1, Qt::DotLine));
        m_level->setSelectable(false);
        m_level->point1->setCoords(0.0, level);
        m_level->point2->setCoords(1.0, level);
    }
    update();
}

void ScopeCursors::attach(const QList<QCPAxisRect *> &rects)
{
    // The plot removed every item together with the old lanes.
    m_lanes.clear();
    m_level = nullptr;
    m_levelRect = nullptr;
    m_labelA = m_labelB = m_labelTrigger = nullptr;
    for (QCPAxisRect *rect : rects) {
        LaneItems lane;
        lane.rect = rect;
        lane.trigger = verticalLine(m_plot, rect, QPen(kTriggerColor, 1, Qt::DashLine));
        lane.a = verticalLine(m_plot, rect, QPen(kCursorColor, 1.5, Qt::SolidLine));
        lane.b = verticalLine(m_plot, rect, QPen(kCursorColor, 1.5, Qt::DashLine));
        m_lanes.append(lane);
    }
    if (!rects.isEmpty()) {
        m_labelA = topLabel(m_plot, rects.first(), QStringLiteral("A"), kCursorColor);
        m_labelB = topLabel(m_plot, rects.first(), QStringLiteral("B"), kCursorColor);
        // The trigger's flag hangs inside the lane, so that a cursor on the trigger time (the
        // usual place for A) keeps its own label visible above it.
        m_labelTrigger = topLabel(m_plot, rects.first(), QStringLiteral("T"), kTriggerColor);
        m_labelTrigger->setPositionAlignment(Qt::AlignHCenter | Qt::AlignTop);
    }
    update();
}

void ScopeCursors::update()
{
    const bool trigger = std::isfinite(m_triggerTime);
    for (const LaneItems &lane : std::as_const(m_lanes)) {
        placeVertical(lane.a, m_a, m_enabled);
        placeVertical(lane.b, m_b, m_enabled);
        placeVertical(lane.trigger, trigger ? m_triggerTime : 0.0, trigger);
    }
    placeLabel(m_labelA, m_a, m_enabled);
    placeLabel(m_labelB, m_b, m_enabled);
    placeLabel(m_labelTrigger, trigger ? m_triggerTime : 0.0, trigger);
    if (m_level)
        m_level->setVisible(trigger);
}

int ScopeCursors::hit(QMouseEvent *event) const
{
    if (!m_enabled)
        return 0;
    const QPointF pos = event->position();
    for (const LaneItems &lane : m_lanes) {
        if (!lane.rect->rect().adjusted(-2, -20, 2, 2).contains(pos.toPoint()))
            continue;
        const QCPAxis *x = lane.rect->axis(QCPAxis::atBottom);
        const double da = std::abs(x->coordToPixel(m_a) - pos.x());
        const double db = std::abs(x->coordToPixel(m_b) - pos.x());
        if (std::min(da, db) > kGrabPixels)
            return 0;
        return da <= db ? 1 : 2;
    }
    return 0;
}

double ScopeCursors::timeAt(QMouseEvent *event) const
{
    if (m_lanes.isEmpty())
        return 0.0;
    return m_lanes.first().rect->axis(QCPAxis::atBottom)->pixelToCoord(event->position().x());
}

bool ScopeCursors::press(QMouseEvent *event)
{
    if (event->button() != Qt::LeftButton)
        return false;
    m_dragging = hit(event);
    return m_dragging != 0;
}

void ScopeCursors::move(QMouseEvent *event)
{
    if (m_dragging == 0) {
        m_plot->setCursor(hit(event) != 0 ? Qt::SplitHCursor : Qt::ArrowCursor);
        return;
    }
    const double t = timeAt(event);
    if (m_dragging == 1)
        setPositions(t, m_b);
    else
        setPositions(m_a, t);
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

void ScopeCursors::release()
{
    m_dragging = 0;
}

} // namespace db::widgets
