#pragma once

#include "deviceconsole.h"

namespace db::app {

class DemoDrive;

// The control lines of a running simulated MovingCap (drivebench-sim movingcap --control): the
// commands of every DeviceConsole, with T the drive's own clock and these details and commands:
//   state             -> "state T position P velocity V statusword 0xSSSS"
//   drop              -> every client of both doors aborted
//   fault CODE        -> the drive faults with this EMCY code (hex, e.g. 7121)
//   heartbeat off|on  -> "heartbeat off|on": the CANopen node stops/resumes its 1017h heartbeat
class SimConsole : public DeviceConsole
{
    Q_OBJECT
public:
    // demo must outlive the console.
    explicit SimConsole(DemoDrive *demo, QObject *parent = nullptr);

    // "7121", "0x7121" or "7121h": a 16-bit EMCY code other than 0.
    static Result<quint16> parseFaultCode(const QString &text);

protected:
    QString motion() const override;
    bool isMoving() const override;
    QString stateDetails() const override;
    int dropClients() override;
    Result<quint16> parseFault(const QString &text) const override { return parseFaultCode(text); }
    void injectFault(quint16 code) override;
    bool executeOwn(const QStringList &words) override;
    QString ownCommands() const override { return QStringLiteral("heartbeat off|on"); }

private:
    DemoDrive *m_demo;
};

} // namespace db::app
