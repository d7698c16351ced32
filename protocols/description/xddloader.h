#pragma once

#include "devicedescription.h"

namespace db {

// CiA 311 XML device descriptions (XDD) and configurations (XDC), read with QXmlStreamReader.
// Identity from the device profile's DeviceIdentity (vendorName, vendorID, productName,
// productID), falling back to the communication profile's identity; objects from
// CANopenObjectList (CANopenObject/CANopenSubObject: index/subIndex/dataType as hex, objectType,
// accessType, PDOmapping, defaultValue, lowLimit/highLimit, actualValue). Where an object gives
// a uniqueIDRef, the referenced ApplicationProcess parameter supplies what the object leaves out
// (name from its label, access, default/actual value, allowed range, enumerated values,
// description). Namespaces are ignored (real files misspell xmlns).
//
// Fails on XML that is not well formed (truncated files included), XML that is not an
// ISO 15745 profile, and profiles without a CANopenObjectList.
Result<DescriptionLoad> loadXdd(const QString &path, const DescriptionOptions &options = {});
Result<DescriptionLoad> parseXdd(const QByteArray &data, const QString &origin,
                                 const DescriptionOptions &options = {});

} // namespace db
