#pragma once

#include "motionaxis.h"
#include "motioncommand.h"

#include <QTimer>

#include <memory>
#include <optional>

namespace db::motion {

// Hand-driven motion (jog, step) that the drive itself bounds: it never commands more travel
// than the axis covers in one lease, kLeaseMs at the effective velocity plus the braking
// distance v^2/(2*dec). While it runs, a timer renews the lease every kRenewMs with a new
// MC_MoveRelative from the actual position (a profile position move of the drive, so it works
// the same over RefGo and CANopen). When the renewals stop for whatever reason (the process is
// killed, its event loop freezes, the link breaks) the drive brakes with its own ramp and stands
// at the last commanded target at the latest kLeaseMs + v/dec after the last renewal it took.
//
// A renewal is sent only once the drive has taken the previous one (the command is Active), so
// a slow link never piles up set-points; it only makes the drive stop early.
class LeasedMove : public QObject
{
    Q_OBJECT
public:
    static constexpr int kLeaseMs = 300;
    static constexpr int kRenewMs = kLeaseMs / 3;
    static_assert(kRenewMs * 3 <= kLeaseMs, "renew at most every lease/3");

    explicit LeasedMove(MotionAxis *axis, QObject *parent = nullptr);
    // Stops renewing and sends nothing: the drive ends the motion at the end of the lease.
    ~LeasedMove() override;

    // Hold-to-run in `direction` (+1/-1) with `profile` (velocity magnitude, ramps, jerk) until
    // halt(), or up to the software limit when the axis uses software limits.
    void jog(int direction, const MoveParams &profile);
    // `distance` from the actual position, in leases; ends Done at the target.
    void step(double distance, const MoveParams &profile);
    // Stops renewing and brakes with the profile's deceleration (MC_Halt). No-op when idle.
    void halt();
    // Stops renewing without sending anything (the lease runs out on the drive).
    void stopRenewing();

    bool isRenewing() const { return m_timer.isActive(); }
    int direction() const { return m_direction; }
    // Travel of one lease at the effective velocity (override, maximum velocity), with braking.
    double leaseTravel() const;
    // Worst-case time from the last renewal the drive took to standstill (ms).
    double leaseTimeMs() const;
    // Absolute target of the last renewal the drive took, and the actual position then.
    double lastTarget() const { return m_move ? m_move->target() : 0.0; }
    double lastRenewalPosition() const { return m_renewedAt; }
    MotionCommand *command() const { return m_move.get(); } // the renewed MC_MoveRelative
    MotionCommand *haltCommand() const { return m_halt.get(); } // halt()'s MC_Halt
    QTimer *renewTimer() { return &m_timer; }

Q_SIGNALS:
    // The move ended by itself: goal reached (Done), refused, superseded or failed.
    void ended(db::motion::MotionCommand::Status status);

private:
    void begin(int direction, std::optional<double> goal, const MoveParams &profile);
    void renew();
    double effectiveVelocity() const;
    double effectiveDeceleration() const;

    MotionAxis *m_axis;
    std::unique_ptr<MotionCommand> m_move;
    std::unique_ptr<MotionCommand> m_halt;
    QTimer m_timer;
    MoveParams m_profile;
    std::optional<double> m_goal; // absolute end point; none = until halt()
    int m_direction = 0;
    bool m_lastLeg = false; // the commanded target is the goal: no more renewals needed
    double m_renewedAt = 0.0;
};

} // namespace db::motion
