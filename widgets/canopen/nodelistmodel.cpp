#include "nodelistmodel.h"

#include "canopen/nmtmaster.h"
#include "canopen/nodemonitor.h"
#include "transport/canbus.h"
#include "widgets/common/widgetstyle.h"

#include <QCanBusFrame>

namespace db::widgets {

using canopen::NmtState;
using canopen::NodeId;

namespace {
// The NMT state by its CANopen name (Operational, Pre-Operational, ...: the terms of the
// standard, in every language); a state not heard yet in the program's language.
QString stateText(NmtState state)
{
    return state == NmtState::Unknown ? NodeListModel::tr("unknown") : canopen::nmtStateName(state);
}
} // namespace

NodeListModel::NodeListModel(QObject *parent)
    : QAbstractTableModel(parent)
{
    m_clock.start();
    m_ageTimer.setInterval(kAgeRefreshMs);
    connect(&m_ageTimer, &QTimer::timeout, this, &NodeListModel::refreshAges);
}

NodeListModel::~NodeListModel() = default;

void NodeListModel::setSources(CanBus *bus, canopen::NodeMonitor *monitor)
{
    for (const auto &c : std::as_const(m_connections))
        disconnect(c);
    m_connections.clear();
    m_bus = bus;
    m_monitor = monitor;
    beginResetModel();
    m_rows.removeIf([this](const Row &r) { return r.node != m_own; });
    for (Row &r : m_rows)
        r = Row { r.node, NmtState::Unknown, -1, false, r.name, r.toolTip, {} };
    endResetModel();
    if (!bus || !monitor) {
        m_ageTimer.stop();
        return;
    }
    // The monitor watches the bus from before this model, so its state is current when our
    // frame slot runs; its signals cover nodes going silent.
    m_connections.append(connect(bus, &CanBus::frameReceived, this, &NodeListModel::onFrame));
    m_connections.append(connect(monitor, &canopen::NodeMonitor::stateChanged, this,
                                 [this](NodeId node, NmtState state) {
                                     ensure(node).state = state;
                                     changed(node);
                                 }));
    m_connections.append(
        connect(monitor, &canopen::NodeMonitor::heartbeatLost, this, [this](NodeId node) {
            ensure(node).lost = true;
            changed(node);
        }));
    m_connections.append(
        connect(monitor, &canopen::NodeMonitor::heartbeatResumed, this, [this](NodeId node) {
            ensure(node).lost = false;
            changed(node);
        }));
    for (NodeId node : monitor->nodes()) {
        Row &r = ensure(node);
        r.state = monitor->state(node);
        r.lost = !monitor->isAlive(node);
    }
    m_ageTimer.start();
}

void NodeListModel::setOwnNode(NodeId node, const QString &name)
{
    m_own = node;
    if (node != 0)
        setNodeName(node, name);
}

void NodeListModel::setNodeName(NodeId node, const QString &name)
{
    ensure(node).name = name;
    changed(node);
}

void NodeListModel::addNode(NodeId node, const QString &name, const QString &toolTip)
{
    Row &r = ensure(node);
    if (!name.isEmpty())
        r.name = name;
    r.toolTip = toolTip;
    changed(node);
}

QString NodeListModel::nodeName(NodeId node) const
{
    const int row = rowOf(node);
    return row < 0 ? QString() : m_rows.at(row).name;
}

bool NodeListModel::setConsumerTime(NodeId node, int ms)
{
    if (!m_monitor || rowOf(node) < 0 || ms < 0)
        return false;
    m_monitor->setConsumerTime(node, ms);
    changed(node);
    return true;
}

Qt::ItemFlags NodeListModel::flags(const QModelIndex &index) const
{
    Qt::ItemFlags f = QAbstractTableModel::flags(index);
    if (index.isValid() && index.column() == Consumer && m_monitor)
        f |= Qt::ItemIsEditable;
    return f;
}

bool NodeListModel::setData(const QModelIndex &index, const QVariant &value, int role)
{
    if (role != Qt::EditRole || !index.isValid() || index.column() != Consumer)
        return false;
    bool ok = false;
    const int ms = value.toInt(&ok);
    return ok && setConsumerTime(nodeAt(index.row()), ms);
}

void NodeListModel::noteCommand(const QString &command, NodeId node)
{
    for (Row &r : m_rows) {
        if (node == 0 || r.node == node)
            r.lastCommand = command;
    }
    if (!m_rows.isEmpty())
        Q_EMIT dataChanged(index(0, State), index(rowCount() - 1, State));
}

NodeListModel::Row &NodeListModel::ensure(NodeId node)
{
    auto it = std::lower_bound(m_rows.begin(), m_rows.end(), node,
                               [](const Row &r, NodeId n) { return r.node < n; });
    if (it != m_rows.end() && it->node == node)
        return *it;
    const int row = int(it - m_rows.begin());
    beginInsertRows({}, row, row);
    Row r;
    r.node = node;
    m_rows.insert(row, r);
    endInsertRows();
    return m_rows[row];
}

void NodeListModel::changed(NodeId node)
{
    if (const int row = rowOf(node); row >= 0)
        Q_EMIT dataChanged(index(row, 0), index(row, ColumnCount - 1));
}

void NodeListModel::onFrame(const QCanBusFrame &frame)
{
    const quint32 id = frame.frameId();
    if (frame.frameType() != QCanBusFrame::DataFrame || frame.hasExtendedFrameFormat()
        || id <= canopen::cob::Heartbeat || id > canopen::cob::Heartbeat + canopen::kMaxNodeId
        || frame.payload().isEmpty())
        return;
    const auto node = NodeId(id - canopen::cob::Heartbeat);
    Row &r = ensure(node);
    r.heardMs = m_clock.elapsed();
    if (m_monitor)
        r.state = m_monitor->state(node);
    r.lost = false;
    changed(node);
}

void NodeListModel::refreshAges()
{
    // Only the ages of nodes that were heard move on; "never" stays (no repaint for nothing).
    for (int row = 0; row < m_rows.size(); ++row) {
        if (m_rows.at(row).heardMs >= 0)
            Q_EMIT dataChanged(index(row, Heartbeat), index(row, Consumer));
    }
}

int NodeListModel::rowOf(NodeId node) const
{
    for (int row = 0; row < m_rows.size(); ++row) {
        if (m_rows.at(row).node == node)
            return row;
    }
    return -1;
}

NodeId NodeListModel::nodeAt(int row) const
{
    return row >= 0 && row < m_rows.size() ? m_rows.at(row).node : 0;
}

NmtState NodeListModel::state(NodeId node) const
{
    const int row = rowOf(node);
    return row < 0 ? NmtState::Unknown : m_rows.at(row).state;
}

qint64 NodeListModel::heartbeatAgeMs(NodeId node) const
{
    const int row = rowOf(node);
    return row < 0 || m_rows.at(row).heardMs < 0 ? -1 : m_clock.elapsed() - m_rows.at(row).heardMs;
}

bool NodeListModel::isLost(NodeId node) const
{
    const int row = rowOf(node);
    return row >= 0 && m_rows.at(row).lost;
}

int NodeListModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_rows.size());
}

int NodeListModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant NodeListModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() >= m_rows.size())
        return {};
    const Row &r = m_rows.at(index.row());
    if (role == Qt::DisplayRole) {
        switch (index.column()) {
        case Node:
            return QStringLiteral("%1 (0x%2)").arg(r.node).arg(r.node, 2, 16, QLatin1Char('0'));
        case State:
            if (r.lost)
                return tr("lost (was %1)").arg(stateText(r.state));
            if (r.state == NmtState::Unknown && !r.lastCommand.isEmpty())
                return tr("unknown (sent %1)").arg(r.lastCommand);
            return stateText(r.state);
        case Heartbeat:
            return r.heardMs < 0
                ? tr("never")
                : tr("%1 s ago").arg(double(m_clock.elapsed() - r.heardMs) / 1000.0, 0, 'f', 1);
        case Consumer: {
            const int ms = m_monitor ? m_monitor->consumerTime(r.node) : 0;
            return ms > 0 ? tr("%1 ms").arg(ms) : tr("off");
        }
        case Name:
            return r.name;
        }
    } else if (role == Qt::EditRole && index.column() == Consumer) {
        return m_monitor ? m_monitor->consumerTime(r.node) : 0;
    } else if (role == Qt::ForegroundRole && index.column() == State) {
        if (r.lost)
            return style::errorColor();
        switch (r.state) {
        case NmtState::Operational:
            return style::okColor();
        case NmtState::Stopped:
        case NmtState::BootUp:
            return style::warningColor();
        case NmtState::Unknown:
            return style::inactiveColor();
        case NmtState::PreOperational:
            break;
        }
    } else if (role == Qt::FontRole && index.column() == Node) {
        QFont font = style::monospaceFont();
        font.setBold(r.node == m_own);
        return font;
    } else if (role == Qt::ToolTipRole && index.column() == Node && r.node == m_own) {
        return tr("The node of this connection");
    } else if (role == Qt::ToolTipRole && index.column() == Consumer) {
        return tr("Heartbeat consumer time: silence longer than this after a heartbeat shows the "
                  "node as lost (double-click to change; 0 = not watched)");
    } else if (role == Qt::ToolTipRole && !r.toolTip.isEmpty()) {
        return r.toolTip;
    }
    return {};
}

QVariant NodeListModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case Node:
        return tr("Node");
    case State:
        return tr("NMT state");
    case Heartbeat:
        return tr("Heartbeat");
    case Consumer:
        return tr("Consumer");
    case Name:
        return tr("Name");
    }
    return {};
}

} // namespace db::widgets
