#include "quietscrollbar.h"

#include <QAbstractItemView>
#include <QApplication>
#include <QPainter>
#include <QStyleOptionSlider>

namespace db::widgets {

QuietScrollBar::QuietScrollBar(Qt::Orientation orientation, QWidget *parent)
    : QScrollBar(orientation, parent)
{
    setAttribute(Qt::WA_OpaquePaintEvent);
}

void QuietScrollBar::install(QAbstractItemView *view)
{
    // Styles whose bars appear only while scrolling draw them over the rows: not opaque.
    if (view->style()->styleHint(QStyle::SH_ScrollBar_Transient, nullptr, view))
        return;
    view->setVerticalScrollBar(new QuietScrollBar(Qt::Vertical, view));
    view->setHorizontalScrollBar(new QuietScrollBar(Qt::Horizontal, view));
    // Taking a bar in clears the attribute.
    view->verticalScrollBar()->setAttribute(Qt::WA_OpaquePaintEvent);
    view->horizontalScrollBar()->setAttribute(Qt::WA_OpaquePaintEvent);
    // The scroll area connects its own slots to new bars; the item view's (fetching more rows
    // at the end, hover after scrolling) were made for the bars it was built with.
    connect(view->verticalScrollBar(), SIGNAL(actionTriggered(int)), view,
            SLOT(verticalScrollbarAction(int)));
    connect(view->verticalScrollBar(), SIGNAL(valueChanged(int)), view,
            SLOT(verticalScrollbarValueChanged(int)));
    connect(view->horizontalScrollBar(), SIGNAL(actionTriggered(int)), view,
            SLOT(horizontalScrollbarAction(int)));
    connect(view->horizontalScrollBar(), SIGNAL(valueChanged(int)), view,
            SLOT(horizontalScrollbarValueChanged(int)));
}

QuietScrollBar::Look QuietScrollBar::look() const
{
    QStyleOptionSlider option;
    initStyleOption(&option);
    Look look;
    look.handle =
        style()->subControlRect(QStyle::CC_ScrollBar, &option, QStyle::SC_ScrollBarSlider, this);
    look.atMinimum = sliderPosition() == minimum();
    look.atMaximum = sliderPosition() == maximum();
    look.empty = minimum() == maximum();
    return look;
}

void QuietScrollBar::sliderChange(SliderChange change)
{
    if (!m_valid || change == SliderOrientationChange) {
        QScrollBar::sliderChange(change);
        return;
    }
    // A view that grows changes the range first and then follows with the value: in between the
    // handle has left the end for a moment. So the picture is compared once the changes are
    // done, before the window is painted.
    if (!m_checkPending) {
        m_checkPending = true;
        QMetaObject::invokeMethod(this, &QuietScrollBar::check, Qt::QueuedConnection);
    }
}

void QuietScrollBar::check()
{
    m_checkPending = false;
    // The handle's geometry and whether it stands at an end (styles draw the arrow there
    // disabled) are all a range, step or value change can alter in the picture.
    if (!m_valid || look() != m_painted)
        update();
}

void QuietScrollBar::paintEvent(QPaintEvent *event)
{
    m_painted = look();
    m_valid = true;
    if (underMouse() || QApplication::mouseButtons() != Qt::NoButton) {
        // Hovered or pressed parts are drawn by QScrollBar, which knows which they are.
        {
            QPainter painter(this);
            painter.fillRect(rect(), palette().window());
        }
        ++m_drawn;
        QScrollBar::paintEvent(event);
        return;
    }
    QStyleOptionSlider option;
    initStyleOption(&option);
    option.subControls = QStyle::SC_All;
    option.activeSubControls = QStyle::SC_None;
    const Picture of { m_painted,          size(), int(option.state), palette().cacheKey(), style(),
                       devicePixelRatioF() };
    if (m_picture.isNull() || of != m_pictureOf) {
        QPixmap picture(size() * of.ratio);
        picture.setDevicePixelRatio(of.ratio);
        picture.fill(palette().color(QPalette::Window));
        QPainter painter(&picture);
        style()->drawComplexControl(QStyle::CC_ScrollBar, &option, &painter, this);
        painter.end();
        m_picture = picture;
        m_pictureOf = of;
        ++m_drawn;
    }
    QPainter(this).drawPixmap(0, 0, m_picture);
}

} // namespace db::widgets
