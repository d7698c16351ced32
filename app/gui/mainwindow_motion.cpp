// MainWindow: the "Motion" dock and the stops that must work whatever has the focus.
#include "mainwindow.h"

#include "widgets/common/logconsole.h"
#include "widgets/common/verticalscrollarea.h"
#include "widgets/connection/drivestatuspanel.h"
#include "widgets/motion/jogpanel.h"

#include <QApplication>
#include <QDockWidget>
#include <QEventLoop>
#include <QKeyEvent>
#include <QTimer>

namespace db::gui {

namespace {
// How long a user's disconnect waits for the quick stop to reach the drive (the stop is written
// from the event loop; closing at once would cancel it).
constexpr int kStopBeforeCloseMs = 500;
constexpr int kDockRoom = 40; // beyond its minimum: the fields show their units once connected

// Esc anywhere in the application quick-stops a moving axis, and the main window losing the
// activation halts a jog. The filter sits on qApp, so it sees the key before any widget can
// consume it, and it never consumes it: Esc still closes a dialog or a menu.
class MotionStopFilter : public QObject
{
public:
    MotionStopFilter(QWidget *window, widgets::JogPanel *panel)
        : QObject(window)
        , m_window(window)
        , m_panel(panel)
    { }

protected:
    bool eventFilter(QObject *watched, QEvent *event) override
    {
        if (event->type() == QEvent::KeyPress
            && static_cast<QKeyEvent *>(event)->key() == Qt::Key_Escape) {
            m_panel->stopAll(QObject::tr("Esc"));
        } else if (event->type() == QEvent::WindowDeactivate && watched == m_window) {
            m_panel->stopJog(QObject::tr("window deactivated"));
        }
        return false;
    }

private:
    QWidget *m_window;
    widgets::JogPanel *m_panel;
};
} // namespace

void MainWindow::createMotionDock()
{
    m_jogPanel = new widgets::JogPanel(this);
    m_jogPanel->setObjectName(QStringLiteral("jogPanel"));
    auto *scroll = new widgets::VerticalScrollArea(m_jogPanel, this);
    auto *dock = new QDockWidget(tr("Motion"), this);
    dock->setObjectName(QStringLiteral("motionDock")); // for saveState()/restoreState()
    dock->setWidget(scroll);
    addDockWidget(Qt::RightDockWidgetArea, dock);
    // The panel is tall: the right dock area takes the full height, beside the log.
    setCorner(Qt::BottomRightCorner, Qt::RightDockWidgetArea);
    // Little wider than the panel needs, so that the pages get the room; until restoreState()
    // knows better.
    resizeDocks({ dock }, { scroll->minimumSizeHint().width() + kDockRoom }, Qt::Horizontal);
    qApp->installEventFilter(new MotionStopFilter(this, m_jogPanel));
    connect(m_jogPanel, &widgets::JogPanel::stopped, this, [this](const QString &reason) {
        if (widgets::LogConsole *log = logConsole())
            log->warning(tr("Motion stopped: %1").arg(reason));
    });
    // The Drive Status page says what the Motion dock says about ErrorStop.
    connect(m_jogPanel, &widgets::JogPanel::motionNoteChanged, this, [this](const QString &note) {
        if (m_statusPanel)
            m_statusPanel->setMotionNote(note);
    });
}

void MainWindow::stopMotionBeforeClose(DeviceConnection *connection)
{
    if (!m_jogPanel || !connection || m_jogPanel->connection() != connection
        || !m_jogPanel->isMotionInProgress())
        return;
    m_jogPanel->stopAll(tr("connection closed by the user"));
    motion::AxisInterface *axis = m_jogPanel->axis();
    if (!axis)
        return;
    QEventLoop loop;
    QTimer::singleShot(kStopBeforeCloseMs, &loop, &QEventLoop::quit);
    connect(axis, &motion::AxisInterface::statusChanged, &loop, [axis, &loop] {
        if (!axis->status().powered) // quick stop active or off: the stop arrived
            loop.quit();
    });
    loop.exec(QEventLoop::ExcludeUserInputEvents);
}

} // namespace db::gui
