#pragma once

// CiA 305 Layer Setting Services: identifiers shared by the master (LssMaster) and the slave of
// the simulated nodes (LssSlave). Requests on 7E5h, responses on 7E4h; byte 0 is the command
// specifier (cs), 32-bit values are little-endian in bytes 1..4 (nm170_canopen.md 2.3).

#include <QMetaType>
#include <QString>

namespace db::canopen {

enum class LssMode : quint8 {
    Waiting = 0, // "operation mode" in the NM170 manual
    Configuration = 1,
};

// The LSS address: the four entries of 1018h.
struct LssAddress
{
    quint32 vendorId = 0;
    quint32 productCode = 0;
    quint32 revision = 0;
    quint32 serial = 0;

    quint32 part(int i) const;
    // "vendor 0x000000EC product 0x00000071 revision 0x00010001 serial 0x4D52F567"
    QString toString() const;
    friend bool operator==(const LssAddress &, const LssAddress &) = default;
};

namespace lss {
constexpr quint8 SwitchGlobal = 0x04;
constexpr quint8 ConfigureNodeId = 0x11;
constexpr quint8 ConfigureBitTiming = 0x13;
constexpr quint8 ActivateBitTiming = 0x15;
constexpr quint8 StoreConfiguration = 0x17;
constexpr quint8 SelectVendor = 0x40; // 40h..43h: vendor, product, revision, serial
constexpr quint8 SelectSerial = 0x43;
constexpr quint8 SelectiveAnswer = 0x44;
constexpr quint8 FastscanAnswer = 0x4F;
constexpr quint8 Fastscan = 0x51;
constexpr quint8 InquireVendor = 0x5A; // 5Ah..5Dh: vendor, product, revision, serial
constexpr quint8 InquireSerial = 0x5D;
constexpr quint8 InquireNodeId = 0x5E;
constexpr quint8 kFastscanReset = 0x80; // BitChecked value that starts a fastscan
constexpr quint8 kUnconfigured = 0xFF; // node id of an LSS slave without one

// Index in the CiA 305 standard bit timing table (TableSel 0) for a bit rate in bit/s; -1 when
// the table has none. 0 = 1000 kbit/s ... 8 = 10 kbit/s (nm170_canopen.md 2.3).
int bitTimingIndex(int bitrate);
int bitrateOfIndex(int index); // -1 when out of 0..8
} // namespace lss

} // namespace db::canopen

Q_DECLARE_METATYPE(db::canopen::LssAddress)
