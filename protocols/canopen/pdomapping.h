#pragma once

// PDO configuration as a value type (CiA 301 7.5.2.35-7.5.2.38) and the decoding of a received
// PDO into object values. Pure: no bus, no SDO (PdoClient reads and writes the configuration).
//
// Communication parameter (RPDO 1400h-15FFh, TPDO 1800h-19FFh): sub 1 COB-ID (bit 31 = not
// valid, bit 30 = no RTR, bit 29 = 29-bit id), sub 2 transmission type, sub 3 inhibit time
// (100 us), sub 5 event timer (ms). Mapping parameter (RPDO 1600h-17FFh, TPDO 1A00h-1BFFh):
// sub 0 = number of entries, sub n = index << 16 | sub << 8 | length in bits.

#include "core/objectdictionary.h"

#include <QList>
#include <QMetaType>

#include <optional>

namespace db::canopen {

enum class PdoDirection { Receive, Transmit };

struct PdoMappingEntry
{
    ObjectAddress address;
    quint8 bits = 0;

    static PdoMappingEntry fromRaw(quint32 raw);
    quint32 toRaw() const;
    // Indices 0001h-0007h are the dummy entries of CiA 301 (a gap of the type's size).
    bool isDummy() const { return address.index >= 1 && address.index <= 7; }
    friend bool operator==(const PdoMappingEntry &, const PdoMappingEntry &) = default;
};

struct PdoConfig
{
    static constexpr quint32 kInvalidBit = 0x80000000u; // COB-ID bit 31: PDO does not exist
    static constexpr quint32 kNoRtrBit = 0x40000000u;
    static constexpr quint32 kExtendedBit = 0x20000000u;
    static constexpr int kMaxPerDirection = 512;
    static constexpr int kMaxEntries = 64;
    // Transmission types (CiA 301 7.5.2.35): 1..kTypeSyncMax after every n-th SYNC; 0xFE
    // (manufacturer) and 0xFF (profile) event driven, with the event timer as the cycle.
    static constexpr quint8 kTypeSyncMax = 240;
    static constexpr quint8 kTypeEventManufacturer = 0xFE;
    static constexpr quint8 kTypeEventProfile = 0xFF;
    static constexpr bool isCyclicSyncType(quint32 type)
    {
        return type >= 1 && type <= kTypeSyncMax;
    }
    static constexpr bool isEventDrivenType(quint32 type)
    {
        return type == kTypeEventManufacturer || type == kTypeEventProfile;
    }

    PdoDirection direction = PdoDirection::Transmit;
    int number = 0; // 0-based: TPDO1 = 0 (1800h/1A00h)
    quint32 cobId = kInvalidBit;
    quint8 transmissionType = 0xFF;
    std::optional<quint16> inhibitTime; // absent when the device has no sub 3
    std::optional<quint16> eventTimer; // absent when the device has no sub 5
    QList<PdoMappingEntry> entries;

    bool isEnabled() const { return !(cobId & kInvalidBit); }
    bool isCyclicSync() const { return isCyclicSyncType(transmissionType); }
    bool isEventDriven() const { return isEventDrivenType(transmissionType); }
    quint32 canId() const { return cobId & (cobId & kExtendedBit ? 0x1FFFFFFFu : 0x7FFu); }
    quint16 communicationIndex() const;
    quint16 mappingIndex() const;
    int totalBits() const;
    QString name() const; // "TPDO1", "RPDO2"
    // "TPDO1 cob 0x185 enabled type 0xFF event 100 ms: 6041:0/16 6064:0/32"
    QString toString() const;
    friend bool operator==(const PdoConfig &, const PdoConfig &) = default;
};

struct PdoValue
{
    ObjectAddress address;
    QVariant raw; // by the dictionary's type; an unsigned qulonglong for unknown objects
};

// The object values a received PDO carries under `config`'s mapping (bits taken LSB first,
// CiA 301 7.2.2). Dummy entries are skipped. Malformed when the payload is shorter than the
// mapping.
Result<QList<PdoValue>> decodePdo(const PdoConfig &config, const QByteArray &payload,
                                  const ObjectDictionary &dictionary);

// The PDO whose COB-ID is `canId` among `configs` (enabled ones only); null when none.
const PdoConfig *pdoForCanId(const QList<PdoConfig> &configs, quint32 canId);

} // namespace db::canopen

Q_DECLARE_METATYPE(db::canopen::PdoConfig)
Q_DECLARE_METATYPE(QList<db::canopen::PdoConfig>)
