#pragma once

// Shared by the motion commands' files (commands_motion.cpp, commands_gear.cpp): one axis per
// command and the waits around it.

#include "canopen/drivesupervision.h"
#include "clisession.h"
#include "commands_motion.h"
#include "motion/motionaxis.h"

#include <functional>
#include <memory>

namespace db::cli::motioncmd {

// One axis for one command: the session, the device's axis (from the axis factory) and the
// command model on it.
struct Axis
{
    explicit Axis(Context &c)
        : session(c.registry, c.options)
    { }
    Session session;
    std::unique_ptr<motion::AxisInterface> cia;
    std::unique_ptr<motion::MotionAxis> model;
    int waitMs = kDefaultWaitMs;
};

// Gives the drive its previous supervision settings back when the command ends normally (on
// every return path); a killed process never gets here, and the drive then reacts.
struct RestoreSupervision
{
    canopen::DriveSupervision *supervision;
    Context &c;
    ~RestoreSupervision();
};

// Runs the event loop until done() or timeoutMs; keeps the deadman watchdog fed meanwhile.
bool waitUntil(Axis &axis, const std::function<bool()> &done, int timeoutMs);
// Arms the drive's own watch of this process where the connection offers one; null otherwise.
std::unique_ptr<canopen::DriveSupervision> superviseDrive(Context &c, Axis &axis);
// The number given with --option; InvalidArgument naming it otherwise.
Result<double> number(Context &c, const QString &option);
// Opens the connection, reads the scaling and limits and waits for the drive's status.
Result<std::unique_ptr<Axis>> openAxis(Context &c);
// Starts the command, waits for its end and reports it; 0 (ExitOk) when it is Done.
int runToEnd(Context &c, Axis &axis, motion::MotionCommand &command);
// Prints the actual position read after the end.
void printPosition(Context &c, Axis &axis);

} // namespace db::cli::motioncmd
