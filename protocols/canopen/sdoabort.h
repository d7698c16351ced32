#pragma once

#include <QString>

namespace db::canopen {

// SDO abort codes of CiA 301 table 22, with readable text. Used by the SDO client (to explain a
// device's abort) and by simulated SDO servers (to pick the right code).
namespace abort {
constexpr quint32 ToggleNotAlternated = 0x05030000;
constexpr quint32 Timeout = 0x05040000;
constexpr quint32 InvalidCommand = 0x05040001;
constexpr quint32 InvalidBlockSize = 0x05040002;
constexpr quint32 InvalidSequence = 0x05040003;
constexpr quint32 CrcError = 0x05040004;
constexpr quint32 OutOfMemory = 0x05040005;
constexpr quint32 UnsupportedAccess = 0x06010000;
constexpr quint32 WriteOnly = 0x06010001;
constexpr quint32 ReadOnly = 0x06010002;
constexpr quint32 NoSuchObject = 0x06020000;
constexpr quint32 NotMappable = 0x06040041;
constexpr quint32 PdoTooLong = 0x06040042;
constexpr quint32 Incompatible = 0x06040043;
constexpr quint32 InternalIncompatibility = 0x06040047;
constexpr quint32 HardwareError = 0x06060000;
constexpr quint32 LengthMismatch = 0x06070010;
constexpr quint32 LengthTooHigh = 0x06070012;
constexpr quint32 LengthTooLow = 0x06070013;
constexpr quint32 NoSuchSubIndex = 0x06090011;
constexpr quint32 InvalidValue = 0x06090030;
constexpr quint32 ValueTooHigh = 0x06090031;
constexpr quint32 ValueTooLow = 0x06090032;
constexpr quint32 MaxBelowMin = 0x06090036;
constexpr quint32 ResourceNotAvailable = 0x060A0023;
constexpr quint32 General = 0x08000000;
constexpr quint32 CannotStore = 0x08000020;
constexpr quint32 CannotStoreLocal = 0x08000021;
constexpr quint32 CannotStoreState = 0x08000022;
constexpr quint32 NoDictionary = 0x08000023;
constexpr quint32 NoData = 0x08000024;
} // namespace abort

// "Attempt to write a read only object" for 0x06010002; "unknown abort code 0x..." otherwise.
QString abortText(quint32 code);

} // namespace db::canopen
