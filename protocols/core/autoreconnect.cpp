#include "autoreconnect.h"

namespace db {

AutoReconnect::AutoReconnect(ConnectionHealth *health, int intervalMs, int windowMs)
    : QObject(health)
    , m_health(health)
    , m_windowMs(qMax(0, windowMs))
{
    m_timer.setSingleShot(true);
    m_timer.setInterval(qMax(1, intervalMs));
    connect(&m_timer, &QTimer::timeout, this, &AutoReconnect::attempt);
    connect(health, &ConnectionHealth::statusChanged, this, &AutoReconnect::onStatusChanged);
}

AutoReconnect *AutoReconnect::of(const DeviceConnection *connection)
{
    const ConnectionHealth *health = ConnectionHealth::of(connection);
    return health ? health->findChild<AutoReconnect *>(QString(), Qt::FindDirectChildrenOnly)
                  : nullptr;
}

void AutoReconnect::stop()
{
    m_timer.stop();
    m_active = false;
}

void AutoReconnect::onStatusChanged(ConnectionHealth::Status status)
{
    switch (status) {
    case ConnectionHealth::Status::Lost:
        if (!m_active) {
            m_active = true;
            m_attempts = 0;
            m_gaveUp = false;
            m_until = QDeadlineTimer(m_windowMs);
        }
        scheduleOrGiveUp();
        break;
    case ConnectionHealth::Status::Failed:
        if (m_active)
            scheduleOrGiveUp();
        break;
    case ConnectionHealth::Status::WaitingForAnswer:
    case ConnectionHealth::Status::Responding:
    case ConnectionHealth::Status::NotResponding:
        if (m_active) {
            stop();
            Q_EMIT reconnected(m_attempts);
        }
        break;
    case ConnectionHealth::Status::ClosedByUser:
        stop();
        m_gaveUp = false;
        break;
    case ConnectionHealth::Status::Idle:
    case ConnectionHealth::Status::Connecting:
        break;
    }
}

void AutoReconnect::scheduleOrGiveUp()
{
    if (m_until.hasExpired()) {
        stop();
        m_gaveUp = true;
        Q_EMIT gaveUp(m_attempts);
        return;
    }
    m_timer.start();
}

void AutoReconnect::attempt()
{
    DeviceConnection *connection = m_health->connection();
    if (!m_active || !connection)
        return;
    if (connection->state() != DeviceConnection::State::Disconnected) {
        // The protocol's own retry is under way: look again later.
        scheduleOrGiveUp();
        return;
    }
    ++m_attempts;
    Q_EMIT attemptStarted(m_attempts);
    connection->open();
}

} // namespace db
