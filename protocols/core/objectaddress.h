#pragma once

#include "result.h"

#include <QHashFunctions>
#include <QMetaType>
#include <QString>

namespace db {

// Where an object lives. For CANopen and RefGo: index and sub-index. For VABus: parameter number
// (index) and data set (sub).
struct ObjectAddress
{
    quint16 index = 0;
    quint8 sub = 0;

    constexpr ObjectAddress() = default;
    constexpr ObjectAddress(quint16 i, quint8 s)
        : index(i)
        , sub(s)
    { }

    // "6041:0": index as 4 hex digits, sub-index in hex without padding (the CLI's form).
    QString toString() const;

    // Accepts "6041:0", "6041:00", "0x6041:0x00", "6041h.00h", "6041.0", "6041sub0" and
    // "6041" (sub-index 0). Index and sub-index are hexadecimal.
    static Result<ObjectAddress> parse(const QString &text);

    constexpr quint32 key() const { return (quint32(index) << 8) | sub; }
    friend constexpr bool operator==(ObjectAddress a, ObjectAddress b)
    {
        return a.key() == b.key();
    }
    friend constexpr auto operator<=>(ObjectAddress a, ObjectAddress b)
    {
        return a.key() <=> b.key();
    }
};

inline size_t qHash(ObjectAddress a, size_t seed = 0)
{
    return ::qHash(a.key(), seed);
}

} // namespace db

Q_DECLARE_METATYPE(db::ObjectAddress)
