#include "widgetstyle.h"

#include <QApplication>
#include <QFontDatabase>
#include <QLabel>
#include <QPainter>
#include <QPixmap>

namespace db::widgets::style {

QFont monospaceFont()
{
    QFont font = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    font.setStyleHint(QFont::Monospace);
    font.setPointSizeF(QApplication::font().pointSizeF());
    return font;
}

QColor okColor()
{
    return QColor(0x1e, 0x8e, 0x3e);
}

QColor warningColor()
{
    return QColor(0xc2, 0x7c, 0x0e);
}

QColor errorColor()
{
    return QColor(0xc6, 0x28, 0x28);
}

QColor inactiveColor()
{
    return QColor(0x80, 0x80, 0x80);
}

void setTextColor(QWidget *widget, const QColor &color)
{
    QPalette pal = widget->palette();
    const QColor c = color.isValid() ? color : QApplication::palette().color(QPalette::WindowText);
    pal.setColor(QPalette::WindowText, c);
    pal.setColor(QPalette::Text, c);
    widget->setPalette(pal);
}

void setFrequentText(QLabel *label, const QString &text)
{
    if (label->text() == text)
        return;
    label->setText(text);
    const QSize hint = label->sizeHint();
    const int step = 4 * qMax(1, label->fontMetrics().averageCharWidth());
    const int fixed = label->minimumWidth() == label->maximumWidth() ? label->maximumWidth() : 0;
    if (hint.width() > fixed || hint.width() < fixed / 2)
        label->setFixedWidth((hint.width() + step - 1) / step * step);
    if (label->minimumHeight() != hint.height() || label->maximumHeight() != hint.height())
        label->setFixedHeight(hint.height());
}

QString toolTip(const QString &plainText)
{
    if (plainText.isEmpty())
        return {};
    return QStringLiteral("<p>") + plainText.toHtmlEscaped() + QStringLiteral("</p>");
}

QColor changedBackground()
{
    QColor c = warningColor();
    c.setAlpha(48);
    return c;
}

void setStale(QLabel *label, bool stale)
{
    if (label->property("stale").toBool() == stale && label->property("stale").isValid())
        return;
    label->setProperty("stale", stale);
    setTextColor(label, stale ? inactiveColor() : QColor());
}

QColor connectionStateColor(DeviceConnection::State state)
{
    switch (state) {
    case DeviceConnection::State::Connected:
        return okColor();
    case DeviceConnection::State::Connecting:
    case DeviceConnection::State::Closing:
        return warningColor();
    case DeviceConnection::State::Disconnected:
        return inactiveColor();
    }
    return inactiveColor();
}

QColor healthColor(ConnectionHealth::Status status)
{
    switch (status) {
    case ConnectionHealth::Status::Responding:
        return okColor();
    case ConnectionHealth::Status::Connecting:
    case ConnectionHealth::Status::WaitingForAnswer:
    case ConnectionHealth::Status::NotResponding:
        return warningColor();
    case ConnectionHealth::Status::Failed:
    case ConnectionHealth::Status::Lost:
        return errorColor();
    case ConnectionHealth::Status::Idle:
    case ConnectionHealth::Status::ClosedByUser:
        return inactiveColor();
    }
    return inactiveColor();
}

namespace {
QIcon roundIcon(const QColor &color)
{
    QPixmap pixmap(16, 16);
    pixmap.fill(Qt::transparent);
    QPainter p(&pixmap);
    p.setRenderHint(QPainter::Antialiasing);
    p.setPen(QPen(color.darker(140), 1));
    p.setBrush(color);
    p.drawEllipse(QRectF(2.5, 2.5, 11, 11));
    return QIcon(pixmap);
}
} // namespace

QIcon connectionStateIcon(DeviceConnection::State state)
{
    return roundIcon(connectionStateColor(state));
}

QIcon healthIcon(ConnectionHealth::Status status)
{
    return roundIcon(healthColor(status));
}

} // namespace db::widgets::style
