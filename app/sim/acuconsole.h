#pragma once

#include "common/deviceconsole.h"

#include <QElapsedTimer>

namespace db::bonfiglioli {
class SimulatedAcu;
}

namespace db::app {

// The control lines of a running simulated ACTIVE Cube (drivebench-sim acu --control): the
// commands of every DeviceConsole, with T the simulator's clock in ms since it started, and
// these details and commands:
//   state              -> "state T position P velocity V statusword 0xSSSS mode M fault 0xFFFF"
//   drop               -> the PLC connection aborted (N = 1, or 0 without one)
//   fault CODE         -> the inverter faults with this code (hex as 260 shows it, e.g. 2714 for
//                         F2714)
//   mains on|off       -> "mains on|off": the simulated mains voltage (status bit 4)
//   sto on|off         -> "sto on|off": the simulated STO hardware enable
//   master SPEED       -> "master SPEED": the electronic gear's master speed in u/s
//   watchdog MS        -> "watchdog MS": the link watchdog's time from now on (as --watchdog-ms)
class AcuConsole : public DeviceConsole
{
    Q_OBJECT
public:
    // acu must outlive the console.
    explicit AcuConsole(bonfiglioli::SimulatedAcu *acu, QObject *parent = nullptr);

    // "2714", "0x2714" or "F2714": a 16-bit fault code other than 0, in hex.
    static Result<quint16> parseFaultCode(const QString &text);

protected:
    QString motion() const override;
    bool isMoving() const override;
    QString stateDetails() const override;
    int dropClients() override;
    Result<quint16> parseFault(const QString &text) const override { return parseFaultCode(text); }
    void injectFault(quint16 code) override;
    bool executeOwn(const QStringList &words) override;
    QString ownCommands() const override
    {
        return QStringLiteral("mains on|off, sto on|off, master SPEED, watchdog MS");
    }

private:
    bonfiglioli::SimulatedAcu *m_acu;
    QElapsedTimer m_clock;
};

} // namespace db::app
