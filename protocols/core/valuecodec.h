#pragma once

#include "datatype.h"
#include "result.h"

#include <QByteArray>
#include <QVariant>

namespace db {

// The one value codec for all CiA 301 basic types (ARCHITECTURE.md: "in one place").
//
// Raw values are QVariants of one canonical C++ type per DataType:
//   BOOLEAN -> bool; INTEGERn -> qlonglong; UNSIGNEDn -> qulonglong; REAL32/64 -> double;
//   VISIBLE_STRING, UNICODE_STRING -> QString; OCTET_STRING, DOMAIN -> QByteArray.
// Bytes are the CANopen wire encoding (CiA 301 7.1: little-endian, two's complement, IEEE 754;
// VISIBLE_STRING ISO 646, UNICODE_STRING UCS-2 little-endian).
// Physical = raw * factor + offset (the object's scaling).
namespace codec {

enum class TextFormat { Decimal, Hex };

// Smallest/largest raw value of an integer or real type (invalid QVariant for the others).
QVariant typeMinimum(DataType type);
QVariant typeMaximum(DataType type);

// Bring any numeric/string/bytes QVariant to the canonical raw type, refusing values that do not
// fit the type (OutOfRange) or cannot be converted (InvalidArgument).
Result<QVariant> normalize(DataType type, const QVariant &value);

// Raw -> bytes. Fixed-size types give exactly datatype::byteSize() bytes.
Result<QByteArray> encode(DataType type, const QVariant &raw);
// Bytes -> raw. Fixed-size types need exactly byteSize() bytes (Malformed otherwise); a
// VISIBLE_STRING stops at the first NUL, as CiA 301 allows.
Result<QVariant> decode(DataType type, const QByteArray &bytes);

// Text typed by a user or read from a file -> raw. Integers: decimal, "0x1F", "1Fh", "0b101",
// (hex and binary literals are bit patterns of the type: "0xFFFF" is -1 as INTEGER16),
// "-5"; booleans: 0/1/true/false/on/off; reals: "1.5", "-2e3"; strings as they are;
// OCTET_STRING/DOMAIN: hex bytes "01 02 ff" or "0102ff".
Result<QVariant> fromText(DataType type, const QString &text);
// Raw -> text. Hex pads integers to the type's width ("0x0427"); bytes as "01 02 FF".
QString toText(DataType type, const QVariant &raw, TextFormat format = TextFormat::Decimal);

// Limits given by an object description (either may be invalid = no limit).
Result<void> checkLimits(DataType type, const QVariant &raw, const QVariant &min,
                         const QVariant &max);

double toPhysical(const QVariant &raw, double factor, double offset);
// Physical -> raw, rounded to the nearest integer for integer types, range-checked.
Result<QVariant> fromPhysical(DataType type, double physical, double factor, double offset);

} // namespace codec
} // namespace db
