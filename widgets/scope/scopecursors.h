#pragma once

#include <QList>
#include <QObject>

#include <limits>

class QCustomPlot;
class QCPAxisRect;
class QCPItemStraightLine;
class QCPItemText;
class QMouseEvent;

namespace db::widgets {

// The A/B measurement cursors and the trigger markers of a ScopePlot: vertical lines through
// every lane (one item per lane, since QCustomPlot items live in one axis rect), labelled in
// the top lane, draggable with the mouse.
//
// Contract: attach() (re)creates the items after the plot's lanes changed; the items belong to
// the QCustomPlot, which deletes them with its layout. Positions are in seconds and survive
// attach(). moved() fires when A or B changes (drag or setPositions()).
class ScopeCursors : public QObject
{
    Q_OBJECT
public:
    static constexpr int kGrabPixels = 6; // how close to a line a press grabs it

    explicit ScopeCursors(QCustomPlot *plot, QObject *parent = nullptr);

    bool isEnabled() const { return m_enabled; }
    void setEnabled(bool enabled);
    double a() const { return m_a; }
    double b() const { return m_b; }
    void setPositions(double a, double b);
    // Moves A and B to 1/4 and 3/4 of [t0, t1] unless both are inside it already.
    void placeWithin(double t0, double t1);

    // Trigger markers: a vertical line at `time`, and a horizontal line at `level` in the lane
    // rect `levelRect` (nullptr: no level line). NaN time hides both.
    void setTrigger(double time, double level = std::numeric_limits<double>::quiet_NaN(),
                    QCPAxisRect *levelRect = nullptr);

    void attach(const QList<QCPAxisRect *> &rects);

    // Mouse handling forwarded by the plot. press() returns true when it grabbed a cursor; the
    // plot must then not pan. move() also sets the hover cursor shape.
    bool press(QMouseEvent *event);
    void move(QMouseEvent *event);
    void release();
    bool isDragging() const { return m_dragging != 0; }

Q_SIGNALS:
    void moved(double a, double b);

private:
    struct LaneItems
    {
        QCPAxisRect *rect = nullptr;
        QCPItemStraightLine *a = nullptr;
        QCPItemStraightLine *b = nullptr;
        QCPItemStraightLine *trigger = nullptr;
    };
    void update();
    int hit(QMouseEvent *event) const;
    double timeAt(QMouseEvent *event) const;

    QCustomPlot *m_plot;
    QList<LaneItems> m_lanes;
    QCPItemText *m_labelA = nullptr;
    QCPItemText *m_labelB = nullptr;
    QCPItemText *m_labelTrigger = nullptr;
    QCPItemStraightLine *m_level = nullptr;
    bool m_enabled = false;
    double m_a = 0.0;
    double m_b = 1.0;
    double m_triggerTime = std::numeric_limits<double>::quiet_NaN();
    double m_triggerLevel = std::numeric_limits<double>::quiet_NaN();
    QCPAxisRect *m_levelRect = nullptr;
    int m_dragging = 0; // 0 none, 1 A, 2 B
};

} // namespace db::widgets
