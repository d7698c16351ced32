#pragma once

// The one place that decides which AxisInterface drives the device behind a connection, with
// that device family's quirks applied: a CiA 402 axis for CANopen and RefGo drives (MovingCap's
// rotary accelerations in devices/movingcap), the ACTIVE Cube axis (state machine 410/411 and
// motion control override) for vabus://. Widgets and the CLI never build an axis themselves.

#include "core/deviceconnection.h"
#include "core/result.h"
#include "motion/axisinterface.h"

#include <memory>

namespace db::devices {

// A new axis on `connection` (not owned; it must outlive the axis), not yet initialised: call
// AxisInterface::initialize() before the first command. Fails with NotSupported and a sentence
// naming the reason when the device has no axis.
Result<std::unique_ptr<motion::AxisInterface>> makeAxis(DeviceConnection *connection);

} // namespace db::devices
