#pragma once

#include "connectionhealth.h"

#include <QDeadlineTimer>
#include <QObject>
#include <QTimer>

namespace db {

// Tries a lost connection again, whatever its protocol: once its ConnectionHealth says Lost
// (never after the user closed it, never after a first attempt that failed), open() every
// intervalMs until the link is up again or windowMs have passed since the loss. Attempts that
// fail inside the window are followed by the next one; after the window it gives up and says so.
// An attempt is only made while the connection is Disconnected (a protocol's own retry may be
// under way).
//
// One per connection, a child of its health: AutoReconnect::of() finds it.
class AutoReconnect : public QObject
{
    Q_OBJECT
public:
    static constexpr int kDefaultIntervalMs = 3000;
    static constexpr int kDefaultWindowMs = 60000;

    explicit AutoReconnect(ConnectionHealth *health, int intervalMs = kDefaultIntervalMs,
                           int windowMs = kDefaultWindowMs);

    static AutoReconnect *of(const DeviceConnection *connection);

    int intervalMs() const { return m_timer.interval(); }
    int windowMs() const { return m_windowMs; }
    // Between a loss and the link being up again (or giving up).
    bool isActive() const { return m_active; }
    // Attempts made since the last loss.
    int attempts() const { return m_attempts; }
    // The last episode ended without a working link (until the next loss).
    bool hasGivenUp() const { return m_gaveUp; }
    // Ends an episode without an attempt (the user closed the connection).
    void stop();

Q_SIGNALS:
    // open() is called for attempt number `attempt` (1, 2, ...).
    void attemptStarted(int attempt);
    // The link is up again after `attempts` attempts.
    void reconnected(int attempts);
    // The window passed without a working link; no more attempts.
    void gaveUp(int attempts);

private:
    void onStatusChanged(ConnectionHealth::Status status);
    void attempt();
    void scheduleOrGiveUp();

    ConnectionHealth *m_health;
    QTimer m_timer;
    QDeadlineTimer m_until;
    int m_windowMs;
    int m_attempts = 0;
    bool m_active = false;
    bool m_gaveUp = false;
};

} // namespace db
