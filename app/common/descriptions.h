#pragma once

#include "description/descriptionlibrary.h"

namespace db::app {

// The description library of this process: our NM170/NM172/NM174 and MovingCap ETH descriptions
// plus the user's folder (descriptionFolder()). Generic CANopen connections without ?eds= take
// their description from it by the node's identity (1018h).
DescriptionLibrary &descriptionLibrary();

// The user's folder of EDS/DCF/XDD/XDC/JSON files: $DRIVEBENCH_DESCRIPTIONS, else the setting
// "descriptions/folder", else drivebench/descriptions in the user's data folder
// (~/.local/share). It may not exist
// yet.
QString descriptionFolder();

} // namespace db::app
