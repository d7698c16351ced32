#pragma once

#include "motion/axisinterface.h"

#include <QGroupBox>
#include <QPointer>

class QCheckBox;
class QLabel;
class QPushButton;
class QSpinBox;

namespace db::widgets {

// Runs a motion block of the drive's own table (AxisInterface::startMotionBlock): block number,
// single block or the sequence it starts, resume; says how it ended. Hidden unless the axis
// offers motion blocks. Esc and the panel's stop buttons stop it like any motion (quick stop).
class MotionBlockBox : public QGroupBox
{
    Q_OBJECT
public:
    explicit MotionBlockBox(QWidget *parent = nullptr);

    // May be null; not owned.
    void setAxis(motion::AxisInterface *axis);
    bool isRunning() const { return m_reply != nullptr; }

public Q_SLOTS:
    void run();

private:
    QPointer<motion::AxisInterface> m_axis;
    QPointer<Reply> m_reply;
    QSpinBox *m_block = nullptr;
    QCheckBox *m_sequence = nullptr;
    QCheckBox *m_resume = nullptr;
    QPushButton *m_run = nullptr;
    QLabel *m_result = nullptr;
};

} // namespace db::widgets
