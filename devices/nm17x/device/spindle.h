#pragma once

// The mechanics and positioning engine of a simulated NM17x display, stepped by the device's
// 10 ms cycle: the spindle position (in the coordinates of 6004h, 1/100 mm), automatic
// positioning with loop (backlash compensation), speed stages by switch points, switch-off
// point, tolerance window, end and collision limits, clamp delays, Tippen (continuous jog) until
// stop or limit, and turning the shaft by hand. Pure: no timers, no bus; the owner reads the
// settings from its objects and calls tick().
//
// Positioning (graph):
//   Idle --start--> ClampOpening --clamp delay--> Running(loop point) --reached--> Dwell
//        --dwell time--> Running(target) --reached--> ClampClosing --clamp delay--> Idle
//   Without loop Running goes straight to the target; without clamping the clamp phases take no
//   time. stop() from any phase: motor off, then ClampClosing. Jogging is Running without a goal
//   until stop() or a limit.

#include "devices/nm17x/nm17xpdo.h"

#include <optional>
#include <utility>

namespace db::nm17x {

struct SpindleSettings
{
    qint32 loop = 100; // 2002h; 0 = no loop
    bool approachDown = false; // 2000h:01 = 1
    bool arrowsWithoutLoop = false; // 2000h:03 = 2 (Uni) or 3 (Off)
    qint32 tolerance = 5; // 2003h
    qint32 slowPoint = 0; // 2042h:01, off when <= creepPoint
    qint32 creepPoint = 150; // 2042h:02
    qint32 switchOff = 0; // 2042h:03
    qint32 endMin = kMinPosition; // 2043h
    qint32 endMax = kMaxPosition;
    bool collision = true; // 2041h:01 = 0
    qint32 collisionMin = kMinPosition; // 2044h
    qint32 collisionMax = kMaxPosition;
    int dwellMs = 1000; // 2047h:01 x 100 ms
    int followingErrorMs = 3000; // 2047h:02 x 100 ms: no shaft movement this long -> Er 3
    bool preShutdown = false; // 2041h:02: adapt the switch-off point after each positioning
    int clampMs = 0; // delay of the clamp handling, 0 = none
};

// What the simulation cannot read from the objects: the motor.
struct MotorModel
{
    double fast = 4000; // 1/100 mm per second (Eilgang)
    double medium = 1500; // Schleichgang
    double slow = 400; // Kriechgang
    // How long the spindle runs on after the motor is switched off, at the speed it had (0: it
    // stops dead). The switch-off point 2042h:03 is there to compensate this.
    int coastMs = 0;
    // Travel in the wrong direction after which the device reports Er 6 (1/100 mm).
    double directionErrorTravel = 50;
};

class Spindle
{
public:
    enum class Phase { Idle, ClampOpening, Running, Dwell, ClampClosing };

    explicit Spindle(bool motor = true)
        : m_motor(motor)
    { }

    double position() const { return m_position; }
    void setPosition(double position) { m_position = position; }
    Phase phase() const { return m_phase; }
    bool isMoving() const { return m_phase != Phase::Idle; }
    // Nothing changes with time: standing, and no Er 4 being shown.
    bool resting() const { return m_phase == Phase::Idle && m_er4Ms <= 0 && !m_newSwitchOff; }
    bool isJogging() const { return m_jog != 0; }
    int jogDirection() const { return m_jog; } // +1 right (counting up), -1 left, 0 none
    MotorModel &motor() { return m_model; }

    // Sets the target (arrows, In Position cleared) without moving. speed caps the stages
    // (plunge cut) but keeps the creep switch point. Returns the error bits (204Eh:02) that refuse
    // it (Er 8, Er 9, Er b; the motor will not start), 0 when accepted.
    quint16 setTarget(qint32 target, bool withLoop, std::optional<Speed> speed,
                      const SpindleSettings &s);
    // Starts the motor towards the accepted target (a running positioning restarts). False when
    // there is none or the device has no motor.
    bool release(const SpindleSettings &s);
    // setTarget() and release() in one.
    quint16 start(qint32 target, bool withLoop, std::optional<Speed> speed,
                  const SpindleSettings &s);
    bool hasTarget() const { return m_hasTarget; }
    // Runs until stop() or a limit; direction +1 = counting up.
    void jog(int direction, Speed speed, const SpindleSettings &s);
    // Motor off; the clamp closes after its delay.
    void stop();
    // The operator turns the shaft (only while the motor is off); delta in 1/100 mm.
    void turnByHand(double delta, const SpindleSettings &s);
    // Marks a key-press abort of an automatic positioning (status bit 1).
    void abortByKey();
    void clearManualAbort() { m_manualAbort = false; }

    void tick(int ms, const SpindleSettings &s);

    // Faults the operator (or a test) injects. A motor fault shows Er 4 when a drive command
    // comes (the motor does not start) and for kMotorFaultShownMs after; a sensor fault (NM174)
    // shows Er C and keeps the motor off while it lasts.
    static constexpr int kMotorFaultShownMs = 5000;
    void setMotorFault(bool on) { m_motorFault = on; }
    void setSensorFault(bool on);
    // The shaft does not turn although the motor is driven (Er 3 after 2047h:02).
    void setShaftBlocked(bool on) { m_blocked = on; }
    // The motor is wired the wrong way round: it turns against the direction signal (Er 6).
    void setWiringReversed(bool on) { m_reversed = on; }
    // After a positioning with dynamic pre-shutdown: the switch-off point (2042h:03) the device
    // now uses, once; nullopt when there is no new one.
    std::optional<qint32> takeSwitchOff() { return std::exchange(m_newSwitchOff, std::nullopt); }

    qint32 target() const { return m_target; }
    // Status bits (204Eh:01) owned by the motion: Moving, manual abort, speed and direction
    // outputs, arrows, In Position.
    quint16 status(const SpindleSettings &s) const;
    quint16 errors() const { return m_errors; }
    void clearErrors(quint16 bits) { m_errors &= ~bits; }

private:
    double speedFor(double remaining, const SpindleSettings &s); // also sets the stage
    void arrive(const SpindleSettings &s);
    void enterRunning();
    void checkLimits(const SpindleSettings &s);

    bool m_motor;
    MotorModel m_model;
    double m_position = 0;
    Phase m_phase = Phase::Idle;
    qint32 m_target = 0;
    bool m_hasTarget = false;
    bool m_accepted = false; // the target passed the limit checks
    std::optional<double> m_loopPoint;
    std::optional<Speed> m_cap;
    int m_jog = 0;
    int m_direction = 0; // of the running leg
    Speed m_speedStage = Speed::Slow;
    int m_phaseMs = 0; // time spent in the current timed phase
    bool m_inPosition = false;
    bool m_manualAbort = false;
    bool m_loopPending = false; // the target needs the loop still (blinking arrow)
    quint16 m_errors = 0;
    bool m_motorFault = false;
    bool m_sensorFault = false;
    int m_er4Ms = 0; // how long Er 4 is still shown
    bool driveRefused(); // a fault keeps the motor off (and shows its error)
    void failWith(quint16 error); // motor off at once, the error shown
    double speedOfStage() const;
    bool m_blocked = false;
    bool m_reversed = false;
    int m_stuckMs = 0; // driven without the shaft turning
    double m_wrongWay = 0; // travelled against the direction signal
    std::optional<qint32> m_newSwitchOff;
};

} // namespace db::nm17x
