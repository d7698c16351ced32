#pragma once

#include <QMetaType>
#include <QString>

#include <optional>

namespace db {

// CiA 301 basic data types, numbered as in CiA 301 table 44 (object dictionary indices
// 0001h-001Bh).
enum class DataType : quint16 {
    Boolean = 0x01,
    Integer8 = 0x02,
    Integer16 = 0x03,
    Integer32 = 0x04,
    Unsigned8 = 0x05,
    Unsigned16 = 0x06,
    Unsigned32 = 0x07,
    Real32 = 0x08,
    VisibleString = 0x09,
    OctetString = 0x0A,
    UnicodeString = 0x0B,
    Domain = 0x0F,
    Integer24 = 0x10,
    Real64 = 0x11,
    Integer40 = 0x12,
    Integer48 = 0x13,
    Integer56 = 0x14,
    Integer64 = 0x15,
    Unsigned24 = 0x16,
    Unsigned40 = 0x18,
    Unsigned48 = 0x19,
    Unsigned56 = 0x1A,
    Unsigned64 = 0x1B,
};

namespace datatype {

// Every basic type, in CiA 301 order (for tests and type pickers).
const QList<DataType> &all();

// Size on the wire in bytes; 0 for the variable-length types (strings, domain).
int byteSize(DataType type);
bool isSignedInteger(DataType type);
bool isUnsignedInteger(DataType type);
inline bool isInteger(DataType type)
{
    return isSignedInteger(type) || isUnsignedInteger(type);
}
bool isReal(DataType type);
bool isNumeric(DataType type); // integer, real or boolean
bool isVariableLength(DataType type);

// "UNSIGNED16", as CiA 301 and EDS files write it.
QString name(DataType type);
// Accepts "UNSIGNED16", "unsigned16", "uint16", "u16", "0x0006" and the other usual spellings.
std::optional<DataType> fromName(const QString &text);
std::optional<DataType> fromCode(quint32 code);

} // namespace datatype
} // namespace db

Q_DECLARE_METATYPE(db::DataType)
