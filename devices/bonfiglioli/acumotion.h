#pragma once

// The drive side of the simulated ACU: the state machine of control word 410 / status word 411
// (412 = 1) and the remote contacts (412 = 2), with simulated mains and STO inputs, and a
// simple motion model (constant-acceleration ramps) for the Motion Control Override modes 1, 2,
// 3, 6, -1, -2 and -3 with their status bits. The actual values 1108, 1107, 240, 1246 and 1249
// and the inputs 250 are written into the store's images (no EEPROM write).
//
// Electronic gear slave (-3): the master is a simulated speed (setMasterSpeed, u/s). Bit 4 runs
// the slave at master speed x 1123 / 1124 with the ramp 1457, bit 4 low or halt brakes with
// 1458. Once at that speed the slave is coupled (the model has no following error, so the 1168
// threshold always holds) and bit 10 "in gear" rises after 1169 ms. Direct sync (bit 6), phasing
// (bits 9, 12, 13; status bit 8) and the master/slave position correction (bit 5; status bit
// 12) are not simulated: those bits are ignored.
//
// Status values as the inverter gives them in its sequences: 0x0050, 0x0031, 0x0033, 0x0237 (bit 9
// remote is set while operation is enabled under 412 = 1; bit 4 follows the mains).

#include "acuindexed.h"
#include "acustore.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

namespace db::bonfiglioli {

class AcuMotion : public QObject
{
    Q_OBJECT
public:
    static constexpr int kTickMs = 5;
    static constexpr double kLimitSwitchTravel = 500.0; // u off a switch until it clears

    enum class State {
        SwitchOnDisabled,
        ReadyToSwitchOn,
        SwitchedOn,
        OperationEnabled,
        QuickStopActive,
        Fault
    };
    Q_ENUM(State)

    AcuMotion(AcuStore &store, AcuIndexed &indexed, QObject *parent = nullptr);

    // 410 written (already stored). Returns a VABus error code (0 = taken).
    quint16 writeControlWord(quint16 word);
    // 1454 written: the value checked (code 1 for modes MCO does not have).
    quint16 checkMode(qint64 mode) const;
    quint16 statusWord() const;
    State state() const { return m_state; }
    bool isRunning() const { return m_state == State::OperationEnabled; }
    quint16 fault() const { return m_fault; }
    void raiseFault(quint16 code);
    // 388 reactions 2 and 3: to "switch on disabled" (3 after a quick stop).
    void switchOff(bool quickStop);
    void powerCycle();

    // Simulated inputs.
    void setMains(bool on);
    void setSto(bool on);
    bool mains() const { return m_mains; }
    bool sto() const { return m_sto; }
    void setLimitSwitches(bool positive, bool negative);
    void setHomingFails(bool fails) { m_homingFails = fails; }
    // The electronic gear's master (u/s).
    void setMasterSpeed(double speed) { m_masterSpeed = speed; }
    double masterSpeed() const { return m_masterSpeed; }
    // Simulated time runs this many times faster than the clock (1 = real time; tests use more
    // so that long moves end sooner). The ramps and the "in gear" time follow it; the state
    // machine and the VABus exchange do not.
    void setTimeScale(double scale) { m_timeScale = scale > 0 ? scale : 1.0; }

    // Whether the ramps' timer runs (it stops while the power stage is off).
    bool ticking() const { return m_timer.isActive(); }
    double position() const { return m_position; }
    double velocity() const { return m_velocity; }
    qint16 mode() const;

private:
    // The ramps run every kTickMs while the power stage is on; otherwise nothing changes with
    // time, so the timer stops and only a new control word starts it again.
    void tick();
    bool resting() const;
    void wake();
    void modeEdges(quint16 old, quint16 word);
    void startBlock(int block);
    void finishBlock();
    void moveTowards(double target, double vmax, double acc, double dec, double dt);
    void rampVelocity(double target, double acc, double dec, double dt);
    void publish();
    double param(quint16 p, double fallback) const;
    double overrideParam(quint16 p, double fallback) const;
    bool positioningConfig() const;
    double uPerRpm() const;

    AcuStore &m_store;
    AcuIndexed &m_indexed;
    QTimer m_timer;
    QElapsedTimer m_clock;
    State m_state = State::SwitchOnDisabled;
    quint16 m_word = 0;
    quint16 m_fault = 0;
    bool m_mains = true;
    bool m_sto = true;
    bool m_limitPositive = false;
    bool m_limitNegative = false;
    double m_limitClearAt = 0.0;
    bool m_homingFails = false;
    double m_position = 0.0;
    double m_velocity = 0.0;
    double m_target = 0.0;
    bool m_positioning = false; // a profile position or block move runs
    bool m_setPointAck = false; // 411 bit 12 in profile position mode
    bool m_pending = false; // a buffered set-point (bits 5 and 9 low)
    double m_pendingTarget = 0.0;
    bool m_homing = false;
    bool m_homed = false;
    bool m_homingError = false;
    bool m_leavingSwitch = false;
    int m_block = 0; // 1246: active motion block, 0 = none
    int m_resumeBlock = -1; // 1249
    bool m_sequence = false;
    double m_blockSpeed = 0.0;
    double m_blockAcc = 0.0;
    double m_blockDec = 0.0;
    double m_masterSpeed = 0.0;
    double m_gearCoupledMs = -1.0; // time the slave has been coupled; < 0: not coupled
    double m_timeScale = 1.0;
};

} // namespace db::bonfiglioli
