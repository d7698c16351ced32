#include "responsetimer.h"

#include <QTimerEvent>

#include <chrono>
#include <limits>

namespace db {

ResponseTimer::ResponseTimer(std::function<void()> onTimeout, QObject *parent)
    : QObject(parent)
    , m_onTimeout(std::move(onTimeout))
{ }

qint64 ResponseTimer::nowNs()
{
    // The clock of Qt's timers (CLOCK_MONOTONIC), read without a system call.
    return std::chrono::duration_cast<std::chrono::nanoseconds>(
               std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

void ResponseTimer::start(int ms)
{
    m_deadlineNs = nowNs() + qint64(qMax(0, ms)) * 1000000;
    m_armed = true;
    if (!m_timer.isActive() || m_dueNs > m_deadlineNs)
        startUnderlying(qint64(qMax(0, ms)) * 1000000);
}

void ResponseTimer::startUnderlying(qint64 ns)
{
    // Rounded up: a timer never fires before its interval, so one pass suffices when on time.
    const int ms = int(qMin<qint64>((ns + 999999) / 1000000, std::numeric_limits<int>::max()));
    m_dueNs = nowNs() + qint64(ms) * 1000000;
    // Precise: a coarse timer may fire up to 5 % early, which would cost a second pass.
    m_timer.start(ms, Qt::PreciseTimer, this);
}

void ResponseTimer::timerEvent(QTimerEvent *event)
{
    if (event->timerId() != m_timer.timerId()) {
        QObject::timerEvent(event);
        return;
    }
    m_timer.stop();
    if (!m_armed)
        return;
    const qint64 left = m_deadlineNs - nowNs();
    if (left > 0) {
        startUnderlying(left);
        return;
    }
    m_armed = false;
    m_onTimeout();
}

} // namespace db
