// Level 3: drive-side supervision (canopen::DriveSupervision) against the simulated MovingCap
// over SLCAN on loopback: the drive offers node guarding (100Ch/100Dh) and 6007h; armed, a drive
// whose master goes away without a word (socket closed) quick-stops by itself; disarmed, the
// previous values are back.
#include "canopen/cannetwork.h"
#include "canopen/drivesupervision.h"
#include "canopen/nodeguarding.h"
#include "canopen/nodemonitor.h"
#include "motionaxisrig.h"

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTest>

using namespace db;
using namespace db::motion;
using namespace db::test;
using canopen::DriveSupervision;
using Status = MotionCommand::Status;

namespace {
constexpr int kMarginMs = 200; // event loop and SLCAN latency on a busy machine

bool powerOn(MotionAxis *axis)
{
    MotionCommand power(axis, CommandKind::Power);
    power.setEnable(true);
    power.setExecute(true);
    return QTest::qWaitFor([&] { return power.isFinished(); }, 5000)
        && power.status() == Status::Done;
}

qint64 value(Rig &rig, quint16 index, quint8 sub = 0)
{
    return rig.drive().read({ index, sub }).value().toLongLong();
}
} // namespace

class TestDriveSupervision : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void onlyCanopenHasIt()
    {
        auto a = makeMotionRig(QStringLiteral("refgo"), 50000);
        QVERIFY(a);
        DriveSupervision s(a->rig->connection.get());
        QCOMPARE(s.mode(), DriveSupervision::Mode::None);
        const auto armed = await(s.arm());
        QCOMPARE(armed.error().kind(), Error::Kind::NotSupported);
        QVERIFY(s.description().contains(QLatin1String("no drive-side supervision")));
    }

    void armThenDisarmRestores()
    {
        auto a = makeMotionRig(QStringLiteral("canopen"), 50000);
        QVERIFY(a);
        DriveSupervision s(a->rig->connection.get());
        QCOMPARE(s.mode(), DriveSupervision::Mode::Guarding); // the MovingCap has no 1016h
        QVERIFY2(s.description().contains(QLatin1String("drive stops within 500 ms")),
                 qPrintable(s.description()));
        QVERIFY(await(s.arm()).ok());
        QVERIFY(s.isArmed());
        QCOMPARE(value(*a->rig, 0x100C), qint64(DriveSupervision::kPeriodMs));
        QCOMPARE(value(*a->rig, 0x100D), qint64(DriveSupervision::kLifeTimeFactor));
        QCOMPARE(value(*a->rig, 0x6007), qint64(DriveSupervision::kAbortQuickStop));
        const auto at = canopen::networkNodeOf(a->rig->connection.get());
        QVERIFY(at.network->guarding()->isGuarding(at.node));
        QVERIFY(await(s.disarm()).ok());
        QVERIFY(!s.isArmed());
        QCOMPARE(value(*a->rig, 0x100C), qint64(0));
        QCOMPARE(value(*a->rig, 0x100D), qint64(0));
        QCOMPARE(value(*a->rig, 0x6007), qint64(1));
        QVERIFY(!at.network->guarding()->isGuarding(at.node));
    }

    void driveHeartbeatIsWatchedFromItsPeriod()
    {
        // The drive produces its heartbeat every 50 ms (1017h): once connected, the tool's
        // node monitor watches it, and a drive that falls silent is reported.
        auto rig = makeRig(QStringLiteral("canopen"), { { ObjectAddress(0x1017, 0), 50 } });
        QVERIFY(rig);
        const auto at = canopen::networkNodeOf(rig->connection.get());
        QTRY_COMPARE(at.network->monitor()->consumerTime(at.node), 100);
        QTRY_VERIFY(at.network->monitor()->isAlive(at.node));
        QSignalSpy lost(rig->connection.get(), &DeviceConnection::supervisionLost);
        QVERIFY(await(rig->connection->write({ 0x1017, 0 }, 0)).ok()); // falls silent
        QVERIFY(lost.wait(2000));
        QVERIFY2(lost.at(0).at(0).toString().contains(
                     QLatin1String("heartbeat lost: node 50 silent for more than 100 ms")),
                 qPrintable(lost.at(0).at(0).toString()));
    }

    void runningMoveEndsWithHeartbeatLost()
    {
        // The drive beats every 50 ms (1017h); it falls silent mid-move (dead, or its bus
        // gone): the move ends with the cause within the consumer time, and the drive, which
        // still answers SDO here, is told to stop.
        auto a =
            makeMotionRig(QStringLiteral("canopen"), 50000, { { ObjectAddress(0x1017, 0), 50 } });
        QVERIFY(a);
        const auto at = canopen::networkNodeOf(a->rig->connection.get());
        QTRY_COMPARE(at.network->monitor()->consumerTime(at.node), 100);
        QVERIFY(powerOn(a->axis.get()));
        MotionCommand move(a->axis.get(), CommandKind::MoveAbsolute);
        move.setParams(moveParams(1e6, 2000, 20000));
        move.setExecute(true);
        const auto &drive = a->rig->drive();
        QTRY_VERIFY_WITH_TIMEOUT(qAbs(drive.axis().velocity() - 2000) < 20, 5000);
        QVERIFY(move.isBusy());
        QElapsedTimer since;
        since.start();
        a->rig->demo->setHeartbeatSilenced(true);
        QTRY_VERIFY_WITH_TIMEOUT(move.isFinished(), 100 + kMarginMs);
        const qint64 endedMs = since.elapsed();
        QCOMPARE(move.status(), Status::Error);
        QVERIFY2(move.error().message().contains(QLatin1String("heartbeat lost: node 50")),
                 qPrintable(move.error().message()));
        QCOMPARE(a->axis->state(), AxisState::ErrorStop);
        QTRY_VERIFY_WITH_TIMEOUT(!drive.axis().isMoving(), 2000);
        qInfo("move ended %lld ms after the heartbeat stopped (consumer time 100 ms); standstill "
              "after %lld ms",
              endedMs, since.elapsed());
    }

    void toolGoneQuickStopsTheDrive()
    {
        auto a = makeMotionRig(QStringLiteral("canopen"), 50000);
        QVERIFY(a);
        DriveSupervision s(a->rig->connection.get());
        QVERIFY(await(s.arm()).ok());
        QVERIFY(powerOn(a->axis.get()));
        // An unbounded jog: only the drive-side supervision can stop it.
        MotionCommand jog(a->axis.get(), CommandKind::MoveVelocity);
        jog.setParams(moveParams(0, 2000, 20000));
        jog.setExecute(true);
        const auto &drive = a->rig->drive();
        // Guarded for more than two life times, the drive keeps going.
        QTRY_VERIFY_WITH_TIMEOUT(
            drive.axis().position() > 2000 * 2 * DriveSupervision::kReactionMs / 1000.0, 10000);
        QCOMPARE(drive.state(), cia402::State::OperationEnabled);
        QVERIFY(qAbs(drive.axis().velocity() - 2000) < 20);
        // The process dies: the socket closes, nothing else is sent.
        QElapsedTimer since;
        since.start();
        a->rig->connection->close();
        QTRY_VERIFY_WITH_TIMEOUT(drive.state() != cia402::State::OperationEnabled,
                                 DriveSupervision::kReactionMs + kMarginMs);
        const qint64 reactedMs = since.elapsed();
        QTRY_VERIFY_WITH_TIMEOUT(!drive.axis().isMoving(), 2000);
        qInfo("quick stop %lld ms after the socket closed (life time %d ms); standstill after "
              "%lld ms",
              reactedMs, DriveSupervision::kReactionMs, since.elapsed());
    }
};

QTEST_GUILESS_MAIN(TestDriveSupervision)
#include "tst_drivesupervision.moc"
