#include "simulation/simulatedaxis.h"

#include <QTest>

#include <cmath>

using namespace db::sim;

namespace {
// Steps the axis in 1 ms pieces for the given time, recording the largest |v| and |a|.
struct Run
{
    double maxVelocity = 0.0;
    double maxAcceleration = 0.0;
};
Run run(SimulatedAxis &axis, double seconds, double dt = 0.001)
{
    Run r;
    double lastV = axis.demandVelocity();
    for (double t = 0; t < seconds - 1e-12; t += dt) {
        axis.step(dt);
        r.maxVelocity = std::max(r.maxVelocity, std::abs(axis.demandVelocity()));
        r.maxAcceleration =
            std::max(r.maxAcceleration, std::abs(axis.demandVelocity() - lastV) / dt);
        lastV = axis.demandVelocity();
    }
    return r;
}

SimulatedAxis poweredAxis()
{
    SimulatedAxis axis;
    axis.setPowered(true);
    axis.setTargetWindow(1.0, 0.01);
    return axis;
}
} // namespace

class TestSimulatedAxis : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void trapezoidReachesTargetExactlyWithinLimits();
    void shortMoveIsTriangularAndStillExact();
    void resultDoesNotDependOnStepSize();
    void immediateSetPointReversesWithDeceleration();
    void queuedSetPointRunsAfterTheCurrentMove();
    void velocityModeRampsAndReverses();
    void stopBrakesWithGivenDeceleration();
    void softLimitClampsTargetAndSetsInternalLimit();
    void softLimitZeroZeroIsOff();
    void softLimitStopsVelocityMode();
    void targetReachedNeedsWindowTime();
    void homingSetPositionKeepsMechanics();
    void hardStopHomingFindsStopAndSetsOffset();
    void pressingAgainstStopIsBlockedWithCurrentAtLimit();
    void currentFollowsAccelerationAndSaturates();
    void unpoweredAxisDoesNotMove();
};

void TestSimulatedAxis::trapezoidReachesTargetExactlyWithinLimits()
{
    SimulatedAxis axis = poweredAxis();
    axis.moveTo(1000, 100, 400, 200);
    QVERIFY(axis.isMoving());
    const Run r = run(axis, 12.0);
    QCOMPARE(axis.demandPosition(), 1000.0);
    QVERIFY(std::abs(axis.position() - 1000.0) < 1e-6);
    QVERIFY(r.maxVelocity <= 100.0 + 1e-9);
    QVERIFY(r.maxAcceleration <= 400.0 + 1e-6);
    QVERIFY(!axis.isMoving());
    QVERIFY(axis.targetReached());
}

void TestSimulatedAxis::shortMoveIsTriangularAndStillExact()
{
    SimulatedAxis axis = poweredAxis();
    axis.moveTo(-10, 1000, 100, 100);
    const Run r = run(axis, 2.0);
    // Triangle: peak sqrt(10 * 100) = 31.6 units/s, never the 1000 limit.
    QVERIFY(r.maxVelocity < 32.0);
    QCOMPARE(axis.demandPosition(), -10.0);
}

void TestSimulatedAxis::resultDoesNotDependOnStepSize()
{
    SimulatedAxis a = poweredAxis();
    SimulatedAxis b = poweredAxis();
    a.moveTo(500, 120, 300, 300);
    b.moveTo(500, 120, 300, 300);
    run(a, 2.5, 0.001);
    run(b, 2.5, 0.05);
    QVERIFY(std::abs(a.position() - b.position()) < 1e-6);
    QVERIFY(std::abs(a.demandPosition() - b.demandPosition()) < 1e-9);
}

void TestSimulatedAxis::immediateSetPointReversesWithDeceleration()
{
    SimulatedAxis axis = poweredAxis();
    axis.moveTo(1000, 100, 1000, 50);
    run(axis, 1.0);
    QVERIFY(axis.demandVelocity() > 99.0);
    axis.moveTo(0, 100, 1000, 50, true);
    const Run r = run(axis, 0.5);
    // Braking from +100 at 50 units/s^2 takes 2 s: after 0.5 s still positive, 75 units/s.
    QVERIFY(std::abs(axis.demandVelocity() - 75.0) < 1e-6);
    QVERIFY(r.maxAcceleration <= 50.0 + 1e-6);
    run(axis, 10.0);
    QCOMPARE(axis.demandPosition(), 0.0);
}

void TestSimulatedAxis::queuedSetPointRunsAfterTheCurrentMove()
{
    SimulatedAxis axis = poweredAxis();
    axis.moveTo(100, 100, 1000, 1000);
    QVERIFY(axis.moveTo(-50, 100, 1000, 1000, false));
    QVERIFY(!axis.moveTo(7, 100, 1000, 1000, false)); // one buffered target only
    run(axis, 1.0);
    QVERIFY(axis.demandPosition() < 100.0); // turned around after reaching 100
    run(axis, 3.0);
    QCOMPARE(axis.demandPosition(), -50.0);
}

void TestSimulatedAxis::velocityModeRampsAndReverses()
{
    SimulatedAxis axis = poweredAxis();
    axis.moveVelocity(200, 100, 400);
    run(axis, 1.0);
    QVERIFY(std::abs(axis.demandVelocity() - 100.0) < 1e-6);
    run(axis, 2.0);
    QCOMPARE(axis.demandVelocity(), 200.0);
    QVERIFY(axis.targetReached());
    axis.moveVelocity(-200, 100, 400);
    run(axis, 0.5); // decelerating at 400: 200 -> 0 in 0.5 s
    QVERIFY(std::abs(axis.demandVelocity()) < 1e-6);
    run(axis, 1.0); // accelerating at 100 in the other direction
    QVERIFY(std::abs(axis.demandVelocity() + 100.0) < 1e-6);
}

void TestSimulatedAxis::stopBrakesWithGivenDeceleration()
{
    SimulatedAxis axis = poweredAxis();
    axis.moveVelocity(300, 1000, 1000);
    run(axis, 1.0);
    const double from = axis.demandPosition();
    axis.stop(600);
    QCOMPARE(axis.mode(), SimulatedAxis::Mode::Stopping);
    run(axis, 0.25);
    QVERIFY(std::abs(axis.demandVelocity() - 150.0) < 1e-6);
    run(axis, 1.0);
    QCOMPARE(axis.demandVelocity(), 0.0);
    // Braking distance v^2 / 2d = 75 units.
    QVERIFY(std::abs(axis.demandPosition() - from - 75.0) < 1e-6);
    QVERIFY(!axis.isMoving());
}

void TestSimulatedAxis::softLimitClampsTargetAndSetsInternalLimit()
{
    SimulatedAxis axis = poweredAxis();
    axis.setSoftLimits(-100, 100);
    axis.moveTo(500, 1000, 1000, 1000);
    QVERIFY(axis.internalLimitActive());
    run(axis, 2.0);
    QCOMPARE(axis.demandPosition(), 100.0);
    axis.moveTo(50, 1000, 1000, 1000);
    QVERIFY(!axis.internalLimitActive());
}

void TestSimulatedAxis::softLimitZeroZeroIsOff()
{
    SimulatedAxis axis = poweredAxis();
    axis.setSoftLimits(0, 0);
    axis.moveTo(500, 1000, 1000, 1000);
    QVERIFY(!axis.internalLimitActive());
    run(axis, 2.0);
    QCOMPARE(axis.demandPosition(), 500.0);
}

void TestSimulatedAxis::softLimitStopsVelocityMode()
{
    SimulatedAxis axis = poweredAxis();
    axis.setSoftLimits(-1000, 300);
    axis.moveVelocity(200, 400, 400);
    run(axis, 5.0);
    QVERIFY(axis.internalLimitActive());
    QVERIFY(axis.demandPosition() <= 300.0 + 1e-6);
    QVERIFY(axis.demandPosition() > 290.0);
    QCOMPARE(axis.demandVelocity(), 0.0);
}

void TestSimulatedAxis::targetReachedNeedsWindowTime()
{
    SimulatedAxis axis;
    axis.setPowered(true);
    axis.setTargetWindow(0.5, 0.2);
    axis.moveTo(10, 100, 10000, 10000);
    run(axis, 0.25); // profile done after ~0.11 s, then inside the window < 0.2 s
    QVERIFY(!axis.targetReached());
    run(axis, 0.2);
    QVERIFY(axis.targetReached());
}

void TestSimulatedAxis::homingSetPositionKeepsMechanics()
{
    SimulatedAxis axis = poweredAxis();
    axis.setHardStops(std::nullopt, 50.0);
    axis.moveTo(20, 100, 1000, 1000);
    run(axis, 1.0);
    axis.setPosition(0.0); // REF35: here is zero now, the stop is 30 units ahead
    QCOMPARE(axis.position(), 0.0);
    QCOMPARE(axis.homingState(), SimulatedAxis::HomingState::Attained);
    axis.moveTo(100, 100, 1000, 1000);
    run(axis, 3.0);
    QCOMPARE(axis.position(), 30.0);
    QVERIFY(axis.blocked());
}

void TestSimulatedAxis::hardStopHomingFindsStopAndSetsOffset()
{
    SimulatedAxis axis = poweredAxis();
    axis.setHardStops(-40.0, std::nullopt);
    axis.startHardStopHoming(-1, 50, 500, 7.0);
    QCOMPARE(axis.homingState(), SimulatedAxis::HomingState::Searching);
    run(axis, 0.5);
    QVERIFY(axis.velocity() < -40.0);
    run(axis, 2.0);
    QCOMPARE(axis.homingState(), SimulatedAxis::HomingState::Attained);
    QCOMPARE(axis.position(), 7.0);
    QVERIFY(!axis.isMoving());
    axis.moveTo(-100, 100, 1000, 1000);
    run(axis, 2.0);
    QCOMPARE(axis.position(), 7.0); // the stop moved with the new frame
}

void TestSimulatedAxis::pressingAgainstStopIsBlockedWithCurrentAtLimit()
{
    SimulatedAxis axis = poweredAxis();
    axis.setCurrentLimit(300);
    axis.setHardStops(std::nullopt, 10.0);
    axis.moveTo(100, 50, 500, 500);
    run(axis, 3.0);
    QVERIFY(axis.blocked());
    QCOMPARE(axis.current(), 300.0);
    axis.setHardStops(std::nullopt, std::nullopt); // blockage removed: continues to target
    run(axis, 1.0);
    QVERIFY(std::abs(axis.position() - 100.0) < 1e-3);
    QVERIFY(!axis.blocked());
}

void TestSimulatedAxis::currentFollowsAccelerationAndSaturates()
{
    SimulatedAxis axis = poweredAxis();
    axis.moveVelocity(1000, 50000, 50000); // 50000 * 0.01 = 500 = 50 % while accelerating
    axis.step(0.005);
    QVERIFY(axis.current() > 480 && axis.current() < 560);
    axis.setCurrentLimit(200);
    axis.moveVelocity(-1000, 100000, 100000);
    axis.step(0.002);
    QCOMPARE(axis.current(), -200.0);
    run(axis, 1.0);
    // Cruising negative: friction (40) plus noise (+-3), negative sign.
    QVERIFY(axis.current() < -35 && axis.current() > -45);
}

void TestSimulatedAxis::unpoweredAxisDoesNotMove()
{
    SimulatedAxis axis;
    axis.moveTo(100, 100, 100, 100);
    run(axis, 2.0);
    QCOMPARE(axis.position(), 0.0);
    QCOMPARE(axis.current(), 0.0);
}

QTEST_GUILESS_MAIN(TestSimulatedAxis)
#include "tst_simulatedaxis.moc"
