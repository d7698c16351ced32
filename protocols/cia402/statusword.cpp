#include "statusword.h"

#include <QObject>

namespace db::cia402 {

State decodeState(quint16 statusword)
{
    // Masks per CiA 402: some states are identified by 4 bits + switch-on-disabled (0x4F),
    // the others by 5 bits + quick stop (0x6F).
    const quint16 s4f = statusword & 0x004F;
    const quint16 s6f = statusword & 0x006F;
    if (s4f == 0x0000)
        return State::NotReadyToSwitchOn;
    if (s4f == 0x0040)
        return State::SwitchOnDisabled;
    if (s6f == 0x0021)
        return State::ReadyToSwitchOn;
    if (s6f == 0x0023)
        return State::SwitchedOn;
    if (s6f == 0x0027)
        return State::OperationEnabled;
    if (s6f == 0x0007)
        return State::QuickStopActive;
    if (s4f == 0x000F)
        return State::FaultReactionActive;
    if (s4f == 0x0008)
        return State::Fault;
    return State::Unknown;
}

QString stateName(State state)
{
    switch (state) {
    case State::NotReadyToSwitchOn:
        return QObject::tr("Not ready to switch on");
    case State::SwitchOnDisabled:
        return QObject::tr("Switch on disabled");
    case State::ReadyToSwitchOn:
        return QObject::tr("Ready to switch on");
    case State::SwitchedOn:
        return QObject::tr("Switched on");
    case State::OperationEnabled:
        return QObject::tr("Operation enabled");
    case State::QuickStopActive:
        return QObject::tr("Quick stop active");
    case State::FaultReactionActive:
        return QObject::tr("Fault reaction active");
    case State::Fault:
        return QObject::tr("Fault");
    case State::Unknown:
        break;
    }
    return QObject::tr("Unknown state");
}

Command decodeCommand(quint16 controlword)
{
    if (controlword & cw::FaultReset)
        return Command::FaultReset;
    const quint16 low = controlword & 0x000F;
    if ((low & 0x0002) == 0)
        return Command::DisableVoltage; // xxxx xx0x
    if ((low & 0x0006) == 0x0002)
        return Command::QuickStop; // xxxx x01x
    if ((low & 0x0007) == 0x0006)
        return Command::Shutdown; // xxxx x110
    if (low == 0x0007)
        return Command::SwitchOn; // also Disable operation (same pattern, by state)
    if (low == 0x000F)
        return Command::EnableOperation; // also switch on + enable operation from RTSO
    return Command::None;
}

QString modeName(int mode)
{
    switch (mode) {
    case 0:
        return QObject::tr("No mode");
    case 1:
        return QObject::tr("Profile position");
    case 2:
        return QObject::tr("Velocity");
    case 3:
        return QObject::tr("Profile velocity");
    case 4:
        return QObject::tr("Profile torque");
    case 6:
        return QObject::tr("Homing");
    case 7:
        return QObject::tr("Interpolated position");
    case 8:
        return QObject::tr("Cyclic sync position");
    case 9:
        return QObject::tr("Cyclic sync velocity");
    case 10:
        return QObject::tr("Cyclic sync torque");
    default:
        break;
    }
    return mode < 0 ? QObject::tr("Manufacturer mode %1").arg(mode)
                    : QObject::tr("Mode %1").arg(mode);
}

} // namespace db::cia402
