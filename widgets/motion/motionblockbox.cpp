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

void MotionBlockBox::setAxis(motion::AxisInterface *axis)
{
    delete m_reply; // a block of the previous axis: its end no longer matters here
    m_axis = axis;
    m_result->clear();
    m_run->setEnabled(true);
    setVisible(axis && (axis->features() & motion::AxisInterface::Feature::MotionBlocks));
}

void MotionBlockBox::run()
{
    if (!m_axis || m_reply)
        return;
    const int block = m_block->value();
    m_reply = m_axis->startMotionBlock(block, m_sequence->isChecked(), m_resume->isChecked());
    m_run->setEnabled(false);
    m_result->setText(tr("Block %1 running").arg(block));
    m_result->setStyleSheet({});
    Reply *r = m_reply;
    connect(r, &Reply::finished, this, [this, r, block] {
        r->deleteLater();
        m_reply = nullptr;
        m_run->setEnabled(true);
        if (r->ok()) {
            m_result->setText(tr("Block %1 done").arg(block));
            return;
        }
        m_result->setText(r->error().message());
        m_result->setStyleSheet(QStringLiteral("color: %1").arg(style::errorColor().name()));
    });
}

} // namespace db::widgets
