#pragma once

#include "core/result.h"

#include <QString>
#include <QStringList>

#include <memory>

namespace db::gui {

// The devices of `drivebench --demo`: the simulated MovingCap with its RefGo and SLCAN doors, an
// ACTIVE Cube inverter over VABus/TCP and a line of three NM17x displays, all on 127.0.0.1 and
// all in one thread of their own (named "demo devices"). Their real-time clocks and their side
// of every exchange then never delay the window, and their CPU time is counted apart from the
// program's (per thread in /proc/PID/task), as it would be for devices on a real bus.
class DemoSimulators
{
public:
    struct Started
    {
        QString acuUri; // empty when the inverter could not start
        QString refgoUri;
        QString slcanUri; // empty when the CANopen door could not start
        quint16 nm17xPort = 0; // SLCAN port of the displays; 0 when they could not start
        QStringList warnings; // what could not start, one sentence each
    };

    DemoSimulators();
    // Stops the devices in their thread and ends it; connections to them see a closed link.
    ~DemoSimulators();
    DemoSimulators(const DemoSimulators &) = delete;
    DemoSimulators &operator=(const DemoSimulators &) = delete;

    // Builds and starts the devices (returns when they listen). Fails only when the MovingCap's
    // RefGo door cannot listen; the other devices are then not started either.
    Result<Started> start();
    bool isRunning() const;
    // The URIs start() returned.
    const Started &uris() const;

private:
    struct Private;
    std::unique_ptr<Private> d;
};

} // namespace db::gui
