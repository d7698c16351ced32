#include "motionform.h"

#include "widgets/common/flowlayout.h"
#include "widgets/common/widgetstyle.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace db::widgets {

using namespace motion;

namespace {
constexpr double kUnbounded = 1e9;
constexpr int kFieldMinimumWidth = 76;

QDoubleSpinBox *spin(const QString &name, double value, QWidget *parent, int decimals = 1)
{
    auto *s = new QDoubleSpinBox(parent);
    s->setObjectName(name);
    s->setDecimals(decimals);
    s->setRange(-kUnbounded, kUnbounded);
    s->setValue(value);
    s->setAccelerated(true);
    s->setKeyboardTracking(false);
    // The size hint follows the widest value of the range; the dock is narrower than that.
    s->setMinimumWidth(kFieldMinimumWidth);
    return s;
}

QString statusName(MotionCommand::Status status)
{
    switch (status) {
    case MotionCommand::Status::Idle:
        return MotionForm::tr("idle");
    case MotionCommand::Status::Busy:
        return MotionForm::tr("busy");
    case MotionCommand::Status::Active:
        return MotionForm::tr("active");
    case MotionCommand::Status::Done:
        return MotionForm::tr("done");
    case MotionCommand::Status::CommandAborted:
        return MotionForm::tr("aborted");
    case MotionCommand::Status::Error:
        return MotionForm::tr("error");
    }
    return {};
}
} // namespace

MotionForm::MotionForm(QWidget *parent)
    : QWidget(parent)
{
    buildUi();
    setAxis(nullptr);
}

MotionForm::~MotionForm()
{
    qDeleteAll(m_commands);
}

void MotionForm::buildUi()
{
    m_command = new QComboBox(this);
    m_command->setObjectName(QStringLiteral("command"));
    for (CommandKind k :
         { CommandKind::MoveAbsolute, CommandKind::MoveRelative, CommandKind::MoveAdditive,
           CommandKind::MoveVelocity, CommandKind::Home, CommandKind::TorqueControl })
        m_command->addItem(commandName(k), int(k));
    m_target = spin(QStringLiteral("target"), 1000, this);
    m_velocity = spin(QStringLiteral("velocity"), 1000, this);
    m_acceleration = spin(QStringLiteral("acceleration"), 20000, this);
    m_deceleration = spin(QStringLiteral("deceleration"), 20000, this);
    m_jerk = spin(QStringLiteral("jerk"), 1e6, this, 0);
    m_direction = new QComboBox(this);
    m_direction->setObjectName(QStringLiteral("direction"));
    m_direction->addItem(tr("Optimised"), int(Direction::Optimised));
    m_direction->addItem(tr("Positive only"), int(Direction::PositiveOnly));
    m_direction->addItem(tr("Negative only"), int(Direction::NegativeOnly));
    m_direction->addItem(tr("Keep direction"), int(Direction::KeepDirection));
    m_direction->setToolTip(tr("Direction of travel: used by MC_MoveAbsolute on an endless axis"));
    m_homingMethod = new QComboBox(this);
    m_homingMethod->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_homingMethod->setMinimumContentsLength(8);
    m_homingMethod->setObjectName(QStringLiteral("homingMethod"));
    m_homingOffset = spin(QStringLiteral("homingOffset"), 0, this);
    m_torque = spin(QStringLiteral("torque"), 0, this);
    m_torque->setRange(-1000, 1000);
    m_torque->setSuffix(tr(" ‰ rated"));
    setHomingMethods({});

    // Two columns of label + field, so that the whole form fits a side dock without scrolling.
    auto *form = new QGridLayout;
    const auto row = [this, form](int r, int c, const QString &label, QWidget *field,
                                  int span = 1) {
        auto *l = new QLabel(label, this);
        l->setBuddy(field);
        form->addWidget(l, r, c * 2);
        form->addWidget(field, r, c * 2 + 1, 1, span);
    };
    row(0, 0, tr("Command:"), m_command, 3);
    row(1, 0, tr("Target:"), m_target, 3);
    row(2, 0, tr("Velocity:"), m_velocity);
    row(2, 1, tr("Jerk:"), m_jerk);
    row(3, 0, tr("Accel.:"), m_acceleration);
    row(3, 1, tr("Decel.:"), m_deceleration);
    row(4, 0, tr("Direction:"), m_direction, 3);
    row(5, 0, tr("Homing:"), m_homingMethod);
    row(5, 1, tr("Offset:"), m_homingOffset);
    row(6, 0, tr("Torque:"), m_torque);
    form->setColumnStretch(1, 1);
    form->setColumnStretch(3, 1);

    m_execute = new QPushButton(tr("Execute"), this);
    m_execute->setObjectName(QStringLiteral("execute"));
    m_execute->setDefault(false);
    m_halt = new QPushButton(tr("Halt"), this);
    m_halt->setObjectName(QStringLiteral("halt"));
    m_halt->setToolTip(tr("MC_Halt: brake with the deceleration; a new command may follow at "
                          "once"));
    m_stop = new QPushButton(tr("Stop"), this);
    m_stop->setObjectName(QStringLiteral("stop"));
    m_stop->setToolTip(tr("MC_Stop: brake with the deceleration; other commands are refused "
                          "until standstill"));
    auto *buttons = new FlowLayout; // Halt and Stop wrap below Execute in a narrow dock
    buttons->addWidget(m_execute);
    buttons->addWidget(m_halt);
    buttons->addWidget(m_stop);

    m_status = new QLabel(tr("No command yet"), this);
    m_status->setObjectName(QStringLiteral("commandStatus"));
    m_status->setWordWrap(true);
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_flags = new QLabel(this);
    m_flags->setObjectName(QStringLiteral("limitFlags"));
    m_flags->setWordWrap(true);
    style::setTextColor(m_flags, style::warningColor());
    m_flags->hide();
    m_limitNote = new QLabel(this);
    m_limitNote->setObjectName(QStringLiteral("limitNote"));
    m_limitNote->setWordWrap(true);
    style::setTextColor(m_limitNote, style::warningColor());
    m_limitNote->hide();
    m_hint = new QLabel(this);
    m_hint->setObjectName(QStringLiteral("hint"));
    m_hint->setWordWrap(true);
    style::setTextColor(m_hint, style::inactiveColor());

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addLayout(form);
    layout->addLayout(buttons);
    layout->addWidget(m_status);
    layout->addWidget(m_flags);
    layout->addWidget(m_limitNote);
    layout->addWidget(m_hint);

    connect(m_command, &QComboBox::currentIndexChanged, this, &MotionForm::updateFields);
    connect(m_execute, &QPushButton::clicked, this, &MotionForm::execute);
    connect(m_stop, &QPushButton::clicked, this, &MotionForm::stop);
    connect(m_halt, &QPushButton::clicked, this, &MotionForm::halt);
    updateFields();
}

void MotionForm::setAxis(MotionAxis *axis)
{
    if (axis == m_axis && axis)
        return;
    // Commands belong to one axis: a new axis gets fresh ones.
    qDeleteAll(m_commands);
    m_commands.clear();
    m_last = nullptr;
    m_axis = axis;
    for (QWidget *w : std::initializer_list<QWidget *> { m_execute, m_stop, m_halt })
        w->setEnabled(axis != nullptr);
    m_status->setText(axis ? tr("No command yet") : tr("No drive"));
    m_flags->clear();
}

void MotionForm::setLimits(const AxisConfig &config, const QString &positionUnit,
                           const QString &velocityUnit)
{
    const QString pos = QLatin1Char(' ') + positionUnit;
    const QString vel = QLatin1Char(' ') + velocityUnit;
    const QString acc = QStringLiteral(" %1/s²").arg(positionUnit);
    m_target->setSuffix(pos);
    m_homingOffset->setSuffix(pos);
    m_velocity->setSuffix(vel);
    m_acceleration->setSuffix(acc);
    m_deceleration->setSuffix(acc);
    m_jerk->setSuffix(QStringLiteral(" %1/s³").arg(positionUnit));
    // Inputs clamp to the drive's limits, and say so; the model still refuses what breaks a rule
    // (R1 for a relative move past the software limit, R5 zero values) and says why.
    QStringList lowered;
    const auto limit = [&](QDoubleSpinBox *box, const QString &name, double maximum,
                           const QString &unit, const QString &why) {
        const double before = box->value();
        box->setRange(0, std::min(maximum, kUnbounded));
        if (maximum < kUnbounded)
            box->setToolTip(tr("At most %1%2: %3").arg(maximum).arg(unit, why));
        if (box->value() < before)
            lowered
                << tr("%1 %2 → %3%4: %5").arg(name).arg(before).arg(box->value()).arg(unit, why);
    };
    limit(m_velocity, tr("Velocity"), config.maxVelocity, vel, tr("the drive's maximum velocity"));
    limit(m_acceleration, tr("Acceleration"), config.maxAcceleration, acc,
          tr("the drive's maximum acceleration"));
    limit(m_deceleration, tr("Deceleration"), config.maxAcceleration, acc,
          tr("the drive's maximum acceleration"));
    limit(m_jerk, tr("Jerk"), config.maxJerk, QStringLiteral(" %1/s³").arg(positionUnit),
          tr("the drive's maximum jerk"));
    m_limitNote->setText(
        lowered.isEmpty()
            ? QString()
            : tr("Lowered to this drive's limits: %1").arg(lowered.join(QStringLiteral("; "))));
    m_limitNote->setVisible(!lowered.isEmpty());
    m_target->setProperty("softLimits", config.softLimitsUsed);
    m_target->setProperty("softMin", config.softLimitNegative);
    m_target->setProperty("softMax", config.softLimitPositive);
    updateFields();
}

void MotionForm::setFeatures(AxisInterface::Features features)
{
    m_features = features;
    updateFields();
}

void MotionForm::setHomingMethods(const QMap<qlonglong, QString> &methods)
{
    m_homingMethod->clear();
    if (methods.isEmpty())
        m_homingMethod->addItem(tr("35: set current position as zero"), 35);
    for (auto it = methods.begin(); it != methods.end(); ++it)
        m_homingMethod->addItem(QStringLiteral("%1: %2").arg(it.key()).arg(it.value()),
                                int(it.key()));
    // CiA 402 method 35 (set the current position as zero) is the harmless default.
    m_homingMethod->setCurrentIndex(std::max(0, m_homingMethod->findData(35)));
}

CommandKind MotionForm::selectedCommand() const
{
    return CommandKind(m_command->currentData().toInt());
}

void MotionForm::selectCommand(CommandKind kind)
{
    const int i = m_command->findData(int(kind));
    if (i >= 0)
        m_command->setCurrentIndex(i);
}

void MotionForm::updateFields()
{
    const CommandKind k = selectedCommand();
    const bool positioning = isPositioning(k);
    m_target->setEnabled(positioning);
    m_velocity->setEnabled(positioning || k == CommandKind::MoveVelocity);
    m_acceleration->setEnabled(positioning || k == CommandKind::MoveVelocity
                               || k == CommandKind::Home);
    m_deceleration->setEnabled(positioning || k == CommandKind::MoveVelocity);
    m_jerk->setEnabled(m_features.testFlag(AxisInterface::Feature::Jerk)
                       && (positioning || k == CommandKind::MoveVelocity));
    m_direction->setEnabled(k == CommandKind::MoveAbsolute);
    m_homingMethod->setEnabled(k == CommandKind::Home);
    m_homingOffset->setEnabled(k == CommandKind::Home);
    m_torque->setEnabled(k == CommandKind::TorqueControl);
    // MC_MoveVelocity takes a signed velocity; the others a magnitude.
    const double vmax = m_velocity->maximum();
    m_velocity->setMinimum(k == CommandKind::MoveVelocity ? -vmax : 0.0);
    // The software limits bound an absolute target (R1); distances are checked by the model.
    const bool soft = m_target->property("softLimits").toBool();
    if (k == CommandKind::MoveAbsolute && soft)
        m_target->setRange(m_target->property("softMin").toDouble(),
                           m_target->property("softMax").toDouble());
    else
        m_target->setRange(-kUnbounded, kUnbounded);
    QString hint;
    if (k == CommandKind::TorqueControl && !m_features.testFlag(AxisInterface::Feature::Torque))
        hint = tr("This drive has no torque mode: the command will be refused.");
    else if (!m_features.testFlag(AxisInterface::Feature::Jerk))
        hint = tr("The drive has no jerk object; the jerk field only satisfies the command "
                  "rules.");
    m_hint->setText(hint);
}

MoveParams MotionForm::params() const
{
    MoveParams p;
    p.position = m_target->value();
    p.velocity = m_velocity->value();
    p.acceleration = m_acceleration->value();
    p.deceleration = m_deceleration->value();
    p.jerk = m_jerk->value();
    p.direction = Direction(m_direction->currentData().toInt());
    p.torque = m_torque->value();
    return p;
}

HomingParams MotionForm::homing() const
{
    HomingParams h;
    h.method = m_homingMethod->currentData().toInt();
    h.speedFast = h.speedSlow = m_velocity->value();
    h.acceleration = m_acceleration->value();
    h.offset = m_homingOffset->value();
    return h;
}

MotionCommand *MotionForm::command(CommandKind kind)
{
    if (!m_axis)
        return nullptr;
    MotionCommand *&c = m_commands[int(kind)];
    if (!c) {
        c = new MotionCommand(m_axis, kind);
        connect(c, &MotionCommand::statusChanged, this, [this, c](MotionCommand::Status s) {
            // Stop/Halt hold Execute until done (Sec. 3.12), then release it.
            if (s == MotionCommand::Status::Done
                && (c->kind() == CommandKind::Stop || c->kind() == CommandKind::Halt))
                c->setExecute(false);
            if (c == m_last)
                showStatus();
        });
    }
    return c;
}

void MotionForm::setLease(LeasedMove *lease)
{
    if (m_lease)
        disconnect(m_lease->command(), nullptr, this, nullptr);
    m_lease = lease;
    if (!lease)
        return;
    connect(lease->command(), &MotionCommand::statusChanged, this, [this] {
        if (m_lease && m_last == m_lease->command())
            showStatus();
    });
}

bool MotionForm::velocityIsLeased() const
{
    return m_lease && (m_features & AxisInterface::Feature::ProfilePosition);
}

void MotionForm::start(CommandKind kind)
{
    MotionCommand *c = command(kind);
    if (!c)
        return;
    MoveParams p = params();
    if (kind == CommandKind::Stop || kind == CommandKind::Halt)
        p.deceleration = std::max(p.deceleration, m_deceleration->minimum());
    if (refusesInput(kind, p))
        return;
    if (kind == CommandKind::MoveVelocity && velocityIsLeased()) {
        m_lease->jog(p.velocity >= 0 ? 1 : -1, p);
        m_last = m_lease->command();
        showStatus();
        Q_EMIT started(m_last);
        return;
    }
    c->setParams(p);
    c->setHoming(homing());
    m_last = c;
    c->setExecute(false);
    c->setExecute(true); // the rising edge latches the inputs
    showStatus();
    Q_EMIT started(c);
}

// A refusal caused only by what was typed (target beyond the software limits or the cycle, a
// direction the axis may not take, a zero profile value) is refused here, as input: started, the
// model would refuse it too and put the axis in ErrorStop, quick-stopping a running motion.
bool MotionForm::refusesInput(CommandKind kind, const MoveParams &p)
{
    const Refusal refusal = m_axis->preview(kind, p).refusal;
    QWidget *field = nullptr;
    switch (refusal) {
    case Refusal::TargetOutsideSoftLimits:
    case Refusal::TargetOutsideCycle:
        field = m_target;
        break;
    case Refusal::DirectionNotPermitted:
        field = m_direction;
        break;
    case Refusal::ZeroProfileValue:
        field = m_velocity;
        break;
    default:
        return false;
    }
    m_status->setText(tr("%1 not started: %2. Correct the input; the axis is unchanged.")
                          .arg(commandName(kind), refusalText(refusal)));
    style::setTextColor(m_status, style::errorColor());
    m_flags->setVisible(false);
    field->setFocus();
    return true;
}

void MotionForm::execute()
{
    start(selectedCommand());
}

void MotionForm::stop()
{
    start(CommandKind::Stop);
}

void MotionForm::halt()
{
    start(CommandKind::Halt);
}

QString MotionForm::statusText() const
{
    return m_status->text();
}

void MotionForm::showStatus()
{
    if (!m_last)
        return;
    const MotionCommand *c = m_last;
    const bool leased = m_lease && c == m_lease->command();
    QString text = QStringLiteral("%1: %2").arg(
        leased ? tr("MC_MoveVelocity in leases") : c->name(), statusName(c->status()));
    if (c->status() == MotionCommand::Status::Error
        || c->status() == MotionCommand::Status::CommandAborted)
        text += QStringLiteral(" — ") + c->error().message();
    else if (isPositioning(c->kind()) && !leased && c->status() != MotionCommand::Status::Idle)
        text += tr(" (target %1)").arg(c->target(), 0, 'f', 1);
    m_status->setText(text);
    const QColor color = c->status() == MotionCommand::Status::Error ? style::errorColor()
        : c->status() == MotionCommand::Status::Done                 ? style::okColor()
        : c->status() == MotionCommand::Status::CommandAborted       ? style::warningColor()
                                                                     : QColor();
    style::setTextColor(m_status, color);
    QStringList flags;
    if (c->limits().velocityLimited)
        flags << tr("velocity limited to the maximum");
    if (c->limits().overrideLimited)
        flags << tr("override clamped at the maximum velocity");
    if (c->limits().accelerationOrJerkLimited)
        flags << tr("acceleration or jerk limited");
    if (c->limits().notReferenced)
        flags << tr("axis not referenced: positions count from the drive's present zero");
    m_flags->setText(flags.join(QStringLiteral("; ")));
    m_flags->setVisible(!flags.isEmpty());
}

QVariantMap MotionForm::values() const
{
    return { { QStringLiteral("command"), m_command->currentData() },
             { QStringLiteral("target"), m_target->value() },
             { QStringLiteral("velocity"), m_velocity->value() },
             { QStringLiteral("acceleration"), m_acceleration->value() },
             { QStringLiteral("deceleration"), m_deceleration->value() },
             { QStringLiteral("jerk"), m_jerk->value() },
             { QStringLiteral("homingOffset"), m_homingOffset->value() },
             { QStringLiteral("torque"), m_torque->value() } };
}

void MotionForm::setValues(const QVariantMap &values)
{
    if (const int i = m_command->findData(values.value(QStringLiteral("command"))); i >= 0)
        m_command->setCurrentIndex(i);
    for (QDoubleSpinBox *box :
         { m_target, m_velocity, m_acceleration, m_deceleration, m_jerk, m_homingOffset }) {
        const QVariant v = values.value(box->objectName());
        if (!v.isValid())
            continue;
        // The previous device's limits do not apply; setLimits() gives this device's.
        box->setRange(box == m_target || box == m_homingOffset ? -kUnbounded : 0, kUnbounded);
        box->setToolTip(QString());
        box->setValue(v.toDouble());
    }
    if (const QVariant v = values.value(QStringLiteral("torque")); v.isValid())
        m_torque->setValue(v.toDouble());
    m_limitNote->clear();
    m_limitNote->hide();
    updateFields();
}

QString MotionForm::limitNote() const
{
    return m_limitNote->text();
}

} // namespace db::widgets
