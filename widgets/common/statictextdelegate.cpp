#include "statictextdelegate.h"

#include <QApplication>
#include <QFontMetrics>
#include <QPainter>

namespace db::widgets {

namespace {
constexpr int kCachedTexts = 4096; // several screens of a log with eight columns
} // namespace

StaticTextDelegate::StaticTextDelegate(QObject *parent)
    : QStyledItemDelegate(parent)
    , m_cache(kCachedTexts)
{ }

const QStaticText &StaticTextDelegate::laidOut(const QString &text, const QFont &font,
                                               int width) const
{
    Key key { text, font.key(), width };
    if (const QStaticText *hit = m_cache.object(key))
        return *hit;
    // Laid out once; measured from the layout (a text that does not fit is laid out again,
    // elided).
    auto *laid = new QStaticText(text);
    laid->setTextFormat(Qt::PlainText);
    laid->setPerformanceHint(QStaticText::AggressiveCaching);
    laid->prepare(QTransform(), font);
    if (laid->size().width() > width) {
        laid->setText(QFontMetrics(font).elidedText(text, Qt::ElideRight, width));
        laid->prepare(QTransform(), font);
    }
    m_cache.insert(key, laid);
    return *m_cache.object(key);
}

QString StaticTextDelegate::shownText(const QString &text, const QFont &font, int width) const
{
    return laidOut(text, font, width).text();
}

void StaticTextDelegate::paint(QPainter *painter, const QStyleOptionViewItem &option,
                               const QModelIndex &index) const
{
    QStyleOptionViewItem opt = option;
    initStyleOption(&opt, index);
    const QWidget *widget = opt.widget;
    QStyle *style = widget ? widget->style() : QApplication::style();

    painter->save();
    style->drawPrimitive(QStyle::PE_PanelItemViewItem, &opt, painter, widget);
    if (!opt.text.isEmpty()) {
        // The standard delegate's text margin, without measuring the text for the layout.
        const int margin = style->pixelMetric(QStyle::PM_FocusFrameHMargin, nullptr, widget) + 1;
        const QRect rect = opt.rect.adjusted(margin, 0, -margin, 0);
        const QStaticText &text = laidOut(opt.text, opt.font, rect.width());
        const QSizeF size = text.size();
        qreal x = rect.left();
        if (opt.displayAlignment & Qt::AlignRight)
            x = rect.right() + 1 - size.width();
        else if (opt.displayAlignment & Qt::AlignHCenter)
            x = rect.left() + (rect.width() - size.width()) / 2;
        const qreal y = rect.top() + (rect.height() - size.height()) / 2;
        const QPalette::ColorGroup group = !(opt.state & QStyle::State_Enabled) ? QPalette::Disabled
            : (opt.state & QStyle::State_Active)                                ? QPalette::Normal
                                                 : QPalette::Inactive;
        painter->setPen(opt.palette.color(
            group,
            (opt.state & QStyle::State_Selected) ? QPalette::HighlightedText : QPalette::Text));
        painter->setFont(opt.font);
        painter->setClipRect(rect);
        painter->drawStaticText(QPointF(x, y), text);
    }
    painter->restore();
    if (opt.state & QStyle::State_HasFocus) {
        QStyleOptionFocusRect focus;
        focus.QStyleOption::operator=(opt);
        focus.rect = style->subElementRect(QStyle::SE_ItemViewItemFocusRect, &opt, widget);
        focus.state |= QStyle::State_KeyboardFocusChange | QStyle::State_Item;
        focus.backgroundColor = opt.palette.color(
            (opt.state & QStyle::State_Selected) ? QPalette::Highlight : QPalette::Window);
        style->drawPrimitive(QStyle::PE_FrameFocusRect, &focus, painter, widget);
    }
}

} // namespace db::widgets
