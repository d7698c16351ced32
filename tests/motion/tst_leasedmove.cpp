// Level 3: hand-driven motion bounded by a lease (LeasedMove) against the simulated MovingCap
// in-process, over RefGo and over CANopen: while renewals go on the axis jogs at the jog velocity
// past many leases; when they stop without any stop being sent (a killed or frozen client) the
// drive brakes with its own ramp and stands at the last commanded target.
#include "motion/leasedmove.h"
#include "motionaxisrig.h"

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTest>

using namespace db;
using namespace db::motion;
using namespace db::test;
using Status = MotionCommand::Status;

namespace {
constexpr double kTolerance = 2.0; // units; the drive reports integer positions
constexpr double kJogVelocity = 2000;
constexpr double kJogRamp = 20000; // braking distance 100 units, braking time 100 ms
// A renewal already on its way when the client dies may still be taken (one SDO/RefGo handshake).
constexpr int kInFlightMs = 250;

bool powerOn(MotionAxis *axis)
{
    MotionCommand power(axis, CommandKind::Power);
    power.setEnable(true);
    power.setExecute(true);
    return QTest::qWaitFor([&] { return power.isFinished(); }, 5000)
        && power.status() == Status::Done;
}

void addKinds()
{
    QTest::addColumn<QString>("kind");
    QTest::newRow("sim") << QStringLiteral("sim");
    QTest::newRow("refgo") << QStringLiteral("refgo");
    QTest::newRow("canopen") << QStringLiteral("canopen");
}
} // namespace

class TestLeasedMove : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void leaseIsBounded()
    {
        auto a = makeMotionRig(QStringLiteral("sim"), 50000);
        QVERIFY(a);
        LeasedMove lease(a->axis.get());
        lease.jog(+1, moveParams(0, kJogVelocity, kJogRamp));
        lease.stopRenewing();
        QCOMPARE(lease.leaseTravel(), kJogVelocity * LeasedMove::kLeaseMs / 1000.0 + 100.0);
        QCOMPARE(lease.leaseTimeMs(), LeasedMove::kLeaseMs + 100.0);
        QVERIFY(LeasedMove::kRenewMs * 3 <= LeasedMove::kLeaseMs);
    }

    void renewedJogKeepsMoving_data() { addKinds(); }
    void renewedJogKeepsMoving()
    {
        QFETCH(QString, kind);
        auto a = makeMotionRig(kind, 50000);
        QVERIFY(a && powerOn(a->axis.get()));
        const auto &drive = a->rig->drive().axis();
        auto lease = std::make_unique<LeasedMove>(a->axis.get());
        lease->jog(+1, moveParams(0, kJogVelocity, kJogRamp));
        // Past five leases' worth of travel, still at the jog velocity.
        const double travel = lease->leaseTravel();
        QTRY_VERIFY_WITH_TIMEOUT(drive.position() > 5 * travel, 10000);
        QVERIFY(drive.isMoving());
        QVERIFY2(qAbs(drive.velocity() - kJogVelocity) < 20,
                 qPrintable(QString::number(drive.velocity())));
        QVERIFY(lease->isRenewing());
        QCOMPARE(a->axis->state(), AxisState::DiscreteMotion);
    }

    void killedClientStopsWithinTheLease_data() { addKinds(); }
    void killedClientStopsWithinTheLease()
    {
        QFETCH(QString, kind);
        auto a = makeMotionRig(kind, 50000);
        QVERIFY(a && powerOn(a->axis.get()));
        const auto &drive = a->rig->drive().axis();
        auto lease = std::make_unique<LeasedMove>(a->axis.get());
        lease->jog(-1, moveParams(0, kJogVelocity, kJogRamp));
        QTRY_VERIFY_WITH_TIMEOUT(drive.position() < -2 * lease->leaseTravel(), 10000);
        QVERIFY(qAbs(drive.velocity() + kJogVelocity) < 20);
        // The client dies: the lease object goes away without sending anything.
        const double travel = lease->leaseTravel();
        const double boundMs = lease->leaseTimeMs() + kInFlightMs;
        const double renewedAt = lease->lastRenewalPosition();
        const double target = lease->lastTarget();
        QVERIFY2(qAbs(target - renewedAt + travel) < kTolerance,
                 qPrintable(QStringLiteral("%1 %2").arg(target).arg(renewedAt)));
        QElapsedTimer since;
        since.start();
        lease.reset();
        QTRY_VERIFY_WITH_TIMEOUT(!drive.isMoving(), int(boundMs));
        qInfo("%s: standstill %lld ms after the renewals stopped (bound %.0f ms); %.1f units "
              "past the last renewal's actual position (lease %.0f)",
              qPrintable(kind), since.elapsed(), boundMs, renewedAt - drive.position(), travel);
        // Stopped by its own profile at the target, not by a quick stop.
        QVERIFY2(qAbs(drive.position() - target) < kTolerance,
                 qPrintable(QStringLiteral("%1 vs %2").arg(drive.position()).arg(target)));
        QVERIFY(renewedAt - drive.position() <= travel + kTolerance);
        QCOMPARE(a->rig->drive().state(), cia402::State::OperationEnabled);
    }

    void stepEndsAtItsTarget()
    {
        auto a = makeMotionRig(QStringLiteral("sim"), 50000);
        QVERIFY(a && powerOn(a->axis.get()));
        LeasedMove lease(a->axis.get());
        QSignalSpy ended(&lease, &LeasedMove::ended);
        lease.step(3000, moveParams(0, kJogVelocity, kJogRamp)); // four leases long
        QVERIFY(ended.wait(5000));
        QCOMPARE(ended.at(0).at(0).value<Status>(), Status::Done);
        QVERIFY(qAbs(a->rig->drive().axis().position() - 3000) < kTolerance);
        QCOMPARE(lease.direction(), 0);
    }

    void jogStopsAtTheSoftwareLimit()
    {
        auto a = makeMotionRig(QStringLiteral("sim"), 50000);
        QVERIFY(a && powerOn(a->axis.get()));
        AxisConfig c = a->axis->config();
        c.softLimitsUsed = true;
        c.softLimitNegative = -1500;
        c.softLimitPositive = 1500;
        a->axis->setConfig(c);
        LeasedMove lease(a->axis.get());
        QSignalSpy ended(&lease, &LeasedMove::ended);
        lease.jog(+1, moveParams(0, kJogVelocity, kJogRamp));
        QVERIFY(ended.wait(5000));
        QCOMPARE(ended.at(0).at(0).value<Status>(), Status::Done);
        QVERIFY(qAbs(a->rig->drive().axis().position() - 1500) < kTolerance);
    }

    void haltBrakesWithTheRamp()
    {
        auto a = makeMotionRig(QStringLiteral("sim"), 50000);
        QVERIFY(a && powerOn(a->axis.get()));
        LeasedMove lease(a->axis.get());
        lease.jog(+1, moveParams(0, kJogVelocity, kJogRamp));
        QTRY_VERIFY(a->rig->drive().axis().position() > 500);
        lease.halt();
        QVERIFY(!lease.isRenewing());
        QTRY_VERIFY(!a->rig->drive().axis().isMoving());
        QTRY_COMPARE(a->axis->state(), AxisState::Standstill);
        QCOMPARE(a->rig->drive().state(), cia402::State::OperationEnabled);
    }
};

QTEST_GUILESS_MAIN(TestLeasedMove)
#include "tst_leasedmove.moc"
