// DriveStatusPanel's widget tree, apart from its polling and rendering (drivestatuspanel.cpp).
#include "drivestatuspanel.h"

#include "widgets/common/lamp.h"
#include "widgets/common/widgetstyle.h"

#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QVBoxLayout>

namespace db::widgets {

namespace {

struct StatusBit
{
    quint16 mask;
    const char *name;
    QColor color;
};

QLabel *valueLabel(const QString &name, QWidget *parent)
{
    auto *label = new QLabel(parent);
    label->setObjectName(name);
    label->setFont(style::monospaceFont());
    label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    label->setText(QStringLiteral("—"));
    return label;
}

} // namespace

void DriveStatusPanel::buildUi()
{
    // State: the CiA 402 state as a coloured badge, statusword and mode beside it.
    auto *stateBox = new QGroupBox(tr("Drive state"), this);
    m_stateLabel = new QLabel(stateBox);
    m_stateLabel->setObjectName(QStringLiteral("stateName"));
    QFont big = font();
    big.setPointSizeF(big.pointSizeF() * 1.8);
    big.setBold(true);
    m_stateLabel->setFont(big);
    m_stateLabel->setAlignment(Qt::AlignCenter);
    m_stateLabel->setMinimumWidth(
        QFontMetrics(big).horizontalAdvance(stateText(cia402::State::FaultReactionActive)) + 40);
    m_statuswordLabel = valueLabel(QStringLiteral("statusword"), stateBox);
    m_modeLabel = new QLabel(stateBox);
    m_modeLabel->setObjectName(QStringLiteral("mode"));

    const StatusBit bits[] = {
        { cia402::sw::TargetReached, QT_TR_NOOP("Target reached"), style::okColor() },
        { cia402::sw::Moving, QT_TR_NOOP("Moving"), QColor(0x1e, 0x6f, 0xd9) },
        { cia402::sw::Warning, QT_TR_NOOP("Warning"), style::warningColor() },
        { cia402::sw::InternalLimitActive, QT_TR_NOOP("Internal limit"), style::warningColor() },
        { cia402::sw::Fault, QT_TR_NOOP("Fault"), style::errorColor() },
    };
    auto *bitRow = new QHBoxLayout;
    for (const StatusBit &bit : bits) {
        auto *lamp = new Lamp(tr(bit.name), bit.color, stateBox);
        lamp->setProperty("mask", bit.mask);
        lamp->setObjectName(QStringLiteral("bit_%1").arg(bit.mask, 4, 16, QLatin1Char('0')));
        m_bitLamps.append(lamp);
        bitRow->addWidget(lamp);
    }
    bitRow->addStretch();

    auto *stateForm = new QFormLayout;
    stateForm->addRow(tr("Statusword:"), m_statuswordLabel);
    stateForm->addRow(tr("Mode:"), m_modeLabel);
    auto *stateTop = new QHBoxLayout;
    stateTop->addWidget(m_stateLabel);
    stateTop->addSpacing(12);
    stateTop->addLayout(stateForm, 1);
    auto *stateLayout = new QVBoxLayout(stateBox);
    stateLayout->addLayout(stateTop);
    stateLayout->addLayout(bitRow);

    // Actual values.
    auto *valuesBox = new QGroupBox(tr("Actual values"), this);
    m_positionLabel = valueLabel(QStringLiteral("position"), valuesBox);
    m_velocityLabel = valueLabel(QStringLiteral("velocity"), valuesBox);
    m_currentLabel = valueLabel(QStringLiteral("current"), valuesBox);
    auto *valuesForm = new QFormLayout(valuesBox);
    valuesForm->addRow(tr("Position (6064h):"), m_positionLabel);
    valuesForm->addRow(tr("Velocity (606Ch):"), m_velocityLabel);
    valuesForm->addRow(tr("Current (6078h):"), m_currentLabel);

    // Faults.
    auto *faultBox = new QGroupBox(tr("Faults"), this);
    m_registerLabel = valueLabel(QStringLiteral("statusRegister"), faultBox);
    m_registerBitsLabel = new QLabel(faultBox);
    m_registerBitsLabel->setObjectName(QStringLiteral("statusRegisterBits"));
    m_registerBitsLabel->setWordWrap(true);
    m_warningBitsLabel = new QLabel(faultBox);
    m_warningBitsLabel->setObjectName(QStringLiteral("statusRegisterWarnings"));
    m_warningBitsLabel->setWordWrap(true);
    m_lastErrorLabel = valueLabel(QStringLiteral("lastErrorCode"), faultBox);
    m_lastErrorText = new QLabel(faultBox);
    m_lastErrorText->setObjectName(QStringLiteral("lastErrorText"));
    m_lastErrorText->setWordWrap(true);
    m_lastErrorText->setToolTip(tr("603Fh keeps the last error after it has been cleared."));
    const auto stacked = [](std::initializer_list<QWidget *> widgets) {
        auto *column = new QVBoxLayout;
        column->setSpacing(2);
        for (QWidget *w : widgets)
            column->addWidget(w);
        return column;
    };
    auto *faultForm = new QFormLayout(faultBox);
    faultForm->addRow(tr("Status register (1002h):"),
                      stacked({ m_registerLabel, m_registerBitsLabel, m_warningBitsLabel }));
    faultForm->addRow(tr("Last error (603Fh):"), stacked({ m_lastErrorLabel, m_lastErrorText }));

    // Digital I/O: inputs in two rows of five, outputs below.
    auto *ioBox = new QGroupBox(tr("Digital I/O"), this);
    auto *ioGrid = new QGridLayout(ioBox);
    constexpr int kPerRow = 5;
    ioGrid->addWidget(new QLabel(tr("Inputs (60FDh):"), ioBox), 0, 0);
    for (int i = 0; i < kInputCount; ++i) {
        auto *lamp = new Lamp(tr("IN%1").arg(i + 1), style::okColor(), ioBox);
        lamp->setObjectName(QStringLiteral("IN%1").arg(i + 1));
        m_inputLamps.append(lamp);
        ioGrid->addWidget(lamp, i / kPerRow, 1 + i % kPerRow);
    }
    const int outputRow = (kInputCount + kPerRow - 1) / kPerRow;
    ioGrid->addWidget(new QLabel(tr("Outputs (60FEh.1):"), ioBox), outputRow, 0);
    for (int i = 0; i < kOutputCount; ++i) {
        auto *lamp = new Lamp(tr("OUT%1").arg(i + 1), QColor(0xe0, 0x9b, 0x00), ioBox);
        lamp->setObjectName(QStringLiteral("OUT%1").arg(i + 1));
        m_outputLamps.append(lamp);
        ioGrid->addWidget(lamp, outputRow, 1 + i);
    }
    ioGrid->setColumnStretch(kPerRow + 1, 1);
    ioGrid->setRowStretch(outputRow + 1, 1);
    ioGrid->setHorizontalSpacing(12);

    m_footer = new QLabel(this);
    m_footer->setObjectName(QStringLiteral("pollStatus"));
    style::setTextColor(m_footer, style::inactiveColor());

    auto *grid = new QGridLayout(this);
    grid->addWidget(stateBox, 0, 0, 1, 2);
    grid->addWidget(valuesBox, 1, 0);
    grid->addWidget(ioBox, 1, 1);
    grid->addWidget(faultBox, 2, 0, 1, 2);
    grid->addWidget(m_footer, 3, 0, 1, 2);
    grid->setRowStretch(4, 1);
    grid->setColumnStretch(0, 1);
    grid->setColumnStretch(1, 1);
}

} // namespace db::widgets
