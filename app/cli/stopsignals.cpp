#include "stopsignals.h"

#include <cerrno>
#include <csignal>
#include <fcntl.h>
#include <unistd.h>
#include <utility>

namespace db::cli {

namespace {

constexpr int kSignals[] = { SIGINT, SIGTERM };
int g_pipe[2] = { -1, -1 }; // read end, write end
struct sigaction g_previous[std::size(kSignals)];
bool g_installed[std::size(kSignals)] = {};

// Async-signal-safe: write(2) of one byte to a non-blocking pipe; errno is preserved.
void onSignal(int signal)
{
    const int saved = errno;
    const char byte = char(signal);
    const ssize_t written = ::write(g_pipe[1], &byte, 1);
    (void)written; // a full pipe already holds a stop request
    errno = saved;
}

} // namespace

StopSignals::StopSignals(QObject *parent)
    : QObject(parent)
{
    if (g_pipe[0] >= 0 || ::pipe2(g_pipe, O_CLOEXEC | O_NONBLOCK) != 0) {
        if (g_pipe[0] < 0)
            g_pipe[0] = g_pipe[1] = -1;
        return; // already taken, or no pipe: the default dispositions stay
    }
    m_notifier = std::make_unique<QSocketNotifier>(g_pipe[0], QSocketNotifier::Read);
    connect(m_notifier.get(), &QSocketNotifier::activated, this, &StopSignals::onReadable);
    struct sigaction action = {};
    action.sa_handler = onSignal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESETHAND | SA_RESTART;
    for (size_t i = 0; i < std::size(kSignals); ++i) {
        // A signal ignored on entry (nohup, a background job of a script) stays ignored.
        g_installed[i] = ::sigaction(kSignals[i], nullptr, &g_previous[i]) == 0
            && g_previous[i].sa_handler != SIG_IGN
            && ::sigaction(kSignals[i], &action, nullptr) == 0;
    }
}

StopSignals::~StopSignals()
{
    if (!m_notifier)
        return;
    for (size_t i = 0; i < std::size(kSignals); ++i) {
        if (std::exchange(g_installed[i], false))
            ::sigaction(kSignals[i], &g_previous[i], nullptr);
    }
    m_notifier.reset();
    ::close(g_pipe[0]);
    ::close(g_pipe[1]);
    g_pipe[0] = g_pipe[1] = -1;
}

QString StopSignals::name(int signal)
{
    switch (signal) {
    case SIGINT:
        return QStringLiteral("SIGINT");
    case SIGTERM:
        return QStringLiteral("SIGTERM");
    default:
        return QStringLiteral("signal %1").arg(signal);
    }
}

void StopSignals::onReadable()
{
    char bytes[16];
    ssize_t n = 0;
    while ((n = ::read(g_pipe[0], bytes, sizeof bytes)) > 0) {
        if (m_signal == 0) {
            m_signal = bytes[0];
            Q_EMIT stopRequested(m_signal);
        }
    }
}

} // namespace db::cli
