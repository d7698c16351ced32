#pragma once

#include "core/result.h"

#include <QObject>

#include <memory>

namespace db::sim {
class MovingCapDrive;
}

namespace db::app {

// The built-in simulated MovingCap for `drivebench --demo`, `drivebench-sim` and tests: a
// simulated drive with its RefGo door on 127.0.0.1 (later issues add its SLCAN door).
class DemoDrive : public QObject
{
    Q_OBJECT
public:
    explicit DemoDrive(QObject *parent = nullptr);
    ~DemoDrive() override;

    // Listens on 127.0.0.1:port (0 = chosen by the OS).
    Result<void> startRefgo(quint16 port = 0);
    quint16 refgoPort() const;
    // "refgo://127.0.0.1:PORT"
    QString refgoUri() const;

    sim::MovingCapDrive &drive();

private:
    struct Private;
    std::unique_ptr<Private> d;
};

} // namespace db::app
