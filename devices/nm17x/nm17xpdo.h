#pragma once

// The process data of the NM170/NM172/NM174 displays, as pure codecs (all PDOs are 8 bytes,
// little-endian):
//   RxPDO1 (broadcast SDO channel, COB-ID 201h on every device): control u8, index u16, sub u8,
//          data u32 (mirrored into 2500h:01..04)
//   RxPDO2 (300h + node): setpoint i32, correction i16 (-32768 = keep 2010h), control word u16
//   TxPDO1 (180h + node): position i32 (6004h), status u16 (204Eh:01), errors u16 (204Eh:02)
//   TxPDO2 (280h + node): position i32, correction i16 (2501h:04), status u16
// and the RxPDO2 control words: the device accepts only 22 combinations and answers anything
// else with EMCY 8230h, so the master builds control words only through controlWord() and checks
// raw ones with classify() before they leave.

#include "core/result.h"

#include <QByteArray>
#include <QString>

#include <optional>

namespace db::nm17x {

constexpr quint32 kBroadcastCobId = 0x201; // RxPDO1 of every display, whatever its node id
constexpr qint16 kKeepCorrection = -32768; // RxPDO2: leave 2010h as it is (32-bit correction)
constexpr qint32 kMinPosition = -99999; // 1/100 mm
constexpr qint32 kMaxPosition = 999999;

// ---- RxPDO1: broadcast ----
struct Broadcast
{
    quint8 control = 0; // reserved, ignored by the device
    quint16 index = 0;
    quint8 subIndex = 0;
    quint32 data = 0;
    friend bool operator==(const Broadcast &, const Broadcast &) = default;
};
QByteArray encodeBroadcast(const Broadcast &b);
Result<Broadcast> decodeBroadcast(const QByteArray &payload);
// The objects the displays take by broadcast: 2001h:0 (unit), 2008h:0 (show node id), 204Dh:01
// (start group / stop), 204Dh:02 (oscillation), 2015h:0 (reset functions), 6003h:0 (preset).
bool isBroadcastObject(quint16 index, quint8 subIndex);

// ---- RxPDO2: positioning command ----
struct PositionCommand
{
    qint32 setpoint = 0; // 1/100 mm
    qint16 correction = 0; // 1/100 mm; kKeepCorrection keeps 2010h
    quint16 control = 0;
    friend bool operator==(const PositionCommand &, const PositionCommand &) = default;
};
QByteArray encodePositionCommand(const PositionCommand &c);
Result<PositionCommand> decodePositionCommand(const QByteArray &payload);

// ---- TxPDO1 / TxPDO2 ----
struct Tpdo1
{
    qint32 position = 0;
    quint16 status = 0;
    quint16 errors = 0;
};
struct Tpdo2
{
    qint32 position = 0;
    qint16 correction = 0;
    quint16 status = 0;
};
Result<Tpdo1> decodeTpdo1(const QByteArray &payload);
Result<Tpdo2> decodeTpdo2(const QByteArray &payload);
QByteArray encodeTpdo1(const Tpdo1 &t); // device side
QByteArray encodeTpdo2(const Tpdo2 &t);

// ---- control words ----
enum class Command {
    None, // 0000h: the device ignores the PDO
    WriteD3, // setpoint -> D3 (2045h:03) + correction
    Reserved, // 0041h / 0061h: accepted by the device, no documented function
    SetpointDirect, // SEF: with release, no loop (2020h:05)
    Setpoint, // standard, without release (2020h:01)
    SetpointRelease, // standard, with release (2020h:02)
    Einsaegen, // plunge-cut setpoint without release (2020h:06) at a speed
    EinsaegenRelease, // with release (2020h:07)
    JogRight, // Tippen right (counting up) until stop or limit
    JogLeft,
    ClampOpen,
    ClampClose,
    Stop, // bit 14; always executed, whatever else is set
};
enum class Speed { Slow = 1, Medium = 2, Fast = 3 }; // control bits 3..4

namespace control {
constexpr quint16 Enable = 1u << 0;
constexpr quint16 Release = 1u << 1;
constexpr quint16 NoLoop = 1u << 2;
constexpr int SpeedShift = 3;
constexpr quint16 WriteD3 = 1u << 5;
constexpr quint16 JogRight = 1u << 7;
constexpr quint16 JogLeft = 1u << 8;
constexpr quint16 Clamp = 1u << 9;
constexpr quint16 Stop = 1u << 14;
constexpr quint16 Toggle = 1u << 15; // ignored by the device; lets a master resend a frame
} // namespace control

// The control word for a command. Speed is required for Einsaegen and jogs and refused for
// every other command (InvalidArgument naming the command).
Result<quint16> controlWord(Command command, std::optional<Speed> speed = {});

// What the device makes of a raw control word: its command and speed, or InvalidArgument
// ("control word 0x0005 is not an allowed combination ...") for the words the device answers
// with EMCY 8230h. Bits 10..13 and the toggle bit 15 are ignored, as the device does.
struct Classified
{
    Command command = Command::None;
    std::optional<Speed> speed;
};
Result<Classified> classify(quint16 word);

QString commandName(Command command);
QString speedName(Speed speed); // "slow", "medium", "fast"
std::optional<Speed> parseSpeed(const QString &text);

} // namespace db::nm17x
