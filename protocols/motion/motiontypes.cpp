#include "motiontypes.h"
#include <QCoreApplication>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::motion)
};
} // namespace

namespace db::motion {

QString commandName(CommandKind kind)
{
    switch (kind) {
    case CommandKind::DoNothing:
        return QStringLiteral("MC_DoNothing");
    case CommandKind::MoveAbsolute:
        return QStringLiteral("MC_MoveAbsolute");
    case CommandKind::MoveRelative:
        return QStringLiteral("MC_MoveRelative");
    case CommandKind::MoveAdditive:
        return QStringLiteral("MC_MoveAdditive");
    case CommandKind::MoveVelocity:
        return QStringLiteral("MC_MoveVelocity");
    case CommandKind::Stop:
        return QStringLiteral("MC_Stop");
    case CommandKind::Home:
        return QStringLiteral("MC_Home");
    case CommandKind::TorqueControl:
        return QStringLiteral("MC_TorqueControl");
    case CommandKind::Halt:
        return QStringLiteral("MC_Halt");
    case CommandKind::Power:
        return QStringLiteral("MC_Power");
    case CommandKind::Reset:
        return QStringLiteral("MC_Reset");
    case CommandKind::MotionBlock:
        return Tr::tr("Motion block");
    case CommandKind::GearIn:
        return QStringLiteral("MC_GearIn");
    case CommandKind::GearOut:
        return QStringLiteral("MC_GearOut");
    }
    return QStringLiteral("MC_?");
}

bool isPositioning(CommandKind kind)
{
    return kind == CommandKind::MoveAbsolute || kind == CommandKind::MoveRelative
        || kind == CommandKind::MoveAdditive;
}

QString axisStateName(AxisState state)
{
    switch (state) {
    case AxisState::Disabled:
        return QStringLiteral("Disabled");
    case AxisState::Standstill:
        return QStringLiteral("Standstill");
    case AxisState::DiscreteMotion:
        return QStringLiteral("Discrete Motion");
    case AxisState::ContinuousMotion:
        return QStringLiteral("Continuous Motion");
    case AxisState::SynchronizedMotion:
        return QStringLiteral("Synchronized Motion");
    case AxisState::Stopping:
        return QStringLiteral("Stopping");
    case AxisState::ErrorStop:
        return QStringLiteral("ErrorStop");
    case AxisState::Homing:
        return QStringLiteral("Homing");
    }
    return QStringLiteral("%1").arg(int(state));
}

QString refusalText(Refusal refusal)
{
    switch (refusal) {
    case Refusal::None:
        return {};
    case Refusal::TargetOutsideSoftLimits:
        return Tr::tr("target outside the software limit switches");
    case Refusal::DirectionNotPermitted:
        return Tr::tr("travel direction not permitted");
    case Refusal::TargetOutsideCycle:
        return Tr::tr("target outside the cycle length");
    case Refusal::HardwareLimitSwitch:
        return Tr::tr("hardware limit switch active in the travel direction");
    case Refusal::ZeroProfileValue:
        return Tr::tr("velocity, acceleration, deceleration or jerk is zero");
    case Refusal::ZeroAxisLimit:
        return Tr::tr("maximum acceleration or maximum jerk of the axis is zero");
    case Refusal::NotAtStandstill:
        return Tr::tr("axis not at standstill");
    case Refusal::HomingInactive:
        return Tr::tr("homing method inactive");
    case Refusal::StopActive:
        return Tr::tr("MC_Stop is active");
    case Refusal::AxisNotReady:
        return Tr::tr("axis not enabled or in ErrorStop");
    case Refusal::ModeChangeWhileMoving:
        return Tr::tr("mode change while moving");
    case Refusal::FeatureMissing:
        return Tr::tr("the drive has no electronic gear");
    case Refusal::InvalidGearRatio:
        return Tr::tr("gear ratio needs a numerator other than 0 and a denominator of at least 1");
    }
    return {};
}

} // namespace db::motion
