// MainWindow: the toolbar, View → Reset Layout and the welcome page shown while no device is
// listed.
#include "mainwindow.h"

#include "scope/recorder.h"
#include "widgets/common/widgetstyle.h"
#include "widgets/motion/jogpanel.h"
#include "widgets/scope/scopepage.h"

#include <QDockWidget>
#include <QEvent>
#include <QLabel>
#include <QPushButton>
#include <QShortcut>
#include <QStackedWidget>
#include <QTabWidget>
#include <QTimer>
#include <QToolBar>
#include <QVBoxLayout>

namespace db::gui {

namespace {
constexpr int kRecentOnWelcome = 5;
constexpr int kWelcomeWidth = 520;

// Keeps an action enabled exactly while a button is: the toolbar's Enable does what the Motion
// dock's Enable does, and only when that one may be pressed.
class EnabledMirror : public QObject
{
public:
    EnabledMirror(QWidget *button, QAction *action)
        : QObject(action)
        , m_action(action)
    {
        button->installEventFilter(this);
        action->setEnabled(button->isEnabled());
    }

protected:
    bool eventFilter(QObject *watched, QEvent *event) override
    {
        if (event->type() == QEvent::EnabledChange)
            m_action->setEnabled(static_cast<QWidget *>(watched)->isEnabled());
        return false;
    }

private:
    QAction *m_action;
};
} // namespace

void MainWindow::createToolBar()
{
    m_toolBar = addToolBar(tr("Main"));
    m_toolBar->setObjectName(QStringLiteral("mainToolBar")); // for saveState()/restoreState()
    m_toolBar->setMovable(false);
    m_toolBar->setToolButtonStyle(Qt::ToolButtonTextOnly);
    m_toolBar->addAction(m_connectAction);
    m_toolBar->addAction(m_disconnectAction);
    m_toolBar->addSeparator();

    m_enableAction =
        m_toolBar->addAction(tr("Enable"), m_jogPanel, &widgets::JogPanel::enableDrive);
    m_enableAction->setObjectName(QStringLiteral("enableAction"));
    m_enableAction->setToolTip(tr("Switch the current drive's power stage on (as in the Motion "
                                  "dock)"));
    if (auto *enable = m_jogPanel->findChild<QWidget *>(QStringLiteral("enable")))
        new EnabledMirror(enable, m_enableAction);
    m_stopAction = m_toolBar->addAction(tr("Stop"), this,
                                        [this] { m_jogPanel->stopAll(tr("Stop in the toolbar")); });
    m_stopAction->setObjectName(QStringLiteral("stopAction"));
    m_stopAction->setToolTip(tr("Quick stop of any motion (Esc)"));
    widgets::style::setTextColor(m_toolBar->widgetForAction(m_stopAction),
                                 widgets::style::errorColor());
    m_toolBar->addSeparator();

    m_scopeAction = m_toolBar->addAction(tr("Start Scope"), this, &MainWindow::toggleScope);
    m_scopeAction->setObjectName(QStringLiteral("scopeAction"));
    m_scopeAction->setToolTip(tr("Start or stop the scope's recording (Space or F5 on the Scope "
                                 "page)"));
    const auto renderScope = [this] {
        m_scopeAction->setText(m_scopePage->recorder()->isRunning() ? tr("Stop Scope")
                                                                    : tr("Start Scope"));
    };
    connect(m_scopePage->recorder(), &scope::Recorder::stateChanged, this, renderScope);
    // Space starts and stops the scope while the focus is on the Scope page (a line edit there
    // still takes its space: it claims the key before shortcuts see it).
    auto *space = new QShortcut(QKeySequence(Qt::Key_Space), m_scopePage);
    space->setContext(Qt::WidgetWithChildrenShortcut);
    connect(space, &QShortcut::activated, this, &MainWindow::toggleScope);
}

void MainWindow::toggleScope()
{
    m_pages->setCurrentWidget(m_scopePage);
    if (m_scopePage->recorder()->isRunning())
        m_scopePage->stop();
    else
        m_scopePage->start();
}

void MainWindow::resetLayout()
{
    restoreState(m_defaultLayout);
    for (QDockWidget *dock : findChildren<QDockWidget *>()) {
        dock->setFloating(false);
        dock->show();
    }
    m_toolBar->show();
    if (auto *log = findChild<QDockWidget *>(QStringLiteral("logDock")))
        log->raise();
}

void MainWindow::createWelcome()
{
    m_welcome = new QWidget(m_central);
    m_welcome->setObjectName(QStringLiteral("welcome"));
    auto *box = new QWidget(m_welcome);
    box->setMaximumWidth(kWelcomeWidth);
    auto *title = new QLabel(tr("No device connected"), box);
    QFont big = title->font();
    big.setPointSizeF(big.pointSizeF() * 1.6);
    big.setBold(true);
    title->setFont(big);
    auto *text = new QLabel(tr("Connect to a drive over RefGo, VABus or CANopen, or try "
                               "drivebench on a simulated drive."),
                            box);
    text->setWordWrap(true);
    auto *connectButton = new QPushButton(tr("Connect…"), box);
    connectButton->setObjectName(QStringLiteral("welcomeConnect"));
    connect(connectButton, &QPushButton::clicked, this, &MainWindow::showConnectDialog);
    auto *demoButton = new QPushButton(tr("Start the Demo"), box);
    demoButton->setObjectName(QStringLiteral("welcomeDemo"));
    demoButton->setToolTip(tr("A simulated MovingCap drive in this program, connected over "
                              "RefGo and CANopen"));
    connect(demoButton, &QPushButton::clicked, this, [this] {
        if (m_demoStarter)
            m_demoStarter();
    });
    m_demoButton = demoButton;
    m_demoButton->setVisible(false);
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(connectButton);
    buttons->addWidget(demoButton);
    buttons->addStretch();
    m_recentBox = new QWidget(box);
    m_recentBox->setObjectName(QStringLiteral("welcomeRecent"));
    (new QVBoxLayout(m_recentBox))->setContentsMargins(0, 0, 0, 0);

    auto *boxLayout = new QVBoxLayout(box);
    boxLayout->addWidget(title);
    boxLayout->addWidget(text);
    boxLayout->addLayout(buttons);
    boxLayout->addSpacing(12);
    boxLayout->addWidget(m_recentBox);
    // Centred, as wide as kWelcomeWidth allows (the wrapped text needs the width to be known).
    auto *row = new QHBoxLayout;
    row->addStretch(1);
    row->addWidget(box, 4);
    row->addStretch(1);
    auto *layout = new QVBoxLayout(m_welcome);
    layout->addStretch(1);
    layout->addLayout(row);
    layout->addStretch(2);
    m_central->addWidget(m_welcome);
}

void MainWindow::setDemoStarter(std::function<void()> start)
{
    m_demoStarter = std::move(start);
    m_demoButton->setVisible(bool(m_demoStarter));
}

void MainWindow::updateWelcome()
{
    const bool none = m_connections.empty();
    m_central->setCurrentWidget(none ? m_welcome : static_cast<QWidget *>(m_pages));
    if (!none)
        return;
    // The recent connections as buttons that connect at once.
    QLayout *layout = m_recentBox->layout();
    while (QLayoutItem *item = layout->takeAt(0)) {
        delete item->widget();
        delete item;
    }
    if (m_recent.isEmpty())
        return;
    layout->addWidget(new QLabel(tr("Recent connections:"), m_recentBox));
    for (const QString &uri : m_recent.mid(0, kRecentOnWelcome)) {
        auto *button = new QPushButton(uri, m_recentBox);
        button->setFlat(true);
        button->setStyleSheet(QStringLiteral("text-align: left"));
        button->setToolTip(tr("Connect to %1").arg(uri));
        connect(button, &QPushButton::clicked, this, [this, uri] {
            // Later: the button is deleted when the welcome page goes.
            QTimer::singleShot(0, this, [this, uri] { openConnection(uri); });
        });
        layout->addWidget(button);
    }
}

} // namespace db::gui
