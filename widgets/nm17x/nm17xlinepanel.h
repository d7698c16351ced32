#pragma once

// The NM17x line panel: every NM170/NM172/NM174 display on a CAN network in one table, live from
// their TxPDOs, with commands for the selected display (setpoint standard / with release /
// direct / plunge cut, jog left/right at a speed, stop) and for the whole line by broadcast
// (mm/inch, show node ids, preset all, start group, stop all), and the guided addressing of
// the line (Nm17xAddressingDialog), and the modes and settings of the selected display
// (Nm17xSettingsBox). Commands are built only from the control words the displays accept; the
// panel starts a node (NMT) before its first PDO, since the displays execute PDOs in Operational
// only. It works on the network it receives; only the bit-rate scan opens short-lived buses of
// its own, from the URI of the line's bus.

#include "canopen/canopenids.h"
#include "core/connectionuri.h"

#include <QPointer>
#include <QWidget>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSpinBox;
class QTableView;

namespace db::canopen {
class CanNetwork;
}
namespace db::nm17x {
class Nm17xLine;
class BitrateScan;
} // namespace db::nm17x

namespace db::widgets {

class Nm17xAddressingDialog;
class Nm17xLineModel;
class Nm17xSettingsBox;

class Nm17xLinePanel : public QWidget
{
    Q_OBJECT
public:
    explicit Nm17xLinePanel(QWidget *parent = nullptr);
    ~Nm17xLinePanel() override;

    // Not owned; nullptr detaches.
    void setNetwork(canopen::CanNetwork *network);
    // The URI of the line's bus, for the scan at other bit rates (empty: no scan).
    void setBusUri(const ConnectionUri &uri);

    Nm17xLineModel *model() const { return m_model; }
    QTableView *view() const { return m_view; }
    // The node of the selected row, 0 when none.
    canopen::NodeId selectedNode() const;
    void selectNode(canopen::NodeId node);
    // The last command's outcome ("node 3: setpoint sent", or the reason it was refused).
    QString message() const;
    Nm17xSettingsBox *settingsBox() const { return m_settings; }
    bool isScanning() const;

public Q_SLOTS:
    void findDisplays();
    // Looks for displays at 125 and 250 kbit/s, each on a bus of its own.
    void scanBitrates();
    void sendSetpoint();
    void jog(int direction);
    void stop();
    void setInch(bool inch);
    void showNodeIds();
    void presetAll();
    void startGroup();
    void stopAll();
    // The guided broadcast addressing (a non-modal dialog, deleted when closed).
    Nm17xAddressingDialog *openAddressing();

private:
    void report(const QString &text);
    void startNode(canopen::NodeId node);
    void updateActions();
    void updateSettingsBox();

    QPointer<canopen::CanNetwork> m_network;
    nm17x::Nm17xLine *m_line = nullptr;
    Nm17xLineModel *m_model;
    QTableView *m_view;
    QLabel *m_message;
    QDoubleSpinBox *m_setpoint;
    QComboBox *m_kind;
    QComboBox *m_speed;
    QDoubleSpinBox *m_preset;
    QSpinBox *m_group;
    QComboBox *m_unit;
    Nm17xSettingsBox *m_settings;
    QPushButton *m_scanButton = nullptr;
    ConnectionUri m_busUri;
    QPointer<nm17x::BitrateScan> m_scan;
    QList<QPushButton *> m_nodeButtons; // need a selected display
    QList<QWidget *> m_lineControls; // need a network
};

} // namespace db::widgets
