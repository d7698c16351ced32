#pragma once

#include "cia402/statusword.h"

namespace db::sim {

// Device side of the CiA 402 power drive system state machine (movingcap.md 5.2, 5.3, 5.5).
// Pure: it decides states and tells its owner what to do (Effects); the owner moves the axis
// and reports back when a stop has completed.
//
//   SwitchOnDisabled -2-> ReadyToSwitchOn -3-> SwitchedOn -4-> OperationEnabled
//        ^  ^  ^   <-7-       |  <-6-             |  <-5-        |  -11-> QuickStopActive
//        |  |  +------10------+                   |              |         | 12 (0/1/2 or
//        |  +--------------------9----------------+--------------+         |  disable voltage)
//        +-15- Fault <-14- FaultReactionActive <-13- any                  16 (605Ah 5/6)
//
// Statusword values follow the manual's examples literally (bit 4 never set): 0x0040, 0x0021,
// 0x0023, 0x0027 (+0x0400 target reached, +0x0100 moving), 0x0007, 0x000F, 0x0008.
class Cia402Machine
{
public:
    using State = cia402::State;
    enum class StopRamp { None, Immediate, ProfileDeceleration, QuickStopDeceleration };

    struct Effects
    {
        bool stateChanged = false;
        bool powerOn = false; // entered OperationEnabled: power stage on
        bool powerOff = false; // left the powered states: power stage off
        StopRamp stop = StopRamp::None; // brake the axis (quick stop, fault reaction)
        bool softwareEnableMissing = false; // switch-on refused: raise FFF2h (spec 5.3)
        bool faultReset = false; // transition 15 happened
        bool newSetPoint = false; // 0->1 edge of bit 4 in OperationEnabled
        bool changeImmediately = false; // bit 5 at that edge
        bool relative = false; // bit 6 at that edge
        bool haltChanged = false; // bit 8 toggled in OperationEnabled
    };

    struct StatusInputs
    {
        bool targetReached = false;
        bool moving = false;
        bool warning = false;
        bool internalLimit = false;
        bool modeBit12 = false; // PP set-point acknowledge / homing attained
        bool modeBit13 = false; // following error / homing error
    };

    Cia402Machine() = default; // transitions 0 and 1 are done: Switch on disabled

    State state() const { return m_state; }
    quint16 controlword() const { return m_controlword; }
    bool powered() const;
    bool halted() const { return m_controlword & cia402::cw::Halt; }

    Effects writeControlword(quint16 controlword);
    // Quick stop from outside the controlword (RefGo SM, input function 5) with its own option.
    Effects quickStop(int option);
    // The braking that the last quick stop or fault reaction started has reached standstill.
    Effects stopCompleted();
    Effects raiseFault(); // transition 13

    void setQuickStopOption(int option) { m_quickStopOption = option; } // 605Ah
    int quickStopOption() const { return m_quickStopOption; }
    // Input function 9: without it every switch-on attempt fails with FFF2h.
    void setSoftwareEnable(bool enabled) { m_softwareEnable = enabled; }
    bool softwareEnable() const { return m_softwareEnable; }
    // FFF5h: a fault that only a power cycle clears.
    void setFaultResetBlocked(bool blocked) { m_faultResetBlocked = blocked; }

    quint16 statusword(const StatusInputs &inputs) const;
    static quint16 stateBits(State state);

private:
    Effects enter(State state);
    Effects switchOn(bool enableOperation);
    Effects startQuickStop(int option);

    State m_state = State::SwitchOnDisabled;
    quint16 m_controlword = 0;
    int m_quickStopOption = 1;
    int m_activeQuickStopOption = 1;
    bool m_softwareEnable = true;
    bool m_faultResetBlocked = false;
};

} // namespace db::sim
