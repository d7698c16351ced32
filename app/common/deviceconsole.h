#pragma once

#include "core/result.h"

#include <QObject>
#include <QStringList>
#include <QTimer>

namespace db::app {

// The control lines of a running simulated device (drivebench-sim ... --control): failure modes
// and observations for end-to-end tests and demos. One command per line; every command answers
// exactly one line through answered() (standstill possibly later). T is the simulator's own
// clock in ms, so that times measured through the console do not include pipe or test latency.
// The commands every simulated drive has:
//   state             -> "state T position P velocity V" and what the device adds (stateDetails)
//   standstill        -> "standstill T position P" as soon as the axis stands (at once if it
//                        does)
//   drop              -> "dropped N T position P velocity V": every client aborted (a cut
//                        cable); the doors keep listening
//   fault CODE        -> "fault CODE": the drive faults with this code (parseFault)
//   anything else     -> a command of the device's own (executeOwn), or "error: ..." naming the
//                        cause
class DeviceConsole : public QObject
{
    Q_OBJECT
public:
    void execute(const QString &line);

    // Four upper-case hex digits.
    static QString hex4(quint16 value);

Q_SIGNALS:
    void answered(const QString &line);

protected:
    explicit DeviceConsole(QObject *parent = nullptr);

    // "T position P velocity V" now.
    virtual QString motion() const = 0;
    virtual bool isMoving() const = 0;
    // What "state" tells after the motion: " statusword 0xSSSS ...".
    virtual QString stateDetails() const = 0;
    // Aborts every client; how many there were.
    virtual int dropClients() = 0;
    virtual Result<quint16> parseFault(const QString &text) const = 0;
    virtual void injectFault(quint16 code) = 0;
    // A command of the device's own (words: the line split at spaces): false when it is none,
    // else it has answered (or refused) it.
    virtual bool executeOwn(const QStringList &words)
    {
        Q_UNUSED(words);
        return false;
    }
    // The device's own commands for the "unknown command" answer, e.g. "heartbeat off|on".
    virtual QString ownCommands() const = 0;

private:
    void checkStandstill();

    QTimer m_standstill; // polls the axis while a standstill answer is owed
    int m_standstillOwed = 0;
};

} // namespace db::app
