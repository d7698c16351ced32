#pragma once
// A single-shot timer that fires at a deadline in ns on a QElapsedTimer's clock.
#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

class QSocketNotifier;

namespace db::scope {

// QTimer counts whole milliseconds, so a wake-up for a deadline 0.2 ms away comes up to 1 ms
// late. On Linux this timer uses a timerfd on the monotonic clock (the clock QElapsedTimer
// reads), which wakes the event loop within tens of microseconds of the deadline; elsewhere it
// falls back to a precise QTimer rounded up to the next millisecond.
// Contract: wakeAt() replaces any earlier deadline; timeout() is emitted once per wakeAt(),
// from the event loop (never from inside wakeAt()), and not after stop().
class WakeupTimer : public QObject
{
    Q_OBJECT
public:
    explicit WakeupTimer(QObject *parent = nullptr);
    ~WakeupTimer() override;

    // Fires when clock.nsecsElapsed() reaches deadlineNs (at once, from the loop, when it has).
    void wakeAt(const QElapsedTimer &clock, qint64 deadlineNs);
    void stop();
    bool isActive() const { return m_active; }

Q_SIGNALS:
    void timeout();

private:
    void fire();

    int m_fd = -1;
    QSocketNotifier *m_notifier = nullptr;
    QTimer m_fallback;
    bool m_active = false;
};

} // namespace db::scope
