#include "cia402machine.h"

namespace db::sim {

using cia402::Command;
namespace cw = cia402::cw;
namespace sw = cia402::sw;

bool Cia402Machine::powered() const
{
    return m_state == State::OperationEnabled || m_state == State::QuickStopActive
        || m_state == State::FaultReactionActive;
}

Cia402Machine::Effects Cia402Machine::enter(State state)
{
    Effects e;
    if (state == m_state)
        return e;
    const bool wasPowered = powered();
    m_state = state;
    e.stateChanged = true;
    e.powerOn = !wasPowered && powered();
    e.powerOff = wasPowered && !powered();
    return e;
}

Cia402Machine::Effects Cia402Machine::switchOn(bool enableOperation)
{
    if (!m_softwareEnable) {
        Effects e;
        e.softwareEnableMissing = true;
        return e;
    }
    return enter(enableOperation ? State::OperationEnabled : State::SwitchedOn); // 3 (+4)
}

Cia402Machine::Effects Cia402Machine::startQuickStop(int option)
{
    m_activeQuickStopOption = option;
    if (option == 0) { // disable drive function: off at once (11 then 12)
        Effects e = enter(State::QuickStopActive);
        const Effects off = enter(State::SwitchOnDisabled);
        e.powerOff = off.powerOff;
        e.stop = StopRamp::Immediate;
        return e;
    }
    Effects e = enter(State::QuickStopActive);
    e.stop = (option == 1 || option == 5) ? StopRamp::ProfileDeceleration
                                          : StopRamp::QuickStopDeceleration;
    return e;
}

Cia402Machine::Effects Cia402Machine::quickStop(int option)
{
    if (m_state != State::OperationEnabled)
        return {};
    return startQuickStop(option);
}

Cia402Machine::Effects Cia402Machine::writeControlword(quint16 controlword)
{
    const quint16 previous = m_controlword;
    m_controlword = controlword;
    const bool faultResetEdge = (controlword & cw::FaultReset) && !(previous & cw::FaultReset);

    if (m_state == State::Fault) {
        if (faultResetEdge && !m_faultResetBlocked) {
            Effects e = enter(State::SwitchOnDisabled); // 15
            e.faultReset = true;
            return e;
        }
        return {};
    }
    if (m_state == State::FaultReactionActive)
        return {};

    const Command command = cia402::decodeCommand(controlword);
    switch (m_state) {
    case State::NotReadyToSwitchOn:
        return {};
    case State::SwitchOnDisabled:
        if (command == Command::Shutdown)
            return enter(State::ReadyToSwitchOn); // 2
        return {};
    case State::ReadyToSwitchOn:
        if (command == Command::SwitchOn)
            return switchOn(false); // 3
        if (command == Command::EnableOperation)
            return switchOn(true); // 3 + 4
        if (command == Command::DisableVoltage || command == Command::QuickStop)
            return enter(State::SwitchOnDisabled); // 7
        return {};
    case State::SwitchedOn:
        if (command == Command::EnableOperation)
            return enter(State::OperationEnabled); // 4
        if (command == Command::Shutdown)
            return enter(State::ReadyToSwitchOn); // 6
        if (command == Command::DisableVoltage || command == Command::QuickStop)
            return enter(State::SwitchOnDisabled); // 10
        return {};
    case State::OperationEnabled: {
        if (command == Command::SwitchOn)
            return enter(State::SwitchedOn); // 5 (disable operation)
        if (command == Command::Shutdown)
            return enter(State::ReadyToSwitchOn); // 8
        if (command == Command::DisableVoltage)
            return enter(State::SwitchOnDisabled); // 9
        if (command == Command::QuickStop)
            return startQuickStop(m_quickStopOption); // 11
        Effects e;
        if ((controlword & cw::NewSetPoint) && !(previous & cw::NewSetPoint)) {
            e.newSetPoint = true;
            e.changeImmediately = controlword & cw::ChangeImmediately;
            e.relative = controlword & cw::Relative;
        }
        e.haltChanged = (controlword ^ previous) & cw::Halt;
        return e;
    }
    case State::QuickStopActive:
        if (command == Command::DisableVoltage)
            return enter(State::SwitchOnDisabled); // 12
        if (command == Command::EnableOperation
            && (m_activeQuickStopOption == 5 || m_activeQuickStopOption == 6))
            return enter(State::OperationEnabled); // 16
        return {};
    case State::FaultReactionActive:
    case State::Fault:
    case State::Unknown:
        break;
    }
    return {};
}

Cia402Machine::Effects Cia402Machine::stopCompleted()
{
    if (m_state == State::FaultReactionActive)
        return enter(State::Fault); // 14
    if (m_state == State::QuickStopActive && m_activeQuickStopOption <= 2)
        return enter(State::SwitchOnDisabled); // 12 (automatic)
    return {};
}

Cia402Machine::Effects Cia402Machine::raiseFault()
{
    if (m_state == State::Fault || m_state == State::FaultReactionActive)
        return {};
    const bool wasPowered = powered();
    Effects e = enter(State::FaultReactionActive); // 13
    e.powerOn = false;
    if (wasPowered) {
        e.stop = StopRamp::QuickStopDeceleration;
        return e;
    }
    const Effects fault = enter(State::Fault); // nothing to brake: 14 at once
    e.powerOff = fault.powerOff;
    return e;
}

quint16 Cia402Machine::stateBits(State state)
{
    switch (state) {
    case State::NotReadyToSwitchOn:
        return 0x0000;
    case State::SwitchOnDisabled:
        return 0x0040;
    case State::ReadyToSwitchOn:
        return 0x0021;
    case State::SwitchedOn:
        return 0x0023;
    case State::OperationEnabled:
        return 0x0027;
    case State::QuickStopActive:
        return 0x0007;
    case State::FaultReactionActive:
        return 0x000F;
    case State::Fault:
        return 0x0008;
    case State::Unknown:
        break;
    }
    return 0x0000;
}

quint16 Cia402Machine::statusword(const StatusInputs &in) const
{
    quint16 word = stateBits(m_state);
    if (in.warning)
        word |= sw::Warning;
    if (m_state == State::Fault)
        return word; // the manual shows a bare 0x0008
    if (in.moving && powered())
        word |= sw::Moving;
    if (m_state == State::OperationEnabled) {
        if (in.targetReached)
            word |= sw::TargetReached;
        if (in.internalLimit)
            word |= sw::InternalLimitActive;
        if (in.modeBit12)
            word |= sw::SetPointAcknowledge;
        if (in.modeBit13)
            word |= sw::FollowingError;
    }
    return word;
}

} // namespace db::sim
