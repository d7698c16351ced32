#pragma once

#include "simulation/cia402machine.h"
#include "simulation/objectstore.h"
#include "simulation/simulatedaxis.h"

#include <QByteArray>
#include <QElapsedTimer>
#include <QHash>
#include <QObject>
#include <QSet>

#include <functional>
#include <optional>

class QTimer;

namespace db::sim {

// How this simulated drive differs from the defaults (test fixtures, simulator command line).
struct MovingCapOptions
{
    // Rotary drive: accelerations in [100 rpm/min] of the motor (spec 9.1); linear drive:
    // [1000 units/s^2].
    bool rotary = true;
    // TPSR BIT8 "inverter voltage" while powered (spec 3.5 [R]); the 2021 firmware of the
    // Docklight log did not set it.
    bool tpsrInverterVoltageBit = true;
    // Mechanical stops in position units at power-up (none by default: a turntable has none).
    std::optional<double> hardStopNegative;
    std::optional<double> hardStopPositive;
    // Factory values that differ from the description and the simulator's choices
    // (e.g. 3511h.8 = 110 for the Docklight transcript).
    QHash<ObjectAddress, QVariant> initialValues;
    SimulatedAxis::Model axisModel;
};

// The simulated MovingCap ETH drive (movingcap.md 11.2): object dictionary values, the CiA 402
// state machine, one axis, faults/EMCY, digital I/O with input and output functions, and the
// RefGo-level operations. Time advances only through advance() (tests) or the real-time timer
// started by startRealTime() (servers). All calls are synchronous; signals are emitted directly.
// In real time the timer runs only while the model changes with time: a drive without power and
// with nothing scheduled rests, and a call from outside first brings it up to the present.
class MovingCapDrive : public QObject
{
    Q_OBJECT
public:
    explicit MovingCapDrive(const ObjectDictionary &dictionary,
                            const MovingCapOptions &options = {}, QObject *parent = nullptr);
    ~MovingCapDrive() override;

    // ---- objects (errors: "object 1234:0 does not exist", "6041:0 is read-only", range) ----
    Result<QVariant> read(ObjectAddress address);
    Result<void> write(ObjectAddress address, const QVariant &value);

    // ---- time, power, faults, inputs ----
    void advance(double seconds);
    void startRealTime(int periodMs = 5);
    void stopRealTime();
    void powerCycle(); // working set := stored NVM image, faults cleared, Switch on disabled
    void injectFault(quint16 emcyCode);
    void setWarnings(quint32 warningBits); // 1002h bits 16 and up; no fault
    void setPhysicalInput(int number, bool high); // IN1..IN10

    // ---- RefGo-level operations (spec 3.3); motion refused in fault state ----
    Result<void> go(std::optional<qint64> target = std::nullopt); // G, G<x>
    Result<void> goWay(std::optional<qint64> distance = std::nullopt); // GW, GW<x>
    Result<void> setTargetPosition(qint64 target); // PO
    Result<void> setWay(qint64 distance); // WA
    Result<void> setSpeed(qint64 velocity); // SP
    Result<void> stopMotion(); // SM
    // The fieldbus master went away (life guarding or heartbeat event): the CiA 402 abort
    // connection reaction of 6007h (0 none, 1 fault, 2 disable voltage, 3 quick stop with 605Ah).
    void connectionLost();
    Result<void> continueMotion(); // CM
    Result<void> powerContinue(); // PWC
    Result<void> powerQuit(); // PQ
    Result<void> reference(std::optional<int> method); // REF
    Result<void> jog(int direction, std::optional<int> milliseconds = std::nullopt); // JP/JN
    Result<void> repeatReverse(std::optional<qint64> distance = std::nullopt); // RR
    void setRepeatWay(qint64 distance); // RW
    void setRepeatWait(qint64 milliseconds); // WT
    Result<void> setOutput(int number, bool high); // SO/CO
    Result<bool> input(int number) const; // TI
    quint32 tpsr() const; // TPSR bits
    int ts() const; // TS 0/1/2/9

    // ---- failure mode (tests, drivebench-sim --reject-write) ----
    // Valid writes to these objects fail with a device error (CANopen abort 08000022 "present
    // device state"), as a drive refusing a parameter in its current state would.
    void setRejectedWrites(const QSet<ObjectAddress> &addresses) { m_rejectedWrites = addresses; }

    // ---- observation ----
    cia402::State state() const { return m_machine.state(); }
    quint16 statusword() const;
    bool ticking() const; // the real-time timer runs (it stops while the drive rests)
    double time() const; // s; at rest in real time, including the time since the last step
    const ObjectDictionary &dictionary() const { return m_store.dictionary(); }
    const SimulatedAxis &axis() const { return m_axis; }

Q_SIGNALS:
    void statusChanged(quint16 statusword);
    // EMCY content (spec 7.1): data8 = code LE, error register, five zero bytes.
    void emergency(quint16 code, quint8 errorRegister, const QByteArray &data8);

private:
    using Effects = Cia402Machine::Effects;

    // movingcapdrive.cpp: time, state machine glue
    void stepOnce(double dt);
    void handle(const Effects &effects);
    void applyControlword(quint16 controlword);
    Result<void> ensureOperational(int mode);
    void setMode(int mode);
    void applyParameters();
    void emitStatusIfChanged();
    void schedule(double delaySeconds, std::function<void()> action);
    // Real time: the model rests when nothing in it changes with time (no power, nothing
    // scheduled, no stop ramp running); the timer is then stopped. Every call from outside brings
    // the model up to the present first (catchUp) and starts the timer again afterwards (wake),
    // so a command is applied at the moment it arrives.
    bool resting() const;
    void catchUp();
    void wake();
    class Present
    {
    public:
        explicit Present(MovingCapDrive *drive)
            : m_drive(drive)
        {
            m_drive->catchUp();
        }
        ~Present() { m_drive->wake(); }
        Q_DISABLE_COPY_MOVE(Present)

    private:
        MovingCapDrive *m_drive;
    };
    // movingcapdrive_objects.cpp: computed objects and writes with side effects
    void refreshComputed();
    Result<void> writeSpecial(ObjectAddress address, const QVariant &raw, bool &handled);
    double accelerationToUser(qint64 raw) const;
    double userToIncrements() const;
    // movingcapdrive_commands.cpp: motion helpers
    Result<void> refuseInFault() const;
    void startPositionMove(double target, bool immediate, double maxVelocity, double acceleration,
                           double deceleration);
    void startPositionMove(double target, bool immediate);
    void startVelocity(double velocity);
    void startHoming(int method, double offset);
    double relativeBase() const;
    // Rotary (60F2h bits 6-7 with 607Dh.1 < 607Dh.2): positions wrap into [607Dh.1, 607Dh.2).
    // The axis runs unwrapped; 6064h shows the wrapped position, and an absolute target is
    // reached from the present one the way bits 6-7 say (shortest, positive or negative only).
    bool rotaryPositions() const;
    double shownPosition(double unwrapped) const;
    double absoluteTarget(double target) const;
    void stepRepeat();
    void noteInterruption();
    // movingcapdrive_io.cpp: inputs, input functions, outputs
    quint32 combinedInputs() const;
    void processInputs(quint32 before);
    void runInputFunction(int input, int function, bool rising);
    void timedMotion(int input, bool relative);
    void evaluateSoftwareEnable();
    bool teachActive() const;
    quint32 outputs() const;
    bool outputFunction(int output, int function) const;

    MovingCapOptions m_options;
    ObjectStore m_store;
    Cia402Machine m_machine;
    SimulatedAxis m_axis;
    double m_time = 0.0;
    QTimer *m_timer = nullptr;
    QElapsedTimer m_clock;
    int m_periodMs = 5;
    bool m_realTime = false;
    bool m_advancing = false;

    struct Pending
    {
        double due;
        quint64 generation;
        std::function<void()> action;
    };
    QList<Pending> m_pending;
    quint64 m_motionGeneration = 0; // a new motion command cancels older timed actions

    quint32 m_physicalInputs = 0;
    quint32 m_manualOutputs = 0;
    quint32 m_errorBits = 0;
    quint32 m_warningBits = 0;
    quint8 m_errorRegister = 0;
    QList<quint16> m_history; // newest first, at most four
    quint16 m_lastError = 0;

    double m_lastTarget = 0.0; // last commanded absolute target (relative moves, RR, CM)
    qint64 m_way = 0; // WA
    std::optional<qint64> m_speed; // SP (jog speed)
    bool m_setPointAcknowledge = false;
    bool m_homingRun = false;
    enum class Interrupted { None, Position, Velocity };
    Interrupted m_interrupted = Interrupted::None;
    double m_interruptedVelocity = 0.0;
    QHash<int, double> m_inputTargets; // last target per input (functions 4/6)

    struct Repeat
    {
        bool active = false;
        double from = 0.0;
        double to = 0.0;
        double waitUntil = -1.0;
    };
    Repeat m_repeat;
    qint64 m_repeatWay = 0;
    qint64 m_repeatWaitMs = 0;

    double m_temperature = 35.0;
    quint16 m_lastStatusword = 0xFFFF;
    QSet<ObjectAddress> m_rejectedWrites;
};

} // namespace db::sim
