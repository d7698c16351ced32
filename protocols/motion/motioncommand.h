#pragma once

#include "motiontypes.h"

#include "core/error.h"

#include <QObject>
#include <QPointer>

namespace db::motion {

class MotionAxis;

// One PLCopen-style function block instance (MC_MoveAbsolute, MC_Stop, MC_Power, ...) on one
// MotionAxis. It starts on the rising edge of Execute; its inputs are latched at that edge
// (stoeber_motion.md 2.2), so later setParams() calls act only on the next edge.
//
// Status (tool-side outputs, Sec. 6.4; the seed's drive has only Done/Error):
//   Idle --rising edge--> Busy --drive took the set-point--> Active --done rule--> Done
//                          |  \--refused--> Error (refusal(), error())   |
//                          |   (MC_Stop/MC_Halt refused at standstill: Done)
//                          +--> CommandAborted (a newer command, stopNow, power off)
//                          +--> Error (drive fault, disconnect, watchdog, request failed)
// Busy is always reported first, also for a refused command (S-30: a fresh edge per start).
// The final status stays until the next rising edge.
class MotionCommand : public QObject
{
    Q_OBJECT
public:
    enum class Status { Idle, Busy, Active, Done, CommandAborted, Error };
    Q_ENUM(Status)

    MotionCommand(MotionAxis *axis, CommandKind kind, QObject *parent = nullptr);
    ~MotionCommand() override;

    CommandKind kind() const { return m_kind; }
    QString name() const { return commandName(m_kind); }

    // Inputs (take effect at the next rising edge).
    void setParams(const MoveParams &params) { m_params = params; }
    const MoveParams &params() const { return m_params; }
    void setHoming(const HomingParams &params) { m_homing = params; }
    const HomingParams &homing() const { return m_homing; }
    void setEnable(bool enable) { m_enable = enable; } // MC_Power: on/off
    void setExecute(bool execute);
    bool execute() const { return m_execute; }

    // Outputs.
    Status status() const { return m_status; }
    bool isBusy() const { return m_status == Status::Busy || m_status == Status::Active; }
    bool isFinished() const { return !isBusy() && m_status != Status::Idle; }
    Error error() const { return m_error; }
    Refusal refusal() const { return m_refusal; }
    LimitFlags limits() const { return m_limits; }
    double target() const { return m_target; } // latched absolute target (1-3)
    const MoveParams &latched() const { return m_latched; }
    bool latchedEnable() const { return m_latchedEnable; } // MC_Power's input at the last start

Q_SIGNALS:
    void statusChanged(db::motion::MotionCommand::Status status);

private:
    friend class MotionAxis;
    void setStatus(Status status, const Error &error = {}, Refusal refusal = Refusal::None);

    QPointer<MotionAxis> m_axis;
    CommandKind m_kind;
    MoveParams m_params;
    HomingParams m_homing;
    bool m_enable = true;
    bool m_execute = false;

    Status m_status = Status::Idle;
    Error m_error;
    Refusal m_refusal = Refusal::None;
    LimitFlags m_limits;
    MoveParams m_latched;
    HomingParams m_latchedHoming;
    bool m_latchedEnable = true;
    double m_target = 0.0;
    quint64 m_generation = 0; // which start a late drive answer belongs to
};

} // namespace db::motion
