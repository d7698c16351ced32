// MainWindow: what ConnectionHealth says about the connections, where the user looks (status bar,
// Drive Status page, device list, Motion dock, log), and the question before a connection with an
// enabled drive is closed.
#include "mainwindow.h"

#include "core/autoreconnect.h"
#include "core/connectionhealth.h"
#include "motion/axisinterface.h"
#include "widgets/common/logconsole.h"
#include "widgets/common/widgetstyle.h"
#include "widgets/connection/connectiondialog.h"
#include "widgets/motion/jogpanel.h"

#include <QLabel>
#include <QLayout>
#include <QMessageBox>
#include <QStatusBar>

namespace db::gui {

void MainWindow::createHealthBanner(QWidget *statusPage)
{
    m_healthBanner = new QLabel(statusPage);
    m_healthBanner->setObjectName(QStringLiteral("healthBanner"));
    m_healthBanner->setWordWrap(true);
    m_healthBanner->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_healthBanner->setMargin(8);
    m_healthBanner->setAutoFillBackground(true);
    m_healthBanner->hide();
    statusPage->layout()->addWidget(m_healthBanner);
}

void MainWindow::onHealthChanged(DeviceConnection *connection)
{
    const ConnectionHealth *health = ConnectionHealth::of(connection);
    if (!health)
        return;
    const QString name = connection->uri().toString();
    switch (health->status()) {
    case ConnectionHealth::Status::Connecting:
        // A new attempt: the messages of the previous one no longer apply.
        if (connection == currentConnection())
            statusBar()->clearMessage();
        break;
    case ConnectionHealth::Status::Responding:
        // Remembered once the device answered: failed attempts and the demo are not.
        if (!m_forget.contains(connection)) {
            m_recent = widgets::ConnectionDialog::withRecent(m_recent, name);
            updateWelcome();
        }
        break;
    case ConnectionHealth::Status::NotResponding:
    case ConnectionHealth::Status::Failed:
    case ConnectionHealth::Status::Lost:
        m_log->error(tr("%1: %2").arg(name, health->description()));
        break;
    case ConnectionHealth::Status::Idle:
    case ConnectionHealth::Status::WaitingForAnswer:
    case ConnectionHealth::Status::ClosedByUser:
        break;
    }
    if (connection == currentConnection()) {
        updateStatusBar();
        renderHealth();
    }
}

void MainWindow::renderHealth()
{
    DeviceConnection *c = currentConnection();
    const ConnectionHealth *health = ConnectionHealth::of(c);
    const auto status = health ? health->status() : ConnectionHealth::Status::Idle;
    m_jogPanel->setDeviceResponding(!health || health->isResponding(),
                                    ConnectionHealth::statusText(status));
    const AutoReconnect *reconnect = AutoReconnect::of(c);
    QString text;
    switch (status) {
    case ConnectionHealth::Status::Connecting:
        if (reconnect && reconnect->isActive())
            text = tr("%1: connection lost; reconnecting automatically, attempt %2.")
                       .arg(c->uri().toString())
                       .arg(reconnect->attempts());
        break;
    case ConnectionHealth::Status::WaitingForAnswer:
        text = tr("%1: the link is up, waiting for the device to answer.").arg(c->uri().toString());
        break;
    case ConnectionHealth::Status::NotResponding:
    case ConnectionHealth::Status::Failed:
    case ConnectionHealth::Status::Lost: {
        text = tr("%1: %2.").arg(c->uri().toString(), health->description());
        if (health->lastAnswer().isValid())
            text += QLatin1Char(' ')
                + tr("The values shown are from %1 and may be out of date.")
                      .arg(health->lastAnswer().toString(QStringLiteral("HH:mm:ss")));
        if (reconnect && reconnect->isActive())
            text += QLatin1Char(' ') + tr("Reconnecting automatically.");
        else if (reconnect && reconnect->hasGivenUp())
            text += QLatin1Char(' ')
                + tr("Automatic reconnect gave up after %n attempt(s).", "", reconnect->attempts());
        break;
    }
    case ConnectionHealth::Status::ClosedByUser:
        text = tr("%1: disconnected by you.").arg(c->uri().toString());
        break;
    case ConnectionHealth::Status::Idle:
    case ConnectionHealth::Status::Responding:
        break;
    }
    m_healthBanner->setText(text);
    m_healthBanner->setVisible(!text.isEmpty());
    QPalette palette = m_healthBanner->palette();
    const QColor color = widgets::style::healthColor(status);
    palette.setColor(QPalette::Window, color.lighter(185));
    palette.setColor(QPalette::WindowText, color.darker(170));
    m_healthBanner->setPalette(palette);
}

void MainWindow::followReconnectSetting(DeviceConnection *connection)
{
    ConnectionHealth *health = ConnectionHealth::of(connection);
    AutoReconnect *reconnect = AutoReconnect::of(connection);
    const int windowMs = m_reconnectWindowS * 1000;
    if (!health || (m_autoReconnect && reconnect && reconnect->windowMs() == windowMs))
        return;
    delete reconnect;
    if (!m_autoReconnect)
        return;
    reconnect = new AutoReconnect(health, AutoReconnect::kDefaultIntervalMs, windowMs);
    const QString name = connection->uri().toString();
    // Once more after the reconnect has seen the change (it connected after onHealthChanged()).
    connect(health, &ConnectionHealth::statusChanged, reconnect, [this, connection] {
        if (connection == currentConnection())
            renderHealth();
    });
    connect(reconnect, &AutoReconnect::attemptStarted, this, [this, name](int attempt) {
        m_log->info(tr("%1: reconnecting automatically, attempt %2").arg(name).arg(attempt));
    });
    connect(reconnect, &AutoReconnect::reconnected, this, [this, name](int attempts) {
        m_log->info(tr("%1: the link is up again after %n attempt(s)", "", attempts).arg(name));
    });
    connect(reconnect, &AutoReconnect::gaveUp, this, [this, connection, name](int attempts) {
        m_log->error(tr("%1: automatic reconnect gave up after %n attempt(s) in %2 s", "", attempts)
                         .arg(name)
                         .arg(m_reconnectWindowS));
        if (connection == currentConnection())
            renderHealth();
    });
}

bool MainWindow::confirmClose(const QList<DeviceConnection *> &connections)
{
    // Only the Motion dock's axis can be enabled from here; it is on the current connection.
    DeviceConnection *axisConnection = m_jogPanel->connection();
    const motion::AxisInterface *axis = m_jogPanel->axis();
    if (!axisConnection || !connections.contains(axisConnection) || !axis
        || !axisConnection->isConnected() || !axis->status().valid || !axis->status().powered)
        return true;
    const QString question =
        tr("The drive at %1 is enabled. Closing the connection leaves it enabled (it stops by "
           "its own supervision only if that is set up). Close the connection anyway?")
            .arg(axisConnection->uri().toString());
    if (m_confirm)
        return m_confirm(question);
    return QMessageBox::question(this, tr("Drive enabled"), question,
                                 QMessageBox::Yes | QMessageBox::No, QMessageBox::No)
        == QMessageBox::Yes;
}

void MainWindow::closeByUser(DeviceConnection *connection)
{
    if (!connection || !confirmClose({ connection }))
        return;
    stopMotionBeforeClose(connection);
    connection->close();
}

} // namespace db::gui
