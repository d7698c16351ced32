#pragma once

// CiA 301 7.5.2.13/14: storing parameters permanently and restoring the factory defaults by
// writing a signature (ASCII, little-endian) to sub-index 1 of 1010h ("save") or 1011h ("load").
// Every CiA 301 device does it this way, whatever carries the write (SDO, or the MovingCap's
// RefGo OW command).

#include "core/objectaddress.h"

namespace db::canopen::store {

constexpr quint32 kSaveSignature = 0x65766173; // "save" (MovingCap: OW1010,1,1702257011)
constexpr quint32 kLoadSignature = 0x64616F6C; // "load"
constexpr ObjectAddress kStoreAll { 0x1010, 1 };
constexpr ObjectAddress kRestoreDefaultsAll { 0x1011, 1 };

} // namespace db::canopen::store
