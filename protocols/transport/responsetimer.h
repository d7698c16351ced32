#pragma once

// The time limit of a request in flight, restarted for every request of a busy client.
//
// Contract:
// - start(ms) arms it: the callback runs once, from the event loop, when ms milliseconds have
//   passed without stop() or another start(). start() again moves the deadline; stop() disarms.
// - Arming only records the deadline. The event-dispatcher timer underneath is started when
//   none runs or when it would fire after the new deadline, and is not stopped by stop(): when
//   it fires early (it was started for an earlier request) it sleeps again for the rest, and
//   when it fires disarmed it ends. So a client that sends thousands of requests a second
//   registers a dispatcher timer about once per time limit, not twice per request.
// - The callback may call start() or stop() and may delete the object that owns this timer
//   only if it returns at once.

#include <QBasicTimer>
#include <QObject>

#include <functional>

namespace db {

class ResponseTimer final : public QObject
{
public:
    explicit ResponseTimer(std::function<void()> onTimeout, QObject *parent = nullptr);

    void start(int ms);
    void stop() { m_armed = false; }
    bool isActive() const { return m_armed; }

protected:
    void timerEvent(QTimerEvent *event) override;

private:
    static qint64 nowNs();
    void startUnderlying(qint64 ns);

    std::function<void()> m_onTimeout;
    QBasicTimer m_timer;
    qint64 m_deadlineNs = 0; // when armed: the callback's time
    qint64 m_dueNs = 0; // when m_timer runs: the time it fires (at the earliest)
    bool m_armed = false;
};

} // namespace db
