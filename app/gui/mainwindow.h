#pragma once

#include "core/protocolregistry.h"

#include <QMainWindow>
#include <QPointer>
#include <QSet>

#include <memory>
#include <vector>

class QDialog;
class QLabel;
class QTabWidget;

namespace db::widgets {
class CanMonitor;
class DeviceList;
class DriveStatusPanel;
class JogPanel;
class LogConsole;
class NodeList;
class Nm17xLinePanel;
class ObjectAccessBox;
class OdEditor;
class ParamCompareView;
class ParameterSetActions;
class ScopePage;
} // namespace db::widgets

namespace db::gui {

// The drivebench main window. It only composes: device list (left), drive status (centre),
// object access (right), log console (bottom), menus and the status bar. It owns the open
// connections, made with ProtocolRegistry::create().
//
// Settings (window geometry/state, recent connections) live in an INI file for organisation and
// application "drivebench" in QSettings::UserScope; tests redirect it with
// QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, dir).
class MainWindow : public QMainWindow
{
    Q_OBJECT
public:
    static constexpr int kCloseTimeoutMs = 1500;

    explicit MainWindow(const ProtocolRegistry &registry, QWidget *parent = nullptr);
    ~MainWindow() override;

    // Makes a connection for `uri`, lists it, makes it current and opens it (asynchronously).
    // The error of an unusable URI is returned and logged.
    Result<DeviceConnection *> openConnection(const QString &uri);
    Result<DeviceConnection *> openConnection(const ConnectionPlan &plan);
    DeviceConnection *currentConnection() const;
    QList<DeviceConnection *> connections() const;
    QStringList recentConnections() const { return m_recent; }

    // Closes every connection and waits (local event loop) up to timeoutMs for all of them to
    // reach Disconnected. Called when the window closes.
    void closeAllConnections(int timeoutMs = kCloseTimeoutMs);

    widgets::DeviceList *deviceList() const { return m_deviceList; }
    widgets::DriveStatusPanel *statusPanel() const { return m_statusPanel; }
    widgets::ObjectAccessBox *objectAccessBox() const { return m_objectAccess; }
    widgets::LogConsole *logConsole() const { return m_log; }
    // CAN monitor and node list: attached to the current connection while it is a CANopen one.
    widgets::CanMonitor *canMonitor() const { return m_canMonitor; }
    widgets::NodeList *nodeList() const { return m_nodeList; }
    widgets::Nm17xLinePanel *nm17xPanel() const { return m_nm17xPanel; }
    // The central pages (tabs): "Drive Status" first, then the larger tools.
    QTabWidget *pages() const { return m_pages; }
    // Brings the CAN monitor's tab to the front.
    void showCanMonitor();
    // The "Motion" dock (right): jog/motion panel of the current connection.
    widgets::JogPanel *jogPanel() const { return m_jogPanel; }
    // "Object Dictionary" and "Parameter Sets" pages and the "Parameters" menu.
    widgets::OdEditor *odEditor() const { return m_odEditor; }
    widgets::ParamCompareView *compareView() const { return m_compareView; }
    widgets::ParameterSetActions *parameterActions() const { return m_paramActions; }
    // The "Scope" page, recording from the current connection.
    widgets::ScopePage *scopePage() const { return m_scopePage; }
    // Connections written to since they were last stored permanently (the window title's "*").
    bool hasUnstoredWrites(const DeviceConnection *connection) const;

public Q_SLOTS:
    void showConnectDialog();
    // The connection dialog with `uri` filled in (e.g. from the Morse panel).
    void showConnectDialogFor(const QString &uri);
    void disconnectCurrent();
    void showAbout();
    // The README, built into the program, in a window of its own (Help → User Manual, F1).
    void showManual();

protected:
    void closeEvent(QCloseEvent *event) override;

private:
    void createDocks();
    void createMenus();
    void watch(DeviceConnection *connection);
    void setCurrent(DeviceConnection *connection);
    void removeConnection(DeviceConnection *connection);
    // "URI (state)[*]": the current connection and whether it has values not stored permanently.
    void updateWindowTitle();
    void createShortcuts(QMenu *view);
    // Attaches the CAN monitor, node list and NM17x panel to the connection's CANopen network
    // when it is on one, else detaches them (their frames stay).
    void attachCanopen(DeviceConnection *connection);
    // mainwindow_motion.cpp: the Motion dock, the application-wide Esc stop and the stops on
    // window deactivation and before a connection is closed by the user.
    void createMotionDock();
    void stopMotionBeforeClose(DeviceConnection *connection);
    // mainwindow_params.cpp: editor and parameter-set pages, the Parameters menu.
    void createParameterPages();
    void attachParameters(DeviceConnection *connection);
    void updateStatusBar();
    void loadSettings();
    void saveSettings() const;

    const ProtocolRegistry &m_registry;
    std::vector<std::shared_ptr<DeviceConnection>> m_connections;
    QStringList m_recent;

    widgets::DeviceList *m_deviceList = nullptr;
    widgets::DriveStatusPanel *m_statusPanel = nullptr;
    widgets::ObjectAccessBox *m_objectAccess = nullptr;
    widgets::LogConsole *m_log = nullptr;
    widgets::CanMonitor *m_canMonitor = nullptr;
    widgets::NodeList *m_nodeList = nullptr;
    widgets::Nm17xLinePanel *m_nm17xPanel = nullptr; // Baumer NM17x displays on the bus
    widgets::JogPanel *m_jogPanel = nullptr;
    widgets::OdEditor *m_odEditor = nullptr;
    widgets::ParamCompareView *m_compareView = nullptr;
    widgets::ParameterSetActions *m_paramActions = nullptr;
    widgets::ScopePage *m_scopePage = nullptr;
    QPointer<DeviceConnection> m_canopen; // the connection whose CANopen network is shown
    QLabel *m_connectionState = nullptr;
    QPointer<QDialog> m_manual; // made on first use
    QSet<const DeviceConnection *> m_unstored; // written, not stored permanently
    QTabWidget *m_pages = nullptr;
    QAction *m_disconnectAction = nullptr;
};

} // namespace db::gui
