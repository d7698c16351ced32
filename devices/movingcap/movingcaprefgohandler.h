#pragma once

#include "refgo/device/refgoserver.h"

namespace db::sim {
class MovingCapDrive;
}

namespace db::refgo {

// Answers RefGo requests from a simulated MovingCap drive with the result lines of
// movingcap.md 3.3, 3.6 and 3.8 (without CR LF; the Server adds echo, CR LF and the prompt).
// Failures give one "ERROR <reason>" line (not authentic: the manual documents none, spec 3.7).
// The drive must outlive the handler; handle() runs synchronously on the caller's thread.
class MovingCapRefgoHandler : public DeviceHandler
{
public:
    explicit MovingCapRefgoHandler(sim::MovingCapDrive *drive);

    QStringList handle(const Request &request) override;

private:
    QStringList readObject(const Request &request);
    QStringList writeObject(const Request &request);

    sim::MovingCapDrive *m_drive;
};

} // namespace db::refgo
