#pragma once

#include "core/protocolregistry.h"

#include <QMainWindow>
#include <QPointer>

#include <memory>
#include <vector>

class QLabel;
class QTabWidget;

namespace db::canopen {
class CanopenConnection;
}

namespace db::widgets {
class CanMonitor;
class DeviceList;
class DriveStatusPanel;
class LogConsole;
class NodeList;
class ObjectAccessBox;
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
    // The central pages (tabs): "Drive Status" first, then the larger tools.
    QTabWidget *pages() const { return m_pages; }
    // Brings the CAN monitor's tab to the front.
    void showCanMonitor();

public Q_SLOTS:
    void showConnectDialog();
    // The connection dialog with `uri` filled in (e.g. from the Morse panel).
    void showConnectDialogFor(const QString &uri);
    void disconnectCurrent();
    void showAbout();

protected:
    void closeEvent(QCloseEvent *event) override;

private:
    void createDocks();
    void createMenus();
    void watch(DeviceConnection *connection);
    void setCurrent(DeviceConnection *connection);
    void removeConnection(DeviceConnection *connection);
    // Attaches the CAN monitor and node list to connection when it is a CanopenConnection,
    // else detaches them (their frames stay).
    void attachCanopen(DeviceConnection *connection);
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
    QPointer<canopen::CanopenConnection> m_canopen;
    QLabel *m_connectionState = nullptr;
    QTabWidget *m_pages = nullptr;
    QAction *m_disconnectAction = nullptr;
};

} // namespace db::gui
