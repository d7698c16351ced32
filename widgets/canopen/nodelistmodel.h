#pragma once

// The CANopen nodes of one bus for the node list: node id, NMT state from
// heartbeat/boot-up (NodeMonitor), age of the last heartbeat, the heartbeat consumer time the
// monitor watches it with (editable: milliseconds, 0 = not watched), name (1008h after a scan).
// The connection's own node is always listed, heard or not. No widgets here; NodeList is the
// view.

#include "canopen/canopenids.h"

#include <QAbstractTableModel>
#include <QElapsedTimer>
#include <QPointer>
#include <QTimer>

class QCanBusFrame;

namespace db {
class CanBus;
}
namespace db::canopen {
class NodeMonitor;
}

namespace db::widgets {

class NodeListModel : public QAbstractTableModel
{
    Q_OBJECT
public:
    enum Column { Node, State, Heartbeat, Consumer, Name, ColumnCount };
    // Heartbeat ages are repainted at this period (one dataChanged for the column).
    static constexpr int kAgeRefreshMs = 500;

    explicit NodeListModel(QObject *parent = nullptr);
    ~NodeListModel() override;

    // Heartbeats of this bus, states from this monitor (both not owned; the monitor must watch
    // the same bus). Nodes the monitor already knows are listed at once. nullptrs detach and
    // forget every node except the own one.
    void setSources(CanBus *bus, canopen::NodeMonitor *monitor);
    // The connection's node, listed even before it is heard (0 = none).
    void setOwnNode(canopen::NodeId node, const QString &name = {});
    void setNodeName(canopen::NodeId node, const QString &name);
    // A node found by a scan (listed even when it never sent a heartbeat); tip: its identity.
    void addNode(canopen::NodeId node, const QString &name, const QString &toolTip = {});
    QString nodeName(canopen::NodeId node) const;
    // The monitor's consumer time for a node (ms, 0 = not watched); false without a monitor.
    bool setConsumerTime(canopen::NodeId node, int ms);
    // Remembers the last NMT command sent to a node (0 = every listed node), shown while its
    // state is unknown (nodes without heartbeat).
    void noteCommand(const QString &command, canopen::NodeId node);

    int rowOf(canopen::NodeId node) const; // -1 when not listed
    canopen::NodeId nodeAt(int row) const;
    canopen::NmtState state(canopen::NodeId node) const;
    // Milliseconds since the last heartbeat or boot-up of the node, -1 if never heard.
    qint64 heartbeatAgeMs(canopen::NodeId node) const;
    bool isLost(canopen::NodeId node) const;

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    Qt::ItemFlags flags(const QModelIndex &index) const override;
    bool setData(const QModelIndex &index, const QVariant &value, int role = Qt::EditRole) override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

private:
    struct Row
    {
        canopen::NodeId node = 0;
        canopen::NmtState state = canopen::NmtState::Unknown;
        qint64 heardMs = -1; // m_clock time of the last heartbeat
        bool lost = false;
        QString name;
        QString toolTip; // identity read by a scan
        QString lastCommand;
    };
    Row &ensure(canopen::NodeId node);
    void changed(canopen::NodeId node);
    void onFrame(const QCanBusFrame &frame);
    void refreshAges();

    QList<Row> m_rows; // ascending node id
    canopen::NodeId m_own = 0;
    QPointer<CanBus> m_bus;
    QPointer<canopen::NodeMonitor> m_monitor;
    QList<QMetaObject::Connection> m_connections;
    QElapsedTimer m_clock;
    QTimer m_ageTimer;
};

} // namespace db::widgets
