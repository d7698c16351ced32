#include "mainwindow.h"

#include "cameralivesource.h"
#include "canopen/cannetwork.h"
#include "core/changelog.h"
#include "core/connectionhealth.h"
#include "morse/input/morseinput.h"
#include "widgets/canopen/canmonitor.h"
#include "widgets/canopen/framesender.h"
#include "widgets/canopen/networkview.h"
#include "widgets/canopen/nodelist.h"
#include "widgets/common/changelogview.h"
#include "widgets/common/logconsole.h"
#include "widgets/common/logpanel.h"
#include "widgets/common/tooltipwrapper.h"
#include "widgets/common/wheelguard.h"
#include "widgets/common/widgetstyle.h"
#include "widgets/connection/connectiondialog.h"
#include "widgets/connection/devicelist.h"
#include "widgets/connection/drivestatuspanel.h"
#include "widgets/morse/morsepanel.h"
#include "widgets/motion/jogpanel.h"
#include "widgets/nm17x/nm17xlinepanel.h"
#include "widgets/odeditor/descriptionlibrarydialog.h"
#include "widgets/odeditor/objectaccessbox.h"
#include "widgets/scope/scopepage.h"

#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QEventLoop>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QScreen>
#include <QScrollArea>
#include <QSettings>
#include <QStackedWidget>
#include <QStatusBar>
#include <QTabBar>
#include <QTabWidget>
#include <QTimer>
#include <QVBoxLayout>

namespace db::gui {

namespace {
QSettings openSettings()
{
    return QSettings(QSettings::IniFormat, QSettings::UserScope, QStringLiteral("drivebench"),
                     QStringLiteral("drivebench"));
}

Result<widgets::MorseSource> loadMorseSource(const QString &path)
{
    auto rec = morseio::readRecording(path);
    if (!rec)
        return rec.error();
    widgets::MorseSource s { std::move(rec->samples), rec->region, rec->frame,
                             rec->frameSize.width(), rec->source };
    if (rec->frameRate > 0.0)
        s.description += QStringLiteral(", %1 fps").arg(rec->frameRate, 0, 'f', 1);
    return s;
}

const QString kGeometryKey = QStringLiteral("mainWindow/geometry");
const QString kStateKey = QStringLiteral("mainWindow/state");
const QString kRecentKey = QStringLiteral("connections/recent");
const QString kConnectTimeoutKey = QStringLiteral("connections/connectTimeoutMs");
const QString kAutoReconnectKey = QStringLiteral("connections/autoReconnect");
const QString kReconnectWindowKey = QStringLiteral("connections/reconnectWindowS");
const QString kRequestTimeoutKey = QStringLiteral("connections/requestTimeoutMs");
const QString kLanguageKey = QStringLiteral("language"); // read by main() before the window
constexpr int kStatusMessageMs = 10000;
} // namespace

MainWindow::MainWindow(const ProtocolRegistry &registry, QWidget *parent)
    : QMainWindow(parent)
    , m_registry(registry)
    , m_deviceList(new widgets::DeviceList(this))
    , m_statusPanel(new widgets::DriveStatusPanel(this))
    , m_objectAccess(new widgets::ObjectAccessBox(this))
    , m_log(new widgets::LogConsole(this))
    , m_canMonitor(new widgets::CanMonitor(this))
    , m_nodeList(new widgets::NodeList(this))
    , m_nm17xPanel(new widgets::Nm17xLinePanel(this))
    , m_connectionState(new QLabel(this))
{
    setWindowTitle(tr("drivebench"));
    setObjectName(QStringLiteral("MainWindow"));
    m_connectionState->setObjectName(QStringLiteral("connectionState"));
    widgets::WheelGuard::install(); // the wheel never changes an unfocused spin or combo box
    widgets::ToolTipWrapper::install(); // long tooltips wrap

    // The centre is a set of pages (drive status, object dictionary, scope, ...); docks around it.
    m_pages = new QTabWidget(this);
    m_pages->setObjectName(QStringLiteral("pages"));
    m_pages->setDocumentMode(true);
    // Objects dragged from the Object Dictionary page to the Scope tab: hovering a tab opens it.
    m_pages->tabBar()->setChangeCurrentOnDrag(true);
    m_pages->tabBar()->setAcceptDrops(true);
    auto *statusPage = new QScrollArea(m_pages);
    auto *statusBox = new QWidget(statusPage);
    auto *statusLayout = new QVBoxLayout(statusBox);
    statusLayout->setContentsMargins(0, 0, 0, 0);
    createHealthBanner(statusBox);
    statusLayout->addWidget(m_statusPanel, 1);
    statusPage->setWidget(statusBox);
    statusPage->setWidgetResizable(true);
    statusPage->setFrameShape(QFrame::NoFrame);
    m_pages->addTab(statusPage, tr("Drive Status"));
    m_central = new QStackedWidget(this);
    m_central->addWidget(m_pages);
    setCentralWidget(m_central);
    createDocks();
    createMenus();
    createParameterPages();
    // Scope: records objects of the current connection.
    m_scopePage = new widgets::ScopePage(m_pages);
    m_pages->addTab(m_scopePage, tr("Scope"));
    // The bus of the current CANopen connection; the tab shows while there is one.
    m_networkView = new widgets::NetworkView(m_pages);
    m_pages->setTabVisible(m_pages->addTab(m_networkView, tr("CANopen Network")), false);
    // One list of nodes: the dock shows the page's nodes and selection.
    m_nodeList->follow(m_networkView->nodeList());
    createChangeLog(); // after every widget that changes devices
    createToolBar();
    createWelcome();
    statusBar()->addPermanentWidget(m_connectionState);

    connect(m_deviceList, &widgets::DeviceList::currentConnectionChanged, this,
            &MainWindow::setCurrent);
    connect(m_deviceList, &widgets::DeviceList::addRequested, this, &MainWindow::showConnectDialog);
    connect(m_deviceList, &widgets::DeviceList::connectRequested, this,
            [](DeviceConnection *c) { c->open(); });
    connect(m_deviceList, &widgets::DeviceList::disconnectRequested, this,
            &MainWindow::closeByUser);
    connect(m_deviceList, &widgets::DeviceList::removeRequested, this,
            &MainWindow::removeConnection);

    // First start: 1600x1000 or the screen's free area, whichever is smaller (a laptop's
    // 1366x768 too); restoreGeometry() replaces this once the user has placed the window.
    QSize size(1600, 1000);
    if (const QScreen *screen = QGuiApplication::primaryScreen())
        size = size.boundedTo(screen->availableGeometry().size());
    resize(size);
    m_defaultLayout = saveState();
    loadSettings();
    updateStatusBar();
    updateWelcome();
}

MainWindow::~MainWindow()
{
    // Connections go first, while every widget that watches them is still whole.
    disconnect(m_deviceList, nullptr, this, nullptr);
    m_statusPanel->setConnection(nullptr);
    m_objectAccess->setConnection(nullptr);
    m_jogPanel->setConnection(nullptr);
    m_scopePage->setConnection(nullptr);
    attachParameters(nullptr);
    attachCanopen(nullptr);
    m_connections.clear();
}

void MainWindow::createDocks()
{
    const auto addDock = [this](QWidget *widget, const QString &title, const QString &name,
                                Qt::DockWidgetArea area) {
        auto *dock = new QDockWidget(title, this);
        dock->setObjectName(name); // for saveState()/restoreState()
        dock->setWidget(widget);
        addDockWidget(area, dock);
        return dock;
    };
    QDockWidget *devices =
        addDock(m_deviceList, tr("Devices"), QStringLiteral("devicesDock"), Qt::LeftDockWidgetArea);
    QDockWidget *access = addDock(m_objectAccess, tr("Object Access"),
                                  QStringLiteral("objectAccessDock"), Qt::LeftDockWidgetArea);
    QDockWidget *nodes = addDock(m_nodeList, tr("CANopen Nodes"), QStringLiteral("nodeListDock"),
                                 Qt::LeftDockWidgetArea);
    splitDockWidget(devices, nodes, Qt::Vertical); // between the devices and object access
    QDockWidget *log = addDock(new widgets::LogPanel(m_log, this), tr("Log"),
                               QStringLiteral("logDock"), Qt::BottomDockWidgetArea);
    m_changeLog = new ChangeLog(this);
    m_changes = new widgets::ChangeLogView(m_changeLog, this);
    QDockWidget *changes =
        addDock(m_changes, tr("Changes"), QStringLiteral("changesDock"), Qt::BottomDockWidgetArea);
    tabifyDockWidget(log, changes);
    QDockWidget *canMonitor = addDock(m_canMonitor, tr("CAN Monitor"),
                                      QStringLiteral("canMonitorDock"), Qt::BottomDockWidgetArea);
    tabifyDockWidget(log, canMonitor);
    createMotionDock();
    // Morse IP decoder: files read by app/morse, "Connect" prefills the dialog.
    auto *morse = new widgets::MorsePanel(this);
    morse->setLoader(loadMorseSource);
    connect(morse, &widgets::MorsePanel::connectRequested, this, &MainWindow::showConnectDialogFor);
    // In a scroll area: the bottom docks stay low on a laptop screen.
    auto *morseScroll = new QScrollArea(this);
    morseScroll->setWidget(morse);
    morseScroll->setWidgetResizable(true);
    morseScroll->setFrameShape(QFrame::NoFrame);
    QDockWidget *morseDock =
        addDock(morseScroll, tr("Morse IP"), QStringLiteral("morseDock"), Qt::BottomDockWidgetArea);
    tabifyDockWidget(log, morseDock);
    auto *nm17xScroll = new QScrollArea(this); // its two rows of buttons stay usable when narrow
    nm17xScroll->setWidget(m_nm17xPanel);
    nm17xScroll->setWidgetResizable(true);
    nm17xScroll->setFrameShape(QFrame::NoFrame);
    QDockWidget *nm17x = addDock(nm17xScroll, tr("NM17x Line"), QStringLiteral("nm17xDock"),
                                 Qt::BottomDockWidgetArea);
    tabifyDockWidget(log, nm17x);
    // Live camera input (Qt Multimedia): listing cameras loads the media backend, so it is
    // attached when the tab is first shown, not at start-up.
    connect(morseDock, &QDockWidget::visibilityChanged, morse, [morse](bool visible) {
        if (visible && !morse->liveSource())
            morse->setLiveSource(new CameraLiveSource(morse));
    });
    log->raise();
    setCorner(Qt::BottomLeftCorner, Qt::LeftDockWidgetArea);
    m_objectAccess->setMinimumWidth(280);
    m_log->setMinimumHeight(100);
    // Initial proportions; restoreState() replaces them once the user has arranged the docks.
    resizeDocks({ devices, nodes, access }, { 160, 150, 300 }, Qt::Vertical);
    resizeDocks({ log }, { 360 }, Qt::Vertical);
}

void MainWindow::createMenus()
{
    QMenu *file = menuBar()->addMenu(tr("&File"));
    m_connectAction = file->addAction(tr("&Connect…"), this, &MainWindow::showConnectDialog);
    m_connectAction->setObjectName(QStringLiteral("connectAction"));
    m_connectAction->setShortcut(QKeySequence::Open);
    m_disconnectAction = file->addAction(tr("&Disconnect"), this, &MainWindow::disconnectCurrent);
    file->addSeparator();
    file->addAction(tr("Description &Library…"), this, &MainWindow::showDescriptionLibrary);
    file->addAction(tr("&Settings…"), this, &MainWindow::showSettings)
        ->setMenuRole(QAction::PreferencesRole);
    file->addSeparator();
    QAction *quit = file->addAction(tr("&Quit"), this, &QWidget::close);
    quit->setShortcut(QKeySequence::Quit);
    quit->setMenuRole(QAction::QuitRole);

    QMenu *view = menuBar()->addMenu(tr("&View"));
    createShortcuts(view);
    view->addSeparator();
    for (QDockWidget *dock : findChildren<QDockWidget *>())
        view->addAction(dock->toggleViewAction());
    view->addSeparator();
    view->addAction(tr("Reset &Layout"), this, &MainWindow::resetLayout)
        ->setObjectName(QStringLiteral("resetLayoutAction"));

    QMenu *help = menuBar()->addMenu(tr("&Help"));
    QAction *manual = help->addAction(tr("&User Manual"), this, &MainWindow::showManual);
    manual->setObjectName(QStringLiteral("manualAction"));
    manual->setShortcut(QKeySequence::HelpContents);
    help->addAction(tr("&About drivebench"), this, &MainWindow::showAbout)
        ->setMenuRole(QAction::AboutRole);
    help->addAction(tr("About &Qt"), qApp, &QApplication::aboutQt);
}

Result<DeviceConnection *> MainWindow::openConnection(const QString &uri, Remember remember)
{
    auto plan = m_registry.prepare(uri, m_connectTimeoutMs, m_requestTimeoutMs);
    if (!plan) {
        m_log->error(tr("Cannot connect to %1: %2").arg(uri, plan.error().toString()));
        return plan.error();
    }
    return openConnection(plan.value(), remember);
}

Result<DeviceConnection *> MainWindow::openConnection(const ConnectionPlan &plan, Remember remember)
{
    const QString uri = plan.uri.toString();
    // Two connections to one device would fight over it (two pollers, two masters of its
    // motion): the listed one is used instead.
    for (const auto &c : m_connections) {
        if (c->uri().toString() != uri)
            continue;
        m_deviceList->setCurrentConnection(c.get());
        if (c->state() == DeviceConnection::State::Disconnected)
            c->open();
        const Error refused(Error::Kind::Busy,
                            tr("%1 is already in the device list; it was not connected a second "
                               "time")
                                .arg(uri));
        m_log->warning(refused.message());
        statusBar()->showMessage(refused.message(), kStatusMessageMs);
        return refused;
    }
    ConnectionPlan timed = plan; // the time limits of the Settings
    timed.connectTimeoutMs = m_connectTimeoutMs;
    timed.requestTimeoutMs = m_requestTimeoutMs;
    auto created = m_registry.create(timed);
    if (!created) {
        m_log->error(tr("Cannot connect to %1: %2").arg(uri, created.error().toString()));
        return created.error();
    }
    std::shared_ptr<DeviceConnection> connection = created.value();
    m_connections.push_back(connection);
    if (remember == Remember::No)
        m_forget.insert(connection.get());
    watch(connection.get());
    m_deviceList->addConnection(connection.get());
    m_deviceList->setCurrentConnection(connection.get());
    m_log->info(tr("Connecting to %1").arg(connection->uri().toString()));
    updateWelcome();
    connection->open();
    return connection.get();
}

void MainWindow::watch(DeviceConnection *connection)
{
    auto *health = new ConnectionHealth(connection);
    connect(health, &ConnectionHealth::statusChanged, this,
            [this, connection] { onHealthChanged(connection); });
    followReconnectSetting(connection);
    connect(connection, &DeviceConnection::objectWritten, this, [this, connection] {
        m_unstored.insert(connection);
        updateWindowTitle();
    });
    const QString name = connection->uri().toString();
    connect(connection, &DeviceConnection::logLine, m_log, [this, name](const QString &line) {
        m_log->traffic(name + QStringLiteral(": ") + line);
    });
    connect(connection, &DeviceConnection::errorOccurred, m_log, [this, name](const Error &e) {
        m_log->error(name + QStringLiteral(": ") + e.toString());
    });
    connect(connection, &DeviceConnection::stateChanged, this,
            [this, name, connection](DeviceConnection::State state) {
                m_log->info(tr("%1 is %2").arg(name, stateName(state)));
                if (state == DeviceConnection::State::Disconnected && connection == m_canopen)
                    attachCanopen(nullptr);
                else if (state != DeviceConnection::State::Disconnected
                         && connection == currentConnection())
                    attachCanopen(connection);
                updateStatusBar();
            });
}

DeviceConnection *MainWindow::currentConnection() const
{
    return m_deviceList->currentConnection();
}

QList<DeviceConnection *> MainWindow::connections() const
{
    QList<DeviceConnection *> result;
    for (const auto &c : m_connections)
        result.append(c.get());
    return result;
}

void MainWindow::setCurrent(DeviceConnection *connection)
{
    m_statusPanel->setConnection(connection);
    m_objectAccess->setConnection(connection);
    m_jogPanel->setConnection(connection);
    m_scopePage->setConnection(connection);
    attachParameters(connection);
    attachCanopen(connection);
    updateStatusBar();
    renderHealth();
}

void MainWindow::attachCanopen(DeviceConnection *connection)
{
    const canopen::NetworkNode at = canopen::networkNodeOf(connection);
    DeviceConnection *canopen = at ? connection : nullptr;
    if (canopen == m_canopen)
        return;
    m_canopen = canopen;
    m_canMonitor->setConnection(canopen);
    m_canMonitor->frameSender()->setChangeLog(m_changeLog,
                                              canopen ? canopen->uri().toString() : QString());
    m_nodeList->setConnection(canopen);
    m_networkView->setConnection(canopen);
    m_pages->setTabVisible(m_pages->indexOf(m_networkView), canopen != nullptr);
    m_nm17xPanel->setNetwork(at.network);
    m_nm17xPanel->setBusUri(canopen ? canopen->uri() : ConnectionUri());
}

void MainWindow::showCanMonitor()
{
    if (auto *dock = findChild<QDockWidget *>(QStringLiteral("canMonitorDock"))) {
        dock->show();
        dock->raise();
    }
}

void MainWindow::removeConnection(DeviceConnection *connection)
{
    const auto it = std::find_if(m_connections.begin(), m_connections.end(),
                                 [connection](const auto &c) { return c.get() == connection; });
    if (it == m_connections.end())
        return;
    std::shared_ptr<DeviceConnection> keep = *it;
    if (!confirmClose({ connection }))
        return;
    stopMotionBeforeClose(connection);
    m_connections.erase(it);
    if (connection == m_canopen)
        attachCanopen(nullptr);
    m_deviceList->removeConnection(connection);
    m_unstored.remove(connection);
    m_forget.remove(connection);
    m_log->info(tr("Removed %1").arg(connection->uri().toString()));
    connection->close();
    // Deleted from the event loop, not inside the click that asked for it.
    QTimer::singleShot(0, this, [keep] {});
    updateStatusBar();
    updateWelcome();
}

void MainWindow::showConnectDialog()
{
    showConnectDialogFor({});
}

void MainWindow::showConnectDialogFor(const QString &uri)
{
    widgets::ConnectionDialog dialog(m_registry, m_recent, this);
    if (m_library) {
        rescanLibrary();
        dialog.setDescriptionEntries(m_library->entries());
    }
    if (!uri.isEmpty())
        dialog.setUri(uri);
    if (dialog.exec() != QDialog::Accepted)
        return;
    // The URI joins the recent connections once its device answered (onHealthChanged()).
    openConnection(dialog.plan());
}

void MainWindow::rescanLibrary()
{
    if (!m_library)
        return;
    if (m_libraryFolder)
        m_library->setFolder(m_libraryFolder()); // the setting may have changed
    m_library->rescan(); // files added since
}

void MainWindow::showDescriptionLibrary()
{
    if (!m_library)
        return;
    rescanLibrary();
    widgets::DescriptionLibraryDialog dialog(*m_library, this);
    connect(&dialog, &widgets::DescriptionLibraryDialog::fileAdded, this,
            [this](const QString &path) {
                m_log->info(tr("%1 added to the description library").arg(path));
            });
    dialog.exec();
}

void MainWindow::disconnectCurrent()
{
    if (DeviceConnection *c = currentConnection())
        closeByUser(c);
}

void MainWindow::updateStatusBar()
{
    DeviceConnection *c = currentConnection();
    const auto state = c ? c->state() : DeviceConnection::State::Disconnected;
    const ConnectionHealth *health = ConnectionHealth::of(c);
    m_connectionState->setText(
        c ? tr("%1 — %2").arg(c->uri().toString(),
                              health ? health->description() : stateName(state))
          : tr("No device"));
    widgets::style::setTextColor(m_connectionState,
                                 health  ? widgets::style::healthColor(health->status())
                                     : c ? widgets::style::connectionStateColor(state)
                                         : QColor());
    m_disconnectAction->setEnabled(c && state != DeviceConnection::State::Disconnected);
    updateWindowTitle();
}

bool MainWindow::hasUnstoredWrites(const DeviceConnection *connection) const
{
    return m_unstored.contains(connection);
}

void MainWindow::updateWindowTitle()
{
    // The platform appends the application's display name ("— drivebench").
    DeviceConnection *c = currentConnection();
    const ConnectionHealth *health = ConnectionHealth::of(c);
    setWindowTitle(c ? tr("%1 (%2)[*]")
                           .arg(c->uri().toString(),
                                health ? ConnectionHealth::statusText(health->status())
                                       : stateName(c->state()))
                     : tr("drivebench"));
    setWindowModified(c && m_unstored.contains(c));
}

void MainWindow::closeAllConnections(int timeoutMs)
{
    const auto allDown = [this] {
        return std::all_of(m_connections.begin(), m_connections.end(), [](const auto &c) {
            return c->state() == DeviceConnection::State::Disconnected;
        });
    };
    for (const auto &c : m_connections) {
        stopMotionBeforeClose(c.get());
        c->close();
    }
    if (allDown())
        return;
    QEventLoop loop;
    QTimer::singleShot(timeoutMs, &loop, &QEventLoop::quit);
    for (const auto &c : m_connections) {
        connect(c.get(), &DeviceConnection::stateChanged, &loop, [&loop, allDown] {
            if (allDown())
                loop.quit();
        });
    }
    loop.exec(QEventLoop::ExcludeUserInputEvents);
}

void MainWindow::closeEvent(QCloseEvent *event)
{
    if (!confirmClose(connections())) {
        event->ignore();
        return;
    }
    saveSettings();
    closeAllConnections();
    event->accept();
}

void MainWindow::loadSettings()
{
    QSettings settings = openSettings();
    restoreGeometry(settings.value(kGeometryKey).toByteArray());
    restoreState(settings.value(kStateKey).toByteArray());
    m_recent = settings.value(kRecentKey).toStringList();
    m_connectTimeoutMs = settings.value(kConnectTimeoutKey, m_connectTimeoutMs).toInt();
    m_requestTimeoutMs = settings.value(kRequestTimeoutKey, m_requestTimeoutMs).toInt();
    m_language = settings.value(kLanguageKey).toString();
    m_autoReconnect = settings.value(kAutoReconnectKey, false).toBool();
    m_reconnectWindowS = settings.value(kReconnectWindowKey, m_reconnectWindowS).toInt();
}

SettingsDialog::Values MainWindow::settingsValues() const
{
    return { m_language, m_connectTimeoutMs, m_requestTimeoutMs,
             m_recent,   m_autoReconnect,    m_reconnectWindowS };
}

void MainWindow::applySettings(const SettingsDialog::Values &values)
{
    m_language = values.language;
    m_connectTimeoutMs = values.connectTimeoutMs;
    m_requestTimeoutMs = values.requestTimeoutMs;
    m_recent = values.recent;
    m_autoReconnect = values.autoReconnect;
    m_reconnectWindowS = values.reconnectWindowS;
    for (const auto &c : m_connections)
        followReconnectSetting(c.get());
    saveSettings();
    updateWelcome();
}

void MainWindow::showSettings()
{
    SettingsDialog dialog(settingsValues(), this);
    if (dialog.exec() == QDialog::Accepted)
        applySettings(dialog.values());
}

void MainWindow::saveSettings() const
{
    QSettings settings = openSettings();
    settings.setValue(kGeometryKey, saveGeometry());
    settings.setValue(kStateKey, saveState());
    settings.setValue(kRecentKey, m_recent);
    settings.setValue(kConnectTimeoutKey, m_connectTimeoutMs);
    settings.setValue(kRequestTimeoutKey, m_requestTimeoutMs);
    settings.setValue(kLanguageKey, m_language);
    settings.setValue(kAutoReconnectKey, m_autoReconnect);
    settings.setValue(kReconnectWindowKey, m_reconnectWindowS);
}

} // namespace db::gui
