#pragma once

#include <QByteArray>
#include <QtGlobal>

namespace db::sim {

// MovingCap error codes (movingcap.md 7.1) with their 1002h bit (7.2, matched by name) and the
// error register byte the manual's CAN monitor shows as EMCY byte 2.
struct MovingCapFault
{
    quint16 code = 0;
    int statusBit = -1; // 1002h bit, -1 = none
    quint8 errorRegister = 0x01;
    bool needsPowerCycle = false; // FFF5h
};

namespace faults {
constexpr quint16 OverCurrent = 0x2220;
constexpr quint16 OverVoltage = 0x3211;
constexpr quint16 UnderVoltage = 0x3221;
constexpr quint16 OverTemperature = 0x4210;
constexpr quint16 Derating = 0x4220;
constexpr quint16 Acknowledge = 0x5200;
constexpr quint16 Stroke = 0x7121;
constexpr quint16 Communication = 0x7510;
constexpr quint16 Sensor = 0xFFF1;
constexpr quint16 SoftwareEnable = 0xFFF2;
constexpr quint16 ExternalTorque = 0xFFF4;
constexpr quint16 NeedsReset = 0xFFF5;
// The master stopped guarding the drive (6007h = 1): the drive names no EMCY code of its own for
// 1002h bit 5 "Abort connection", so the CiA 301 code for a life guard or heartbeat error.
constexpr quint16 AbortConnection = 0x8130;

// Known codes as the manual lists them; others get no 1002h bit and error register 01h.
MovingCapFault lookup(quint16 code);
// The 8 EMCY data bytes: code little-endian, error register, five zero bytes (spec 7.1).
QByteArray emergencyData(quint16 code, quint8 errorRegister);
} // namespace faults

} // namespace db::sim
