#pragma once

#include <QMetaType>
#include <QString>

#include <optional>

namespace db::motion {

// The motion commands (stoeber_motion.md Sec. 1, Tab. 1 numbers) plus the PLCopen
// administrative blocks MC_Power and MC_Reset, which have no STÖBER number.
enum class CommandKind {
    DoNothing = 0,
    MoveAbsolute = 1,
    MoveRelative = 2,
    MoveAdditive = 3,
    MoveVelocity = 4,
    Stop = 5,
    Home = 6,
    TorqueControl = 9,
    Halt = 11,
    Power = 100,
    Reset = 101,
    // A motion block of the drive's own table (MoveParams::block), alone or the sequence it
    // starts; tool-side, for drives that hold such a table (the ACTIVE Cube's table travel).
    MotionBlock = 102,
    // PLCopen MC_GearIn / MC_GearOut: the axis follows its master at the ratio
    // MoveParams::gearNumerator / gearDenominator (the drive's own master, e.g. an encoder input).
    GearIn = 103,
    GearOut = 104,
};
QString commandName(CommandKind kind); // "MC_MoveAbsolute"
bool isPositioning(CommandKind kind); // 1, 2, 3

// PLCopen state of the axis (I89, Sec. 6.1). Disabled (power stage off) is PLCopen's own
// state; the seed does not name it [I].
enum class AxisState {
    Disabled = 0,
    Standstill = 2,
    DiscreteMotion = 3,
    ContinuousMotion = 4,
    SynchronizedMotion = 5, // coupled to a master (MC_GearIn)
    Stopping = 6,
    ErrorStop = 7,
    Homing = 8,
};
QString axisStateName(AxisState state);

// Why the command model refused a command (Sec. 2.5; the R-codes of that table). The seed gives
// no I90 codes, so these are tool-side.
enum class Refusal {
    None,
    TargetOutsideSoftLimits, // R1
    DirectionNotPermitted, // R2
    TargetOutsideCycle, // R3
    HardwareLimitSwitch, // R4
    ZeroProfileValue, // R5, R5v, R5s
    ZeroAxisLimit, // R6 (I11 or I16 zero)
    NotAtStandstill, // R8
    HomingInactive, // R9
    StopActive, // R10
    AxisNotReady, // [I] power off or ErrorStop: only MC_Power / MC_Reset help
    // The drive would have to change its operating mode for the command, which it cannot do
    // while the axis moves: the running motion goes on.
    ModeChangeWhileMoving,
    // The drive has no such function (e.g. no electronic gear): nothing is sent and whatever
    // runs goes on.
    FeatureMissing,
    // A gear ratio with a zero numerator or a denominator below 1.
    InvalidGearRatio,
};
QString refusalText(Refusal refusal);

// Bewegungsrichtung I411 (Sec. 4.2), for MC_MoveAbsolute on an endless axis.
enum class Direction { Optimised = 0, PositiveOnly = 1, NegativeOnly = 2, KeepDirection = 3 };
// Permitted direction I04 (encoding not in the seed [I]).
enum class PermittedDirection { Both, PositiveOnly, NegativeOnly };

// The axis configuration that decides refusal and clamping (Sec. 7.3 item 6).
struct AxisConfig
{
    bool endless = false; // I00: false = limited, true = endless (rotary)
    double cycleLength = 360.0; // I01
    PermittedDirection permitted = PermittedDirection::Both; // I04
    double maxVelocity = 1e9; // I10
    double maxAcceleration = 1e9; // I11 (acceleration and deceleration)
    double maxJerk = 1e12; // I16
    bool softLimitsUsed = false; // software limit switches in use
    double softLimitNegative = 0.0; // I51
    double softLimitPositive = 0.0; // I50
    double positionWindow = 1.0; // I22
    // I87 (CiA 402: 6068h): Done only once the position has stayed in the window this long
    // (S-03/S-04; [R] timed from entering the window).
    int positionWindowTimeMs = 0;
    double velocityWindow = 1.0; // C40
    int homingMethod = 35; // A586; 0 = inactive (R9)
};

// The inputs of one command, latched at its rising edge of Execute.
struct MoveParams
{
    double position = 0.0; // target (MoveAbsolute) or distance (Relative, Additive)
    double velocity = 0.0; // profile / set velocity
    double acceleration = 0.0;
    double deceleration = 0.0;
    double jerk = 0.0;
    Direction direction = Direction::Optimised;
    double overridePercent = 100.0; // I230, multiplicative [I]
    double torque = 0.0; // MC_TorqueControl
    int block = 1; // MotionBlock: 1-based block number
    bool sequence = false; // MotionBlock: run on through the blocks that follow
    bool resume = false; // MotionBlock: continue the interrupted block
    int gearNumerator = 1; // GearIn: slave turns per master turn = numerator / denominator;
    int gearDenominator = 1; // a negative numerator turns the slave the other way
};

struct HomingParams
{
    int method = 35;
    double speedFast = 0.0;
    double speedSlow = 0.0;
    double acceleration = 0.0;
    double offset = 0.0; // reference position I34 / 607Ch
};

// Limitation flags (Sec. 2.6).
struct LimitFlags
{
    bool velocityLimited = false; // I190
    bool accelerationOrJerkLimited = false; // I191
    bool overrideLimited = false; // I193 (override > 100 % clamped at I10)
    // [I] An absolute target, or software limits, on an axis not known to be referenced: the
    // drive's present zero is taken as it is. A warning, not a refusal (the seed refuses with
    // I86 = 0), because most drives cannot tell the tool whether they are referenced (CiA 402
    // only in homing mode) and a drive homed before this connection would be refused for good.
    bool notReferenced = false;
    friend bool operator==(const LimitFlags &, const LimitFlags &) = default;
};

// What the command model knows about the axis when a command starts.
struct AxisSnapshot
{
    AxisState state = AxisState::Standstill;
    double position = 0.0;
    double velocity = 0.0;
    bool referenced = false; // homed, or the drive says so
    bool hardwareLimitPositive = false;
    bool hardwareLimitNegative = false;
    double brakingDistance = 0.0; // from the present velocity, for starts from motion
    // The drive reports motion in a status read after the last command was taken (velocity
    // inside the window too).
    bool driveMoving = false;
    // The command needs another operating mode of the drive than the present one
    // (AxisInterface::needsModeChange).
    bool modeChangeNeeded = false;
    // The drive can couple to a master (AxisInterface::Feature::ElectronicGear).
    bool electronicGear = false;
};

} // namespace db::motion
