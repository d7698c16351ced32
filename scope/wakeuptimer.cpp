#include "wakeuptimer.h"

#include <QSocketNotifier>
#include <algorithm>
#include <cmath>

#ifdef Q_OS_LINUX
#include <sys/timerfd.h>
#include <unistd.h>
#endif

namespace db::scope {

WakeupTimer::WakeupTimer(QObject *parent)
    : QObject(parent)
{
    m_fallback.setSingleShot(true);
    m_fallback.setTimerType(Qt::PreciseTimer);
    connect(&m_fallback, &QTimer::timeout, this, &WakeupTimer::fire);
#ifdef Q_OS_LINUX
    m_fd = ::timerfd_create(CLOCK_MONOTONIC, TFD_NONBLOCK | TFD_CLOEXEC);
    if (m_fd >= 0) {
        m_notifier = new QSocketNotifier(qintptr(m_fd), QSocketNotifier::Read, this);
        connect(m_notifier, &QSocketNotifier::activated, this, [this] {
            quint64 expirations = 0;
            if (::read(m_fd, &expirations, sizeof expirations) == sizeof expirations)
                fire();
        });
    }
#endif
}

WakeupTimer::~WakeupTimer()
{
#ifdef Q_OS_LINUX
    delete m_notifier;
    if (m_fd >= 0)
        ::close(m_fd);
#endif
}

void WakeupTimer::wakeAt(const QElapsedTimer &clock, qint64 deadlineNs)
{
    // At least 1 ns: a zero timerfd value disarms instead of firing.
    const qint64 remainingNs = std::max<qint64>(1, deadlineNs - clock.nsecsElapsed());
    m_active = true;
#ifdef Q_OS_LINUX
    if (m_fd >= 0) {
        itimerspec spec {};
        spec.it_value.tv_sec = time_t(remainingNs / 1000000000);
        spec.it_value.tv_nsec = long(remainingNs % 1000000000);
        if (::timerfd_settime(m_fd, 0, &spec, nullptr) == 0)
            return;
    }
#endif
    // QTimer takes an int of ms: rounded up so that it never fires early, capped at ~24 days.
    m_fallback.start(int(std::min(std::ceil(double(remainingNs) * 1e-6), 2.0e9)));
}

void WakeupTimer::stop()
{
    m_active = false;
    m_fallback.stop();
#ifdef Q_OS_LINUX
    if (m_fd >= 0) {
        const itimerspec disarm {};
        ::timerfd_settime(m_fd, 0, &disarm, nullptr);
        quint64 expirations = 0; // an expiry not yet read would fire after stop()
        [[maybe_unused]] const auto drained = ::read(m_fd, &expirations, sizeof expirations);
    }
#endif
}

void WakeupTimer::fire()
{
    if (!m_active)
        return;
    m_active = false;
    Q_EMIT timeout();
}

} // namespace db::scope
