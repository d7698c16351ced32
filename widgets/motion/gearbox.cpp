#include "gearbox.h"

#include "widgets/common/widgetstyle.h"

#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>

namespace db::widgets {

namespace {
// The ACTIVE Cube's gear factor: numerator -32767..32767, denominator 1..65535.
constexpr int kMaxNumerator = 32767;
constexpr int kMaxDenominator = 65535;
constexpr double kMaxRamp = 999999999.0; // u/s², within 1457/1458
} // namespace

GearBox::GearBox(QWidget *parent)
    : QGroupBox(tr("Electronic gear"), parent)
{
    m_numerator = new QSpinBox(this);
    m_numerator->setObjectName(QStringLiteral("gearNumerator"));
    m_numerator->setRange(-kMaxNumerator, kMaxNumerator);
    m_numerator->setValue(1);
    m_numerator->setToolTip(tr("Slave turns per master turn: numerator (negative: the other "
                               "way)"));
    m_denominator = new QSpinBox(this);
    m_denominator->setObjectName(QStringLiteral("gearDenominator"));
    m_denominator->setRange(1, kMaxDenominator);
    m_denominator->setValue(1);
    m_acceleration = new QDoubleSpinBox(this);
    m_acceleration->setObjectName(QStringLiteral("gearAcceleration"));
    m_deceleration = new QDoubleSpinBox(this);
    m_deceleration->setObjectName(QStringLiteral("gearDeceleration"));
    for (QDoubleSpinBox *ramp : { m_acceleration, m_deceleration }) {
        ramp->setRange(0, kMaxRamp);
        ramp->setDecimals(0);
        ramp->setSpecialValueText(tr("drive's own"));
    }
    m_couple = new QPushButton(tr("Couple"), this);
    m_couple->setObjectName(QStringLiteral("gearIn"));
    m_couple->setToolTip(tr("MC_GearIn: follow the drive's master at this ratio"));
    m_couple->setAutoDefault(false);
    m_uncouple = new QPushButton(tr("Uncouple"), this);
    m_uncouple->setObjectName(QStringLiteral("gearOut"));
    m_uncouple->setToolTip(tr("MC_GearOut: the drive brakes the axis to a stop"));
    m_uncouple->setAutoDefault(false);
    m_result = new QLabel(this);
    m_result->setObjectName(QStringLiteral("gearResult"));
    m_result->setWordWrap(true);

    // Three short rows: the Motion dock must fit a 1366 px wide screen beside the pages.
    auto *layout = new QGridLayout(this);
    auto *ratio = new QLabel(tr("Ratio:"), this);
    ratio->setBuddy(m_numerator);
    layout->addWidget(ratio, 0, 0);
    layout->addWidget(m_numerator, 0, 1);
    layout->addWidget(new QLabel(QStringLiteral(":"), this), 0, 2);
    layout->addWidget(m_denominator, 0, 3);
    auto *acc = new QLabel(tr("Acc.:"), this);
    acc->setBuddy(m_acceleration);
    layout->addWidget(acc, 1, 0);
    layout->addWidget(m_acceleration, 1, 1);
    auto *dec = new QLabel(tr("Dec.:"), this);
    dec->setBuddy(m_deceleration);
    layout->addWidget(dec, 1, 2);
    layout->addWidget(m_deceleration, 1, 3);
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(m_couple);
    buttons->addWidget(m_uncouple);
    buttons->addWidget(m_result, 1);
    layout->addLayout(buttons, 2, 0, 1, 4);
    layout->setColumnStretch(1, 1);
    layout->setColumnStretch(3, 1);
    connect(m_couple, &QPushButton::clicked, this, &GearBox::gearIn);
    connect(m_uncouple, &QPushButton::clicked, this, &GearBox::gearOut);
    setVisible(false);
}

void GearBox::setAxis(motion::MotionAxis *axis)
{
    m_in.reset();
    m_out.reset();
    m_axis = axis;
    m_result->clear();
    m_result->setStyleSheet({});
    const bool offered =
        axis && (axis->axis()->features() & motion::AxisInterface::Feature::ElectronicGear);
    setVisible(offered);
    if (!offered)
        return;
    m_in = std::make_unique<motion::MotionCommand>(axis, motion::CommandKind::GearIn);
    m_out = std::make_unique<motion::MotionCommand>(axis, motion::CommandKind::GearOut);
    follow(m_in.get());
    follow(m_out.get());
}

bool GearBox::isCoupled() const
{
    return m_in && m_in->status() == motion::MotionCommand::Status::Done && m_axis
        && m_axis->state() == motion::AxisState::SynchronizedMotion;
}

void GearBox::follow(motion::MotionCommand *command)
{
    connect(command, &motion::MotionCommand::statusChanged, this,
            [this, command](motion::MotionCommand::Status s) {
                using Status = motion::MotionCommand::Status;
                const bool in = command == m_in.get();
                m_result->setStyleSheet({});
                const auto &p = command->latched();
                switch (s) {
                case Status::Busy:
                case Status::Active:
                    m_result->setText(
                        in ? tr("Coupling at %1:%2 …").arg(p.gearNumerator).arg(p.gearDenominator)
                           : tr("Uncoupling …"));
                    return;
                case Status::Done:
                    m_result->setText(
                        in ? tr("In gear at %1:%2").arg(p.gearNumerator).arg(p.gearDenominator)
                           : tr("Uncoupled, at standstill"));
                    return;
                case Status::CommandAborted:
                    if (in && m_out && m_out->isBusy())
                        return; // uncoupling on purpose
                    [[fallthrough]];
                case Status::Error:
                    m_result->setText(command->error().message());
                    m_result->setStyleSheet(
                        QStringLiteral("color: %1").arg(style::errorColor().name()));
                    return;
                case Status::Idle:
                    return;
                }
            });
}

void GearBox::gearIn()
{
    if (!m_in)
        return;
    motion::MoveParams p;
    p.gearNumerator = m_numerator->value();
    p.gearDenominator = m_denominator->value();
    p.acceleration = m_acceleration->value();
    p.deceleration = m_deceleration->value();
    m_in->setParams(p);
    m_in->setExecute(false);
    m_in->setExecute(true);
}

void GearBox::gearOut()
{
    if (!m_out)
        return;
    motion::MoveParams p;
    p.deceleration = m_deceleration->value();
    m_out->setParams(p);
    m_out->setExecute(false);
    m_out->setExecute(true);
}

} // namespace db::widgets
