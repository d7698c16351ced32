#pragma once

#include <QScrollArea>

namespace db::widgets {

// A scroll area for a tall panel in a side dock: it scrolls vertically only, and its minimum
// width follows the panel's minimum width (also when the panel's contents change later, e.g.
// units appear in its fields after connecting), so no column of the panel is ever cut off.
class VerticalScrollArea : public QScrollArea
{
public:
    explicit VerticalScrollArea(QWidget *panel, QWidget *parent = nullptr);

    QSize minimumSizeHint() const override;

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;
};

} // namespace db::widgets
