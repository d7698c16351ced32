#pragma once

#include "core/protocolregistry.h"

namespace db::app {

// Every protocol compiled into drivebench, registered in this one place (ARCHITECTURE.md).
// Connections come with their default device description (RefGo: MovingCap ETH).
const ProtocolRegistry &protocolRegistry();

} // namespace db::app
