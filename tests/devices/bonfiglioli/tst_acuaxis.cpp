// Level 3: the ACTIVE Cube axis and the PLCopen command model on it, against the simulated ACU
// over loopback TCP: enable and its preconditions, each mode's handshake (profile position,
// profile velocity, velocity in rpm, homing, table travel, move away from the limit switch),
// halt and quick stop, the refusals (mode change while moving, the override value -1, no
// positioning control) and the fault reset; every control word goes to a RAM data set.

#include "devices/axisfactory.h"
#include "devices/bonfiglioli/acuaxis.h"
#include "devices/bonfiglioli/acudescription.h"
#include "devices/bonfiglioli/acusteps.h"
#include "devices/bonfiglioli/simulatedacu.h"
#include "motion/leasedmove.h"
#include "motion/motionaxis.h"
#include "vabus/vabusconnection.h"
#include "wait.h"

#include <QtTest>

#include <memory>

using namespace db;
using namespace db::motion;
using db::bonfiglioli::AcuAxis;
using db::bonfiglioli::SimulatedAcu;

namespace {

Result<QVariant> await(Reply *reply, int timeoutMs = 10000)
{
    return db::test::await(reply, timeoutMs);
}

MoveParams params(double position, double velocity = 20000, double acceleration = 100000)
{
    MoveParams p;
    p.position = position;
    p.velocity = velocity;
    p.acceleration = p.deceleration = acceleration;
    p.jerk = 1e9;
    return p;
}

} // namespace

class TstAcuAxis : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void init()
    {
        m_acu = std::make_unique<SimulatedAcu>();
        QVERIFY(m_acu->listen(0).ok());
        const auto uri =
            ConnectionUri::parse(QStringLiteral("vabus://127.0.0.1:%1").arg(m_acu->port()));
        m_connection = std::make_unique<vabus::VabusConnection>(uri.value());
        m_connection->setDictionary(bonfiglioli::acuDictionary());
        QVERIFY(m_connection->openAndWait(3000).ok());
        auto made = devices::makeAxis(m_connection.get());
        QVERIFY(made.ok());
        m_axis.reset(qobject_cast<AcuAxis *>(made.value().release()));
        QVERIFY(m_axis);
        QVERIFY(await(m_axis->initialize()).ok());
        m_model = std::make_unique<MotionAxis>(m_axis.get());
        m_model->setConfig(m_axis->limits());
        m_eepromBefore = m_acu->eepromWrites();
        DB_TRY_VERIFY(m_axis->status().valid);
    }
    void cleanup()
    {
        if (m_acu) {
            QCOMPARE(m_acu->controlWritesEeprom(), quint64(0));
            QCOMPARE(m_acu->eepromWrites(), m_eepromBefore);
        }
        m_model.reset();
        m_axis.reset();
        m_connection.reset();
        m_acu.reset();
    }

    void factoryGivesAcuAxis()
    {
        QCOMPARE(m_axis->configuration(), 240);
        QVERIFY(m_axis->hasPositioning());
        QVERIFY(m_axis->features() & AxisInterface::Feature::ProfilePosition);
        QCOMPARE(m_axis->velocityUnit(), QStringLiteral("u/s"));
        QCOMPARE(m_axis->limits().positionWindow, 182.0); // 1165
    }

    void enableWalksTheStateMachine()
    {
        QCOMPARE(m_axis->status().rawStatus & 0x006F, 0x0040); // switch on disabled
        QVERIFY(power(true));
        QCOMPARE(m_acu->statusWord() & 0x02FF, 0x0237); // 0xnn37 with remote (bit 9)
        QVERIFY(m_acu->controlWritesRam() >= 4); // 0x0000, 0x0006, 0x0007, 0x000F
        QVERIFY(power(false));
        QCOMPARE(m_acu->statusWord() & 0x006F, 0x0040);
    }

    // A wait step is judged by its own read of 411: one queued behind other requests past the
    // step's time (here 1 ms behind 200 reads) is an answer, not a timeout.
    void waitJudgedByItsOwnStatusRead()
    {
        QList<Reply *> ahead;
        for (int i = 0; i < 200; ++i)
            ahead.append(m_connection->read(ObjectAddress(12, 0)));
        auto *steps = new bonfiglioli::AcuSteps(m_axis.get(), QStringLiteral("slow queue"));
        steps->waitStatus([](quint16 word) { return (word & 0x006F) == 0x0040; }, 1,
                          QStringLiteral("not switch on disabled"));
        QElapsedTimer clock;
        clock.start();
        Result<QVariant> r = await(steps->start());
        QVERIFY2(r.ok(), qPrintable(r.error().toString()));
        QVERIFY(clock.elapsed() > 1);
        for (Reply *reply : ahead) {
            QVERIFY(reply->isFinished());
            reply->deleteLater();
        }
    }

    void enableNeedsMainsAndSto()
    {
        m_acu->motion().setMains(false);
        Result<QVariant> r = await(m_axis->power(true));
        QVERIFY(!r.ok());
        QVERIFY2(r.error().message().contains(QLatin1String("no mains voltage")),
                 qPrintable(r.error().message()));
        m_acu->motion().setMains(true);
        m_acu->motion().setSto(false);
        r = await(m_axis->power(true));
        QVERIFY(!r.ok());
        QVERIFY2(r.error().message().contains(QLatin1String("STO")),
                 qPrintable(r.error().message()));
        QCOMPARE(m_acu->statusWord() & 0x006F, 0x0023); // stays in "switched on" (0x33)
        m_acu->motion().setSto(true);
        QVERIFY(await(m_axis->power(true)).ok());
        m_acu->motion().setSto(false); // STO lost while enabled: back to "switched on"
        QCOMPARE(m_acu->statusWord() & 0x006F, 0x0023);
    }

    void moveAbsoluteHandshake()
    {
        m_acu->motion().setTimeScale(5);
        QVERIFY(power(true));
        MotionCommand move(m_model.get(), CommandKind::MoveAbsolute);
        move.setParams(params(30000));
        move.setExecute(true);
        // The drive acknowledges the set-point (bit 12) and moves before Done.
        DB_TRY_VERIFY_WITH_TIMEOUT(m_axis->status().moving, 3000);
        QCOMPARE(m_acu->motion().mode(), qint16(1));
        DB_TRY_COMPARE_WITH_TIMEOUT(move.status(), MotionCommand::Status::Done, 10000);
        QCOMPARE(m_acu->motion().position(), 30000.0);
        QVERIFY(m_acu->statusWord() & 0x0400); // target reached
        QVERIFY(!(m_acu->statusWord() & 0x1000)); // bit 4 fell, so did bit 12
        // Relative and additive moves add to the actual position and to the last target.
        MotionCommand add(m_model.get(), CommandKind::MoveAdditive);
        add.setParams(params(5000));
        add.setExecute(true);
        DB_TRY_COMPARE_WITH_TIMEOUT(add.status(), MotionCommand::Status::Done, 10000);
        QCOMPARE(m_acu->motion().position(), 35000.0);
        MotionCommand rel(m_model.get(), CommandKind::MoveRelative);
        rel.setParams(params(-2000));
        rel.setExecute(true);
        DB_TRY_COMPARE_WITH_TIMEOUT(rel.status(), MotionCommand::Status::Done, 10000);
        QCOMPARE(m_acu->motion().position(), 33000.0);
    }

    void newTargetWhileMovingChangesImmediately()
    {
        QVERIFY(power(true));
        MotionCommand first(m_model.get(), CommandKind::MoveAbsolute);
        first.setParams(params(100000, 10000));
        first.setExecute(true);
        DB_TRY_VERIFY_WITH_TIMEOUT(m_acu->motion().position() > 1000, 5000);
        MotionCommand second(m_model.get(), CommandKind::MoveAbsolute);
        second.setParams(params(3000, 10000));
        second.setExecute(true);
        DB_TRY_COMPARE_WITH_TIMEOUT(first.status(), MotionCommand::Status::CommandAborted, 3000);
        DB_TRY_COMPARE_WITH_TIMEOUT(second.status(), MotionCommand::Status::Done, 10000);
        QCOMPARE(m_acu->motion().position(), 3000.0);
    }

    void velocityAndHalt()
    {
        QVERIFY(power(true));
        MotionCommand velocity(m_model.get(), CommandKind::MoveVelocity);
        velocity.setParams(params(0, -5000));
        velocity.setExecute(true);
        DB_TRY_COMPARE_WITH_TIMEOUT(velocity.status(), MotionCommand::Status::Done, 5000);
        QCOMPARE(m_acu->motion().mode(), qint16(3)); // profile velocity [u/s]
        QCOMPARE(m_acu->motion().velocity(), -5000.0);
        QVERIFY(m_acu->statusWord() & 0x0400); // at the target velocity (1276 window)
        MotionCommand halt(m_model.get(), CommandKind::Halt);
        halt.setParams(params(0, 0, 50000));
        halt.setExecute(true);
        DB_TRY_COMPARE_WITH_TIMEOUT(halt.status(), MotionCommand::Status::Done, 5000);
        QCOMPARE(m_acu->motion().velocity(), 0.0);
        QVERIFY(m_axis->controlWord() & 0x0100); // halt bit
        QVERIFY(m_acu->isRunning()); // halt stays in "operation enabled"
    }

    // The command model refuses a command that needs another MCO mode while the axis moves,
    // before anything is written: the command ends in Error with the rule, the running
    // velocity move goes on, and the axis is neither stopped nor in ErrorStop.
    void modeChangeWhileMovingIsRefused()
    {
        QVERIFY(power(true));
        MotionCommand velocity(m_model.get(), CommandKind::MoveVelocity);
        velocity.setParams(params(0, 5000));
        velocity.setExecute(true);
        DB_TRY_COMPARE_WITH_TIMEOUT(velocity.status(), MotionCommand::Status::Done, 5000);
        DB_TRY_VERIFY(m_axis->status().moving);
        QVERIFY(m_axis->needsModeChange(CommandKind::MoveAbsolute));
        QVERIFY(!m_axis->needsModeChange(CommandKind::MoveVelocity));
        QVERIFY(!m_axis->needsModeChange(CommandKind::Halt));
        QCOMPARE(m_model->preview(CommandKind::MoveAbsolute, params(0)).refusal,
                 Refusal::ModeChangeWhileMoving);
        const quint64 controlWrites = m_acu->controlWritesRam();
        const quint16 controlWord = m_axis->controlWord();
        MotionCommand move(m_model.get(), CommandKind::MoveAbsolute);
        move.setParams(params(0));
        move.setExecute(true);
        QCOMPARE(move.status(), MotionCommand::Status::Busy); // a fresh edge first
        DB_TRY_COMPARE_WITH_TIMEOUT(move.status(), MotionCommand::Status::Error, 3000);
        QCOMPARE(move.refusal(), Refusal::ModeChangeWhileMoving);
        QVERIFY2(
            move.error().message().contains(QLatin1String("refused: mode change while moving")),
            qPrintable(move.error().message()));
        // Nothing was sent and nothing stopped.
        QCOMPARE(m_acu->controlWritesRam(), controlWrites);
        QCOMPARE(m_axis->controlWord(), controlWord);
        QCOMPARE(m_acu->motion().mode(), qint16(3)); // 1454 untouched
        QCOMPARE(m_model->state(), AxisState::ContinuousMotion);
        QCOMPARE(velocity.status(), MotionCommand::Status::Done);
        QCOMPARE(m_model->activeCommand(), &velocity);
        QCOMPARE(m_acu->motion().state(), bonfiglioli::AcuMotion::State::OperationEnabled);
        QCOMPARE(m_acu->motion().velocity(), 5000.0);
        // Halted to rest, the same move is taken: the mode changes at standstill.
        MotionCommand halt(m_model.get(), CommandKind::Halt);
        halt.setParams(params(0, 0, 100000));
        halt.setExecute(true);
        DB_TRY_COMPARE_WITH_TIMEOUT(halt.status(), MotionCommand::Status::Done, 5000);
        halt.setExecute(false);
        DB_TRY_VERIFY(!m_axis->status().moving);
        move.setExecute(false);
        move.setExecute(true);
        DB_TRY_COMPARE_WITH_TIMEOUT(move.status(), MotionCommand::Status::Done, 10000);
        QCOMPARE(m_acu->motion().mode(), qint16(1));
        QCOMPARE(m_acu->motion().position(), 0.0);
    }

    void overrideOffValueIsNeverSent()
    {
        QVERIFY(power(true));
        const Result<QVariant> r = await(m_axis->moveTo(-1, { 1000, 1000, 1000, 0 }));
        QVERIFY(!r.ok());
        QVERIFY(r.error().message().contains(QLatin1String("-1 u cannot be approached")));
        QVERIFY(!await(m_axis->moveVelocity(-1, { 0, 1000, 1000, 0 })).ok());
        QVERIFY(m_acu->store().value(1455, 0).toLongLong() != -1
                || m_acu->motion().mode() != 1); // never written as a target
    }

    void homing()
    {
        QVERIFY(power(true));
        MotionCommand home(m_model.get(), CommandKind::Home);
        HomingParams h = m_axis->driveHoming();
        h.method = 17;
        home.setHoming(h);
        home.setExecute(true);
        DB_TRY_COMPARE_WITH_TIMEOUT(home.status(), MotionCommand::Status::Done, 10000);
        QCOMPARE(m_acu->motion().mode(), qint16(6));
        QCOMPARE(m_acu->store().value(1130, 0).toInt(), 17);
        QVERIFY(m_acu->statusWord() & 0x1000); // homing attained
        QCOMPARE(m_acu->motion().position(), 0.0);
    }

    void homingErrorFails()
    {
        QVERIFY(power(true));
        m_acu->motion().setHomingFails(true);
        const Result<QVariant> r = await(m_axis->home(m_axis->driveHoming()));
        QVERIFY(!r.ok());
        QVERIFY2(r.error().message().contains(QLatin1String("homing error")),
                 qPrintable(r.error().message()));
        QVERIFY(m_acu->statusWord() & 0x2000);
    }

    void tableTravelSingleAndSequence()
    {
        m_acu->motion().setTimeScale(10); // block 4 travels 123000 u
        QVERIFY(power(true));
        QVERIFY(await(m_axis->startMotionBlock(2, false, false)).ok());
        QCOMPARE(m_acu->motion().mode(), qint16(-1));
        QCOMPARE(m_acu->motion().position(), 5000.0);
        QCOMPARE(m_acu->store().value(1246, 0).toInt(), 0); // no block active any more
        QVERIFY(!(m_acu->statusWord() & 0x0100));
        // Block 4 (123000 u) hands over to block 2 (5000 u) in a sequence; 1246 shows each.
        Reply *sequence = m_axis->startMotionBlock(4, true, false);
        DB_TRY_COMPARE_WITH_TIMEOUT(m_acu->store().value(1246, 0).toInt(), 4, 3000);
        QVERIFY(m_acu->statusWord() & 0x0100); // motion block in progress
        DB_TRY_COMPARE_WITH_TIMEOUT(m_acu->store().value(1246, 0).toInt(), 2, 15000);
        QVERIFY(await(sequence, 15000).ok());
        QCOMPARE(m_acu->motion().position(), 5000.0);
    }

    // Table travel through the command model: Busy until the block ended, then Done; refused
    // while the axis moves in another mode.
    void motionBlockCommand()
    {
        QVERIFY(power(true));
        MotionCommand block(m_model.get(), CommandKind::MotionBlock);
        MoveParams p;
        p.block = 3; // relative 2000 u
        block.setParams(p);
        block.setExecute(true);
        QVERIFY(block.isBusy());
        DB_TRY_COMPARE_WITH_TIMEOUT(block.status(), MotionCommand::Status::Done, 10000);
        QCOMPARE(m_acu->motion().position(), 2000.0);
        QCOMPARE(m_model->state(), AxisState::Standstill);
        MotionCommand velocity(m_model.get(), CommandKind::MoveVelocity);
        velocity.setParams(params(0, 3000));
        velocity.setExecute(true);
        DB_TRY_COMPARE_WITH_TIMEOUT(velocity.status(), MotionCommand::Status::Done, 5000);
        block.setExecute(false);
        block.setExecute(true);
        DB_TRY_COMPARE_WITH_TIMEOUT(block.status(), MotionCommand::Status::Error, 3000);
        QCOMPARE(block.refusal(), Refusal::NotAtStandstill);
    }

    void moveAwayFromLimitSwitch()
    {
        QVERIFY(power(true));
        m_acu->motion().setLimitSwitches(true, false);
        const double before = m_acu->motion().position();
        QVERIFY(await(m_axis->moveAwayFromLimitSwitch()).ok());
        QCOMPARE(m_acu->motion().position(), before - 500.0); // away from the positive switch
        m_acu->motion().setLimitSwitches(true, true); // both: F1449
        QVERIFY(!await(m_axis->moveAwayFromLimitSwitch()).ok());
        QCOMPARE(m_acu->fault(), quint16(0x1449));
    }

    // Electronic gear slave (1454 = -3): bit 4 starts the gear, status bit 10 rises once the
    // slave runs at master speed x 1123 / 1124 for 1169 ms; halt brakes to 0 with bit 10 at
    // speed 0; a positioning command afterwards changes the mode at rest.
    void electronicGear()
    {
        QVERIFY(power(true));
        m_acu->motion().setMasterSpeed(3000);
        QVERIFY(await(m_connection->write(ObjectAddress(1169, 5), qulonglong(50))).ok());
        const Result<QVariant> geared = await(m_axis->gearIn(3, 2, 100000, 100000)); // RAM
        QVERIFY2(geared.ok(), qPrintable(geared.error().message()));
        QCOMPARE(m_acu->motion().mode(), qint16(-3));
        QCOMPARE(m_axis->mode(), AcuAxis::Mode::ElectronicGear);
        QCOMPARE(m_acu->motion().velocity(), 4500.0); // 3000 x 3 / 2
        QVERIFY(m_acu->statusWord() & 0x0400); // in gear
        m_acu->motion().setMasterSpeed(1000); // the master slows: out of gear until coupled
        DB_TRY_VERIFY(!(m_acu->statusWord() & 0x0400));
        DB_TRY_COMPARE(m_acu->motion().velocity(), 1500.0);
        DB_TRY_VERIFY(m_acu->statusWord() & 0x0400);
        // Other modes are refused while the slave turns, then taken at rest.
        QVERIFY(m_axis->needsModeChange(CommandKind::MoveAbsolute));
        DB_TRY_VERIFY(m_axis->status().moving);
        QCOMPARE(m_model->preview(CommandKind::MoveAbsolute, params(0)).refusal,
                 Refusal::ModeChangeWhileMoving);
        QVERIFY(await(m_axis->halt(100000)).ok());
        DB_TRY_COMPARE(m_acu->motion().velocity(), 0.0);
        QVERIFY(m_acu->statusWord() & 0x0400); // halt: bit 10 at speed 0
        DB_TRY_VERIFY(!m_axis->status().moving);
        QVERIFY(await(m_axis->moveTo(0, { 20000, 100000, 100000, 0 })).ok());
        QCOMPARE(m_acu->motion().mode(), qint16(1));
    }

    // MC_GearIn / MC_GearOut on the command model: Busy until the inverter reports "in gear"
    // (status bit 10), then Done (InGear) with the axis in Synchronized Motion; the ratio and
    // the ramps go to RAM data sets; MC_GearOut drops bit 4 and the slave brakes to a stop.
    void gearInAndOutCommands()
    {
        QVERIFY(power(true));
        m_acu->motion().setMasterSpeed(2000);
        QVERIFY(await(m_connection->write(ObjectAddress(1169, 5), qulonglong(300))).ok());
        MotionCommand gearIn(m_model.get(), CommandKind::GearIn);
        MoveParams p = params(0, 0, 80000);
        p.gearNumerator = 5;
        p.gearDenominator = 4;
        gearIn.setParams(p);
        gearIn.setExecute(true);
        QVERIFY(gearIn.isBusy());
        QCOMPARE(m_model->state(), AxisState::SynchronizedMotion);
        // Coupling takes the ramp plus 300 ms of "gear coupled" time: Busy, not yet in gear.
        DB_TRY_COMPARE_WITH_TIMEOUT(m_acu->motion().mode(), qint16(-3), 3000);
        QVERIFY(gearIn.isBusy());
        QVERIFY(!(m_acu->statusWord() & 0x0400));
        DB_TRY_COMPARE_WITH_TIMEOUT(gearIn.status(), MotionCommand::Status::Done, 10000);
        QVERIFY(m_acu->statusWord() & 0x0400); // in gear
        QCOMPARE(m_acu->motion().velocity(), 2500.0); // 2000 x 5 / 4
        QCOMPARE(m_acu->store().value(1123, 0).toInt(), 5);
        QCOMPARE(m_acu->store().value(1124, 0).toInt(), 4);
        QCOMPARE(m_acu->store().value(1457, 0).toInt(), 80000);
        QCOMPARE(m_model->state(), AxisState::SynchronizedMotion);

        MotionCommand gearOut(m_model.get(), CommandKind::GearOut);
        gearOut.setParams(params(0, 0, 50000));
        gearOut.setExecute(true);
        DB_TRY_COMPARE_WITH_TIMEOUT(gearOut.status(), MotionCommand::Status::Done, 10000);
        QCOMPARE(gearIn.status(), MotionCommand::Status::CommandAborted);
        QCOMPARE(m_acu->motion().velocity(), 0.0);
        QCOMPARE(m_acu->store().value(1458, 0).toInt(), 50000);
        QCOMPARE(m_model->state(), AxisState::Standstill);
        QVERIFY(!(m_acu->store().value(410, 0).toUInt() & 0x0010)); // bit 4 low
    }

    // Refusals before anything is sent: a bad ratio, a gear started while another mode moves
    // the axis, and MC_GearOut when the inverter is not coupled.
    void gearRefusals()
    {
        QVERIFY(power(true));
        MotionCommand gearIn(m_model.get(), CommandKind::GearIn);
        MoveParams p = params(0, 0, 80000);
        p.gearDenominator = 0;
        gearIn.setParams(p);
        gearIn.setExecute(true);
        DB_TRY_COMPARE(gearIn.status(), MotionCommand::Status::Error);
        QCOMPARE(gearIn.refusal(), Refusal::InvalidGearRatio);
        QVERIFY(gearIn.error().message().contains(QLatin1String("denominator")));
        QVERIFY(m_acu->motion().mode() != -3);

        MotionCommand reset(m_model.get(), CommandKind::Reset);
        reset.setExecute(true);
        DB_TRY_VERIFY(reset.isFinished());
        QVERIFY(power(true));
        MotionCommand velocity(m_model.get(), CommandKind::MoveVelocity);
        velocity.setParams(params(0, 3000));
        velocity.setExecute(true);
        DB_TRY_COMPARE_WITH_TIMEOUT(velocity.status(), MotionCommand::Status::Done, 5000);
        p.gearDenominator = 1;
        gearIn.setParams(p);
        gearIn.setExecute(false);
        gearIn.setExecute(true);
        DB_TRY_COMPARE(gearIn.status(), MotionCommand::Status::Error);
        QCOMPARE(gearIn.refusal(), Refusal::ModeChangeWhileMoving);
        QCOMPARE(m_acu->motion().velocity(), 3000.0); // the running motion goes on
        QCOMPARE(velocity.status(), MotionCommand::Status::Done);

        // Not coupled: the inverter's own mode says so.
        const Result<QVariant> out = await(m_axis->gearOut(0));
        QVERIFY(!out.ok());
        QVERIFY2(out.error().message().contains(QLatin1String("1454 = -3")),
                 qPrintable(out.error().message()));
    }

    // The jog moves in leases: when the renewals stop (the program died), the drive ends the
    // motion by itself at the last leased target.
    void leasedJogStopsWhenRenewalsStop()
    {
        QVERIFY(power(true));
        auto lease = std::make_unique<LeasedMove>(m_model.get());
        lease->jog(+1, params(0, 5000, 50000));
        DB_TRY_VERIFY_WITH_TIMEOUT(m_acu->motion().position() > 2000, 5000); // renewed
        QVERIFY(m_acu->motion().velocity() > 0);
        const double leaseMs = lease->leaseTimeMs();
        m_model->setWatchdogTimeout(0); // only the drive's side acts now
        lease.reset();
        QElapsedTimer clock;
        clock.start();
        DB_TRY_COMPARE_WITH_TIMEOUT(m_acu->motion().velocity(), 0.0, 3000);
        QVERIFY2(clock.elapsed() <= leaseMs + 200, qPrintable(QString::number(clock.elapsed())));
    }

    void linkSilenceShowsTimeLeft()
    {
        QVERIFY(m_axis->linkSupervision().contains(QLatin1String("388 = 1")));
        QVERIFY(!m_axis->linkSupervision().contains(QLatin1String("No answer")));
        vabus::Server::FailureMode silent;
        silent.failure = vabus::Server::Failure::Silent;
        m_acu->server().setFailure(silent);
        DB_TRY_VERIFY_WITH_TIMEOUT(m_axis->linkSupervision().contains(QLatin1String("No answer")),
                                   5000);
        QVERIFY2(m_axis->linkSupervision().contains(QLatin1String("reacts in")),
                 qPrintable(m_axis->linkSupervision()));
        m_acu->server().setFailure({});
    }

    // A silent inverter: the first read's own failure ends initialize() at once, and the
    // reads queued behind it are dropped instead of timing out one after the other.
    void initializeAgainstASilentInverterFailsAtOnce()
    {
        vabus::Server::FailureMode silent;
        silent.failure = vabus::Server::Failure::Silent;
        m_acu->server().setFailure(silent);
        QElapsedTimer clock;
        clock.start();
        const auto init = await(m_axis->initialize(), 60000);
        const qint64 elapsed = clock.elapsed();
        QVERIFY(!init.ok());
        QCOMPARE(init.error().kind(), Error::Kind::Timeout);
        // One request's time limit with its retransmissions, not twelve of them.
        QVERIFY2(elapsed < 8000, qPrintable(QString::number(elapsed)));
        m_acu->server().setFailure({});
        // Nothing of the dropped reads is left in the queue ahead of the next request.
        QElapsedTimer next;
        next.start();
        QVERIFY(await(m_connection->read(ObjectAddress(30, 0)), 5000).ok());
        QVERIFY2(next.elapsed() < 2500, qPrintable(QString::number(next.elapsed())));
    }

    void quickStop()
    {
        QVERIFY(power(true));
        QVERIFY(await(m_axis->moveVelocity(8000, { 0, 100000, 100000, 0 })).ok());
        DB_TRY_VERIFY(m_acu->motion().velocity() > 1000);
        QVERIFY(await(m_axis->stopNow()).ok());
        QCOMPARE(m_acu->motion().state(), bonfiglioli::AcuMotion::State::QuickStopActive);
        DB_TRY_COMPARE_WITH_TIMEOUT(m_acu->motion().velocity(), 0.0, 2000);
    }

    void faultResetAfterF2714()
    {
        QVERIFY(power(true));
        m_acu->raiseFault(0x2714);
        DB_TRY_VERIFY(m_axis->status().fault);
        MotionCommand reset(m_model.get(), CommandKind::Reset);
        reset.setExecute(true);
        DB_TRY_VERIFY_WITH_TIMEOUT(reset.isFinished(), 5000);
        QVERIFY2(reset.status() == MotionCommand::Status::Done,
                 qPrintable(reset.error().message()));
        QCOMPARE(m_acu->fault(), quint16(0));
        QCOMPARE(m_axis->faultCode(), quint16(0x2714)); // read from 260 before the reset
    }

    void withoutPositioningOnlyVelocityInRpm()
    {
        QVERIFY(await(m_connection->write(ObjectAddress(30, 5), qulonglong(210))).ok());
        QVERIFY(await(m_axis->initialize()).ok());
        QVERIFY(!m_axis->hasPositioning());
        QCOMPARE(m_axis->features(),
                 AxisInterface::Features(AxisInterface::Feature::ProfileVelocity));
        QVERIFY(m_axis->featureNote().contains(QLatin1String("no positioning control")));
        QCOMPARE(m_axis->velocityUnit(), QStringLiteral("rpm"));
        QVERIFY(!await(m_axis->moveTo(100, { 1000, 1000, 1000, 0 })).ok());
        // 1454 is fixed to velocity mode there.
        QVERIFY(!await(m_connection->write(ObjectAddress(1454, 5), qlonglong(1))).ok());
        QVERIFY(power(true));
        QVERIFY(await(m_axis->moveVelocity(300, {})).ok());
        DB_TRY_COMPARE_WITH_TIMEOUT(m_acu->store().value(240, 0).toInt(), 300, 3000);
    }

    // A configuration without positioning control has no electronic gear: MC_GearIn is refused
    // by name, with the reason, and nothing is written.
    void gearRefusedWithoutPositioning()
    {
        QVERIFY(await(m_connection->write(ObjectAddress(30, 5), qulonglong(210))).ok());
        QVERIFY(await(m_axis->initialize()).ok());
        QVERIFY(!(m_axis->features() & AxisInterface::Feature::ElectronicGear));
        QVERIFY(power(true));
        int writes = 0;
        connect(&m_acu->server(), &vabus::Server::requestHandled, this,
                [&writes](const vabus::Telegram &request) { writes += request.write ? 1 : 0; });
        MotionCommand gearIn(m_model.get(), CommandKind::GearIn);
        gearIn.setParams(params(0, 0, 80000));
        gearIn.setExecute(true);
        DB_TRY_COMPARE(gearIn.status(), MotionCommand::Status::Error);
        QCOMPARE(gearIn.refusal(), Refusal::FeatureMissing);
        QVERIFY2(gearIn.error().message().startsWith(
                     QLatin1String("MC_GearIn refused: the drive has no electronic gear "
                                   "(configuration 210 has no positioning control")),
                 qPrintable(gearIn.error().message()));
        QCOMPARE(m_model->state(), AxisState::Standstill); // no ErrorStop
        QCOMPARE(writes, 0);
    }

    void modesMcoDoesNotHaveAreRejected()
    {
        for (const qlonglong mode : { 7, 8, 9 })
            QCOMPARE(await(m_connection->write(ObjectAddress(1454, 5), mode)).error().deviceCode(),
                     1u);
    }

private:
    bool power(bool on)
    {
        MotionCommand p(m_model.get(), CommandKind::Power);
        p.setEnable(on);
        p.setExecute(true);
        if (!test::waitFor([&p] { return p.isFinished(); }, 5000))
            return false;
        if (p.status() != MotionCommand::Status::Done)
            qWarning() << p.error().message();
        return p.status() == MotionCommand::Status::Done;
    }

    std::unique_ptr<SimulatedAcu> m_acu;
    std::unique_ptr<vabus::VabusConnection> m_connection;
    std::unique_ptr<AcuAxis> m_axis;
    std::unique_ptr<MotionAxis> m_model;
    quint64 m_eepromBefore = 0;
};

QTEST_GUILESS_MAIN(TstAcuAxis)
#include "tst_acuaxis.moc"
