#pragma once

// A scroll bar for views that grow while the user watches them (logs that follow their last
// row). QScrollBar repaints on every change of its range or value, and an item view raises its
// two scroll bars in turn on every relayout, so both are repainted with every batch of rows,
// together with the frame, dock and window beneath them. This one
// - compares its picture once the changes of a batch are done and repaints only when it differs
//   (the handle moved or resized, an end reached or left): in a long log that follows its last
//   row the handle soon sits at the bottom at its smallest size and stays there;
// - paints every pixel of its rectangle (nothing beneath it is repainted with it) and keeps its
//   last picture, so a repaint it cannot avoid is a copy while the mouse is elsewhere.
// Hovering, pressing, resizing and style or palette changes paint as QScrollBar does.

#include <QPixmap>
#include <QScrollBar>

namespace db::widgets {

class QuietScrollBar : public QScrollBar
{
    Q_OBJECT
public:
    explicit QuietScrollBar(Qt::Orientation orientation, QWidget *parent = nullptr);

    // Puts quiet scroll bars into `view` in place of its own (not with a style whose scroll bars
    // appear over the contents only while scrolling).
    static void install(class QAbstractItemView *view);

    // Pictures drawn by the style so far (the others were copies of the last one).
    int drawnPictures() const { return m_drawn; }

protected:
    void sliderChange(SliderChange change) override;
    void paintEvent(QPaintEvent *event) override;

private:
    struct Look
    {
        QRect handle;
        bool atMinimum = false;
        bool atMaximum = false;
        bool empty = false;
        bool operator==(const Look &o) const
        {
            return handle == o.handle && atMinimum == o.atMinimum && atMaximum == o.atMaximum
                && empty == o.empty;
        }
    };
    struct Picture
    {
        Look look;
        QSize size;
        int state = 0;
        qint64 palette = 0;
        const void *style = nullptr;
        qreal ratio = 0;
        bool operator==(const Picture &o) const = default;
    };
    Look look() const;
    void check();

    Look m_painted;
    bool m_valid = false; // m_painted holds the look of the last paint
    bool m_checkPending = false;
    QPixmap m_picture;
    Picture m_pictureOf;
    int m_drawn = 0;
};

} // namespace db::widgets
