#pragma once

#include <QString>

namespace db {
class ChangeLog;
}

namespace db::motion {

class MotionAxis;

// Records every command started on `axis` in `log` as a change of `device` (enable, disable,
// fault reset, motion), one entry from the command's start to its end: done, aborted by
// another command, refused or failed with the cause. A command restarted while it still runs
// (a jog's lease renewal, a new target) continues its entry. Stops recording when the axis or
// the log goes away.
void recordCommands(MotionAxis *axis, ChangeLog *log, const QString &device);

} // namespace db::motion
