#include "tooltipwrapper.h"

#include "widgetstyle.h"

#include <QApplication>
#include <QHelpEvent>
#include <QTextDocument>
#include <QToolTip>
#include <QWidget>

namespace db::widgets {

ToolTipWrapper::ToolTipWrapper(QObject *parent)
    : QObject(parent)
{
    setObjectName(QStringLiteral("toolTipWrapper"));
}

void ToolTipWrapper::install()
{
    if (qApp->findChild<ToolTipWrapper *>(QStringLiteral("toolTipWrapper"),
                                          Qt::FindDirectChildrenOnly))
        return;
    qApp->installEventFilter(new ToolTipWrapper(qApp));
}

bool ToolTipWrapper::eventFilter(QObject *watched, QEvent *event)
{
    if (event->type() != QEvent::ToolTip || !watched->isWidgetType())
        return false;
    auto *widget = static_cast<QWidget *>(watched);
    const QString tip = widget->toolTip();
    if (tip.size() <= kWrapAfter || Qt::mightBeRichText(tip))
        return false;
    const auto *help = static_cast<QHelpEvent *>(event);
    QToolTip::showText(help->globalPos(), style::toolTip(tip), widget, {},
                       widget->toolTipDuration());
    return true;
}

} // namespace db::widgets
