#include "nm17xlinepanel.h"

#include "nm17xaddressingdialog.h"

#include "nm17xlinemodel.h"
#include "nm17xsettingsbox.h"

#include "canopen/cannetwork.h"
#include "canopen/nmtmaster.h"
#include "devices/nm17x/nm17xline.h"
#include "devices/nm17x/nm17xscan.h"
#include "widgets/common/flowlayout.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QItemSelectionModel>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QTableView>
#include <QVBoxLayout>

namespace db::widgets {

using namespace db::nm17x;

namespace {
constexpr double kMinMm = -999.99;
constexpr double kMaxMm = 9999.99;

QDoubleSpinBox *millimetreBox(QWidget *parent)
{
    auto *box = new QDoubleSpinBox(parent);
    box->setRange(kMinMm, kMaxMm);
    box->setDecimals(2);
    box->setSuffix(QStringLiteral(" mm"));
    return box;
}
} // namespace

Nm17xLinePanel::Nm17xLinePanel(QWidget *parent)
    : QWidget(parent)
    , m_model(new Nm17xLineModel(this))
    , m_view(new QTableView(this))
    , m_message(new QLabel(this))
    , m_setpoint(millimetreBox(this))
    , m_kind(new QComboBox(this))
    , m_speed(new QComboBox(this))
    , m_preset(millimetreBox(this))
    , m_group(new QSpinBox(this))
    , m_unit(new QComboBox(this))
    , m_settings(new Nm17xSettingsBox(this))
{
    m_view->setModel(m_model);
    m_view->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_view->setSelectionMode(QAbstractItemView::SingleSelection);
    // As tall as its rows (in a low dock the commands below stay in sight), more when there is
    // room.
    m_view->setSizeAdjustPolicy(QAbstractScrollArea::AdjustToContents);
    m_view->verticalHeader()->hide();
    m_view->horizontalHeader()->setStretchLastSection(true);
    m_view->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_kind->addItem(tr("standard"), int(SetpointKind::Standard));
    m_kind->addItem(tr("with release"), int(SetpointKind::Release));
    m_kind->addItem(tr("direct (no loop)"), int(SetpointKind::Direct));
    m_kind->addItem(tr("plunge cut"), int(SetpointKind::Plunge));
    m_kind->addItem(tr("plunge cut with release"), int(SetpointKind::PlungeRelease));
    // The display's speed steps, named as the device's own texts are (the command line keeps
    // the English words it parses).
    m_speed->addItem(QCoreApplication::translate("Nm17x", "slow"), int(Speed::Slow));
    m_speed->addItem(QCoreApplication::translate("Nm17x", "medium"), int(Speed::Medium));
    m_speed->addItem(QCoreApplication::translate("Nm17x", "fast"), int(Speed::Fast));
    m_group->setRange(1, 8);
    m_unit->addItem(QStringLiteral("mm"));
    m_unit->addItem(tr("inch"));

    const auto button = [this](const QString &text, const QString &name, auto slot) {
        auto *b = new QPushButton(text, this);
        b->setObjectName(name);
        connect(b, &QPushButton::clicked, this, slot);
        return b;
    };
    auto *find = button(tr("Find displays"), QStringLiteral("find"), &Nm17xLinePanel::findDisplays);
    m_scanButton = button(tr("Scan 125/250 kbit/s"), QStringLiteral("scanBitrates"),
                          &Nm17xLinePanel::scanBitrates);
    m_scanButton->setToolTip(tr("Look for displays at 125 and 250 kbit/s: they are delivered "
                                "at 125 kbit/s, but their bit-rate setting defaults to 250"));
    auto *send = button(tr("Send setpoint"), QStringLiteral("send"), &Nm17xLinePanel::sendSetpoint);
    auto *left = button(tr("Jog left"), QStringLiteral("jogLeft"), [this] { jog(-1); });
    auto *right = button(tr("Jog right"), QStringLiteral("jogRight"), [this] { jog(1); });
    auto *stopOne = button(tr("Stop"), QStringLiteral("stop"), &Nm17xLinePanel::stop);
    auto *ids =
        button(tr("Show node ids"), QStringLiteral("showIds"), &Nm17xLinePanel::showNodeIds);
    auto *preset =
        button(tr("Preset all"), QStringLiteral("presetAll"), &Nm17xLinePanel::presetAll);
    auto *start =
        button(tr("Start group"), QStringLiteral("startGroup"), &Nm17xLinePanel::startGroup);
    auto *stopLine = button(tr("Stop all"), QStringLiteral("stopAll"), &Nm17xLinePanel::stopAll);
    auto *addressLine =
        button(tr("Address line…"), QStringLiteral("addressLine"), [this] { openAddressing(); });
    addressLine->setToolTip(tr("Give the displays their node ids one after the other: the "
                               "display whose shaft is turned takes the id offered"));
    m_setpoint->setObjectName(QStringLiteral("setpoint"));
    m_kind->setObjectName(QStringLiteral("kind"));
    m_speed->setObjectName(QStringLiteral("speed"));
    m_preset->setObjectName(QStringLiteral("preset"));
    m_unit->setObjectName(QStringLiteral("unit"));
    connect(m_unit, &QComboBox::activated, this, [this](int i) { setInch(i == 1); });

    // Groups that keep together; the rows wrap in a narrow dock.
    const auto group = [this](std::initializer_list<QWidget *> widgets) {
        auto *box = new QWidget(this);
        auto *row = new QHBoxLayout(box);
        row->setContentsMargins(0, 0, 0, 0);
        for (QWidget *w : widgets)
            row->addWidget(w);
        return box;
    };
    auto *lineRow = new FlowLayout;
    for (QWidget *w : std::initializer_list<QWidget *> {
             find, m_scanButton, addressLine, group({ new QLabel(tr("Unit:"), this), m_unit }), ids,
             group({ m_preset, preset }), group({ m_group, start }), stopLine })
        lineRow->addWidget(w);
    auto *nodeRow = new FlowLayout;
    for (QWidget *w : std::initializer_list<QWidget *> {
             group({ m_setpoint, m_kind, send }),
             group({ new QLabel(tr("Speed:"), this), m_speed, left, right }), stopOne })
        nodeRow->addWidget(w);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(lineRow);
    layout->addWidget(m_view);
    layout->addLayout(nodeRow);
    auto *settingsGroup = new QGroupBox(tr("Selected display: modes and settings"), this);
    auto *settingsLayout = new QVBoxLayout(settingsGroup);
    settingsLayout->addWidget(m_settings);
    layout->addWidget(settingsGroup);
    layout->addWidget(m_message);
    connect(m_settings, &Nm17xSettingsBox::message, this, &Nm17xLinePanel::report);
    m_nodeButtons = { send, left, right, stopOne };
    m_lineControls = { find, addressLine, m_unit, ids, preset, start, stopLine };
    connect(m_view->selectionModel(), &QItemSelectionModel::selectionChanged, this,
            &Nm17xLinePanel::updateActions);
    connect(m_model, &QAbstractItemModel::modelReset, this, &Nm17xLinePanel::updateActions);
    connect(m_view->selectionModel(), &QItemSelectionModel::selectionChanged, this,
            &Nm17xLinePanel::updateSettingsBox);
    connect(m_model, &QAbstractItemModel::modelReset, this, &Nm17xLinePanel::updateSettingsBox);
    updateActions();
}

Nm17xLinePanel::~Nm17xLinePanel() = default;

Nm17xAddressingDialog *Nm17xLinePanel::openAddressing()
{
    if (!m_network)
        return nullptr;
    auto *dialog = new Nm17xAddressingDialog(m_network, this);
    dialog->setObjectName(QStringLiteral("addressingDialog"));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &Nm17xAddressingDialog::addressingFinished, this, [this](bool) {
        report(tr("Addressing finished; the displays restart with their new node ids."));
    });
    dialog->show();
    return dialog;
}

void Nm17xLinePanel::setBusUri(const ConnectionUri &uri)
{
    m_busUri = uri;
    updateActions();
}

bool Nm17xLinePanel::isScanning() const
{
    return m_scan && m_scan->isRunning();
}

void Nm17xLinePanel::scanBitrates()
{
    if (m_busUri.scheme().isEmpty() || isScanning())
        return;
    m_scan = new BitrateScan(m_busUri, BitrateScan::defaultBitrates(), this);
    report(tr("looking for displays at 125 and 250 kbit/s ..."));
    updateActions();
    connect(m_scan, &BitrateScan::finished, this, [this, scan = m_scan.data()] {
        QStringList parts;
        for (const BitrateResult &r : scan->results()) {
            QStringList nodes;
            for (const DisplayState &d : r.displays)
                nodes.append(QString::number(d.node));
            QString part = nodes.isEmpty() ? tr("%1 kbit/s: no display").arg(r.bitrate / 1000)
                                           : tr("%1 kbit/s: node %2")
                                                 .arg(r.bitrate / 1000)
                                                 .arg(nodes.join(QLatin1String(", ")));
            if (nodes.isEmpty() && !r.problem.isEmpty())
                part += QStringLiteral(" (%1)").arg(r.problem);
            parts.append(part);
        }
        report(parts.join(QLatin1String("; ")));
        scan->deleteLater();
        updateActions();
    });
    m_scan->start();
}

void Nm17xLinePanel::updateSettingsBox()
{
    const canopen::NodeId node = selectedNode();
    const int row = m_model->rowOf(node);
    const Variant variant = row >= 0 ? m_model->displays().at(row).variant : Variant::Nm172;
    m_settings->setDisplay(m_line, node, variant);
}

void Nm17xLinePanel::setNetwork(canopen::CanNetwork *network)
{
    if (network == m_network && (m_line || !network))
        return;
    m_model->setLine(nullptr);
    delete m_line;
    m_line = nullptr;
    m_network = network;
    m_model->setDisplays({});
    if (network) {
        m_line = new Nm17xLine(network, this);
        m_model->setLine(m_line);
    }
    updateActions();
}

canopen::NodeId Nm17xLinePanel::selectedNode() const
{
    const QModelIndexList rows = m_view->selectionModel()->selectedRows();
    if (rows.isEmpty() || rows.first().row() >= m_model->displays().size())
        return 0;
    return m_model->displays().at(rows.first().row()).node;
}

void Nm17xLinePanel::selectNode(canopen::NodeId node)
{
    const int row = m_model->rowOf(node);
    if (row >= 0)
        m_view->selectRow(row);
}

QString Nm17xLinePanel::message() const
{
    return m_message->text();
}

void Nm17xLinePanel::report(const QString &text)
{
    m_message->setText(text);
}

void Nm17xLinePanel::updateActions()
{
    const bool line = m_line != nullptr;
    for (QWidget *w : std::as_const(m_lineControls))
        w->setEnabled(line);
    for (QPushButton *b : std::as_const(m_nodeButtons))
        b->setEnabled(line && selectedNode() != 0);
    m_scanButton->setEnabled(!m_busUri.scheme().isEmpty() && !isScanning());
}

void Nm17xLinePanel::startNode(canopen::NodeId node)
{
    if (m_network)
        m_network->nmt()->send(canopen::NmtCommand::Start, node);
}

void Nm17xLinePanel::findDisplays()
{
    if (!m_line)
        return;
    if (!m_network->isOpen()) {
        report(tr("The CAN bus %1 is not open (yet).").arg(m_network->name()));
        return;
    }
    report(tr("looking for displays ..."));
    Reply *reply = m_line->findDisplays();
    connect(reply, &Reply::finished, this, [this, reply] {
        reply->deleteLater();
        const auto displays = reply->value().value<QList<DisplayState>>();
        m_model->setDisplays(displays);
        report(tr("%n display(s) found", nullptr, int(displays.size())));
        if (!displays.isEmpty())
            m_view->selectRow(0);
    });
}

void Nm17xLinePanel::sendSetpoint()
{
    const canopen::NodeId node = selectedNode();
    if (!m_line || node == 0)
        return;
    const auto kind = SetpointKind(m_kind->currentData().toInt());
    const bool plunge = kind == SetpointKind::Plunge || kind == SetpointKind::PlungeRelease;
    const auto speed = plunge ? std::optional(Speed(m_speed->currentData().toInt())) : std::nullopt;
    startNode(node);
    const qint32 value = qint32(qRound(m_setpoint->value() * 100));
    const auto sent = m_line->setpoint(node, value, kind, {}, speed);
    if (sent)
        m_model->setSetpoint(node, value);
    report(sent ? tr("node %1: setpoint %2 sent").arg(node).arg(formatPosition(value, false))
                : sent.error().message());
}

void Nm17xLinePanel::jog(int direction)
{
    const canopen::NodeId node = selectedNode();
    if (!m_line || node == 0)
        return;
    startNode(node);
    const auto sent = m_line->jog(node, direction, Speed(m_speed->currentData().toInt()));
    report(sent ? tr("node %1: jogging %2").arg(node).arg(direction > 0 ? tr("right") : tr("left"))
                : sent.error().message());
}

void Nm17xLinePanel::stop()
{
    const canopen::NodeId node = selectedNode();
    if (!m_line || node == 0)
        return;
    startNode(node);
    const auto sent = m_line->stop(node);
    report(sent ? tr("node %1: stop sent").arg(node) : sent.error().message());
}

void Nm17xLinePanel::setInch(bool inch)
{
    if (!m_line)
        return;
    startNode(0);
    const auto sent = m_line->setUnit(inch);
    report(sent ? tr("every display shows %1").arg(inch ? tr("inch") : tr("mm"))
                : sent.error().message());
}

void Nm17xLinePanel::showNodeIds()
{
    if (!m_line)
        return;
    startNode(0);
    const auto sent = m_line->showNodeIds(true);
    report(sent ? tr("every display shows its node id") : sent.error().message());
}

void Nm17xLinePanel::presetAll()
{
    if (!m_line)
        return;
    startNode(0);
    const qint32 value = qint32(qRound(m_preset->value() * 100));
    const auto sent = m_line->presetAll(value);
    report(sent ? tr("every display preset to %1").arg(formatPosition(value, false))
                : sent.error().message());
}

void Nm17xLinePanel::startGroup()
{
    if (!m_line)
        return;
    startNode(0);
    const auto sent = m_line->startGroup(m_group->value());
    report(sent ? tr("group %1 started").arg(m_group->value()) : sent.error().message());
}

void Nm17xLinePanel::stopAll()
{
    if (!m_line)
        return;
    startNode(0);
    const auto sent = m_line->stopAll();
    report(sent ? tr("every display stopped") : sent.error().message());
}

} // namespace db::widgets
