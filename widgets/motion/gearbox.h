#pragma once

#include "motion/motionaxis.h"
#include "motion/motioncommand.h"

#include <QGroupBox>
#include <QPointer>

#include <memory>

class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSpinBox;

namespace db::widgets {

// The electronic gear (PLCopen MC_GearIn / MC_GearOut): couples the axis to the drive's master
// at numerator:denominator with the ramps (0 = the drive's own), shows "in gear" once the drive
// reports it, and uncouples (the drive brakes the axis to a stop). Hidden unless the axis has an
// electronic gear. Esc stops it like any motion.
class GearBox : public QGroupBox
{
    Q_OBJECT
public:
    explicit GearBox(QWidget *parent = nullptr);

    // May be null; not owned (it must outlive this box or be replaced first).
    void setAxis(motion::MotionAxis *axis);
    bool isCoupled() const;

public Q_SLOTS:
    void gearIn();
    void gearOut();

private:
    void follow(motion::MotionCommand *command);

    QPointer<motion::MotionAxis> m_axis;
    std::unique_ptr<motion::MotionCommand> m_in;
    std::unique_ptr<motion::MotionCommand> m_out;
    QSpinBox *m_numerator = nullptr;
    QSpinBox *m_denominator = nullptr;
    QDoubleSpinBox *m_acceleration = nullptr;
    QDoubleSpinBox *m_deceleration = nullptr;
    QPushButton *m_couple = nullptr;
    QPushButton *m_uncouple = nullptr;
    QLabel *m_result = nullptr;
};

} // namespace db::widgets
