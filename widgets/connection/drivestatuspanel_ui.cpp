// DriveStatusPanel's widget tree, apart from its rendering (drivestatuspanel.cpp): the fixed
// frame, and the parts that depend on the device family (lamps, actual values, I/O).
#include "drivestatuspanel.h"

#include "widgets/common/flowlayout.h"
#include "widgets/common/lamp.h"
#include "widgets/common/widgetstyle.h"

#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QVBoxLayout>

#include <functional>

namespace db::widgets {

namespace {

QLabel *valueLabel(const QString &name, QWidget *parent)
{
    auto *label = new QLabel(parent);
    label->setObjectName(name);
    label->setFont(style::monospaceFont());
    label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    label->setText(QStringLiteral("—"));
    return label;
}

QLabel *textLabel(const QString &name, QWidget *parent)
{
    auto *label = new QLabel(parent);
    label->setObjectName(name);
    label->setWordWrap(true);
    return label;
}

QColor lampColor(StatusLamp::Kind kind)
{
    switch (kind) {
    case StatusLamp::Kind::Ok:
        return style::okColor();
    case StatusLamp::Kind::Warning:
        return style::warningColor();
    case StatusLamp::Kind::Error:
        return style::errorColor();
    case StatusLamp::Kind::Info:
        break;
    }
    return QColor(0x1e, 0x6f, 0xd9);
}

QVBoxLayout *stacked(std::initializer_list<QWidget *> widgets)
{
    auto *column = new QVBoxLayout;
    column->setSpacing(2);
    for (QWidget *w : widgets)
        column->addWidget(w);
    return column;
}

} // namespace

void DriveStatusPanel::setMotionNote(const QString &note)
{
    m_motionNote->setText(note);
    m_motionNote->setVisible(!note.isEmpty());
}

QString DriveStatusPanel::motionNote() const
{
    return m_motionNote->text();
}

void DriveStatusPanel::buildUi()
{
    // State: the state as a coloured badge, status word and mode beside it, bit lamps below.
    auto *stateBox = new QGroupBox(tr("Drive state"), this);
    m_stateLabel = new QLabel(stateBox);
    m_stateLabel->setObjectName(QStringLiteral("stateName"));
    QFont big = font();
    big.setPointSizeF(big.pointSizeF() * 1.8);
    big.setBold(true);
    m_stateLabel->setFont(big);
    m_stateLabel->setAlignment(Qt::AlignCenter);
    m_stateLabel->setMinimumWidth(QFontMetrics(big).horizontalAdvance(StatusSource::stateText(
                                      StatusSource::State::FaultReactionActive))
                                  + 40);
    m_statuswordLabel = valueLabel(QStringLiteral("statusword"), stateBox);
    m_statusWordName = new QLabel(tr("Statusword:"), stateBox);
    m_modeLabel = new QLabel(stateBox);
    m_modeLabel->setObjectName(QStringLiteral("mode"));
    m_modeName = new QLabel(tr("Mode:"), stateBox);
    m_bitRow = new FlowLayout;

    auto *stateForm = new QFormLayout;
    stateForm->addRow(m_statusWordName, m_statuswordLabel);
    stateForm->addRow(m_modeName, m_modeLabel);
    auto *stateTop = new QHBoxLayout;
    stateTop->addWidget(m_stateLabel);
    stateTop->addSpacing(12);
    stateTop->addLayout(stateForm, 1);
    auto *stateLayout = new QVBoxLayout(stateBox);
    stateLayout->addLayout(stateTop);
    stateLayout->addLayout(m_bitRow);
    // The motion command model's state where it differs from the drive's (ErrorStop after a
    // quick stop), so that this page and the Motion dock tell the same story.
    m_motionNote = new QLabel(stateBox);
    m_motionNote->setObjectName(QStringLiteral("motionNote"));
    m_motionNote->setWordWrap(true);
    style::setTextColor(m_motionNote, style::errorColor());
    m_motionNote->hide();
    stateLayout->addWidget(m_motionNote);

    // Actual values: rows per family.
    m_valuesBox = new QGroupBox(tr("Actual values"), this);
    m_valuesForm = new QFormLayout(m_valuesBox);

    // Digital I/O, where the family has them: per row its name and the lamps, which wrap.
    m_ioBox = new QGroupBox(tr("Digital I/O"), this);
    new QVBoxLayout(m_ioBox);

    // Faults and warnings.
    m_faultBox = new QGroupBox(tr("Faults"), this);
    m_registerLabel = valueLabel(QStringLiteral("statusRegister"), m_faultBox);
    m_registerBitsLabel = textLabel(QStringLiteral("statusRegisterBits"), m_faultBox);
    m_warningBitsLabel = textLabel(QStringLiteral("statusRegisterWarnings"), m_faultBox);
    m_lastErrorLabel = valueLabel(QStringLiteral("lastErrorCode"), m_faultBox);
    m_lastErrorText = textLabel(QStringLiteral("lastErrorText"), m_faultBox);
    m_linkLossLabel = textLabel(QStringLiteral("linkLoss"), m_faultBox);
    m_registerName = new QLabel(m_faultBox);
    m_lastErrorName = new QLabel(m_faultBox);
    auto *faultForm = new QFormLayout(m_faultBox);
    faultForm->addRow(m_registerName, stacked({ m_registerLabel, m_registerBitsLabel }));
    faultForm->addRow(m_lastErrorName, stacked({ m_lastErrorLabel, m_lastErrorText }));
    faultForm->addRow(tr("Warnings:"), m_warningBitsLabel);
    faultForm->addRow(m_linkLossLabel);

    m_footer = new QLabel(this);
    m_footer->setObjectName(QStringLiteral("pollStatus"));
    style::setTextColor(m_footer, style::inactiveColor());

    auto *grid = new QGridLayout(this);
    grid->addWidget(stateBox, 0, 0, 1, 2);
    grid->addWidget(m_valuesBox, 1, 0);
    grid->addWidget(m_ioBox, 1, 1);
    grid->addWidget(m_faultBox, 2, 0, 1, 2);
    grid->addWidget(m_footer, 3, 0, 1, 2);
    grid->setRowStretch(4, 1);
    grid->setColumnStretch(0, 1);
    grid->setColumnStretch(1, 1);
}

// The parts that depend on the source: lamps, value rows, I/O rows and the row names.
void DriveStatusPanel::buildFamilyUi()
{
    qDeleteAll(m_bitLamps);
    m_bitLamps.clear();
    while (QLayoutItem *item = m_bitRow->takeAt(0))
        delete item;
    while (m_valuesForm->rowCount() > 0)
        m_valuesForm->removeRow(0);
    m_valueLabels.clear();
    for (const auto &row : std::as_const(m_ioLamps))
        qDeleteAll(row);
    m_ioLamps.clear();
    // The rows' layouts go with their items; the lamps and labels are deleted above or here.
    const std::function<void(QLayout *)> clear = [&clear](QLayout *layout) {
        while (QLayoutItem *item = layout->takeAt(0)) {
            if (item->layout())
                clear(item->layout());
            delete item->widget();
            delete item;
        }
    };
    auto *ioRows = static_cast<QVBoxLayout *>(m_ioBox->layout());
    clear(ioRows);
    StatusSource *source = m_source;
    if (source) {
        for (const StatusLamp &bit : source->lamps()) {
            auto *lamp = new Lamp(bit.name, lampColor(bit.kind), this);
            lamp->setProperty("mask", bit.mask);
            lamp->setObjectName(QStringLiteral("bit_%1").arg(bit.mask, 4, 16, QLatin1Char('0')));
            m_bitLamps.append(lamp);
            m_bitRow->addWidget(lamp);
        }
        for (const StatusValue &value : source->actualValues()) {
            QLabel *label = valueLabel(value.key, m_valuesBox);
            m_valueLabels.append(label);
            m_valuesForm->addRow(value.label, label);
        }
        // One row per kind (inputs, outputs): its name, then the lamps, wrapping when narrow.
        for (const StatusIoRow &io : source->ioRows()) {
            auto *row = new QHBoxLayout;
            auto *name = new QLabel(io.label, m_ioBox);
            name->setAlignment(Qt::AlignLeft | Qt::AlignTop);
            row->addWidget(name, 0, Qt::AlignTop);
            auto *lampsRow = new FlowLayout;
            QList<Lamp *> lamps;
            const bool input = io.prefix == QLatin1String("IN");
            for (int i = 0; i < io.count; ++i) {
                const QString lampName = QStringLiteral("%1%2").arg(io.prefix).arg(i + 1);
                auto *lamp = new Lamp(lampName, input ? style::okColor() : QColor(0xe0, 0x9b, 0x00),
                                      m_ioBox);
                lamp->setObjectName(lampName);
                lamps.append(lamp);
                lampsRow->addWidget(lamp);
            }
            row->addLayout(lampsRow, 1);
            ioRows->addLayout(row);
            m_ioLamps.append(lamps);
        }
        ioRows->addStretch(1);
        m_statusWordName->setText(source->statusWordLabel());
    }
    m_ioBox->setVisible(source && !source->ioRows().isEmpty());
    m_valuesBox->setVisible(!source || !m_valueLabels.isEmpty());
    const bool hasMode = source && !source->mode().key.isEmpty();
    m_modeName->setVisible(!source || hasMode);
    m_modeLabel->setVisible(!source || hasMode);
    const bool hasRegister = source && !source->faultRegister().key.isEmpty();
    m_registerName->setVisible(hasRegister);
    m_registerLabel->setVisible(hasRegister);
    m_registerName->setText(hasRegister ? source->faultRegister().label : QString());
    m_lastErrorName->setText(source ? source->fault().label : tr("Fault:"));
}

} // namespace db::widgets
