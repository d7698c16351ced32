#pragma once

#include "motion/motionaxis.h"
#include "motion/motioncommand.h"

#include <QGroupBox>

#include <memory>

class QCheckBox;
class QLabel;
class QPushButton;
class QSpinBox;

namespace db::widgets {

// Runs a motion block of the drive's own table (the command model's MotionBlock command): block
// number, single block or the sequence it starts, resume; shows the command's state and how it
// ended. Hidden unless the axis offers motion blocks. Esc stops it like any motion.
class MotionBlockBox : public QGroupBox
{
    Q_OBJECT
public:
    explicit MotionBlockBox(QWidget *parent = nullptr);

    // May be null; not owned (it must outlive this box or be replaced first).
    void setAxis(motion::MotionAxis *axis);
    bool isRunning() const { return m_command && m_command->isBusy(); }

public Q_SLOTS:
    void run();

private:
    std::unique_ptr<motion::MotionCommand> m_command;
    QSpinBox *m_block = nullptr;
    QCheckBox *m_sequence = nullptr;
    QCheckBox *m_resume = nullptr;
    QPushButton *m_run = nullptr;
    QLabel *m_result = nullptr;
};

} // namespace db::widgets
