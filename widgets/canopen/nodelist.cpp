#include "nodelist.h"

#include "canopen/cannetwork.h"
#include "canopen/nmtanswer.h"
#include "canopen/nmtmaster.h"
#include "canopen/nodescanner.h"
#include "core/changelog.h"
#include "nodelistmodel.h"
#include "transport/canbus.h"
#include "widgets/common/flowlayout.h"
#include "widgets/common/widgetstyle.h"

#include <QCheckBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
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
    , m_commandStatus(new QLabel(this))
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
    m_commandStatus->setObjectName(QStringLiteral("commandStatus"));
    // One line that never widens the dock nor takes the list's rows: the whole text is the
    // tool tip (and a failure is in the status bar too).
    m_commandStatus->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
    m_commandStatus->hide();
    layout->addWidget(m_commandStatus);

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
    m_device = connection->uri().toString();
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
    if (m_leader) { // the leader keeps the model
        updateActions();
        return;
    }
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
    // Watching starts before the command goes out: a fast node's heartbeat is not missed.
    auto *answer = node == 0 || !m_network
        ? nullptr
        : new canopen::NmtAnswer(m_network->bus(), m_network->monitor(), command,
                                 canopen::NodeId(node), this);
    if (!m_nmt->send(command, canopen::NodeId(node))) {
        delete answer;
        return false;
    }
    const QString name = canopen::NmtMaster::commandName(command);
    m_model->noteCommand(name, canopen::NodeId(node));
    int entry = 0;
    if (m_changeLog) {
        ChangeLog::Entry e;
        e.device = m_device;
        e.kind = ChangeLog::Kind::Nmt;
        e.object = node == 0 ? tr("all nodes") : tr("node %1").arg(node);
        e.newValue = name;
        if (!answer)
            e.outcome = ChangeLog::Outcome::Ok; // a broadcast: no node answers for all
        entry = m_changeLog->add(e);
    }
    Q_EMIT commandSent(name, node);
    if (!answer) {
        showCommandStatus(tr("%1 sent to all nodes").arg(name), false);
        return true;
    }
    showCommandStatus(tr("%1 sent to node %2: waiting for its heartbeat").arg(name).arg(node),
                      false);
    connect(
        answer, &canopen::NmtAnswer::finished, this,
        [this, answer, name, node, entry](const Error &error) {
            answer->deleteLater();
            if (m_changeLog && entry)
                m_changeLog->complete(
                    entry, error.isError() ? ChangeLog::Outcome::Failed : ChangeLog::Outcome::Ok,
                    answer->note());
            if (error.isError())
                showCommandStatus(tr("%1 to node %2: %3").arg(name).arg(node).arg(error.message()),
                                  true);
            else if (!answer->note().isEmpty())
                showCommandStatus(
                    tr("%1 sent to node %2; %3").arg(name).arg(node).arg(answer->note()), false);
            else
                showCommandStatus(tr("%1: node %2 followed").arg(name).arg(node), false);
            Q_EMIT commandAnswered(name, node, error, answer->note());
        });
    return true;
}

void NodeList::setChangeLog(ChangeLog *log)
{
    m_changeLog = log;
}

QString NodeList::commandStatus() const
{
    return m_commandStatus->text();
}

void NodeList::showCommandStatus(const QString &text, bool error)
{
    m_commandStatus->setText(text);
    m_commandStatus->setToolTip(text);
    m_commandStatus->setVisible(!text.isEmpty());
    style::setTextColor(m_commandStatus, error ? style::errorColor() : style::inactiveColor());
}

bool NodeList::isScanning() const
{
    if (m_leader)
        return m_leader->isScanning();
    return m_scanner && m_scanner->isRunning();
}

void NodeList::follow(NodeList *leader)
{
    if (!leader || leader == this || m_leader)
        return;
    m_leader = leader;
    NodeListModel *own = m_model;
    QList<int> widths;
    for (int c = 0; c < own->columnCount(); ++c)
        widths.append(m_view->horizontalHeader()->sectionSize(c));
    m_model = leader->m_model;
    m_view->setModel(m_model);
    m_view->setSelectionModel(leader->m_view->selectionModel());
    delete own;
    for (int c = 0; c < widths.size(); ++c)
        m_view->horizontalHeader()->resizeSection(c, widths.at(c));
    connect(m_view->selectionModel(), &QItemSelectionModel::selectionChanged, this,
            &NodeList::updateActions);
    // The model goes with the leader: an empty one of our own from then on.
    connect(leader, &QObject::destroyed, this, [this] {
        m_leader = nullptr;
        m_model = new NodeListModel(this);
        m_view->setModel(m_model);
        connect(m_view->selectionModel(), &QItemSelectionModel::selectionChanged, this,
                &NodeList::updateActions);
        updateActions();
    });
    setBroadcast(leader->broadcast());
    connect(m_broadcast, &QCheckBox::toggled, leader, &NodeList::setBroadcast);
    connect(leader->m_broadcast, &QCheckBox::toggled, this, &NodeList::setBroadcast);
    connect(leader, &NodeList::scanStarted, this, &NodeList::updateActions);
    connect(leader, &NodeList::scanFinished, this, &NodeList::updateActions);
    updateActions();
}

bool NodeList::scan()
{
    if (m_leader)
        return m_leader->scan();
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
    Q_EMIT scanStarted();
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
