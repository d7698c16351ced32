#include "flowlayout.h"

#include <QStyle>
#include <QWidget>

namespace db::widgets {

FlowLayout::FlowLayout(QWidget *parent)
    : QLayout(parent)
{ }

FlowLayout::~FlowLayout()
{
    while (QLayoutItem *item = takeAt(0))
        delete item;
}

void FlowLayout::addItem(QLayoutItem *item)
{
    m_items.append(item);
}

QLayoutItem *FlowLayout::takeAt(int index)
{
    if (index < 0 || index >= m_items.size())
        return nullptr;
    return m_items.takeAt(index);
}

int FlowLayout::heightForWidth(int width) const
{
    return arrange(QRect(0, 0, width, 0), false);
}

QSize FlowLayout::sizeHint() const
{
    int width = 0;
    int height = 0;
    int visible = 0;
    for (const QLayoutItem *item : m_items) {
        if (item->isEmpty())
            continue;
        const QSize hint = item->sizeHint();
        width += hint.width();
        height = qMax(height, hint.height());
        ++visible;
    }
    width += qMax(0, visible - 1) * horizontalGap();
    const QMargins m = contentsMargins();
    return QSize(width + m.left() + m.right(), height + m.top() + m.bottom());
}

QSize FlowLayout::minimumSize() const
{
    QSize size;
    for (const QLayoutItem *item : m_items) {
        if (!item->isEmpty())
            size = size.expandedTo(item->minimumSize());
    }
    const QMargins m = contentsMargins();
    return size + QSize(m.left() + m.right(), m.top() + m.bottom());
}

void FlowLayout::setGeometry(const QRect &rect)
{
    QLayout::setGeometry(rect);
    arrange(rect, true);
}

int FlowLayout::horizontalGap() const
{
    if (spacing() >= 0)
        return spacing();
    const QWidget *parent = parentWidget();
    return parent
        ? parent->style()->pixelMetric(QStyle::PM_LayoutHorizontalSpacing, nullptr, parent)
        : 6;
}

int FlowLayout::verticalGap() const
{
    if (spacing() >= 0)
        return spacing();
    const QWidget *parent = parentWidget();
    return parent ? parent->style()->pixelMetric(QStyle::PM_LayoutVerticalSpacing, nullptr, parent)
                  : 6;
}

int FlowLayout::arrange(const QRect &rect, bool apply) const
{
    const QRect area = rect.marginsRemoved(contentsMargins());
    const int gapX = qMax(0, horizontalGap());
    const int gapY = qMax(0, verticalGap());
    QList<QLayoutItem *> visible;
    for (QLayoutItem *item : m_items) {
        if (!item->isEmpty())
            visible.append(item);
    }
    // Widths at size hint, but never narrower than the item's minimum nor wider than the area.
    const auto width = [&area](const QLayoutItem *item) {
        return qMax(item->minimumSize().width(), qMin(item->sizeHint().width(), area.width()));
    };
    int y = area.top();
    int start = 0;
    while (start < visible.size()) {
        // The items of this row: as many as fit, at least one.
        int end = start;
        int used = 0;
        int rowHeight = 0;
        int expanding = 0;
        while (end < visible.size()) {
            const int w = width(visible[end]);
            const int next = used + (end > start ? gapX : 0) + w;
            if (end > start && next > area.width())
                break;
            used = next;
            rowHeight = qMax(rowHeight, visible[end]->sizeHint().height());
            if (visible[end]->expandingDirections() & Qt::Horizontal)
                ++expanding;
            ++end;
        }
        if (apply) {
            int extra = qMax(0, area.width() - used);
            int x = area.left();
            for (int i = start; i < end; ++i) {
                QLayoutItem *item = visible[i];
                int w = width(item);
                if (expanding > 0 && (item->expandingDirections() & Qt::Horizontal)) {
                    const int share = extra / expanding;
                    w = qMin(w + share, qMax(w, item->maximumSize().width()));
                    extra -= share;
                    --expanding;
                }
                item->setGeometry(QRect(x, y, w, rowHeight));
                x += w + gapX;
            }
        }
        y += rowHeight + gapY;
        start = end;
    }
    const int height = visible.isEmpty() ? 0 : y - gapY - area.top();
    const QMargins m = contentsMargins();
    return height + m.top() + m.bottom();
}

} // namespace db::widgets
