#pragma once

#include "core/protocolregistry.h"
#include "description/descriptionlibrary.h"
#include "settingsdialog.h"

#include <QMainWindow>
#include <QPointer>
#include <QSet>

#include <functional>
#include <memory>
#include <vector>

class QDialog;
class QLabel;
class QStackedWidget;
class QTabWidget;
class QToolBar;

namespace db {
class ChangeLog;
}

namespace db::widgets {
class CanMonitor;
class ChangeLogView;
class DeviceList;
class DriveStatusPanel;
class JogPanel;
class LogConsole;
class NetworkView;
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

    // Whether a connection's URI joins the recent connections once its device answered (not for
    // the demo's simulated drive).
    enum class Remember { Yes, No };
    // Makes a connection for `uri`, lists it, makes it current and opens it (asynchronously).
    // The error of an unusable URI is returned and logged; a URI that is already listed is
    // refused (that entry becomes current and is reconnected when it is down).
    Result<DeviceConnection *> openConnection(const QString &uri,
                                              Remember remember = Remember::Yes);
    Result<DeviceConnection *> openConnection(const ConnectionPlan &plan,
                                              Remember remember = Remember::Yes);
    DeviceConnection *currentConnection() const;
    QList<DeviceConnection *> connections() const;
    QStringList recentConnections() const { return m_recent; }
    // Asked before a connection with an enabled drive is closed (Disconnect, Remove, Quit): true
    // closes it. The default asks with a message box; tests answer themselves.
    using Confirmation = std::function<bool(const QString &question)>;
    void setConfirmation(Confirmation confirm) { m_confirm = std::move(confirm); }
    // File → Settings: the values shown and what applying them changes (new connections get the
    // time limits, the language is stored for the next start, the recent list is replaced).
    SettingsDialog::Values settingsValues() const;
    void applySettings(const SettingsDialog::Values &values);

    // Closes every connection and waits (local event loop) up to timeoutMs for all of them to
    // reach Disconnected. Called when the window closes.
    void closeAllConnections(int timeoutMs = kCloseTimeoutMs);

    widgets::DeviceList *deviceList() const { return m_deviceList; }
    widgets::DriveStatusPanel *statusPanel() const { return m_statusPanel; }
    widgets::ObjectAccessBox *objectAccessBox() const { return m_objectAccess; }
    widgets::LogConsole *logConsole() const { return m_log; }
    // What the user changed on the devices this session (writes, restores, stores, enables,
    // motion and NMT commands).
    ChangeLog *changeLog() const { return m_changeLog; }
    widgets::ChangeLogView *changeLogView() const { return m_changes; }
    // CAN monitor and node list: attached to the current connection while it is a CANopen one.
    widgets::CanMonitor *canMonitor() const { return m_canMonitor; }
    widgets::NodeList *nodeList() const { return m_nodeList; }
    // The "CANopen Network" page (scan, PDOs, LSS, SYNC), shown while a CANopen node is current.
    widgets::NetworkView *networkView() const { return m_networkView; }
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

    // mainwindow_layout.cpp. The toolbar: Connect, Disconnect, Enable, Stop (quick stop of any
    // motion, like Esc) and the scope's Start/Stop (Space on the Scope page, F5 there).
    QToolBar *mainToolBar() const { return m_toolBar; }
    // Shown instead of the pages while no device is listed: Connect, the demo, recent
    // connections.
    QWidget *welcomePage() const { return m_welcome; }
    // What "Start the demo" on the welcome page runs (the composition root starts the simulated
    // drive and opens connections to it); without one the button is hidden.
    void setDemoStarter(std::function<void()> start);
    // The description library (owned by the composition root) and where its folder is now: the
    // connection dialog offers its files, File → Description Library… shows and adds to it.
    void setDescriptionLibrary(DescriptionLibrary *library, std::function<QString()> folder)
    {
        m_library = library;
        m_libraryFolder = std::move(folder);
    }

public Q_SLOTS:
    void showConnectDialog();
    // File → Description Library…: the library's entries, Add… and drop (needs the library).
    void showDescriptionLibrary();
    // The connection dialog with `uri` filled in (e.g. from the Morse panel).
    void showConnectDialogFor(const QString &uri);
    void disconnectCurrent();
    void showAbout();
    // The About box's text: version, build commit, Qt version and the licence.
    QString aboutText() const;
    // The README, built into the program, in a window of its own (Help → User Manual, F1).
    void showManual();
    void showSettings();
    // View → Reset Layout: every dock back where it was at the first start, shown and docked.
    void resetLayout();

protected:
    void closeEvent(QCloseEvent *event) override;

private:
    void createDocks();
    void createToolBar();
    void createWelcome();
    void updateWelcome();
    // Starts or stops the scope's recording and shows the Scope page.
    void toggleScope();
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
    void rescanLibrary();
    // mainwindow_motion.cpp: the Motion dock, the application-wide Esc stop and the stops on
    // window deactivation and before a connection is closed by the user.
    void createMotionDock();
    void stopMotionBeforeClose(DeviceConnection *connection);
    // mainwindow_health.cpp: what the connection's ConnectionHealth says, in the status bar, on
    // the Drive Status page, in the Motion dock and the log; the question before closing a
    // connection whose drive is enabled.
    void createHealthBanner(QWidget *statusPage);
    void onHealthChanged(DeviceConnection *connection);
    void renderHealth();
    bool confirmClose(const QList<DeviceConnection *> &connections);
    void closeByUser(DeviceConnection *connection);
    // mainwindow_params.cpp: editor and parameter-set pages, the Parameters menu.
    void createParameterPages();
    void attachParameters(DeviceConnection *connection);
    // mainwindow_changes.cpp: the change log fed by the editor, object access, parameter sets,
    // motion dock and node list; each finished change as a line in the log.
    void createChangeLog();
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
    ChangeLog *m_changeLog = nullptr;
    widgets::ChangeLogView *m_changes = nullptr;
    QSet<int> m_logged; // change-log entries already shown as a log line
    widgets::CanMonitor *m_canMonitor = nullptr;
    widgets::NodeList *m_nodeList = nullptr;
    widgets::NetworkView *m_networkView = nullptr;
    widgets::Nm17xLinePanel *m_nm17xPanel = nullptr; // Baumer NM17x displays on the bus
    widgets::JogPanel *m_jogPanel = nullptr;
    widgets::OdEditor *m_odEditor = nullptr;
    widgets::ParamCompareView *m_compareView = nullptr;
    widgets::ParameterSetActions *m_paramActions = nullptr;
    widgets::ScopePage *m_scopePage = nullptr;
    DescriptionLibrary *m_library = nullptr;
    std::function<QString()> m_libraryFolder;
    QPointer<DeviceConnection> m_canopen; // the connection whose CANopen network is shown
    QLabel *m_connectionState = nullptr;
    QPointer<QDialog> m_manual; // made on first use
    QSet<const DeviceConnection *> m_unstored; // written, not stored permanently
    QTabWidget *m_pages = nullptr;
    QAction *m_connectAction = nullptr;
    QAction *m_disconnectAction = nullptr;
    QAction *m_enableAction = nullptr;
    QAction *m_stopAction = nullptr;
    QAction *m_scopeAction = nullptr;
    QToolBar *m_toolBar = nullptr;
    QStackedWidget *m_central = nullptr; // the welcome page or the pages
    QWidget *m_welcome = nullptr;
    QWidget *m_recentBox = nullptr; // recent connections on the welcome page
    QWidget *m_demoButton = nullptr;
    std::function<void()> m_demoStarter;
    QByteArray m_defaultLayout; // saveState() before the user's settings were restored
    QLabel *m_healthBanner = nullptr; // on the Drive Status page: lost, failed, not responding
    QSet<const DeviceConnection *> m_forget; // not to be remembered as recent (the demo)
    Confirmation m_confirm;
    int m_connectTimeoutMs = 3000; // for new connections (Settings)
    int m_requestTimeoutMs = 1000;
    QString m_language; // the setting "language": "" follows the system
};

} // namespace db::gui
