#include "verticalscrollarea.h"

#include <QEvent>
#include <QScrollBar>

namespace db::widgets {

VerticalScrollArea::VerticalScrollArea(QWidget *panel, QWidget *parent)
    : QScrollArea(parent)
{
    setWidget(panel);
    setWidgetResizable(true);
    setFrameShape(QFrame::NoFrame);
    setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    panel->installEventFilter(this);
}

QSize VerticalScrollArea::minimumSizeHint() const
{
    QSize size = QScrollArea::minimumSizeHint();
    if (const QWidget *panel = widget())
        size.setWidth(panel->minimumSizeHint().width() + verticalScrollBar()->sizeHint().width()
                      + 2 * frameWidth());
    return size;
}

bool VerticalScrollArea::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == widget() && event->type() == QEvent::LayoutRequest)
        updateGeometry(); // the dock asks minimumSizeHint() again
    return QScrollArea::eventFilter(watched, event);
}

} // namespace db::widgets
