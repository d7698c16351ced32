#pragma once
// SIGINT and SIGTERM as an event-loop signal, for commands that must finish their work (write
// what they have) instead of dying on Ctrl-C.
#include <QObject>
#include <QSocketNotifier>

#include <memory>

namespace db::cli {

// While an instance lives, SIGINT and SIGTERM do not end the process: the async-signal-safe
// handler only writes the signal number into a pipe, and stopRequested() is emitted on the event
// loop of the creating thread. A signal ignored when the instance is made stays ignored (nohup and
// background jobs of scripts ignore SIGINT on purpose). Each handler is one-shot (SA_RESETHAND): a
// second Ctrl-C ends the process at once, should the work after the first one get stuck. The
// destructor restores the previous dispositions. At most one instance at a time (the pipe is
// process-wide).
class StopSignals : public QObject
{
    Q_OBJECT
public:
    explicit StopSignals(QObject *parent = nullptr);
    ~StopSignals() override;

    // "SIGINT", "SIGTERM".
    static QString name(int signal);

Q_SIGNALS:
    // Once, for the first signal received.
    void stopRequested(int signal);

private:
    void onReadable();

    std::unique_ptr<QSocketNotifier> m_notifier;
    int m_signal = 0;
};

} // namespace db::cli
