#pragma once

#include "motion/leasedmove.h"
#include "motion/motionaxis.h"

#include <QHash>
#include <QPointer>
#include <QVariantMap>
#include <QWidget>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;

namespace db::widgets {

// The motion command form of the jog panel (stoeber_motion.md Sec. 7.1, 7.2): command, target,
// velocity, acceleration, deceleration, jerk, direction, homing method, torque; Execute, Stop,
// Halt; the status of the last command (busy/active/done/aborted/error with its cause) and its
// limitation flags.
//
// One MotionCommand instance per command kind, owned by the form: Execute gives it a rising edge
// with the current field values (latched by the model, Sec. 2.2). Stop and Halt hold Execute
// until their command is done, then release it (the state stays Stopping/Discrete Motion until
// then, Sec. 3.12). Fields are clamped to the axis limits (setLimits()), never silently: a value
// lowered to a limit is named with the limit, and each field's tooltip gives its range; the model
// refuses what the fields cannot express, and the refusal reason is shown.
class MotionForm : public QWidget
{
    Q_OBJECT
public:
    explicit MotionForm(QWidget *parent = nullptr);
    ~MotionForm() override;

    // May be null. The axis is not owned.
    void setAxis(motion::MotionAxis *axis);
    // The lease that MC_MoveVelocity runs in (may be null, not owned): on a drive with profile
    // position, a velocity command from the form moves in leases renewed while it runs, like a
    // jog, so that the drive stops by itself when the renewals stop; Stop and Halt end it.
    // Without profile position it is the drive's MC_MoveVelocity, which nothing bounds.
    void setLease(motion::LeasedMove *lease);
    // Field ranges from the axis configuration; units for the suffixes.
    void setLimits(const motion::AxisConfig &config, const QString &positionUnit,
                   const QString &velocityUnit);
    void setFeatures(motion::AxisInterface::Features features);
    // The drive's homing methods (e.g. 6098h's enumeration); empty = the CiA 402 set-zero 35.
    void setHomingMethods(const QMap<qlonglong, QString> &methods);

    // The fields as they are, to be kept per device (JogPanel) and given back with setValues().
    QVariantMap values() const;
    // Sets the fields as given, free of the previous device's limits; the next setLimits()
    // lowers what exceeds the new ones and says so (limitNote()).
    void setValues(const QVariantMap &values);
    // What setLimits() lowered, and why ("Velocity 5000 → 2000 mm/s: the drive's maximum");
    // empty when it lowered nothing. Shown under the fields.
    QString limitNote() const;

    motion::CommandKind selectedCommand() const;
    void selectCommand(motion::CommandKind kind);
    // The values Execute would latch.
    motion::MoveParams params() const;
    motion::HomingParams homing() const;

    // The command of kind (created on first use), for tests and the status display.
    motion::MotionCommand *command(motion::CommandKind kind);
    // The command Execute/Stop/Halt started last (null before).
    motion::MotionCommand *lastCommand() const { return m_last; }
    QString statusText() const;

public Q_SLOTS:
    void execute();
    void stop();
    void halt();

Q_SIGNALS:
    // A command was started from the form (the panel keeps its watchdog alive meanwhile).
    void started(motion::MotionCommand *command);

private:
    void buildUi();
    void updateFields();
    void start(motion::CommandKind kind);
    bool refusesInput(motion::CommandKind kind, const motion::MoveParams &params);
    bool velocityIsLeased() const;
    void showStatus();

    QPointer<motion::MotionAxis> m_axis;
    QHash<int, motion::MotionCommand *> m_commands;
    QPointer<motion::MotionCommand> m_last;
    QPointer<motion::LeasedMove> m_lease;
    motion::AxisInterface::Features m_features;

    QComboBox *m_command = nullptr;
    QDoubleSpinBox *m_target = nullptr;
    QDoubleSpinBox *m_velocity = nullptr;
    QDoubleSpinBox *m_acceleration = nullptr;
    QDoubleSpinBox *m_deceleration = nullptr;
    QDoubleSpinBox *m_jerk = nullptr;
    QComboBox *m_direction = nullptr;
    QComboBox *m_homingMethod = nullptr;
    QDoubleSpinBox *m_homingOffset = nullptr;
    QDoubleSpinBox *m_torque = nullptr;
    QPushButton *m_execute = nullptr;
    QPushButton *m_stop = nullptr;
    QPushButton *m_halt = nullptr;
    QLabel *m_status = nullptr;
    QLabel *m_flags = nullptr;
    QLabel *m_hint = nullptr;
    QLabel *m_limitNote = nullptr;
};

} // namespace db::widgets
