// JogPanel's widget tree and its rendering, apart from the motion logic (jogpanel.cpp).
#include "jogpanel.h"

#include "gearbox.h"
#include "motionblockbox.h"
#include "motionform.h"
#include "widgets/common/flowlayout.h"
#include "widgets/common/lamp.h"
#include "widgets/common/widgetstyle.h"

#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

#include <tuple>

namespace db::widgets {

using namespace motion;

namespace {
// The axis state by its PLCopen name, which engineers know from the standard and from the
// drives' manuals; a translation adds its own term ("Standstill (Stillstand)").
QString stateText(AxisState state)
{
    switch (state) {
    case AxisState::Disabled:
        return JogPanel::tr("Disabled", "PLCopen axis state");
    case AxisState::Standstill:
        return JogPanel::tr("Standstill", "PLCopen axis state");
    case AxisState::DiscreteMotion:
        return JogPanel::tr("Discrete Motion", "PLCopen axis state");
    case AxisState::ContinuousMotion:
        return JogPanel::tr("Continuous Motion", "PLCopen axis state");
    case AxisState::Stopping:
        return JogPanel::tr("Stopping", "PLCopen axis state");
    case AxisState::ErrorStop:
        return JogPanel::tr("ErrorStop", "PLCopen axis state");
    case AxisState::Homing:
        return JogPanel::tr("Homing", "PLCopen axis state");
    case AxisState::SynchronizedMotion:
        return JogPanel::tr("Synchronized Motion", "PLCopen axis state");
    }
    return axisStateName(state);
}

constexpr double kUnbounded = 1e9;
constexpr int kFieldMinimumWidth = 76;
constexpr double kInt32Max = 2147483647.0;

// Lamps in display order; render() fills them in the same order.
enum LampIndex { Powered, Fault, Moving, TargetReached, Referenced, LimitNeg, LimitPos, LampCount };

QLabel *valueLabel(const QString &name, QWidget *parent)
{
    auto *label = new QLabel(QStringLiteral("—"), parent);
    label->setObjectName(name);
    label->setFont(style::monospaceFont());
    label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    label->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    return label;
}

QDoubleSpinBox *field(const QString &name, double value, double min, QWidget *parent)
{
    auto *s = new QDoubleSpinBox(parent);
    s->setObjectName(name);
    s->setDecimals(1);
    s->setRange(min, kUnbounded);
    s->setValue(value);
    s->setKeyboardTracking(false);
    s->setMinimumWidth(kFieldMinimumWidth); // not the width of the widest value of the range
    return s;
}

QPushButton *button(const QString &text, const QString &name, QWidget *parent)
{
    auto *b = new QPushButton(text, parent);
    b->setObjectName(name);
    b->setAutoDefault(false);
    return b;
}
} // namespace

void JogPanel::buildUi()
{
    // Power: enable / disable / reset and the PLCopen state.
    auto *powerBox = new QGroupBox(tr("Drive"), this);
    m_enableButton = button(tr("Enable"), QStringLiteral("enable"), powerBox);
    m_disableButton = button(tr("Disable"), QStringLiteral("disable"), powerBox);
    m_resetButton = button(tr("Fault reset"), QStringLiteral("reset"), powerBox);
    m_state = new QLabel(tr("No drive"), powerBox);
    m_state->setObjectName(QStringLiteral("axisState"));
    m_state->setWordWrap(true); // "not responding: ..." keeps the dock narrow
    QFont bold = m_state->font();
    bold.setBold(true);
    m_state->setFont(bold);
    auto *powerRow = new FlowLayout; // Fault reset wraps below in a narrow dock
    powerRow->addWidget(m_enableButton);
    powerRow->addWidget(m_disableButton);
    powerRow->addWidget(m_resetButton);

    const struct
    {
        const char *text;
        QColor color;
    } lamps[LampCount] = {
        { QT_TR_NOOP("Powered"), style::okColor() },
        { QT_TR_NOOP("Fault"), style::errorColor() },
        { QT_TR_NOOP("Moving"), QColor(0x1e, 0x6f, 0xd9) },
        { QT_TR_NOOP("Target reached"), style::okColor() },
        { QT_TR_NOOP("Referenced"), style::okColor() },
        { QT_TR_NOOP("Limit −"), style::warningColor() },
        { QT_TR_NOOP("Limit +"), style::warningColor() },
    };
    const QStringList lampNames { QStringLiteral("powered"),      QStringLiteral("fault"),
                                  QStringLiteral("moving"),       QStringLiteral("targetReached"),
                                  QStringLiteral("referenced"),   QStringLiteral("limitNegative"),
                                  QStringLiteral("limitPositive") };
    auto *lampGrid = new QGridLayout;
    for (int i = 0; i < LampCount; ++i) {
        auto *lamp = new Lamp(tr(lamps[i].text), lamps[i].color, powerBox);
        lamp->setObjectName(lampNames.at(i));
        m_lamps.append(lamp);
        lampGrid->addWidget(lamp, i / 3, i % 3); // three columns: the dock stays narrow
    }
    m_position = valueLabel(QStringLiteral("position"), powerBox);
    m_velocity = valueLabel(QStringLiteral("velocity"), powerBox);
    QFont big = style::monospaceFont();
    big.setPointSizeF(big.pointSizeF() * 1.4);
    m_position->setFont(big);
    m_velocity->setFont(big);
    auto *values = new QFormLayout;
    values->addRow(tr("State:"), m_state);
    values->addRow(tr("Position:"), m_position);
    values->addRow(tr("Velocity:"), m_velocity);
    auto *powerLayout = new QVBoxLayout(powerBox);
    powerLayout->addLayout(powerRow);
    powerLayout->addLayout(values);
    powerLayout->addLayout(lampGrid);

    // Jog: hold-to-run buttons, step jog, their profile and the velocity override.
    auto *jogBox = new QGroupBox(tr("Jog (hold to run; keys ← → or − +)"), this);
    m_jogVelocity = field(QStringLiteral("jogVelocity"), kDefaultJogVelocity, 0, jogBox);
    m_jogAcceleration =
        field(QStringLiteral("jogAcceleration"), kDefaultJogAcceleration, 0, jogBox);
    m_stepSize = field(QStringLiteral("stepSize"), kDefaultStep, 0, jogBox);
    m_override = field(QStringLiteral("override"), 100, 0, jogBox);
    m_override->setRange(0, MotionAxis::kMaxOverridePercent);
    m_override->setSuffix(QStringLiteral(" %"));
    m_override->setDecimals(0);
    m_jogMinus = button(tr("◀ Jog −"), QStringLiteral("jogMinus"), jogBox);
    m_jogPlus = button(tr("Jog + ▶"), QStringLiteral("jogPlus"), jogBox);
    m_stepMinus = button(tr("Step −"), QStringLiteral("stepMinus"), jogBox);
    m_stepPlus = button(tr("Step +"), QStringLiteral("stepPlus"), jogBox);
    for (QPushButton *b : { m_jogMinus, m_jogPlus })
        b->setMinimumHeight(b->sizeHint().height() * 3 / 2);
    auto *jogForm = new QGridLayout;
    const auto row = [jogBox, jogForm](int r, int c, const QString &label, QWidget *field) {
        auto *l = new QLabel(label, jogBox);
        l->setBuddy(field);
        jogForm->addWidget(l, r, c * 2);
        jogForm->addWidget(field, r, c * 2 + 1);
    };
    row(0, 0, tr("Velocity:"), m_jogVelocity);
    row(0, 1, tr("Accel.:"), m_jogAcceleration);
    row(1, 0, tr("Step:"), m_stepSize);
    row(1, 1, tr("Override:"), m_override);
    jogForm->setColumnStretch(1, 1);
    jogForm->setColumnStretch(3, 1);
    auto *jogButtons = new QGridLayout;
    jogButtons->addWidget(m_jogMinus, 0, 0);
    jogButtons->addWidget(m_jogPlus, 0, 1);
    jogButtons->addWidget(m_stepMinus, 1, 0);
    jogButtons->addWidget(m_stepPlus, 1, 1);
    auto *jogLayout = new QVBoxLayout(jogBox);
    jogLayout->addLayout(jogButtons);
    jogLayout->addLayout(jogForm);
    m_supervision = new QLabel(jogBox);
    m_supervision->setObjectName(QStringLiteral("supervision"));
    m_supervision->setWordWrap(true);
    jogLayout->addWidget(m_supervision);

    auto *limitsBox = new QGroupBox(tr("Drive limits"), this);
    m_limits = new QLabel(tr("Not read yet"), limitsBox);
    m_limits->setObjectName(QStringLiteral("limits"));
    m_limits->setWordWrap(true);
    m_limits->setTextInteractionFlags(Qt::TextSelectableByMouse);
    (new QVBoxLayout(limitsBox))->addWidget(m_limits);

    auto *commandBox = new QGroupBox(tr("Motion command"), this);
    m_form = new MotionForm(commandBox);
    m_form->setObjectName(QStringLiteral("motionForm"));
    (new QVBoxLayout(commandBox))->addWidget(m_form);

    m_blocks = new MotionBlockBox(this);
    m_blocks->setObjectName(QStringLiteral("motionBlocks"));
    m_gear = new GearBox(this);
    m_gear->setObjectName(QStringLiteral("gearBox"));

    m_message = new QLabel(this);
    m_message->setObjectName(QStringLiteral("message"));
    m_message->setWordWrap(true);
    m_message->setTextInteractionFlags(Qt::TextSelectableByMouse);

    auto *layout = new QVBoxLayout(this);
    layout->addWidget(powerBox);
    layout->addWidget(jogBox);
    layout->addWidget(commandBox);
    layout->addWidget(m_blocks);
    layout->addWidget(m_gear);
    layout->addWidget(limitsBox);
    // After a quick stop (Esc, Stop) the axis is in ErrorStop: the reason and the way out, here.
    m_stopReset = button(tr("Reset"), QStringLiteral("stopReset"), this);
    m_stopReset->setToolTip(tr("MC_Reset: leave ErrorStop so that the axis takes commands again"));
    m_stopReset->hide();
    auto *messageRow = new QHBoxLayout;
    messageRow->addWidget(m_message, 1);
    messageRow->addWidget(m_stopReset, 0, Qt::AlignTop);
    layout->addLayout(messageRow);
    layout->addStretch();
}

void JogPanel::render()
{
    const bool linked = m_cia && m_connection && m_connection->isConnected();
    const bool have = linked && m_responding;
    const AxisInterface::Status s = m_cia ? m_cia->status() : AxisInterface::Status {};
    const bool valid = have && s.valid;
    const bool on[LampCount] = { s.powered,
                                 s.fault,
                                 s.moving,
                                 s.targetReached,
                                 m_motion && m_motion->isReferenced(),
                                 s.hardwareLimitNegative,
                                 s.hardwareLimitPositive };
    for (int i = 0; i < LampCount; ++i) {
        m_lamps[i]->setOn(valid && on[i]);
        m_lamps[i]->setStale(!valid);
    }
    m_position->setText(valid
                            ? QStringLiteral("%1 %2").arg(s.position, 0, 'f', 1).arg(m_positionUnit)
                            : QStringLiteral("—"));
    m_velocity->setText(valid
                            ? QStringLiteral("%1 %2").arg(s.velocity, 0, 'f', 1).arg(m_velocityUnit)
                            : QStringLiteral("—"));
    style::setStale(m_position, !valid);
    style::setStale(m_velocity, !valid);
    QString state = tr("No drive");
    if (m_motion && have)
        state = stateText(m_motion->state());
    else if (linked)
        state = m_silentWhy.isEmpty() ? tr("Not responding") : m_silentWhy;
    else if (m_connection)
        state = tr("Not connected");
    m_state->setText(state);
    const bool fault = m_motion && m_motion->state() == AxisState::ErrorStop;
    style::setTextColor(m_state, fault || (linked && !have) ? style::errorColor() : QColor());
    m_stopReset->setVisible(have && fault);
    const QString note = have && fault
        ? tr("ErrorStop: %1. The axis takes no motion command until Reset in the Motion dock.")
              .arg(m_lastStopReason.isEmpty() ? tr("stopped") : m_lastStopReason)
        : QString();
    if (note != m_motionNote) {
        m_motionNote = note;
        Q_EMIT motionNoteChanged(note);
    }
    for (QWidget *w :
         std::initializer_list<QWidget *> { m_enableButton, m_disableButton, m_resetButton,
                                            m_jogMinus, m_jogPlus, m_stepMinus, m_stepPlus })
        w->setEnabled(have);
}

void JogPanel::renderLimits()
{
    if (!m_limitsKnown) {
        m_limits->setText(m_connection ? tr("Reading the limits…") : tr("No drive"));
        return;
    }
    const QString u = m_positionUnit;
    QStringList lines;
    const bool fullRange =
        m_config.softLimitNegative <= -kInt32Max && m_config.softLimitPositive >= kInt32Max;
    lines << (m_config.softLimitsUsed && fullRange
                  ? tr("Software limits (607Dh): the full 32-bit range")
                  : m_config.softLimitsUsed ? tr("Software limits (607Dh): %1 … %2 %3")
                                                  .arg(m_config.softLimitNegative, 0, 'f', 0)
                                                  .arg(m_config.softLimitPositive, 0, 'f', 0)
                                                  .arg(u)
                                            : tr("Software limits (607Dh): none"));
    lines
        << (m_config.maxVelocity < kUnbounded
                ? tr("Max velocity: %1 %2").arg(m_config.maxVelocity, 0, 'f', 0).arg(m_velocityUnit)
                : tr("Max velocity: not given by the drive"));
    lines << (m_config.maxAcceleration < kUnbounded
                  ? tr("Max acceleration: %1 %2/s²").arg(m_config.maxAcceleration, 0, 'f', 0).arg(u)
                  : tr("Max acceleration: not given by the drive"));
    lines << tr("Position window: %1 %2").arg(m_config.positionWindow, 0, 'f', 1).arg(u);
    m_limits->setText(lines.join(QLatin1Char('\n')));
    // Inputs clamp to the limits (QDoubleSpinBox bounds): nothing faster than the drive allows,
    // and a value lowered to a limit is said, with the limit.
    QStringList lowered;
    for (auto [box, maximum, name] :
         { std::tuple { m_jogVelocity, m_config.maxVelocity, tr("Jog velocity") },
           std::tuple { m_jogAcceleration, m_config.maxAcceleration, tr("Jog acceleration") } }) {
        const double before = box->value();
        box->setMaximum(std::min(maximum, kUnbounded));
        if (box->value() < before)
            lowered << tr("%1 %2 → %3 (the drive's maximum)")
                           .arg(name)
                           .arg(before, 0, 'f', 0)
                           .arg(box->value(), 0, 'f', 0);
    }
    if (!lowered.isEmpty()) // (the form says what it lowered itself)
        setMessage(tr("Lowered to this drive's limits: %1").arg(lowered.join(QStringLiteral("; "))),
                   style::warningColor());
    for (QDoubleSpinBox *f : { m_jogVelocity, m_jogAcceleration, m_stepSize })
        f->setSuffix(QLatin1Char(' ')
                     + (f == m_jogVelocity    ? m_velocityUnit
                            : f == m_stepSize ? u
                                              : u + QStringLiteral("/s²")));
}

void JogPanel::setMessage(const QString &text, const QColor &color)
{
    m_message->setText(text);
    style::setTextColor(m_message, color);
}

} // namespace db::widgets
