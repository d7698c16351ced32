#pragma once

#include "core/objectdictionary.h"

namespace db::resources {

// The device descriptions we wrote ourselves and compile into every binary.
// "movingcap_eth" -> resources/devices/movingcap_eth.json
Result<ObjectDictionary> builtinDescription(const QString &name);
QStringList builtinDescriptionNames();

// The MovingCap ETH dictionary (the RefGo connection's and the simulator's default).
const ObjectDictionary &movingCapDictionary();

} // namespace db::resources
