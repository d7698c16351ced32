#pragma once

#include "core/objectaddress.h"
#include "core/result.h"

#include <QHash>
#include <QObject>
#include <QVariant>

#include <memory>

namespace db::sim {
class MovingCapDrive;
}

namespace db::app {

// The built-in simulated MovingCap for `drivebench --demo`, `drivebench-sim` and tests: a
// simulated drive with its RefGo door and its SLCAN door (CANopen node 50, movingcap.md 4) on
// 127.0.0.1; both doors serve the same drive object.
class DemoDrive : public QObject
{
    Q_OBJECT
public:
    // initialValues: raw values that differ from the simulator's factory settings.
    explicit DemoDrive(const QHash<ObjectAddress, QVariant> &initialValues = {},
                       QObject *parent = nullptr);
    ~DemoDrive() override;

    // Listens on 127.0.0.1:port (0 = chosen by the OS).
    Result<void> startRefgo(quint16 port = 0);
    quint16 refgoPort() const;
    // "refgo://127.0.0.1:PORT"
    QString refgoUri() const;

    // SLCAN over TCP on 127.0.0.1:port (0 = chosen by the OS), CANopen node 50.
    Result<void> startSlcan(quint16 port = 0);
    quint16 slcanPort() const;
    // "canopen+slcan://127.0.0.1:PORT?node=50"
    QString slcanUri() const;

    sim::MovingCapDrive &drive();

    // ---- failure modes (drivebench-sim --control, tests) ----
    // Aborts every client of both doors and keeps listening (a cut cable); returns how many.
    int dropClients();
    // The CANopen node stops (true) or resumes (false) producing its 1017h heartbeat.
    void setHeartbeatSilenced(bool on);
    // While on, both doors keep their links up and answer nothing (a hung drive): RefGo
    // requests and CAN frames are dropped, and the CANopen node sends nothing.
    void setSilent(bool on);

private:
    struct Private;
    std::unique_ptr<Private> d;
};

} // namespace db::app
