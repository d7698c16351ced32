#include "wheelguard.h"

#include <QAbstractScrollArea>
#include <QAbstractSpinBox>
#include <QApplication>
#include <QComboBox>
#include <QEvent>
#include <QWheelEvent>

namespace db::widgets {

namespace {
QWidget *guarded(QObject *object)
{
    if (auto *spin = qobject_cast<QAbstractSpinBox *>(object))
        return spin;
    if (auto *combo = qobject_cast<QComboBox *>(object))
        return combo;
    return nullptr;
}
} // namespace

WheelGuard::WheelGuard(QObject *parent)
    : QObject(parent)
{
    setObjectName(QStringLiteral("wheelGuard"));
}

void WheelGuard::install()
{
    if (qApp->findChild<WheelGuard *>(QStringLiteral("wheelGuard"), Qt::FindDirectChildrenOnly))
        return;
    qApp->installEventFilter(new WheelGuard(qApp));
}

bool WheelGuard::eventFilter(QObject *watched, QEvent *event)
{
    if (event->type() == QEvent::Show || event->type() == QEvent::Polish) {
        if (QWidget *box = guarded(watched); box && box->focusPolicy() == Qt::WheelFocus)
            box->setFocusPolicy(Qt::StrongFocus);
    } else if (event->type() == QEvent::Wheel) {
        if (QWidget *box = guarded(watched); box && !box->hasFocus()) {
            // Not delivered to the box: the scroll area around it scrolls instead. (Qt passes an
            // ignored wheel event to the parent only when it came from the window system; the
            // parent is usually a plain panel, so the scroll area is asked directly.)
            for (QWidget *w = box->parentWidget(); w; w = w->parentWidget()) {
                auto *area = qobject_cast<QAbstractScrollArea *>(w);
                if (!area || !area->viewport()->isAncestorOf(box))
                    continue;
                auto *wheel = static_cast<QWheelEvent *>(event);
                const QPointF pos = area->viewport()->mapFromGlobal(wheel->globalPosition());
                QWheelEvent copy(pos, wheel->globalPosition(), wheel->pixelDelta(),
                                 wheel->angleDelta(), wheel->buttons(), wheel->modifiers(),
                                 wheel->phase(), wheel->inverted());
                QApplication::sendEvent(area->viewport(), &copy);
                event->accept();
                return true;
            }
            event->ignore(); // no scroll area: passed on to the parents (window-system events)
            return true;
        }
    }
    return false;
}

} // namespace db::widgets
