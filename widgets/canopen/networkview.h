#pragma once

// The CANopen network page: the nodes of the current connection's bus (NodeList: scan, NMT
// state, heartbeat and consumer time, names, NMT commands), the SYNC producer switch with its
// period, and for the selected node its PDO configuration (PdoPanel); layer setting services
// (LssPanel) for the whole bus. It receives the network and never creates a transport.

#include "canopen/canopenids.h"

#include <QPointer>
#include <QWidget>

class QCheckBox;
class QLabel;
class QSpinBox;
class QTabWidget;

namespace db {
class ChangeLog;
class DeviceConnection;
} // namespace db
namespace db::canopen {
class CanNetwork;
}

namespace db::widgets {

class LssPanel;
class NodeList;
class PdoPanel;

class NetworkView : public QWidget
{
    Q_OBJECT
public:
    explicit NetworkView(QWidget *parent = nullptr);
    ~NetworkView() override;

    // The network of a connection to a CANopen node, its node listed first; nullptr or any other
    // connection detaches. Not owned.
    void setConnection(DeviceConnection *connection);
    void setNetwork(canopen::CanNetwork *network, canopen::NodeId ownNode = 0,
                    const QString &ownName = {});
    canopen::CanNetwork *network() const;

    NodeList *nodeList() const { return m_nodes; }
    PdoPanel *pdoPanel() const { return m_pdo; }
    LssPanel *lssPanel() const { return m_lss; }
    QTabWidget *tools() const { return m_tools; }
    // PDO writes, LSS settings and NMT commands go to this log.
    void setChangeLog(ChangeLog *log);

    // The SYNC producer of the network: on with the period of the spin box, or off. False
    // without a network or while its bus is closed (on only).
    bool setSync(bool on);
    void setSyncPeriodMs(int ms);
    bool isSyncOn() const;

private:
    void updateSync();

    QPointer<canopen::CanNetwork> m_network;
    QLabel *m_title;
    NodeList *m_nodes;
    QCheckBox *m_sync;
    QSpinBox *m_syncPeriod;
    QTabWidget *m_tools;
    PdoPanel *m_pdo;
    LssPanel *m_lss;
};

} // namespace db::widgets
