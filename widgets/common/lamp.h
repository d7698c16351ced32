#pragma once

#include <QColor>
#include <QWidget>

namespace db::widgets {

// A small round indicator with a caption, for status bits and digital I/O.
// Stale lamps (value not current, e.g. after a failed read) are drawn washed out.
class Lamp : public QWidget
{
    Q_OBJECT
public:
    explicit Lamp(const QString &text, const QColor &onColor = QColor(0x2e, 0xa0, 0x43),
                  QWidget *parent = nullptr);

    QString text() const { return m_text; }
    bool isOn() const { return m_on; }
    void setOn(bool on);
    bool isStale() const { return m_stale; }
    void setStale(bool stale);
    void setOnColor(const QColor &color);

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override { return sizeHint(); }

protected:
    void paintEvent(QPaintEvent *event) override;

private:
    QString m_text;
    QColor m_onColor;
    bool m_on = false;
    bool m_stale = true;
};

} // namespace db::widgets
