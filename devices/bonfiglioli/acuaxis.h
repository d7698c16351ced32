#pragma once

// The axis of a Bonfiglioli ACTIVE Cube over VABus/TCP: the inverter's own state machine
// (control word 410, status word 411, 412 = 1) and the Motion Control Override (1454-1460).
//
// Every write goes to a RAM data set (data set + 5), so that cyclic control never wears the
// EEPROM. The state is decoded from 411 with the mask 0x006F. The operating mode (1454) is
// changed only in "switched on" (0x0007) and never while the axis moves; a request that would
// need a change while moving fails with "refused: mode change while moving". The override value
// -1 switches an override off, so it is never sent as a target, velocity or ramp.
//
// Modes: 1 profile position (moveTo: new set-point bit 4 / set-point acknowledged bit 12
// handshake, "change immediately" bit 5), 3 profile velocity (moveVelocity in u/s), 2 velocity
// (moveVelocity in rpm, the only mode of configurations without positioning control, 30 != x40),
// 6 homing (bit 4; bit 12 attained, bit 13 error), -1 table travel record (bits 4, 6, 9, 11-15)
// and -2 move away from the limit switch (bit 4), -3 electronic gear slave (bit 4; status bit 10
// in gear). Halt is bit 8, quick stop 0x0002.
//
// Status: 411, 1108, 1107, 240 and 274 from the connection's status source (an ACU one is made
// when the connection has none), a cycle at least every kStatusPollMs while connected;
// statusChanged() after each cycle that read 411 and 1108. The cycles also keep the inverter's
// 10 s link watchdog (388) fed.

#include "motion/connectionaxis.h"

#include <QElapsedTimer>
#include <QPointer>

namespace db::bonfiglioli {

class AcuSteps;

class AcuAxis : public motion::ConnectionAxis
{
    Q_OBJECT
public:
    static constexpr int kStateTimeoutMs = 2000; // one state machine transition
    static constexpr int kHandshakeTimeoutMs = 2000; // set-point acknowledged
    static constexpr int kHomingTimeoutMs = 60000;
    static constexpr int kTableTravelTimeoutMs = 120000;
    static constexpr int kGearTimeoutMs = 60000; // until in gear
    static constexpr int kLinkWatchdogMs = 10000; // the module's PLC link timeout
    static constexpr int kSilenceShownMs = 1000; // no answer this long: the time left is shown

    // 1454 Override Modes Of Operation; negative modes are sent as 256 + mode.
    enum class Mode : qint16 {
        None = 0,
        ProfilePosition = 1,
        Velocity = 2,
        ProfileVelocity = 3,
        Homing = 6,
        TableTravel = -1,
        LimitSwitch = -2,
        ElectronicGear = -3, // slave
    };

    explicit AcuAxis(DeviceConnection *connection, QObject *parent = nullptr);
    ~AcuAxis() override;

    // Configuration (30) read by initialize(); x40 has positioning control.
    int configuration() const { return m_configuration; }
    bool hasPositioning() const { return m_configuration % 100 == 40; }
    Mode mode() const { return m_mode; }
    quint16 controlWord() const { return m_controlWord; }
    quint16 faultCode() const { return m_faultCode; } // 260 as last read

    motion::AxisInterface::Features features() const override;

    Reply *initialize() override;
    motion::AxisConfig limits() const override { return m_limits; }
    Profile driveProfile() const override { return m_profile; }
    motion::HomingParams driveHoming() const override { return m_homing; }
    QString positionUnit() const override;
    QString velocityUnit() const override;
    QString featureNote() const override;
    // The MCO mode `kind` runs in differs from 1454 as last written or read.
    bool needsModeChange(motion::CommandKind kind) const override;
    // 388 as read by initialize(), with the inverter's 10 s link watchdog; once the inverter
    // has not answered for kSilenceShownMs, also the time left until it reacts.
    QString linkSupervision() const override;

    Reply *power(bool on) override;
    // Reads 260, then gives bit 7 a rising edge; finishes with the fault code once the fault
    // is gone. Leaves the power stage off.
    Reply *reset() override;
    Reply *moveTo(double target, const Profile &profile) override;
    Reply *moveVelocity(double velocity, const Profile &profile) override;
    Reply *halt(double deceleration) override;
    Reply *home(const motion::HomingParams &params) override;
    Reply *torque(double torquePerMille, double slope) override;
    Reply *stopNow() override;

    // Table travel record mode: starts motion block `block` (1-32), alone or as the start of
    // an automatic sequence, or resumes the interrupted block. Finishes when the block (or the
    // sequence) has ended in its target, with the last active block as value.
    Reply *startMotionBlock(int block, bool sequence, bool resume) override;
    // Moves off an active hardware limit switch (mode -2); finishes once it is cleared.
    Reply *moveAwayFromLimitSwitch();
    // Electronic gear slave (mode -3): writes the gear factor (1123 numerator, 1124 denominator,
    // RAM data set), starts the gear (bit 4, without direct sync or phasing) with the override
    // ramps 1457/1458 when given (> 0), and finishes once the inverter reports "in gear" (status
    // bit 10). gearOut() drops bit 4 (the inverter brakes with 1458); halt() or stopNow() end it
    // too. The master source (1122) is the drive's own parameter.
    Reply *gearIn(int numerator, int denominator, double acceleration,
                  double deceleration) override;
    // Fails unless the inverter is in electronic gear mode (1454 = -3).
    Reply *gearOut(double deceleration) override;

protected:
    bool takeStatus(const StatusSource &source, Status &status) override;
    void onDisconnected() override;

private:
    friend class AcuSteps;
    Reply *run(AcuSteps *steps);
    // The steps that put the drive in `mode` (nothing when it is in it); false with the reason
    // when the change is refused.
    Result<void> addModeChange(AcuSteps *steps, Mode mode);
    // The MCO mode a command runs in; None for those that work in any mode (halt, stop).
    Mode modeFor(motion::CommandKind kind) const;
    // A step that fails unless the inverter is in "operation enabled" (411 read then).
    void requireEnabled(AcuSteps *steps) const;

    QPointer<AcuSteps> m_running;
    quint16 m_controlWord = 0;
    Mode m_mode = Mode::None;
    int m_configuration = 0;
    int m_busErrorBehaviour = -1; // 388, -1 = not read
    quint16 m_faultCode = 0;
    bool m_modeChanging = false; // passing "switched on" to change 1454
    QElapsedTimer m_lastAnswer; // since the last complete status cycle
    motion::AxisConfig m_limits;
    Profile m_profile;
    motion::HomingParams m_homing;
};

} // namespace db::bonfiglioli
