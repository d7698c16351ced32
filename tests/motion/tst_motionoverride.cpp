// Level 2: the velocity override I230 of the command model (stoeber_motion.md Sec. 2.7, 8.3
// item 11) against the simulated MovingCap in-process: S-26 (override 0 holds the axis without
// Done, it continues when the override rises), S-27 (MC_Stop during override 0: the axis stays
// stopped until a new command), the override clamped at I10 with I193 (D-15), and the
// position window time I87 before Done (S-03, S-04).
#include "motionaxisrig.h"

#include <QTest>

using namespace db;
using namespace db::motion;
using namespace db::test;
using Status = MotionCommand::Status;

namespace {
constexpr double kTolerance = 2.0;

// The simulated MovingCap in-process, limited to 3000 units/s, powered.
std::unique_ptr<MotionRig> makeAxis()
{
    auto a = makeMotionRig(QStringLiteral("sim"), 3000);
    if (!a)
        return nullptr;
    MotionCommand power(a->axis.get(), CommandKind::Power);
    power.setExecute(true);
    if (!QTest::qWaitFor([&] { return power.isFinished(); }, 5000)
        || power.status() != Status::Done)
        return nullptr;
    return a;
}

MoveParams params(double position, double velocity)
{
    return moveParams(position, velocity, 20000);
}

// Lets the status poll run `rounds` times (no fixed sleep: counts statusChanged).
bool waitRounds(Cia402Axis *axis, int rounds)
{
    QSignalSpy spy(axis, &AxisInterface::statusChanged);
    return QTest::qWaitFor([&] { return spy.size() >= rounds; }, 5000);
}
} // namespace

class TestMotionOverride : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void overrideZeroHoldsWithoutDone() // S-26
    {
        auto a = makeAxis();
        QVERIFY(a);
        MotionCommand abs(a->axis.get(), CommandKind::MoveAbsolute);
        abs.setParams(params(3000, 1000));
        abs.setExecute(true);
        QTRY_VERIFY(a->rig->drive().axis().position() > 300);
        a->axis->setVelocityOverride(0);
        QTRY_VERIFY_WITH_TIMEOUT(!a->rig->drive().axis().isMoving(), 3000);
        const double heldAt = a->rig->drive().axis().position();
        QVERIFY2(heldAt < 2900, qPrintable(QString::number(heldAt)));
        QVERIFY(waitRounds(a->cia.get(), 10));
        QCOMPARE(abs.status(), Status::Active); // stands, but no Done
        QCOMPARE(a->axis->state(), AxisState::DiscreteMotion);
        QCOMPARE(qRound(a->rig->drive().axis().position()), qRound(heldAt));
        a->axis->setVelocityOverride(100);
        QTRY_COMPARE_WITH_TIMEOUT(abs.status(), Status::Done, 10000);
        QVERIFY(qAbs(a->rig->drive().axis().position() - 3000) < kTolerance);
    }
    void stopDuringOverrideZeroStaysStopped() // S-27
    {
        auto a = makeAxis();
        QVERIFY(a);
        MotionCommand abs(a->axis.get(), CommandKind::MoveAbsolute);
        abs.setParams(params(3000, 1000));
        abs.setExecute(true);
        QTRY_VERIFY(a->rig->drive().axis().position() > 300);
        a->axis->setVelocityOverride(0);
        QTRY_VERIFY_WITH_TIMEOUT(!a->rig->drive().axis().isMoving(), 3000);
        MotionCommand stop(a->axis.get(), CommandKind::Stop);
        stop.setParams(params(0, 0));
        stop.setExecute(true);
        QCOMPARE(abs.status(), Status::CommandAborted);
        QTRY_COMPARE_WITH_TIMEOUT(stop.status(), Status::Done, 3000);
        stop.setExecute(false);
        QCOMPARE(a->axis->state(), AxisState::Standstill);
        const double stoppedAt = a->rig->drive().axis().position();
        a->axis->setVelocityOverride(100);
        QVERIFY(waitRounds(a->cia.get(), 10));
        QVERIFY(!a->rig->drive().axis().isMoving());
        QCOMPARE(qRound(a->rig->drive().axis().position()), qRound(stoppedAt));
        // A new command starts it again, with the override now at 100 %.
        MotionCommand again(a->axis.get(), CommandKind::MoveAbsolute);
        again.setParams(params(3000, 1000));
        again.setExecute(true);
        QTRY_COMPARE_WITH_TIMEOUT(again.status(), Status::Done, 10000);
        QVERIFY(qAbs(a->rig->drive().axis().position() - 3000) < kTolerance);
    }
    void overrideZeroAtStartWaits() // S-26 from standstill
    {
        auto a = makeAxis();
        QVERIFY(a);
        a->axis->setVelocityOverride(0);
        MotionCommand abs(a->axis.get(), CommandKind::MoveAbsolute);
        abs.setParams(params(500, 1000));
        abs.setExecute(true);
        QTRY_COMPARE(abs.status(), Status::Active);
        QVERIFY(waitRounds(a->cia.get(), 10));
        QCOMPARE(abs.status(), Status::Active);
        QVERIFY(qAbs(a->rig->drive().axis().position()) < kTolerance);
        a->axis->setVelocityOverride(50);
        QTRY_COMPARE_WITH_TIMEOUT(abs.status(), Status::Done, 10000);
        QVERIFY(qAbs(a->rig->drive().axis().position() - 500) < kTolerance);
    }
    void overrideAboveHundredClampedAtMaxVelocity() // D-15 on a running command
    {
        auto a = makeAxis();
        QVERIFY(a);
        MotionCommand vel(a->axis.get(), CommandKind::MoveVelocity);
        vel.setParams(params(0, 2500));
        vel.setExecute(true);
        QTRY_COMPARE_WITH_TIMEOUT(vel.status(), Status::Done, 3000);
        QVERIFY(!vel.limits().overrideLimited);
        a->axis->setVelocityOverride(150);
        QCOMPARE(a->axis->velocityOverride(), 150.0);
        QVERIFY(vel.limits().overrideLimited); // I193: 3750 clamped at I10 = 3000
        QVERIFY(!vel.limits().velocityLimited);
        QTRY_VERIFY_WITH_TIMEOUT(qAbs(a->rig->drive().axis().velocity() - 3000) < 15, 3000);
        a->axis->setVelocityOverride(1000); // clamped to kMaxOverridePercent
        QCOMPARE(a->axis->velocityOverride(), MotionAxis::kMaxOverridePercent);
        a->axis->stopNow();
        QTRY_VERIFY(!a->rig->drive().axis().isMoving());
    }
    void windowTimeDelaysDone() // S-04: Done only after the position stayed in the window I87
    {
        auto a = makeAxis();
        QVERIFY(a);
        AxisConfig c = a->axis->config();
        c.positionWindowTimeMs = 400;
        a->axis->setConfig(c);
        MotionCommand abs(a->axis.get(), CommandKind::MoveAbsolute);
        abs.setParams(params(300, 3000));
        abs.setExecute(true);
        QTRY_VERIFY_WITH_TIMEOUT(!a->rig->drive().axis().isMoving()
                                     && qAbs(a->rig->drive().axis().position() - 300) < 1,
                                 5000);
        QVERIFY(waitRounds(a->cia.get(), 3)); // the model has seen the axis stand at the target
        QCOMPARE(abs.status(), Status::Active); // profile finished, but I87 not yet over
        QTRY_COMPARE_WITH_TIMEOUT(abs.status(), Status::Done, 3000);
        // Without a window time (S-03), Done comes with the first round at standstill.
        c.positionWindowTimeMs = 0;
        a->axis->setConfig(c);
        MotionCommand back(a->axis.get(), CommandKind::MoveAbsolute);
        back.setParams(params(0, 3000));
        back.setExecute(true);
        QTRY_VERIFY_WITH_TIMEOUT(!a->rig->drive().axis().isMoving()
                                     && qAbs(a->rig->drive().axis().position()) < 1,
                                 5000);
        QVERIFY(waitRounds(a->cia.get(), 3));
        QCOMPARE(back.status(), Status::Done);
    }
};

QTEST_GUILESS_MAIN(TestMotionOverride)
#include "tst_motionoverride.moc"
