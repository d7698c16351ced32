#pragma once

// VABus/TCP telegrams (Bonfiglioli CM-VABus/TCP manual, chapter 7): pure encode/decode, no
// socket, no request state.
//
// Layout (7.1.2, 7.1.3), multi-byte numbers little-endian:
//   byte 0  header: bit 7 R/W (0 enquiry, 1 select), bit 6 E (error), bits 5..0 zero
//   byte 1  NoB: number of bytes that follow (SYS, DS, P.-No. and the data), so a telegram is
//           NoB + 2 bytes long
//   byte 2  SYS: system bus node (0x00 the inverter itself, 0x40 + id a system bus slave)
//   byte 3  DS: data set, 0-4 (EEPROM), 5-9 the RAM copies of 0-4 (writes only)
//   byte 4,5 parameter number 0-1599
//   byte 6.. data: uInt/Int 2 bytes, Long 4 bytes, a string 1-99 characters without terminator;
//           in an error answer (E = 1, NoB = 6) the error code, 2 bytes.
// The binary telegram carries no checksum and no type: the parameter's type and decimals come
// from its description.

#include "core/datatype.h"
#include "core/result.h"

#include <QByteArray>
#include <QString>
#include <QVariant>

namespace db::vabus {

constexpr quint8 kRwBit = 0x80;
constexpr quint8 kErrorBit = 0x40;
constexpr int kAddressBytes = 4; // SYS, DS, P.-No. (counted in NoB)
constexpr int kMinTelegramBytes = 2 + kAddressBytes;
constexpr int kMaxDataBytes = 99;
constexpr int kMaxNob = kAddressBytes + kMaxDataBytes;
constexpr int kMaxTelegramBytes = 2 + kMaxNob;
constexpr quint16 kMaxParameter = 1599;
constexpr quint8 kMaxReadDataSet = 4;
constexpr quint8 kMaxWriteDataSet = 9;
constexpr quint8 kRamDataSetOffset = 5; // DS n is written to RAM as DS n + 5 (8.1)
constexpr quint8 kNak = 0x15; // serial VABus's negative acknowledge, tolerated on TCP
constexpr quint8 kSlaveSysBase = 0x40; // SYS of system bus slave id = 0x40 + id (7.1.4)

// Error codes of an E = 1 answer (7.2). 10 and 12 are "not available"; 13 and 30 both mean a
// syntax error.
enum ErrorCode : quint16 {
    NoError = 0,
    InvalidValue = 1,
    InvalidDataSet = 2,
    NotReadable = 3,
    NotWritable = 4,
    EepromReadError = 5,
    EepromWriteError = 6,
    EepromChecksumError = 7,
    NotWritableWhileRunning = 8,
    DataSetsDiffer = 9,
    UnknownParameter = 11,
    SyntaxError = 13,
    LengthMismatch = 14,
    UnknownError = 15,
    NodeNotAvailable = 20,
    SyntaxError2 = 30,
};

// The English text of an error code ("invalid parameter value"), translatable.
QString errorText(quint16 code);

// One telegram, request or answer.
struct Telegram
{
    bool write = false; // R/W bit: select (write) telegram or its answer
    bool error = false; // E bit: error answer, data holds the 2-byte code
    quint8 sys = 0;
    quint8 dataSet = 0;
    quint16 parameter = 0;
    QByteArray data;

    // The code of an error answer (0 when data is not 2 bytes).
    quint16 errorCode() const;

    static Telegram readRequest(quint16 parameter, quint8 dataSet, quint8 sys = 0);
    static Telegram writeRequest(quint16 parameter, quint8 dataSet, const QByteArray &data,
                                 quint8 sys = 0);
    // The error answer to request: its R/W bit, SYS, DS and parameter, E = 1, the code.
    static Telegram errorAnswer(const Telegram &request, quint16 code);

    friend bool operator==(const Telegram &, const Telegram &) = default;
};

// Telegram -> bytes. InvalidArgument for more than 99 data bytes, an error telegram without a
// 2-byte code, or a parameter number above 1599.
Result<QByteArray> encode(const Telegram &telegram);
// Exactly one telegram -> Telegram. Malformed for a short frame, NoB that does not match the
// length, header bits 5..0 set, or an error answer whose NoB is not 6.
Result<Telegram> decode(const QByteArray &bytes);

// The VABus type a CiA 301 type is carried as: UNSIGNED16 (uInt), INTEGER16 (Int), INTEGER32
// (Long) and VISIBLE_STRING (String). Other integer types are sent with their own width only if
// it is 2 or 4 bytes.
bool isCarried(DataType type);
// Raw value (codec's canonical type) -> data bytes: 2 bytes for 16-bit, 4 for 32-bit types,
// the characters of a string (at most 99, Latin-1). Errors name the cause.
Result<QByteArray> encodeValue(DataType type, const QVariant &raw);
// Data bytes -> raw value. Fixed-size types need their exact size (Malformed otherwise).
Result<QVariant> decodeValue(DataType type, const QByteArray &data);
// The type a value of unknown description is read as, from its size: 2 bytes INTEGER16,
// 4 bytes INTEGER32, anything else VISIBLE_STRING.
DataType typeForSize(qsizetype bytes);

// "E8 03 00 00", for logs.
QString hex(const QByteArray &bytes);

} // namespace db::vabus
