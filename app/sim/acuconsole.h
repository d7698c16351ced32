#pragma once

#include "core/result.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

namespace db::bonfiglioli {
class SimulatedAcu;
}

namespace db::app {

// Control lines for a running simulated ACTIVE Cube (drivebench-sim acu --control): inputs,
// faults and observations for end-to-end tests and demos, like the MovingCap's console. One
// command per line; every command answers exactly one line through answered() (standstill
// possibly later). T is the simulator's clock in ms since it started, so that times measured
// through the console do not include pipe or test latency.
//   state              -> "state T position P velocity V statusword 0xSSSS mode M fault 0xFFFF"
//   standstill         -> "standstill T position P" as soon as the motor stands (at once if it
//                         does)
//   drop               -> "dropped N T position P velocity V": the PLC connection aborted (a cut
//                         cable; N = 1, or 0 without one); the port keeps listening
//   fault CODE         -> "fault CODE": the inverter faults with this code (hex as 260 shows
//                         it, e.g. 2714 for F2714)
//   mains on|off       -> "mains on|off": the simulated mains voltage (status bit 4)
//   sto on|off         -> "sto on|off": the simulated STO hardware enable
//   master SPEED       -> "master SPEED": the electronic gear's master speed in u/s
//   watchdog MS        -> "watchdog MS": the link watchdog's time from now on (as --watchdog-ms)
//   anything else      -> "error: ..." naming the cause
class AcuConsole : public QObject
{
    Q_OBJECT
public:
    // acu must outlive the console.
    explicit AcuConsole(bonfiglioli::SimulatedAcu *acu, QObject *parent = nullptr);

    void execute(const QString &line);

    // "2714", "0x2714" or "F2714": a 16-bit fault code other than 0, in hex.
    static Result<quint16> parseFaultCode(const QString &text);

Q_SIGNALS:
    void answered(const QString &line);

private:
    QString motion() const;
    void checkStandstill();

    bonfiglioli::SimulatedAcu *m_acu;
    QElapsedTimer m_clock;
    QTimer m_standstill; // polls the motor while a standstill answer is owed
    int m_standstillOwed = 0;
};

} // namespace db::app
