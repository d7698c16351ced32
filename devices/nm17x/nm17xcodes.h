#pragma once

// Status bits, display errors (Er 1 ... Er d) and emergency codes of the Baumer NM170/NM172/NM174
// spindle position displays: their names and texts, for the line panel, the CLI and the CAN
// monitor. Pure tables; no state.

#include <QList>
#include <QString>

namespace db::nm17x {

// 204Eh:01 device status (NM172/NM174; 1002h carries the same flags, NM170 only bit 12).
namespace status {
constexpr quint16 Moving = 1u << 0;
constexpr quint16 ManualAbort = 1u << 1;
constexpr quint16 Oscillating = 1u << 2;
constexpr quint16 Takten = 1u << 3;
constexpr quint16 ExternPosi = 1u << 4;
constexpr quint16 LeftKey = 1u << 5;
constexpr quint16 RightKey = 1u << 6;
// Bits 8..9: speed outputs, bit 8 = IN4, bit 9 = IN3; bits 10..11: direction outputs,
// bit 10 = IN2 (right), bit 11 = IN1 (left) (the order the device lists them, LSB first).
constexpr quint16 In4 = 1u << 8;
constexpr quint16 In3 = 1u << 9;
constexpr quint16 In2Right = 1u << 10;
constexpr quint16 In1Left = 1u << 11;
constexpr quint16 ArrowsActive = 1u << 12;
constexpr quint16 Error = 1u << 14;
constexpr quint16 InPosition = 1u << 15;
} // namespace status

struct BitText
{
    int bit;
    QString name; // in the language the program speaks
    QString english = {}; // the name in English (files, descriptions)
};

// One display error of 204Eh:02.
struct DisplayError
{
    int bit; // in 204Eh:02
    QString code; // "Er 1" ... "Er d"
    QString text; // what happened
    QString remedy; // what the operator does about it
    QString englishText = {}; // text in English (files, descriptions)
};

// The named bits of 204Eh:01 (reserved bits left out).
QList<BitText> statusBits();
// Every display error, in bit order.
QList<DisplayError> displayErrors();
// The errors set in an error word (204Eh:02), highest display priority first
// (Er C, Er d, Er 4, Er 1, Er 2, Er 3, Er 5, Er 6, Er 8, Er 9, Er A, Er b).
QList<DisplayError> activeErrors(quint16 errors);
// "Moving, In Position" for a status word; "-" when no named bit is set.
QString statusText(quint16 status);
// "Er 8 (setpoint above end limit MAX), Er b (...)"; empty when none.
QString errorText(quint16 errors);

// An emergency code of the device, with the sub-code it comes with (byte 7 of the EMCY frame).
struct EmcyCode
{
    quint16 code;
    quint8 subCode;
    QString text;
};
QList<EmcyCode> emcyCodes();
// The text for code + sub-code; the code's first text when the sub-code is unknown; empty when
// the code is not one of the device's.
QString emcyText(quint16 code, quint8 subCode);

} // namespace db::nm17x
