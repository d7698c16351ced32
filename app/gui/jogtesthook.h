#pragma once

// A hook for end-to-end tests that kill the GUI mid-jog: with the environment variable
// DRIVEBENCH_TEST_HOLD_JOG="VELOCITY[,RAMP]" (signed velocity in the drive's units/s, ramp in
// units/s^2), once the current connection's axis has read its limits and its first status, the
// hook clicks Enable unless the drive is enabled already, fills the jog velocity and ramp fields
// and presses (never releases) Jog + or Jog − with a mouse event, as a user holding the button
// would. It writes one line to standard error when it presses. Without the variable it does
// nothing; a malformed value is reported and ignored.

namespace db::gui {

class MainWindow;

void holdJogFromEnvironment(MainWindow &window);

} // namespace db::gui
