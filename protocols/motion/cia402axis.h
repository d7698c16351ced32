#pragma once

#include "connectionaxis.h"

#include "cia402/drivecontroller.h"
#include "cia402/modes.h"
#include "cia402/scaling.h"

#include <QHash>
#include <QPointer>

#include <optional>

namespace db::motion {

// AxisInterface over any CiA 402 drive reachable through a DeviceConnection (MovingCap over RefGo
// OR/OW, any drive over CANopen SDO). Positions and velocities are the drive's user units
// (607Ah, 6081h, 6064h, 606Ch already carry the factor group); accelerations are converted when
// the drive uses the rotary MovingCap unit [100 rpm/min] (movingcap.md 9.1).
//
// Status: 6041h, 6064h, 606Ch and 60FDh from the connection's status source (a CiA 402 one is
// made when the connection has none), a cycle at least every kStatusPollMs while connected
// (kIdleStatusPollMs while the drive is off and still, see ConnectionAxis); statusChanged()
// after each cycle that read the statusword and the position.
class Cia402Axis : public ConnectionAxis
{
    Q_OBJECT
public:
    static constexpr int kHomingTimeoutMs = 30000;

    enum class AccelerationUnit { UserUnits, RotaryMotor };

    explicit Cia402Axis(DeviceConnection *connection, QObject *parent = nullptr);
    ~Cia402Axis() override;

    // Reads the factor group (608Fh, 6091h, 6092h), 6502h supported modes, the limit objects
    // (motion/axislimits.h) and the drive's profile and homing values; the reply finishes when
    // done (missing objects keep the defaults). Caller owns the reply.
    Reply *initialize() override;
    AxisConfig limits() const override { return m_limits; }
    Profile driveProfile() const override { return m_profile; }
    HomingParams driveHoming() const override { return m_homing; }
    QString positionUnit() const override;
    QString velocityUnit() const override;
    // A drive that needs no homing (absolute position kept by the drive) reports its reference
    // from the start; others only in homing mode (6061h = 6, statusword bits 12 and 10).
    void setReferencedWithoutHoming(bool yes) { m_referencedWithoutHoming = yes; }
    // Before initialize(): how the drive's accelerations are given.
    void setAccelerationUnit(AccelerationUnit unit) { m_accelerationUnit = unit; }
    AccelerationUnit accelerationUnit() const { return m_accelerationUnit; }
    const cia402::Scaling &scaling() const { return m_scaling; }

    Features features() const override { return m_features; }

    Reply *power(bool on) override;
    Reply *reset() override;
    Reply *moveTo(double target, const Profile &profile) override;
    Reply *moveVelocity(double velocity, const Profile &profile) override;
    Reply *halt(double deceleration) override;
    Reply *home(const HomingParams &params) override;
    Reply *torque(double torquePerMille, double slope) override;
    Reply *stopNow() override;

protected:
    bool takeStatus(const StatusSource &source, Status &status) override;
    bool commandRunning() const override;

private:
    Reply *runMotion(cia402::Sequence *sequence, bool homing = false);
    quint32 accelerationRaw(double user) const;
    static QList<ObjectAddress> profileObjects();
    void applyInitialValues(const QHash<ObjectAddress, QVariant> &values);

    cia402::DriveController m_controller;
    cia402::Scaling m_scaling;
    AccelerationUnit m_accelerationUnit = AccelerationUnit::UserUnits;
    Features m_features = Feature::ProfilePosition | Feature::ProfileVelocity | Feature::Homing;
    std::optional<ObjectAddress> m_jerkObject; // 60A4h.1 or .0, whichever is described
    bool m_referencedWithoutHoming = false;
    bool m_homingMode = false; // the drive is in homing mode (6061h at start, or our homing)
    AxisConfig m_limits;
    Profile m_profile;
    HomingParams m_homing;
    QPointer<cia402::Sequence> m_motion;
};

} // namespace db::motion
