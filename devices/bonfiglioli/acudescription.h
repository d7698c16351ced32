#pragma once

// The ACTIVE Cube ACU parameters reachable over VABus/TCP, as NUMBER:DATASET objects: type,
// decimals, unit, data sets (0-4 for four-data-set parameters, 0 for single ones), access,
// limits, selections, status/control word bits, and the fault codes of parameter 260.

#include "core/objectdictionary.h"

namespace db::bonfiglioli {

// Compiled in (acu.json); a load failure is a build defect and gives an empty dictionary.
const ObjectDictionary &acuDictionary();
// The same, with the loader's error (for tests).
Result<ObjectDictionary> loadAcuDictionary();

// True when the parameter has four data sets (described at data sets 1-4).
bool hasDataSets(const ObjectDictionary &dictionary, quint16 parameter);

} // namespace db::bonfiglioli
