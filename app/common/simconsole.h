#pragma once

#include "core/result.h"

#include <QObject>
#include <QTimer>

namespace db::app {

class DemoDrive;

// Control lines for a running simulated MovingCap (drivebench-sim movingcap --control): failure
// modes and observations for end-to-end tests and demos. One command per line; every command
// answers exactly one line through answered() (standstill possibly later). T is the drive's own
// clock in ms, so that times measured through the console do not include pipe or test latency.
//   state             -> "state T position P velocity V statusword 0xSSSS"
//   standstill        -> "standstill T position P" as soon as the axis stands (at once if it does)
//   drop              -> "dropped N T position P velocity V": every client of both doors aborted
//                        (a cut cable); the doors keep listening
//   fault CODE        -> "fault CODE": the drive faults with this EMCY code (hex, e.g. 7121)
//   heartbeat off|on  -> "heartbeat off|on": the CANopen node stops/resumes its 1017h heartbeat
//   anything else     -> "error: ..." naming the cause
class SimConsole : public QObject
{
    Q_OBJECT
public:
    // demo must outlive the console.
    explicit SimConsole(DemoDrive *demo, QObject *parent = nullptr);

    void execute(const QString &line);

    // "7121", "0x7121" or "7121h": a 16-bit EMCY code other than 0.
    static Result<quint16> parseFaultCode(const QString &text);

Q_SIGNALS:
    void answered(const QString &line);

private:
    QString motion() const;
    void checkStandstill();

    DemoDrive *m_demo;
    QTimer m_standstill; // polls the axis while a standstill answer is owed
    int m_standstillOwed = 0;
};

} // namespace db::app
