#pragma once

#include <QLayout>
#include <QList>

namespace db::widgets {

// A row of widgets that wraps onto further rows when the room is too narrow for one, so that
// tool rows and button rows never make a window wider than a laptop screen. Within each row the
// widgets whose horizontal size policy expands share the room left over (a filter field grows,
// buttons keep their size hint); rows are left-aligned.
//
// sizeHint() is everything in one row; minimumSize() is the widest single widget. The height
// follows the width (hasHeightForWidth()), so a QBoxLayout above it gives the wrapped rows room.
class FlowLayout : public QLayout
{
public:
    explicit FlowLayout(QWidget *parent = nullptr);
    ~FlowLayout() override;

    void addItem(QLayoutItem *item) override;
    int count() const override { return int(m_items.size()); }
    QLayoutItem *itemAt(int index) const override { return m_items.value(index); }
    QLayoutItem *takeAt(int index) override;

    Qt::Orientations expandingDirections() const override { return {}; }
    bool hasHeightForWidth() const override { return true; }
    int heightForWidth(int width) const override;
    QSize sizeHint() const override;
    QSize minimumSize() const override;
    void setGeometry(const QRect &rect) override;

private:
    // Lays the items out in rect (only measures when apply is false); returns the height used.
    int arrange(const QRect &rect, bool apply) const;
    int horizontalGap() const;
    int verticalGap() const;

    QList<QLayoutItem *> m_items;
};

} // namespace db::widgets
