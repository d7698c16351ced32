#pragma once

#include <QString>

namespace db::cia402 {

// CiA 402 power drive system states (movingcap.md 5.5; CiA 402-2 figure "PDS FSA").
enum class State {
    NotReadyToSwitchOn,
    SwitchOnDisabled,
    ReadyToSwitchOn,
    SwitchedOn,
    OperationEnabled,
    QuickStopActive,
    FaultReactionActive,
    Fault,
    Unknown,
};

// Statusword 6041h bits (movingcap.md 5.4).
namespace sw {
constexpr quint16 ReadyToSwitchOn = 0x0001;
constexpr quint16 SwitchedOn = 0x0002;
constexpr quint16 OperationEnabled = 0x0004;
constexpr quint16 Fault = 0x0008;
constexpr quint16 VoltageEnabled = 0x0010;
constexpr quint16 QuickStop = 0x0020; // active-low: 0 = quick stop active
constexpr quint16 SwitchOnDisabled = 0x0040;
constexpr quint16 Warning = 0x0080;
constexpr quint16 Moving = 0x0100; // MovingCap manufacturer bit 8 "drive moving"
constexpr quint16 Remote = 0x0200;
constexpr quint16 TargetReached = 0x0400;
constexpr quint16 InternalLimitActive = 0x0800;
constexpr quint16 SetPointAcknowledge = 0x1000; // PP; homing: attained
constexpr quint16 FollowingError = 0x2000; // PP; homing: error
} // namespace sw

// Controlword 6040h values and bits (movingcap.md 5.1, 5.2).
namespace cw {
constexpr quint16 SwitchOn = 0x0001;
constexpr quint16 EnableVoltage = 0x0002;
constexpr quint16 QuickStopBit = 0x0004; // active-low
constexpr quint16 EnableOperation = 0x0008;
constexpr quint16 NewSetPoint = 0x0010; // PP; homing: start
constexpr quint16 ChangeImmediately = 0x0020;
constexpr quint16 Relative = 0x0040;
constexpr quint16 FaultReset = 0x0080;
constexpr quint16 Halt = 0x0100;

constexpr quint16 Shutdown = 0x0006;
constexpr quint16 SwitchOnCmd = 0x0007;
constexpr quint16 EnableOperationCmd = 0x000F;
constexpr quint16 DisableVoltage = 0x0000;
constexpr quint16 QuickStopCmd = 0x0002;
constexpr quint16 DisableOperation = 0x0007;
constexpr quint16 FaultResetCmd = 0x0080;
} // namespace cw

// Decodes the state from (sw & 0x006F), as CiA 402 and movingcap.md 5.5 do.
State decodeState(quint16 statusword);
// English state name as CiA 402 writes it ("Operation enabled"); translated by the caller's tr().
QString stateName(State state);

// Device control commands decoded from controlword bits 0-3 and 7 (movingcap.md 5.2, errata 18).
enum class Command {
    None, // fault-reset bit low and no state command pattern
    Shutdown,
    SwitchOn,
    SwitchOnEnableOperation, // 0x0F from Ready to switch on: transitions 3 + 4
    DisableVoltage,
    QuickStop,
    DisableOperation,
    EnableOperation,
    FaultReset,
};
Command decodeCommand(quint16 controlword);

// Modes of operation 6060h/6061h names ("Profile position").
QString modeName(int mode);

} // namespace db::cia402
