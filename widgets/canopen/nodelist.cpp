#include "nodelist.h"

#include "canopen/cannetwork.h"
#include "canopen/nmtmaster.h"
#include "canopen/nodescanner.h"
#include "nodelistmodel.h"
#include "transport/canbus.h"
#include "widgets/common/flowlayout.h"
#include "widgets/common/widgetstyle.h"

#include <QCheckBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QTableView>
#include <QToolButton>

namespace db::widgets {

using canopen::NmtCommand;

NodeList::NodeList(QWidget *parent)
    : QWidget(parent)
    , m_model(new NodeListModel(this))
    , m_view(new QTableView(this))
    , m_broadcast(new QCheckBox(tr("All nodes"), this))
    , m_scanButton(new QToolButton(this))
{
    m_view->setObjectName(QStringLiteral("nodes"));
    m_view->setModel(m_model);
    m_view->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_view->setSelectionMode(QAbstractItemView::SingleSelection);
    m_view->setShowGrid(false);
    m_view->setWordWrap(false);
    m_view->verticalHeader()->hide();
    m_view->verticalHeader()->setSectionResizeMode(QHeaderView::Fixed);
    m_view->verticalHeader()->setDefaultSectionSize(fontMetrics().height() + 6);
    m_view->horizontalHeader()->setStretchLastSection(true);
    m_view->horizontalHeader()->setHighlightSections(false);
    m_view->horizontalHeader()->setDefaultAlignment(Qt::AlignLeft | Qt::AlignVCenter);
    const auto width = [this](const char *sample) {
        return fontMetrics().horizontalAdvance(QString::fromLatin1(sample)) + 12;
    };
    QFont bold = style::monospaceFont();
    bold.setBold(true);
    m_view->horizontalHeader()->resizeSection(
        NodeListModel::Node,
        QFontMetrics(bold).horizontalAdvance(QStringLiteral("127 (0x7F)")) + 12);
    m_view->horizontalHeader()->resizeSection(NodeListModel::State, width("pre-operational"));
    m_view->horizontalHeader()->setMinimumSectionSize(40);
    m_view->horizontalHeader()->resizeSection(NodeListModel::Heartbeat, width("00.0 s ago"));
    m_view->horizontalHeader()->resizeSection(NodeListModel::Consumer, width("00000 ms"));
    m_view->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed);

    m_broadcast->setObjectName(QStringLiteral("broadcast"));
    m_broadcast->setToolTip(tr("Send NMT commands to every node (node id 0)"));
    auto *buttons = new FlowLayout; // wraps in a narrow dock
    buttons->setContentsMargins(0, 0, 0, 0);
    buttons->setSpacing(2);
    m_scanButton->setObjectName(QStringLiteral("scan"));
    m_scanButton->setText(tr("Scan"));
    m_scanButton->setToolTip(
        tr("Ask node ids 1..127 by SDO and list every node that answers, with its name (1008h) "
           "and identity (1018h)"));
    connect(m_scanButton, &QToolButton::clicked, this, &NodeList::scan);
    buttons->addWidget(m_scanButton);
    const struct
    {
        NmtCommand command;
        const char *name;
        const char *text;
        const char *toolTip;
    } commands[] = {
        { NmtCommand::Start, "start", QT_TR_NOOP("Start"), QT_TR_NOOP("NMT start: operational") },
        { NmtCommand::Stop, "stop", QT_TR_NOOP("Stop"), QT_TR_NOOP("NMT stop: stopped") },
        { NmtCommand::EnterPreOperational, "preop", QT_TR_NOOP("Pre-op"),
          QT_TR_NOOP("NMT enter pre-operational") },
        { NmtCommand::ResetNode, "reset", QT_TR_NOOP("Reset"),
          QT_TR_NOOP("NMT reset node (application)") },
        { NmtCommand::ResetCommunication, "resetComm", QT_TR_NOOP("Reset comm"),
          QT_TR_NOOP("NMT reset communication") },
    };
    for (const auto &c : commands) {
        auto *button = new QToolButton(this);
        button->setObjectName(QString::fromLatin1(c.name));
        button->setText(tr(c.text));
        button->setToolTip(tr(c.toolTip));
        const NmtCommand command = c.command;
        connect(button, &QToolButton::clicked, this, [this, command] { sendCommand(command); });
        buttons->addWidget(button);
        m_commandButtons.append(button);
    }

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->setSpacing(4);
    layout->addWidget(m_view, 1);
    layout->addLayout(buttons);
    layout->addWidget(m_broadcast); // own row: the dock stays narrow on a laptop screen

    connect(m_broadcast, &QCheckBox::toggled, this, &NodeList::updateActions);
    connect(m_view->selectionModel(), &QItemSelectionModel::selectionChanged, this,
            &NodeList::updateActions);
    connect(m_model, &QAbstractItemModel::rowsInserted, this, [this] {
        if (!m_view->selectionModel()->hasSelection() && m_model->rowCount() > 0)
            m_view->selectRow(0);
    });
    updateActions();
}

NodeList::~NodeList() = default;

void NodeList::setConnection(DeviceConnection *connection)
{
    const canopen::NetworkNode at = canopen::networkNodeOf(connection);
    if (!at) {
        setNetwork(nullptr);
        return;
    }
    const DeviceIdentity &id = connection->dictionary().identity;
    setNetwork(at.network, at.node, id.productName.isEmpty() ? id.vendorName : id.productName);
}

void NodeList::setNetwork(canopen::CanNetwork *network, canopen::NodeId ownNode,
                          const QString &ownName)
{
    if (m_scanner)
        m_scanner->deleteLater(); // its SDO client belongs to the old network
    if (m_network)
        disconnect(m_network, nullptr, this, nullptr);
    m_network = network;
    if (network) { // Scan follows the bus
        connect(network, &canopen::CanNetwork::opened, this, &NodeList::updateActions);
        connect(network, &canopen::CanNetwork::closed, this, &NodeList::updateActions);
    }
    m_nmt = network ? network->nmt() : nullptr;
    m_model->setOwnNode(0);
    m_model->setSources(nullptr, nullptr); // forgets the previous bus's nodes
    m_model->setOwnNode(ownNode, ownName);
    m_model->setSources(network ? network->bus() : nullptr, network ? network->monitor() : nullptr);
    if (m_model->rowCount() > 0)
        m_view->selectRow(0);
    updateActions();
}

int NodeList::targetNode() const
{
    if (broadcast())
        return 0;
    const QModelIndexList rows = m_view->selectionModel()->selectedRows();
    return rows.isEmpty() ? -1 : int(m_model->nodeAt(rows.first().row()));
}

void NodeList::selectNode(canopen::NodeId node)
{
    if (const int row = m_model->rowOf(node); row >= 0)
        m_view->selectRow(row);
}

bool NodeList::broadcast() const
{
    return m_broadcast->isChecked();
}

void NodeList::setBroadcast(bool on)
{
    m_broadcast->setChecked(on);
}

bool NodeList::sendCommand(canopen::NmtCommand command)
{
    const int node = targetNode();
    if (!m_nmt || node < 0)
        return false;
    if (!m_nmt->send(command, canopen::NodeId(node)))
        return false;
    m_model->noteCommand(canopen::NmtMaster::commandName(command), canopen::NodeId(node));
    Q_EMIT commandSent(canopen::NmtMaster::commandName(command), node);
    return true;
}

bool NodeList::isScanning() const
{
    return m_scanner && m_scanner->isRunning();
}

bool NodeList::scan()
{
    if (!m_network || !m_network->isOpen() || isScanning())
        return false;
    auto *scanner = new canopen::NodeScanner(m_network->sdo(), m_network->monitor(), this);
    m_scanner = scanner;
    connect(scanner, &canopen::NodeScanner::nodeFound, this,
            [this](const canopen::NodeInfo &node) { m_model->addNode(node.id, {}); });
    connect(scanner, &canopen::NodeScanner::finished, this, [this, scanner] {
        const QList<canopen::NodeInfo> nodes = scanner->nodes();
        for (const canopen::NodeInfo &node : nodes) {
            const QString identity = node.hasIdentity
                ? tr("vendor %1, product %2, revision %3, serial %4")
                      .arg(QStringLiteral("%1h").arg(node.vendorId, 8, 16, QLatin1Char('0')),
                           QStringLiteral("%1h").arg(node.productCode, 8, 16, QLatin1Char('0')),
                           QStringLiteral("%1h").arg(node.revision, 8, 16, QLatin1Char('0')),
                           QStringLiteral("%1h").arg(node.serial, 8, 16, QLatin1Char('0')))
                : QString();
            m_model->addNode(node.id, node.name, identity);
        }
        scanner->deleteLater();
        updateActions();
        Q_EMIT scanFinished(int(nodes.size()));
    });
    if (!scanner->start()) {
        scanner->deleteLater();
        return false;
    }
    updateActions();
    return true;
}

void NodeList::updateActions()
{
    const bool enabled = m_nmt && targetNode() >= 0;
    for (QToolButton *button : std::as_const(m_commandButtons))
        button->setEnabled(enabled);
    m_scanButton->setEnabled(m_network && m_network->isOpen() && !isScanning());
    m_scanButton->setText(isScanning() ? tr("Scanning…") : tr("Scan"));
    const QModelIndexList rows = m_view->selectionModel()->selectedRows();
    const canopen::NodeId selected = rows.isEmpty() ? 0 : m_model->nodeAt(rows.first().row());
    if (selected != m_selected) {
        m_selected = selected;
        Q_EMIT selectedNodeChanged(selected);
    }
}

} // namespace db::widgets
