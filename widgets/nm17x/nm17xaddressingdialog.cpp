#include "nm17xaddressingdialog.h"

#include "devices/nm17x/nm17xaddressing.h"

#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QListWidget>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

namespace db::widgets {

using nm17x::BroadcastAddressing;

namespace {
constexpr int kTickMs = 250; // countdown refresh
constexpr int kDefaultStepSeconds = BroadcastAddressing::kStepTimeoutMs / 1000;
} // namespace

Nm17xAddressingDialog::Nm17xAddressingDialog(canopen::CanNetwork *network, QWidget *parent)
    : QDialog(parent)
    , m_network(network)
    , m_addressing(new BroadcastAddressing(network, this))
    , m_first(new QSpinBox(this))
    , m_count(new QSpinBox(this))
    , m_stepSeconds(new QSpinBox(this))
    , m_instruction(new QLabel(this))
    , m_countdown(new QLabel(this))
    , m_progress(new QProgressBar(this))
    , m_steps(new QListWidget(this))
    , m_start(new QPushButton(tr("Start"), this))
    , m_cancel(new QPushButton(tr("Cancel"), this))
{
    setWindowTitle(tr("Address the displays along the line"));
    m_first->setObjectName(QStringLiteral("firstNode"));
    m_count->setObjectName(QStringLiteral("count"));
    m_stepSeconds->setObjectName(QStringLiteral("stepSeconds"));
    m_instruction->setObjectName(QStringLiteral("instruction"));
    m_steps->setObjectName(QStringLiteral("steps"));
    m_start->setObjectName(QStringLiteral("start"));
    m_cancel->setObjectName(QStringLiteral("cancel"));
    m_progress->setObjectName(QStringLiteral("progress"));
    m_progress->setFormat(tr("%v of %m"));

    m_first->setRange(canopen::kMinNodeId, canopen::kMaxNodeId);
    m_first->setValue(2);
    m_count->setRange(0, canopen::kMaxNodeId);
    m_count->setSpecialValueText(tr("until none answers"));
    m_stepSeconds->setRange(5, 600);
    m_stepSeconds->setValue(kDefaultStepSeconds);
    m_stepSeconds->setSuffix(tr(" s"));
    QFont big = m_instruction->font();
    big.setPointSizeF(big.pointSizeF() * 1.3);
    big.setBold(true);
    m_instruction->setFont(big);
    m_instruction->setWordWrap(true);
    m_instruction->setText(
        tr("Every display on the bus will show the node id offered. The display whose shaft "
           "is turned (or whose key is pressed) takes it; then the next id is offered."));

    auto *form = new QFormLayout;
    form->addRow(tr("First node id:"), m_first);
    form->addRow(tr("Number of displays:"), m_count);
    form->addRow(tr("Time per display:"), m_stepSeconds);
    auto *buttons = new QDialogButtonBox(this);
    buttons->addButton(m_start, QDialogButtonBox::ActionRole);
    buttons->addButton(m_cancel, QDialogButtonBox::RejectRole);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_instruction);
    layout->addWidget(m_countdown);
    layout->addWidget(m_progress);
    layout->addWidget(m_steps, 1);
    layout->addWidget(buttons);

    connect(m_start, &QPushButton::clicked, this, &Nm17xAddressingDialog::start);
    connect(m_cancel, &QPushButton::clicked, this, &Nm17xAddressingDialog::reject);
    connect(m_addressing, &BroadcastAddressing::offering, this, &Nm17xAddressingDialog::onOffering);
    connect(m_addressing, &BroadcastAddressing::assigned, this, &Nm17xAddressingDialog::onAssigned);
    connect(m_addressing, &BroadcastAddressing::finished, this, &Nm17xAddressingDialog::onFinished);
    m_tick.setInterval(kTickMs);
    connect(&m_tick, &QTimer::timeout, this, &Nm17xAddressingDialog::updateCountdown);
    setRunning(false);
    resize(460, 420);
}

Nm17xAddressingDialog::~Nm17xAddressingDialog()
{
    if (m_addressing->state() == BroadcastAddressing::State::Offering)
        m_addressing->cancel(); // the displays leave addressing mode and are reset
}

void Nm17xAddressingDialog::setFirstNode(canopen::NodeId node)
{
    m_first->setValue(node);
}

void Nm17xAddressingDialog::setCount(int count)
{
    m_count->setValue(count);
}

void Nm17xAddressingDialog::setStepSeconds(int seconds)
{
    m_stepSeconds->setMinimum(1);
    m_stepSeconds->setValue(seconds);
}

// From Start until the summary is shown (finished() of the addressing comes from the event loop).
bool Nm17xAddressingDialog::isRunning() const
{
    return m_running;
}

QString Nm17xAddressingDialog::instruction() const
{
    return m_instruction->text();
}

QStringList Nm17xAddressingDialog::steps() const
{
    QStringList lines;
    for (int i = 0; i < m_steps->count(); ++i)
        lines.append(m_steps->item(i)->text());
    return lines;
}

QList<canopen::NodeId> Nm17xAddressingDialog::assignedIds() const
{
    return m_addressing->assignedIds();
}

void Nm17xAddressingDialog::start()
{
    if (isRunning())
        return;
    m_steps->clear();
    m_addressing->setStepTimeoutMs(m_stepSeconds->value() * 1000);
    const int count = m_count->value();
    m_progress->setRange(0, count > 0 ? count : 0); // 0..0: busy indicator
    m_progress->setValue(0);
    if (auto started = m_addressing->start(canopen::NodeId(m_first->value()), count); !started) {
        addStep(started.error().message(), true);
        m_instruction->setText(tr("Addressing could not start."));
        return;
    }
    setRunning(true);
}

void Nm17xAddressingDialog::cancel()
{
    if (m_addressing->state() != BroadcastAddressing::State::Offering)
        return;
    addStep(tr("cancelled while node %1 was offered").arg(m_offered), true);
    m_addressing->cancel();
}

void Nm17xAddressingDialog::reject()
{
    if (isRunning()) {
        cancel(); // the dialog stays open for the summary
        return;
    }
    QDialog::reject();
}

void Nm17xAddressingDialog::onOffering(canopen::NodeId node)
{
    m_offered = node;
    m_stepClock.start();
    m_instruction->setText(
        tr("Turn the shaft (or press a key) of the display that should become node %1.").arg(node));
    updateCountdown();
}

void Nm17xAddressingDialog::onAssigned(canopen::NodeId node)
{
    addStep(tr("node %1: taken by a display").arg(node));
    if (m_progress->maximum() > 0)
        m_progress->setValue(int(m_addressing->assignedIds().size()));
}

void Nm17xAddressingDialog::onFinished(bool ok)
{
    setRunning(false);
    const Error error = m_addressing->error();
    if (!ok && error.isError())
        addStep(tr("node %1: %2").arg(m_offered).arg(error.message()), true);
    const QList<canopen::NodeId> ids = m_addressing->assignedIds();
    QStringList names;
    for (const canopen::NodeId id : ids)
        names.append(QString::number(id));
    m_instruction->setText(
        ids.isEmpty() ? tr("No display took a node id.")
                      : tr("%n display(s) addressed: node %1. All nodes were reset so that the "
                           "new ids are in effect; find the displays again.",
                           nullptr, int(ids.size()))
                            .arg(names.join(QStringLiteral(", "))));
    if (m_progress->maximum() == 0)
        m_progress->setRange(0, 1);
    m_progress->setValue(m_progress->maximum() > 1 ? int(ids.size()) : (ok ? 1 : 0));
    Q_EMIT addressingFinished(ok);
}

void Nm17xAddressingDialog::updateCountdown()
{
    if (m_addressing->state() != BroadcastAddressing::State::Offering || !m_stepClock.isValid()) {
        m_countdown->clear();
        return;
    }
    const qint64 left = qMax<qint64>(0, m_stepSeconds->value() * 1000 - m_stepClock.elapsed());
    m_countdown->setText(tr("%1 s left for node %2").arg((left + 999) / 1000).arg(m_offered));
}

void Nm17xAddressingDialog::addStep(const QString &text, bool error)
{
    auto *item = new QListWidgetItem(text, m_steps);
    if (error)
        item->setForeground(QColor(0xc6, 0x28, 0x28));
    m_steps->scrollToItem(item);
}

void Nm17xAddressingDialog::setRunning(bool running)
{
    m_running = running;
    m_first->setEnabled(!running);
    m_count->setEnabled(!running);
    m_stepSeconds->setEnabled(!running);
    m_start->setEnabled(!running && m_network);
    m_cancel->setText(running ? tr("Cancel") : tr("Close"));
    if (running)
        m_tick.start();
    else
        m_tick.stop();
    updateCountdown();
}

} // namespace db::widgets
