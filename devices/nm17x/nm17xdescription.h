#pragma once

// Our own descriptions of the Baumer NM170, NM172 and NM174 spindle position displays (CANopen,
// vendor 000000ECh): one object dictionary per variant, chosen from the identity (1018h:01/02).
// Positions and lengths are in 1/100 mm on the bus, also when the display shows inch.

#include "canopen/canopenids.h"
#include "core/objectdictionary.h"

#include <optional>

namespace db::nm17x {

enum class Variant { Nm170, Nm172, Nm174 };

constexpr quint32 kVendorId = 0x000000EC;
constexpr quint32 kDeviceType = 0x00020196;
constexpr canopen::NodeId kDeliveryNodeId = 127;
constexpr int kDeliveryBitrate = 125000;

quint32 productCode(Variant v); // 70h, 71h, 72h
QString variantName(Variant v); // "NM172"
QString deviceName(Variant v); // 1008h: "NM172 Standard"
quint32 mspDeviceType(Variant v); // 2006h:02: 8081h, 8281h, 8481h
bool hasMotor(Variant v); // NM172 and NM174
// The variant of a device with this identity; nullopt for any other device.
std::optional<Variant> variantOf(quint32 vendorId, quint32 productCode);
std::optional<Variant> parseVariant(const QString &text); // "nm172", "NM174"

// The objects of one variant; defaults that follow the node id (1014h, 1401h:01, 1800h:01,
// 1801h:01) are those of `node`. Holds the emergency codes with their texts.
ObjectDictionary dictionary(Variant v, canopen::NodeId node = kDeliveryNodeId);

// Storage class of an object: how a write persists.
enum class Storage { None, Ram, Eeprom, Flash };
Storage storageOf(ObjectAddress address);

} // namespace db::nm17x
