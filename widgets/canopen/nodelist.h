#pragma once

// The node list dock: the CANopen nodes on the network of a connection with their NMT state,
// heartbeat age, heartbeat consumer time and name, and the NMT commands (start, stop,
// pre-operational, reset, reset communication) for the selected node or, with "All nodes", as
// a broadcast (node 0). Scan probes node ids 1..127 by SDO (NodeScanner) and lists every node
// that answers with its name (1008h) and identity (1018h).
// It receives the network and never creates a transport.

#include "canopen/canopenids.h"

#include <QPointer>
#include <QWidget>

class QCheckBox;
class QTableView;
class QToolButton;

namespace db {
class DeviceConnection;
}

namespace db::canopen {
class CanNetwork;
class NmtMaster;
class NodeScanner;
} // namespace db::canopen

namespace db::widgets {

class NodeListModel;

class NodeList : public QWidget
{
    Q_OBJECT
public:
    explicit NodeList(QWidget *parent = nullptr);
    ~NodeList() override;

    // Nodes on the connection's CANopen network, its own node first in mind (named after its
    // description). nullptr, or a connection on no CANopen network, detaches. Not owned.
    void setConnection(DeviceConnection *connection);
    // The nodes of a network, ownNode (if any) listed before it is heard. Not owned; nullptr
    // detaches.
    void setNetwork(canopen::CanNetwork *network, canopen::NodeId ownNode = 0,
                    const QString &ownName = {});

    NodeListModel *model() const { return m_model; }
    QTableView *view() const { return m_view; }
    // The node the commands go to: the selected one, 0 with "All nodes", -1 when none.
    int targetNode() const;
    void selectNode(canopen::NodeId node);
    bool broadcast() const;
    void setBroadcast(bool on);

    bool isScanning() const;

public Q_SLOTS:
    // Sends to targetNode(); false when there is none or the bus is not open.
    bool sendCommand(db::canopen::NmtCommand command);
    // Starts a scan of the network; false without one, while its bus is closed or while a scan
    // runs. scanFinished() follows.
    bool scan();

Q_SIGNALS:
    // The selected node changed (0 = none selected).
    void selectedNodeChanged(db::canopen::NodeId node);
    void scanFinished(int nodesFound);
    // An NMT command went out: its name ("start", ...) and the node (0: all nodes).
    void commandSent(const QString &command, int node);

private:
    void updateActions();

    NodeListModel *m_model;
    QTableView *m_view;
    QCheckBox *m_broadcast;
    QToolButton *m_scanButton;
    QList<QToolButton *> m_commandButtons;
    QPointer<canopen::NmtMaster> m_nmt;
    QPointer<canopen::CanNetwork> m_network;
    QPointer<canopen::NodeScanner> m_scanner;
    canopen::NodeId m_selected = 0;
};

} // namespace db::widgets
