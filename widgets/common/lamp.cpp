#include "lamp.h"

#include <QPainter>

namespace db::widgets {

namespace {
constexpr int kSpacing = 5;
}

Lamp::Lamp(const QString &text, const QColor &onColor, QWidget *parent)
    : QWidget(parent)
    , m_text(text)
    , m_onColor(onColor)
{
    setSizePolicy(QSizePolicy::Minimum, QSizePolicy::Fixed);
}

void Lamp::setOn(bool on)
{
    if (m_on == on && !m_stale)
        return;
    m_on = on;
    m_stale = false;
    update();
}

void Lamp::setStale(bool stale)
{
    if (m_stale == stale)
        return;
    m_stale = stale;
    update();
}

void Lamp::setOnColor(const QColor &color)
{
    m_onColor = color;
    update();
}

QSize Lamp::sizeHint() const
{
    const QFontMetrics fm = fontMetrics();
    const int diameter = fm.height() - 2;
    return { diameter + kSpacing + fm.horizontalAdvance(m_text) + 2, fm.height() + 4 };
}

void Lamp::paintEvent(QPaintEvent *)
{
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const QFontMetrics fm = fontMetrics();
    const int diameter = fm.height() - 2;
    const QRectF circle(1, (height() - diameter) / 2.0, diameter - 2, diameter - 2);

    QColor fill = m_on ? m_onColor : palette().color(QPalette::Button).darker(115);
    if (m_stale)
        fill = palette().color(QPalette::Window);
    p.setPen(QPen(palette().color(QPalette::Mid), 1));
    p.setBrush(fill);
    p.drawEllipse(circle);

    QColor textColor = palette().color(QPalette::WindowText);
    if (m_stale)
        textColor = palette().color(QPalette::Disabled, QPalette::WindowText);
    p.setPen(textColor);
    const QRect textRect(diameter + kSpacing, 0, width() - diameter - kSpacing, height());
    p.drawText(textRect, Qt::AlignVCenter | Qt::AlignLeft, m_text);
}

} // namespace db::widgets
