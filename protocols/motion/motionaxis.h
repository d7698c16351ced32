#pragma once

#include "axisinterface.h"
#include "motioncommand.h"
#include "motionrules.h"
#include "targettracker.h"

#include <QElapsedTimer>
#include <QPointer>
#include <QTimer>

namespace db::motion {

// The command model of one axis (stoeber_motion.md Sec. 2, 6): the PLCopen state, the one
// active motion command, the last valid target, refusal and abort rules, and the safety stops,
// over any AxisInterface.
//
// Abort rules (Sec. 6.5): an accepted motion command aborts the active one (CommandAborted);
// while MC_Stop is active (until standstill and Execute released) every command is refused;
// MC_Home only from Standstill. A refusal puts the axis in ErrorStop and, if it moves, stops
// it by quick stop [I: the seed says so for commands 1-3; the tool does it for all].
// MC_Reset leaves ErrorStop. Two refusals leave the running motion and the state alone: R10
// (MC_Stop active) and a command that would need another operating mode of the drive while
// the axis moves (AxisInterface::needsModeChange).
//
// Safety: stopNow() sends a quick stop at once in every state. The deadman watchdog
// (setWatchdogTimeout, at most kMaxWatchdogMs) stops the axis the same way when keepAlive() has
// not been called for that long while a motion command is busy or the axis moves; restarting
// the running command with a new set-point (a LeasedMove renewal) does not feed it. A lost
// connection fails the busy command with the cause.
class MotionAxis : public QObject
{
    Q_OBJECT
public:
    static constexpr int kMaxWatchdogMs = 500;

    explicit MotionAxis(AxisInterface *axis, QObject *parent = nullptr);
    ~MotionAxis() override;

    AxisInterface *axis() const { return m_axis; }
    void setConfig(const AxisConfig &config) { m_config = config; }
    const AxisConfig &config() const { return m_config; }
    AxisState state() const { return m_state; }
    // Referenced: a homing completed on this axis, or the drive reports its reference
    // (AxisInterface::Status::homingAttained, e.g. a drive that needs no homing). False until
    // then, and from the start of a homing until it completes. Absolute moves and software
    // limits on an axis that is not referenced are warned about (LimitFlags::notReferenced).
    bool isReferenced() const { return m_referenced; }
    void setReferenced(bool referenced) { m_referenced = referenced; }
    const TargetTracker &targets() const { return m_tracker; }
    MotionCommand *activeCommand() const { return m_active; }
    Error lastError() const { return m_lastError; }
    // What starting `kind` with these inputs now would do (refusal, target, clamping), without
    // starting anything: lets a panel refuse bad input before a refusal puts the axis in
    // ErrorStop (Sec. 2.5).
    Plan preview(CommandKind kind, const MoveParams &params) const;

    // 0 switches the watchdog off; other values are clamped to 1..kMaxWatchdogMs.
    void setWatchdogTimeout(int ms);
    int watchdogTimeout() const { return m_watchdogMs; }
    void keepAlive();
    void stopNow();

    // Velocity override I230 in % (0..kMaxOverridePercent), multiplied into the velocity of
    // MC_MoveAbsolute/Relative/Additive/MoveVelocity (Sec. 2.7, [I] multiplicative): at their next
    // start and at once for the running one. 0 holds a positioning axis without Done until the
    // override rises again (S-26); an MC_Stop meanwhile ends the command for good (S-27).
    static constexpr double kMaxOverridePercent = 200.0;
    void setVelocityOverride(double percent);
    double velocityOverride() const { return m_override; }

Q_SIGNALS:
    void stateChanged(db::motion::AxisState state);
    void watchdogExpired();
    // A command got a rising Execute edge and is about to start (also when it will be refused,
    // and when a running command restarts with new inputs).
    void commandStarted(db::motion::MotionCommand *command);

private:
    friend class MotionCommand;
    void start(MotionCommand *command);
    void executeReleased(MotionCommand *command);
    void forget(MotionCommand *command);

    void startPower(MotionCommand *command);
    void startReset(MotionCommand *command);
    void startMotion(MotionCommand *command);
    void refuse(MotionCommand *command, const Plan &plan);
    Reply *request(MotionCommand *command, const Plan &plan);
    void onAccepted(MotionCommand *command, quint64 generation, Reply *reply);
    void onStatus();
    void evaluateActive(const AxisInterface::Status &s);
    void onConnectionLost(const Error &error);
    void onSupervisionLost(const QString &reason);
    void emergencyStop(const Error &cause, bool asError);
    void abortActive(MotionCommand::Status status, const Error &error);
    void setState(AxisState state);
    bool motionInProgress() const;
    bool controlsAxis(const MotionCommand *command) const;
    static bool usesOverride(CommandKind kind);
    AxisSnapshot snapshot(CommandKind kind) const;
    // Runs reply and calls done(reply) once on this axis; the reply is deleted afterwards.
    void whenFinished(Reply *reply, std::function<void(Reply *)> done);

    AxisInterface *m_axis;
    AxisConfig m_config;
    AxisState m_state = AxisState::Disabled;
    bool m_referenced = false;
    bool m_powerWanted = false;
    TargetTracker m_tracker;
    QPointer<MotionCommand> m_active;
    double m_activeVelocity = 0.0; // MC_MoveVelocity set velocity after clamping
    quint64 m_rounds = 0; // status rounds seen
    int m_externalOnRounds = 0; // rounds in a row the drive was on while the model was Disabled
    quint64 m_acceptedRound = 0; // m_rounds when the active command's set-point was taken
    QTimer m_watchdog;
    int m_watchdogMs = 0;
    Error m_lastError;
    double m_override = 100.0;
    bool m_overrideHeld = false; // the active positioning stands because the override is 0
    MoveParams m_activeParams; // latched inputs of the active command, before the axis override
    QElapsedTimer m_inWindow; // since the active positioning entered its window (I87)
};

} // namespace db::motion
