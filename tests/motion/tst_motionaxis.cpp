// Level 2/3: the command model over Cia402Axis against the simulated MovingCap (in-process, over
// RefGo and over CANopen SDO): sequences of stoeber_motion.md Sec. 10 and the safety stops.
#include "core/changelog.h"
#include "motion/motionchangelog.h"
#include "motionaxisrig.h"

#include <QSignalSpy>
#include <QTest>

using namespace db;
using namespace db::motion;
using namespace db::test;
using Status = MotionCommand::Status;

namespace {
constexpr double kTolerance = 2.0; // units; the drive reports integer positions

std::unique_ptr<MotionRig> makeAxis(const QString &kind)
{
    return makeMotionRig(kind, 50000);
}

MoveParams params(double position, double velocity = 20000, double acceleration = 100000)
{
    return moveParams(position, velocity, acceleration);
}

void pulse(MotionCommand &c)
{
    c.setExecute(false);
    c.setExecute(true);
}

bool powerOn(MotionAxis *axis)
{
    MotionCommand power(axis, CommandKind::Power);
    power.setEnable(true);
    power.setExecute(true);
    return QTest::qWaitFor([&] { return power.isFinished(); }, 5000)
        && power.status() == Status::Done;
}
} // namespace

class TestMotionAxis : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void absoluteThenAdditive_data() // S-09 over each transport
    {
        QTest::addColumn<QString>("kind");
        QTest::newRow("sim") << QStringLiteral("sim");
        QTest::newRow("refgo") << QStringLiteral("refgo");
        QTest::newRow("canopen") << QStringLiteral("canopen");
    }
    void absoluteThenAdditive()
    {
        QFETCH(QString, kind);
        auto a = makeAxis(kind);
        QVERIFY(a);
        QVERIFY(powerOn(a->axis.get()));
        QCOMPARE(a->axis->state(), AxisState::Standstill);
        MotionCommand abs(a->axis.get(), CommandKind::MoveAbsolute);
        abs.setParams(params(1000));
        abs.setExecute(true);
        QCOMPARE(abs.status(), Status::Busy);
        QCOMPARE(a->axis->state(), AxisState::DiscreteMotion);
        QTRY_COMPARE_WITH_TIMEOUT(abs.status(), Status::Done, 5000);
        QCOMPARE(a->axis->state(), AxisState::Standstill);
        MotionCommand add(a->axis.get(), CommandKind::MoveAdditive);
        add.setParams(params(200));
        add.setExecute(true);
        QTRY_COMPARE_WITH_TIMEOUT(add.status(), Status::Done, 5000);
        QCOMPARE(add.target(), 1200.0);
        QVERIFY(qAbs(a->rig->drive().axis().position() - 1200) < kTolerance);
    }
    void jerkReachesTheDrive_data()
    {
        QTest::addColumn<QString>("kind");
        QTest::newRow("refgo") << QStringLiteral("refgo");
        QTest::newRow("canopen") << QStringLiteral("canopen");
    }
    // The MovingCap describes its profile jerk as 60A4h.0 (not the CiA 402 array's 60A4h.1):
    // the axis offers jerk and a move writes it there.
    void jerkReachesTheDrive()
    {
        QFETCH(QString, kind);
        auto a = makeAxis(kind);
        QVERIFY(a && powerOn(a->axis.get()));
        QVERIFY(a->cia->features().testFlag(AxisInterface::Feature::Jerk));
        MotionCommand move(a->axis.get(), CommandKind::MoveAbsolute);
        MoveParams p = params(300);
        p.jerk = 54321;
        move.setParams(p);
        move.setExecute(true);
        QTRY_COMPARE_WITH_TIMEOUT(move.status(), Status::Done, 5000);
        QCOMPARE(a->rig->drive().read({ 0x60A4, 0 }).value().toLongLong(), 54321LL);
    }
    void newAbsoluteAbortsRunning() // S-02
    {
        auto a = makeAxis(QStringLiteral("sim"));
        QVERIFY(a && powerOn(a->axis.get()));
        MotionCommand first(a->axis.get(), CommandKind::MoveAbsolute);
        first.setParams(params(1000, 2000));
        first.setExecute(true);
        QTRY_VERIFY(a->rig->drive().axis().position() > 200);
        MotionCommand second(a->axis.get(), CommandKind::MoveAbsolute);
        second.setParams(params(2000, 4000));
        second.setExecute(true);
        QCOMPARE(first.status(), Status::CommandAborted);
        QTRY_COMPARE_WITH_TIMEOUT(second.status(), Status::Done, 5000);
        QVERIFY(qAbs(a->rig->drive().axis().position() - 2000) < kTolerance);
    }
    void relativeFromActualPosition() // S-06
    {
        auto a = makeAxis(QStringLiteral("sim"));
        QVERIFY(a && powerOn(a->axis.get()));
        MotionCommand first(a->axis.get(), CommandKind::MoveRelative);
        first.setParams(params(1000, 2000));
        first.setExecute(true);
        QTRY_VERIFY(a->rig->drive().axis().position() > 300);
        MotionCommand second(a->axis.get(), CommandKind::MoveRelative);
        second.setParams(params(1000, 2000));
        const double actualAtStart = a->rig->drive().axis().position();
        second.setExecute(true);
        // Target = actual position at start + 1000 (the polled position lags <= ~2 rounds).
        QVERIFY2(qAbs(second.target() - 1000 - actualAtStart) < 100,
                 qPrintable(QString::number(second.target())));
        QVERIFY(second.target() < 1999);
        QTRY_COMPARE_WITH_TIMEOUT(second.status(), Status::Done, 5000);
        QVERIFY(qAbs(a->rig->drive().axis().position() - second.target()) < kTolerance);
    }
    void stopRefusesOthersAndKeepsTarget() // S-10, S-20
    {
        auto a = makeAxis(QStringLiteral("sim"));
        QVERIFY(a && powerOn(a->axis.get()));
        MotionCommand abs(a->axis.get(), CommandKind::MoveAbsolute);
        abs.setParams(params(1000, 2000, 20000));
        abs.setExecute(true);
        QTRY_VERIFY(a->rig->drive().axis().position() > 200);
        MotionCommand stop(a->axis.get(), CommandKind::Stop);
        stop.setParams(params(0, 0, 5000));
        stop.setExecute(true);
        QCOMPARE(abs.status(), Status::CommandAborted);
        QCOMPARE(a->axis->state(), AxisState::Stopping);
        MotionCommand other(a->axis.get(), CommandKind::MoveAbsolute);
        other.setParams(params(0));
        other.setExecute(true);
        QTRY_COMPARE(other.status(), Status::Error);
        QCOMPARE(other.refusal(), Refusal::StopActive);
        QTRY_COMPARE_WITH_TIMEOUT(stop.status(), Status::Done, 5000);
        QCOMPARE(a->axis->state(), AxisState::Stopping); // until Execute is released
        stop.setExecute(false);
        QCOMPARE(a->axis->state(), AxisState::Standstill);
        MotionCommand add(a->axis.get(), CommandKind::MoveAdditive);
        add.setParams(params(200));
        add.setExecute(true);
        QCOMPARE(add.target(), 1200.0);
        QTRY_COMPARE_WITH_TIMEOUT(add.status(), Status::Done, 5000);
    }
    void enableOffMakesActualTheOrigin() // S-11
    {
        auto a = makeAxis(QStringLiteral("sim"));
        QVERIFY(a && powerOn(a->axis.get()));
        MotionCommand abs(a->axis.get(), CommandKind::MoveAbsolute);
        abs.setParams(params(1000, 2000));
        abs.setExecute(true);
        QTRY_VERIFY(a->rig->drive().axis().position() > 300);
        MotionCommand power(a->axis.get(), CommandKind::Power);
        power.setEnable(false);
        power.setExecute(true);
        QCOMPARE(abs.status(), Status::CommandAborted);
        QTRY_COMPARE(power.status(), Status::Done);
        QCOMPARE(a->axis->state(), AxisState::Disabled);
        QTRY_VERIFY(qAbs(a->cia->status().position - a->rig->drive().axis().position()) < 1);
        const double stoppedAt = a->rig->drive().axis().position();
        QVERIFY(powerOn(a->axis.get()));
        MotionCommand add(a->axis.get(), CommandKind::MoveAdditive);
        add.setParams(params(200));
        add.setExecute(true);
        QVERIFY2(qAbs(add.target() - (stoppedAt + 200)) < kTolerance,
                 qPrintable(QString::number(add.target())));
        QTRY_COMPARE_WITH_TIMEOUT(add.status(), Status::Done, 5000);
    }
    void driveEnabledElsewhereIsAdopted()
    {
        // PLCopen's axis state follows the drive: enabled by another tool (web UI, RefGo
        // terminal) the axis is at Standstill; switched off by MC_Power it stays Disabled.
        auto a = makeAxis(QStringLiteral("sim"));
        QVERIFY(a);
        QSignalSpy rounds(a->cia.get(), &AxisInterface::statusChanged);
        QTRY_VERIFY(rounds.count() >= 3);
        QCOMPARE(a->axis->state(), AxisState::Disabled);
        for (int word : { 6, 7, 15 })
            QVERIFY(bool(a->rig->drive().write({ 0x6040, 0 }, word)));
        QTRY_COMPARE(a->axis->state(), AxisState::Standstill);
        MotionCommand power(a->axis.get(), CommandKind::Power);
        power.setEnable(false);
        power.setExecute(true);
        QTRY_COMPARE(power.status(), Status::Done);
        rounds.clear();
        QTRY_VERIFY(rounds.count() >= 4);
        QCOMPARE(a->axis->state(), AxisState::Disabled);
    }
    void velocitySequenceThenHalt() // S-18, S-23
    {
        auto a = makeAxis(QStringLiteral("sim"));
        QVERIFY(a && powerOn(a->axis.get()));
        MotionCommand vel(a->axis.get(), CommandKind::MoveVelocity);
        for (double v : { 300.0, 200.0, 400.0 }) {
            vel.setParams(params(0, v, 2000));
            pulse(vel);
            QTRY_COMPARE_WITH_TIMEOUT(vel.status(), Status::Done, 3000);
            QVERIFY(qAbs(a->rig->drive().axis().velocity() - v) < 15);
            QCOMPARE(a->axis->state(), AxisState::ContinuousMotion);
        }
        vel.setParams(params(0, 100, 1000));
        pulse(vel);
        QTRY_COMPARE(vel.status(), Status::Active);
        MotionCommand halt(a->axis.get(), CommandKind::Halt);
        halt.setParams(params(0, 0, 2000));
        halt.setExecute(true);
        QCOMPARE(vel.status(), Status::CommandAborted);
        QTRY_COMPARE_WITH_TIMEOUT(halt.status(), Status::Done, 3000);
        QCOMPARE(a->axis->state(), AxisState::DiscreteMotion); // MC_Halt until release
        halt.setExecute(false);
        QCOMPARE(a->axis->state(), AxisState::Standstill);
        pulse(vel); // S-23: the aborted command starts again with a second Execute
        QTRY_COMPARE_WITH_TIMEOUT(vel.status(), Status::Done, 3000);
    }
    void refusalFromMotionQuickStops() // D-10, S-30
    {
        auto a = makeAxis(QStringLiteral("sim"));
        QVERIFY(a && powerOn(a->axis.get()));
        MotionCommand vel(a->axis.get(), CommandKind::MoveVelocity);
        vel.setParams(params(0, 500));
        vel.setExecute(true);
        QTRY_COMPARE(vel.status(), Status::Done);
        MotionCommand abs(a->axis.get(), CommandKind::MoveAbsolute);
        QSignalSpy spy(&abs, &MotionCommand::statusChanged);
        MoveParams p = params(0);
        p.jerk = 0;
        abs.setParams(p);
        abs.setExecute(true);
        QTRY_COMPARE(abs.status(), Status::Error);
        QCOMPARE(spy.size(), 2);
        QCOMPARE(spy.at(0).at(0).value<Status>(), Status::Busy);
        QCOMPARE(abs.refusal(), Refusal::ZeroProfileValue);
        QCOMPARE(vel.status(), Status::CommandAborted);
        QCOMPARE(a->axis->state(), AxisState::ErrorStop);
        QTRY_VERIFY(!a->rig->drive().axis().isMoving());
        QVERIFY(a->rig->drive().state() != cia402::State::OperationEnabled);
        MotionCommand reset(a->axis.get(), CommandKind::Reset);
        reset.setExecute(true);
        QTRY_COMPARE_WITH_TIMEOUT(reset.status(), Status::Done, 3000);
        QCOMPARE(a->axis->state(), AxisState::Standstill);
        QCOMPARE(a->rig->drive().state(), cia402::State::OperationEnabled);
    }
    // A CiA 402 drive that says nothing about its reference is not referenced: an absolute
    // move runs with the warning. A homing references it, and a new axis on the drive, still in
    // homing mode with bit 12, is referenced from the drive's word. Once the drive has left
    // homing mode (bit 12 is the set-point acknowledge then) a new axis knows nothing again.
    void referencedOnlyWhenHomedOrTold_data()
    {
        QTest::addColumn<QString>("kind");
        QTest::newRow("refgo") << QStringLiteral("refgo");
        QTest::newRow("canopen") << QStringLiteral("canopen");
    }
    void referencedOnlyWhenHomedOrTold()
    {
        QFETCH(QString, kind);
        auto a = makeAxis(kind);
        QVERIFY(a && powerOn(a->axis.get()));
        QTRY_VERIFY(a->cia->status().valid);
        QVERIFY(!a->axis->isReferenced());
        MotionCommand abs(a->axis.get(), CommandKind::MoveAbsolute);
        abs.setParams(params(500));
        abs.setExecute(true);
        QVERIFY(abs.limits().notReferenced);
        QTRY_COMPARE_WITH_TIMEOUT(abs.status(), Status::Done, 5000);
        MotionCommand home(a->axis.get(), CommandKind::Home);
        HomingParams h;
        h.method = 35;
        home.setHoming(h);
        home.setExecute(true);
        QVERIFY(!a->axis->isReferenced()); // not while the homing runs
        QTRY_COMPARE_WITH_TIMEOUT(home.status(), Status::Done, 3000);
        QVERIFY(a->axis->isReferenced());

        Cia402Axis again(a->rig->connection.get());
        again.setAccelerationUnit(Cia402Axis::AccelerationUnit::RotaryMotor); // as the rig's
        QVERIFY(await(again.initialize()).ok());
        MotionAxis model(&again);
        QTRY_VERIFY(again.status().valid);
        QTRY_VERIFY(model.isReferenced()); // the drive, still in homing mode, says so
        MotionCommand abs2(&model, CommandKind::MoveAbsolute);
        abs2.setParams(params(-200));
        abs2.setExecute(true);
        QVERIFY(!abs2.limits().notReferenced);
        QTRY_VERIFY2_WITH_TIMEOUT(abs2.status() == Status::Done, qPrintable(abs2.error().message()),
                                  5000);

        Cia402Axis third(a->rig->connection.get());
        third.setAccelerationUnit(Cia402Axis::AccelerationUnit::RotaryMotor); // as the rig's
        QVERIFY(await(third.initialize()).ok());
        MotionAxis model3(&third);
        QTRY_VERIFY(third.status().valid);
        QTRY_VERIFY(model3.state() != AxisState::Disabled); // a few rounds seen
        QVERIFY(!model3.isReferenced()); // in profile position mode: bit 12 says nothing
    }
    void homeSetsReference()
    {
        auto a = makeAxis(QStringLiteral("sim"));
        QVERIFY(a && powerOn(a->axis.get()));
        a->axis->setReferenced(false);
        MotionCommand home(a->axis.get(), CommandKind::Home);
        HomingParams h;
        h.method = 35;
        h.offset = 100;
        home.setHoming(h);
        home.setExecute(true);
        QTRY_COMPARE_WITH_TIMEOUT(home.status(), Status::Done, 3000);
        QVERIFY(a->axis->isReferenced());
        QCOMPARE(qRound(a->rig->drive().axis().position()), 100);
    }
    void watchdogExpiryStopsTheAxis()
    {
        auto a = makeAxis(QStringLiteral("sim"));
        QVERIFY(a && powerOn(a->axis.get()));
        a->axis->setWatchdogTimeout(200);
        QSignalSpy expired(a->axis.get(), &MotionAxis::watchdogExpired);
        MotionCommand vel(a->axis.get(), CommandKind::MoveVelocity);
        vel.setParams(params(0, 500));
        vel.setExecute(true);
        QVERIFY(expired.wait(1000));
        QCOMPARE(vel.status(), Status::Error);
        QCOMPARE(vel.error().kind(), Error::Kind::Timeout);
        QTRY_VERIFY(!a->rig->drive().axis().isMoving());
        QCOMPARE(a->axis->state(), AxisState::ErrorStop);
    }
    void watchdogKeptAliveDoesNotStop()
    {
        auto a = makeAxis(QStringLiteral("sim"));
        QVERIFY(a && powerOn(a->axis.get()));
        a->axis->setWatchdogTimeout(1000); // clamped to 500 ms
        QCOMPARE(a->axis->watchdogTimeout(), MotionAxis::kMaxWatchdogMs);
        QTimer refresh;
        QObject::connect(&refresh, &QTimer::timeout, a->axis.get(), &MotionAxis::keepAlive);
        refresh.start(50);
        QSignalSpy expired(a->axis.get(), &MotionAxis::watchdogExpired);
        MotionCommand vel(a->axis.get(), CommandKind::MoveVelocity);
        vel.setParams(params(0, 500));
        vel.setExecute(true);
        QVERIFY(!expired.wait(800));
        QCOMPARE(vel.status(), Status::Done);
        refresh.stop(); // the GUI hangs: the watchdog stops the axis
        QVERIFY(expired.wait(1000));
        QTRY_VERIFY(!a->rig->drive().axis().isMoving());
    }
    void idleDriveIsPolledSlowly()
    {
        // A switched-off drive at standstill is read every kIdleStatusPollMs, a powered one
        // every kStatusPollMs. Counted over the same window (a fixed wait on purpose: what is
        // measured is how often something happens within it); only the idle bound is firm.
        auto a = makeAxis(QStringLiteral("sim"));
        QVERIFY(a);
        int rounds = 0;
        connect(a->rig->connection.get(), &DeviceConnection::requestFinished, this,
                [&rounds](ObjectAddress address, const Error &) {
                    rounds += address == ObjectAddress(0x6041, 0) ? 1 : 0;
                });
        QTRY_VERIFY(a->cia->status().valid);
        const auto roundsWithin = [&rounds](int ms) {
            rounds = 0;
            QTest::qWait(ms);
            return rounds;
        };
        const int idle = roundsWithin(1000);
        QVERIFY2(idle <= 1000 / Cia402Axis::kIdleStatusPollMs + 1,
                 qPrintable(QString::number(idle)));
        QVERIFY(powerOn(a->axis.get()));
        const int powered = roundsWithin(1000);
        QVERIFY2(powered > 2 * idle && powered > 1000 / Cia402Axis::kIdleStatusPollMs + 1,
                 qPrintable(QStringLiteral("%1 rounds powered, %2 idle").arg(powered).arg(idle)));
    }
    void stopNowAlwaysWorks()
    {
        auto a = makeAxis(QStringLiteral("sim"));
        QVERIFY(a && powerOn(a->axis.get()));
        MotionCommand abs(a->axis.get(), CommandKind::MoveAbsolute);
        abs.setParams(params(100000, 2000));
        abs.setExecute(true);
        a->axis->stopNow(); // even before the set-point handshake has finished
        QCOMPARE(abs.status(), Status::CommandAborted);
        QTRY_VERIFY(a->rig->drive().state() != cia402::State::OperationEnabled);
        QTRY_VERIFY(!a->rig->drive().axis().isMoving());
        QVERIFY(a->rig->drive().axis().position() < 1000);
    }
    void disconnectFailsRunningCommand()
    {
        auto a = makeAxis(QStringLiteral("sim"));
        QVERIFY(a && powerOn(a->axis.get()));
        MotionCommand abs(a->axis.get(), CommandKind::MoveAbsolute);
        abs.setParams(params(100000, 2000));
        abs.setExecute(true);
        QTRY_COMPARE(abs.status(), Status::Active);
        a->rig->sim->goAway();
        QTRY_COMPARE(abs.status(), Status::Error);
        QCOMPARE(abs.error().kind(), Error::Kind::Disconnected);
        QVERIFY(abs.error().message().contains(QLatin1String("connection lost")));
        QCOMPARE(a->axis->state(), AxisState::ErrorStop);
    }
    // Every start of the same MC_Power block is its own change-log entry, pending until its own
    // outcome: not completed at once with the status of the block's previous run.
    void eachPowerStartIsLoggedWithItsOwnOutcome()
    {
        auto a = makeAxis(QStringLiteral("sim"));
        QVERIFY(a);
        a->rig->sim->immediate = false;
        a->rig->sim->replyDelayMs = 5;
        ChangeLog log;
        recordCommands(a->axis.get(), &log, QStringLiteral("drive"));
        MotionCommand power(a->axis.get(), CommandKind::Power);
        for (bool on : { true, false, true, false }) {
            power.setEnable(on);
            pulse(power);
            QVERIFY(!log.entries().isEmpty());
            const ChangeLog::Entry started = log.entries().last();
            QCOMPARE(started.kind, on ? ChangeLog::Kind::Enable : ChangeLog::Kind::Disable);
            QCOMPARE(started.outcome, ChangeLog::Outcome::Pending);
            QTRY_COMPARE(power.status(), Status::Done);
            QCOMPARE(log.find(started.id)->outcome, ChangeLog::Outcome::Ok);
        }

        // A failed enable, then one that works: the second is not the first's failure again.
        a->rig->sim->silent.insert({ 0x6040, 0 });
        a->rig->connection->setRequestTimeoutMs(100);
        power.setEnable(true);
        pulse(power);
        QTRY_COMPARE(power.status(), Status::Error);
        QCOMPARE(log.entries().last().outcome, ChangeLog::Outcome::Failed);
        a->rig->sim->silent.clear();
        pulse(power);
        const int id = log.entries().last().id;
        QCOMPARE(log.find(id)->outcome, ChangeLog::Outcome::Pending);
        QTRY_COMPARE(power.status(), Status::Done);
        QVERIFY2(log.find(id)->outcome == ChangeLog::Outcome::Ok,
                 qPrintable(log.find(id)->message));
    }
    void torqueNotSupportedByMovingCap()
    {
        auto a = makeAxis(QStringLiteral("sim"));
        QVERIFY(a && powerOn(a->axis.get()));
        MotionCommand torque(a->axis.get(), CommandKind::TorqueControl);
        torque.setExecute(true);
        QTRY_COMPARE(torque.status(), Status::Error);
        QCOMPARE(torque.error().kind(), Error::Kind::NotSupported);
    }
};

QTEST_GUILESS_MAIN(TestMotionAxis)
#include "tst_motionaxis.moc"
