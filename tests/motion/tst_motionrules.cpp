// Level 1: the pure rules of the command model against the test vectors of stoeber_motion.md
// Sec. 10 (targets S-01..S-17, D-20..D-23; refusals; limitations D-14..D-16; direction D-01..D-07).
#include "motion/motionrules.h"
#include "motion/targettracker.h"

#include <QTest>

Q_DECLARE_METATYPE(db::motion::MoveParams)
Q_DECLARE_METATYPE(db::motion::AxisConfig)
Q_DECLARE_METATYPE(db::motion::AxisSnapshot)

using namespace db::motion;

namespace {
MoveParams move(double position)
{
    MoveParams p;
    p.position = position;
    p.velocity = p.acceleration = p.deceleration = p.jerk = 100;
    return p;
}
} // namespace

class TestMotionRules : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    // Script: "abs X", "rel X", "add X" start a command from the actual position; "done" puts
    // the axis on the last target; "at P" is an actual position (standstill or mid-travel);
    // "stop"/"halt" keep the target; "off"/"on" switch the enable.
    void targets_data()
    {
        QTest::addColumn<QString>("script");
        QTest::addColumn<double>("expected");
        QTest::newRow("S-01") << "abs 1000; done; abs 2000" << 2000.0;
        QTest::newRow("S-02") << "abs 1000; at 400; abs 2000" << 2000.0;
        QTest::newRow("S-05") << "rel 1000; done; rel 1000" << 2000.0;
        QTest::newRow("S-06") << "rel 1000; at 570; rel 1000" << 1570.0;
        QTest::newRow("S-07") << "add 1000; done; add 1000" << 2000.0;
        QTest::newRow("S-08") << "add 1000; at 400; add 1000" << 2000.0;
        QTest::newRow("S-09") << "abs 1000; done; add 200" << 1200.0;
        QTest::newRow("S-10") << "abs 1000; at 400; stop; at 450; add 200" << 1200.0;
        QTest::newRow("S-11") << "abs 1000; at 578.9; off; on; add 200" << 778.9;
        QTest::newRow("S-12") << "add 200; done; add 200" << 400.0;
        QTest::newRow("S-13") << "add 200; at 100; stop; at 120; add 200" << 400.0;
        QTest::newRow("S-14") << "add 200; at 91.2; off; on; add 200" << 291.2;
        QTest::newRow("S-15") << "at 9.5; rel 200; done; add 200" << 409.5;
        QTest::newRow("S-16") << "at 9.5; rel 200; at 100; stop; at 120; add 200" << 409.5;
        QTest::newRow("S-17") << "at 9.5; rel 200; at 91.2; off; on; add 200" << 291.2;
        QTest::newRow("D-20") << "abs 1000; at 999.98; off; on; add 200" << 1200.0;
        QTest::newRow("D-21") << "abs 1000; at 999.98; off; at 995; on; add 200" << 1195.0;
        QTest::newRow("D-22") << "at 37; add 10" << 47.0;
        QTest::newRow("D-23") << "abs 500; done; halt; add 100" << 600.0;
    }
    void targets()
    {
        QFETCH(QString, script);
        QFETCH(double, expected);
        AxisConfig config;
        config.positionWindow = 0.1;
        TargetTracker tracker;
        AxisSnapshot axis;
        double last = 0;
        for (const QString &step : script.split(QLatin1Char(';'))) {
            const QStringList w = step.trimmed().split(QLatin1Char(' '));
            const QString op = w[0];
            const double x = w.size() > 1 ? w[1].toDouble() : 0.0;
            if (op == QLatin1String("at") || op == QLatin1String("done")) {
                axis.position = op == QLatin1String("at") ? x : last;
                tracker.observe(axis.position, config.positionWindow);
            } else if (op == QLatin1String("off")) {
                tracker.enableOff();
            } else if (op == QLatin1String("abs") || op == QLatin1String("rel")
                       || op == QLatin1String("add")) {
                const CommandKind kind = op == QLatin1String("abs") ? CommandKind::MoveAbsolute
                    : op == QLatin1String("rel")                    ? CommandKind::MoveRelative
                                                                    : CommandKind::MoveAdditive;
                const Plan plan = planCommand(kind, move(x), config, axis,
                                              tracker.origin(axis.position, config.positionWindow));
                QVERIFY(!plan.refused());
                tracker.setTarget(plan.target);
                last = plan.target;
            }
        }
        QVERIFY2(qAbs(last - expected) < 1e-9, qPrintable(QString::number(last)));
    }

    void refusal_data()
    {
        QTest::addColumn<int>("kind");
        QTest::addColumn<MoveParams>("params");
        QTest::addColumn<AxisConfig>("config");
        QTest::addColumn<AxisSnapshot>("axis");
        QTest::addColumn<int>("refusal");
        QTest::addColumn<bool>("success");
        QTest::addColumn<bool>("quickStop");
        const AxisConfig base;
        AxisSnapshot still;
        still.referenced = true;
        AxisSnapshot moving = still;
        moving.state = AxisState::DiscreteMotion;
        moving.velocity = 50;
        AxisConfig endless = base;
        endless.endless = true;
        endless.cycleLength = 360;
        AxisConfig limited = base;
        limited.softLimitsUsed = true;
        limited.softLimitNegative = -1000;
        limited.softLimitPositive = 1000;
        const auto abs = int(CommandKind::MoveAbsolute);
        const auto rel = int(CommandKind::MoveRelative);
        const auto vel = int(CommandKind::MoveVelocity);
        const auto stop = int(CommandKind::Stop);
        const auto halt = int(CommandKind::Halt);
        const auto home = int(CommandKind::Home);
        const auto none = int(Refusal::None);
        MoveParams zeroJerk = move(500);
        zeroJerk.jerk = 0;
        MoveParams zeroVelocity = move(500);
        zeroVelocity.velocity = 0;
        MoveParams stopNoDecel = move(0);
        stopNoDecel.deceleration = 0;
        AxisConfig noAcc = base;
        noAcc.maxAcceleration = 0;
        AxisConfig noJerk = base;
        noJerk.maxJerk = 0;
        AxisSnapshot unreferenced;
        unreferenced.referenced = false;
        AxisSnapshot stopping;
        stopping.state = AxisState::Stopping;
        AxisSnapshot continuous = moving;
        continuous.state = AxisState::ContinuousMotion;
        AxisConfig positiveOnly = endless;
        positiveOnly.permitted = PermittedDirection::PositiveOnly;
        AxisSnapshot hwPositive;
        hwPositive.hardwareLimitPositive = true;
        AxisConfig homingOff = base;
        homingOff.homingMethod = 0;

        QTest::newRow("D-08 R3 outside cycle")
            << abs << move(400) << endless << still << int(Refusal::TargetOutsideCycle) << false
            << false;
        QTest::newRow("D-09 R1 soft limit")
            << abs << move(1500) << limited << still << int(Refusal::TargetOutsideSoftLimits)
            << false << false;
        QTest::newRow("D-10 R5 jerk 0 from motion")
            << abs << zeroJerk << base << moving << int(Refusal::ZeroProfileValue) << false << true;
        QTest::newRow("S-30 R5 velocity 0") << abs << zeroVelocity << base << still
                                            << int(Refusal::ZeroProfileValue) << false << false;
        QTest::newRow("D-11 velocity 0 accepted")
            << vel << zeroVelocity << base << still << none << false << false;
        QTest::newRow("R6 I16 = 0")
            << abs << move(10) << noJerk << still << int(Refusal::ZeroAxisLimit) << false << false;
        // R7 and the I86 precondition are warnings here (notReferencedIsWarned).
        QTest::newRow("D-13 R7 unreferenced, soft limits")
            << rel << move(10) << limited << unreferenced << none << false << false;
        QTest::newRow("abs unreferenced [I]")
            << abs << move(10) << base << unreferenced << none << false << false;
        QTest::newRow("R2 direction") << rel << move(-10) << positiveOnly << still
                                      << int(Refusal::DirectionNotPermitted) << false << false;
        MoveParams backwards = move(0);
        backwards.velocity = -5;
        QTest::newRow("R2 velocity sign") << vel << backwards << positiveOnly << still
                                          << int(Refusal::DirectionNotPermitted) << false << false;
        QTest::newRow("R4 hw limit") << abs << move(100) << base << hwPositive
                                     << int(Refusal::HardwareLimitSwitch) << false << false;
        QTest::newRow("R4 away from the switch")
            << abs << move(-100) << base << hwPositive << none << false << false;
        QTest::newRow("S-20 R10 during MC_Stop")
            << abs << move(10) << base << stopping << int(Refusal::StopActive) << false << false;
        QTest::newRow("S-22 stop dec 0 at standstill")
            << stop << stopNoDecel << base << still << none << false << false;
        QTest::newRow("stop dec 0 moving") << stop << stopNoDecel << base << moving
                                           << int(Refusal::ZeroProfileValue) << false << false;
        QTest::newRow("S-22b stop I11 0 at standstill")
            << stop << move(0) << noAcc << still << int(Refusal::ZeroAxisLimit) << true << false;
        QTest::newRow("S-25 halt I16 0 at standstill")
            << halt << move(0) << noJerk << still << int(Refusal::ZeroAxisLimit) << true << false;
        QTest::newRow("S-28 R8 home in motion") << home << move(0) << base << continuous
                                                << int(Refusal::NotAtStandstill) << false << false;
        QTest::newRow("D-17 R9 homing inactive") << home << move(0) << homingOff << still
                                                 << int(Refusal::HomingInactive) << false << false;
        QTest::newRow("S-29 home zero speeds")
            << home << MoveParams() << base << still << none << false << false;
        // A drive that changes its operating mode only at rest (the ACTIVE Cube's 1454).
        AxisSnapshot otherMode = continuous;
        otherMode.modeChangeNeeded = true;
        AxisSnapshot otherModeCreeping = still; // inside the velocity window, still turning
        otherModeCreeping.driveMoving = true;
        otherModeCreeping.modeChangeNeeded = true;
        AxisSnapshot otherModeAtRest = still;
        otherModeAtRest.modeChangeNeeded = true;
        const auto modeChange = int(Refusal::ModeChangeWhileMoving);
        QTest::newRow("mode change while moving: abs")
            << abs << move(10) << base << otherMode << modeChange << false << false;
        QTest::newRow("mode change while moving: abs, bad profile too")
            << abs << zeroJerk << base << otherMode << modeChange << false << false;
        QTest::newRow("mode change while moving: velocity")
            << vel << move(0) << base << otherModeCreeping << modeChange << false << false;
        QTest::newRow("mode change at rest accepted")
            << abs << move(10) << base << otherModeAtRest << none << false << false;
        // A velocity from a status read before the last command was taken does not count.
        AxisSnapshot otherModeStale = otherModeAtRest;
        otherModeStale.velocity = 50;
        QTest::newRow("mode change, only a stale velocity")
            << abs << move(10) << base << otherModeStale << none << false << false;
        QTest::newRow("same mode while moving accepted")
            << abs << move(10) << base << continuous << none << false << false;
        QTest::newRow("halt needs no mode change")
            << halt << move(0) << base << moving << none << false << false;
        QTest::newRow("home in motion stays R8") << home << move(0) << base << otherMode
                                                 << int(Refusal::NotAtStandstill) << false << false;
        QTest::newRow("S-34 torque never refused")
            << int(CommandKind::TorqueControl) << MoveParams() << noJerk << still << none << false
            << false;
    }
    void refusal()
    {
        QFETCH(int, kind);
        QFETCH(MoveParams, params);
        QFETCH(AxisConfig, config);
        QFETCH(AxisSnapshot, axis);
        QFETCH(int, refusal);
        QFETCH(bool, success);
        QFETCH(bool, quickStop);
        const Plan plan = planCommand(CommandKind(kind), params, config, axis, axis.position);
        QCOMPARE(int(plan.refusal), refusal);
        QCOMPARE(plan.successAtStandstill, success);
        QCOMPARE(plan.quickStop, quickStop);
    }

    void limits_data()
    {
        QTest::addColumn<double>("velocity");
        QTest::addColumn<double>("override");
        QTest::addColumn<double>("expected");
        QTest::addColumn<bool>("i190");
        QTest::addColumn<bool>("i193");
        QTest::newRow("D-14") << 5000.0 << 100.0 << 3000.0 << true << false;
        QTest::newRow("D-15") << 2500.0 << 150.0 << 3000.0 << false << true;
        QTest::newRow("within") << 2500.0 << 100.0 << 2500.0 << false << false;
        QTest::newRow("override 50 %") << 2500.0 << 50.0 << 1250.0 << false << false;
        QTest::newRow("negative") << -5000.0 << 100.0 << -3000.0 << true << false;
    }
    void limits()
    {
        QFETCH(double, velocity);
        QFETCH(double, override);
        QFETCH(double, expected);
        QFETCH(bool, i190);
        QFETCH(bool, i193);
        AxisConfig c;
        c.maxVelocity = 3000;
        MoveParams p = move(0);
        p.velocity = velocity;
        p.overridePercent = override;
        LimitFlags f;
        const MoveParams out = clampProfile(p, c, &f);
        QCOMPARE(out.velocity, expected);
        QCOMPARE(f.velocityLimited, i190);
        QCOMPARE(f.overrideLimited, i193);
    }
    void accelerationAndJerkLimited()
    {
        AxisConfig c;
        c.maxAcceleration = 50;
        c.maxJerk = 1000;
        MoveParams p = move(0);
        p.jerk = 5000;
        LimitFlags f;
        const MoveParams out = clampProfile(p, c, &f);
        QCOMPARE(out.acceleration, 50.0);
        QCOMPARE(out.deceleration, 50.0);
        QCOMPARE(out.jerk, 1000.0);
        QVERIFY(f.accelerationOrJerkLimited); // I191
    }
    // An axis not known to be referenced: absolute targets, and any positioning with software
    // limits, run with the warning flag; relative moves without software limits and a
    // referenced axis have none.
    void notReferencedIsWarned_data()
    {
        QTest::addColumn<int>("kind");
        QTest::addColumn<bool>("softLimits");
        QTest::addColumn<bool>("referenced");
        QTest::addColumn<bool>("warned");
        const auto abs = int(CommandKind::MoveAbsolute);
        const auto rel = int(CommandKind::MoveRelative);
        QTest::newRow("abs") << abs << false << false << true;
        QTest::newRow("abs referenced") << abs << false << true << false;
        QTest::newRow("rel, soft limits (R7)") << rel << true << false << true;
        QTest::newRow("rel, no soft limits") << rel << false << false << false;
        QTest::newRow("rel, soft limits, referenced") << rel << true << true << false;
    }
    void notReferencedIsWarned()
    {
        QFETCH(int, kind);
        QFETCH(bool, softLimits);
        QFETCH(bool, referenced);
        QFETCH(bool, warned);
        AxisConfig c;
        c.softLimitsUsed = softLimits;
        c.softLimitNegative = -1000;
        c.softLimitPositive = 1000;
        AxisSnapshot a;
        a.referenced = referenced;
        const Plan plan = planCommand(CommandKind(kind), move(10), c, a, 0);
        QCOMPARE(int(plan.refusal), int(Refusal::None));
        QCOMPARE(plan.flags.notReferenced, warned);
        QCOMPARE(plan.flags.velocityLimited, false); // the profile clamp keeps the warning apart
    }
    void homingClampedWithoutFlags() // D-16
    {
        AxisConfig c;
        c.maxVelocity = 3000;
        HomingParams h;
        h.speedFast = 5000;
        QCOMPARE(clampHoming(h, c).speedFast, 3000.0);
        const Plan plan = planCommand(CommandKind::Home, MoveParams(), c, AxisSnapshot(), 0);
        QCOMPARE(plan.flags, LimitFlags());
    }

    void direction_data()
    {
        QTest::addColumn<double>("position");
        QTest::addColumn<double>("target");
        QTest::addColumn<int>("direction");
        QTest::addColumn<double>("velocity");
        QTest::addColumn<double>("braking");
        QTest::addColumn<double>("travel");
        QTest::newRow("D-01") << 350.0 << 10.0 << 0 << 0.0 << 0.0 << 20.0;
        QTest::newRow("D-02") << 350.0 << 10.0 << 3 << 0.0 << 0.0 << 20.0;
        QTest::newRow("D-03") << 350.0 << 10.0 << 2 << 0.0 << 0.0 << -340.0;
        QTest::newRow("D-04") << 10.0 << 9.95 << 1 << 0.0 << 0.0 << -0.05;
        QTest::newRow("D-05") << 10.0 << 9.5 << 1 << 0.0 << 0.0 << 359.5;
        QTest::newRow("D-06") << 100.0 << 90.0 << 0 << 50.0 << 0.0 << 350.0;
        QTest::newRow("D-06 long braking") << 100.0 << 90.0 << 0 << 50.0 << 400.0 << 710.0;
        QTest::newRow("D-07 brakes past") << 100.0 << 90.0 << 1 << -50.0 << 20.0 << -10.0;
        QTest::newRow("D-07 short braking") << 100.0 << 90.0 << 1 << -50.0 << 5.0 << 350.0;
    }
    void direction()
    {
        QFETCH(double, position);
        QFETCH(double, target);
        QFETCH(int, direction);
        QFETCH(double, velocity);
        QFETCH(double, braking);
        QFETCH(double, travel);
        const double got =
            endlessTravel(position, target, 360, Direction(direction), 0.1, velocity, braking);
        QVERIFY2(qAbs(got - travel) < 1e-9, qPrintable(QString::number(got)));
    }
};

QTEST_GUILESS_MAIN(TestMotionRules)
#include "tst_motionrules.moc"
