#pragma once

// The node list dock: the CANopen nodes on the network of a connection with their NMT state,
// heartbeat age, heartbeat consumer time and name, and the NMT commands (start, stop,
// pre-operational, reset, reset communication) for the selected node or, with "All nodes", as
// a broadcast (node 0). Scan probes node ids 1..127 by SDO (NodeScanner) and lists every node
// that answers with its name (1008h) and identity (1018h).
// Whether a node followed a command is judged from its heartbeat (NmtAnswer) and shown below
// the list and in the change log; a command to all nodes expects no answer.
// It receives the network and never creates a transport.

#include "canopen/canopenids.h"
#include "core/error.h"

#include <QPointer>
#include <QWidget>

class QCheckBox;
class QLabel;
class QTableView;
class QToolButton;

namespace db {
class ChangeLog;
class DeviceConnection;
} // namespace db

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
    // NMT commands go to this log (not owned), as changes of the connection's device (its URI).
    void setChangeLog(ChangeLog *log);
    // The last command's outcome as shown below the list (empty before the first one).
    QString commandStatus() const;

    // Makes this list a second view of `leader`: the same model (nodes, states, names), the same
    // selection and "All nodes", one scan at a time. The leader keeps attaching the network;
    // setConnection()/setNetwork() on this list then only enable its buttons. Call once.
    void follow(NodeList *leader);
    NodeList *leader() const { return m_leader; }

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
    void scanStarted();
    // An NMT command went out: its name ("start", ...) and the node (0: all nodes).
    void commandSent(const QString &command, int node);
    // Whether the node followed it (after commandSent; not for all nodes): the error says
    // that it did not answer or stayed in another state; `note` says why it is not confirmed.
    void commandAnswered(const QString &command, int node, const db::Error &error,
                         const QString &note);

private:
    void updateActions();
    void showCommandStatus(const QString &text, bool error);

    NodeListModel *m_model;
    QTableView *m_view;
    QCheckBox *m_broadcast;
    QToolButton *m_scanButton;
    QList<QToolButton *> m_commandButtons;
    QPointer<canopen::NmtMaster> m_nmt;
    QPointer<canopen::CanNetwork> m_network;
    QPointer<canopen::NodeScanner> m_scanner;
    canopen::NodeId m_selected = 0;
    QPointer<NodeList> m_leader;
    QLabel *m_commandStatus;
    QPointer<ChangeLog> m_changeLog;
    QString m_device; // the connection's URI, for the change log
};

} // namespace db::widgets
