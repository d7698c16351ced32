#include "motionblockbox.h"

#include "widgets/common/widgetstyle.h"

#include <QCheckBox>
#include <QGridLayout>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>

namespace db::widgets {

namespace {
constexpr int kMaxBlock = 32;
} // namespace

MotionBlockBox::MotionBlockBox(QWidget *parent)
    : QGroupBox(tr("Motion block table"), parent)
{
    m_block = new QSpinBox(this);
    m_block->setObjectName(QStringLiteral("motionBlock"));
    m_block->setRange(1, kMaxBlock);
    m_sequence = new QCheckBox(tr("Sequence"), this);
    m_sequence->setObjectName(QStringLiteral("motionBlockSequence"));
    m_sequence->setToolTip(tr("Run on through the blocks that follow this one"));
    m_resume = new QCheckBox(tr("Resume"), this);
    m_resume->setObjectName(QStringLiteral("motionBlockResume"));
    m_resume->setToolTip(tr("Continue the interrupted block instead"));
    m_run = new QPushButton(tr("Run block"), this);
    m_run->setObjectName(QStringLiteral("runMotionBlock"));
    m_run->setAutoDefault(false);
    m_result = new QLabel(this);
    m_result->setObjectName(QStringLiteral("motionBlockResult"));
    m_result->setWordWrap(true);
    auto *layout = new QGridLayout(this);
    auto *label = new QLabel(tr("Block:"), this);
    label->setBuddy(m_block);
    layout->addWidget(label, 0, 0);
    layout->addWidget(m_block, 0, 1);
    layout->addWidget(m_sequence, 0, 2);
    layout->addWidget(m_resume, 0, 3);
    layout->addWidget(m_run, 0, 4);
    layout->addWidget(m_result, 1, 0, 1, 5);
    layout->setColumnStretch(1, 1);
    connect(m_run, &QPushButton::clicked, this, &MotionBlockBox::run);
    setVisible(false);
}

void MotionBlockBox::setAxis(motion::MotionAxis *axis)
{
    m_command.reset();
    m_result->clear();
    m_result->setStyleSheet({});
    m_run->setEnabled(true);
    const bool offered =
        axis && (axis->axis()->features() & motion::AxisInterface::Feature::MotionBlocks);
    setVisible(offered);
    if (!offered)
        return;
    m_command = std::make_unique<motion::MotionCommand>(axis, motion::CommandKind::MotionBlock);
    connect(m_command.get(), &motion::MotionCommand::statusChanged, this,
            [this](motion::MotionCommand::Status s) {
                using Status = motion::MotionCommand::Status;
                const int block = m_command->latched().block;
                m_run->setEnabled(s != Status::Busy && s != Status::Active);
                m_result->setStyleSheet({});
                switch (s) {
                case Status::Busy:
                case Status::Active:
                    m_result->setText(tr("Block %1 running").arg(block));
                    return;
                case Status::Done:
                    m_result->setText(tr("Block %1 done").arg(block));
                    return;
                case Status::CommandAborted:
                case Status::Error:
                    m_result->setText(m_command->error().message());
                    m_result->setStyleSheet(
                        QStringLiteral("color: %1").arg(style::errorColor().name()));
                    return;
                case Status::Idle:
                    return;
                }
            });
}

void MotionBlockBox::run()
{
    if (!m_command)
        return;
    motion::MoveParams p;
    p.block = m_block->value();
    p.sequence = m_sequence->isChecked();
    p.resume = m_resume->isChecked();
    m_command->setParams(p);
    m_command->setExecute(false);
    m_command->setExecute(true);
}

} // namespace db::widgets
