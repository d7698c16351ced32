// Level 2/3: the CiA 402 power state machine driver and the modes against the simulated
// MovingCap in-process, over RefGo (OR/OW) and over CANopen SDO (SLCAN door, node 50).
#include "cia402/cia402statussource.h"
#include "cia402/drivecontroller.h"
#include "cia402/modes.h"
#include "cia402/sequence.h"
#include "cia402/statusword.h"
#include "devices/movingcap/movingcapfaults.h"
#include "driverig.h"

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTest>

#include <algorithm>

using namespace db;
using namespace db::cia402;
using namespace db::test;

class TestDriveController : public QObject
{
    Q_OBJECT
private:
    void transports()
    {
        QTest::addColumn<QString>("kind");
        QTest::newRow("sim") << QStringLiteral("sim");
        QTest::newRow("refgo") << QStringLiteral("refgo");
        QTest::newRow("canopen") << QStringLiteral("canopen");
    }

private Q_SLOTS:
    void enableAndDisable_data() { transports(); }
    void enableAndDisable()
    {
        QFETCH(QString, kind);
        auto rig = makeRig(kind);
        QVERIFY(rig);
        DriveController dc(rig->connection.get());
        auto r = await(dc.enableOperation());
        QVERIFY2(r.ok(), qPrintable(r.error().toString()));
        QCOMPARE(decodeState(quint16(r->toUInt())), State::OperationEnabled);
        QCOMPARE(rig->drive().state(), State::OperationEnabled);
        QVERIFY(await(dc.switchOn()).ok());
        QCOMPARE(rig->drive().state(), State::SwitchedOn);
        QVERIFY(await(dc.shutdown()).ok());
        QCOMPARE(rig->drive().state(), State::ReadyToSwitchOn);
        QVERIFY(await(dc.enableOperation()).ok());
        QVERIFY(await(dc.disableVoltage()).ok());
        QCOMPARE(rig->drive().state(), State::SwitchOnDisabled);
    }
    void faultResetThenEnable_data() { transports(); }
    void faultResetThenEnable()
    {
        QFETCH(QString, kind);
        auto rig = makeRig(kind);
        QVERIFY(rig);
        DriveController dc(rig->connection.get());
        QVERIFY(await(dc.enableOperation()).ok());
        rig->drive().injectFault(sim::faults::Stroke);
        QTRY_COMPARE(rig->drive().state(), State::Fault);
        QVERIFY(await(dc.faultReset()).ok());
        QCOMPARE(rig->drive().state(), State::SwitchOnDisabled);
        rig->drive().injectFault(sim::faults::Stroke);
        QTRY_COMPARE(rig->drive().state(), State::Fault);
        auto r = await(dc.enableOperation()); // plans 0 -> 0x80 -> 6 -> 7 -> 15
        QVERIFY2(r.ok(), qPrintable(r.error().toString()));
        QCOMPARE(rig->drive().state(), State::OperationEnabled);
    }
    void quickStop_data() { transports(); }
    void quickStop()
    {
        QFETCH(QString, kind);
        auto rig = makeRig(kind);
        QVERIFY(rig);
        DriveController dc(rig->connection.get());
        QVERIFY(await(dc.enableOperation()).ok());
        QVERIFY(await(profileVelocity(rig->connection.get(), 500, 1000, 1000, &dc)->start()).ok());
        QTRY_VERIFY(rig->drive().axis().velocity() > 100);
        QVERIFY(await(dc.quickStop()).ok());
        QVERIFY(rig->drive().state() != State::OperationEnabled);
        QTRY_VERIFY(!rig->drive().axis().isMoving());
    }
    void profilePositionHandshake_data() { transports(); }
    void profilePositionHandshake()
    {
        QFETCH(QString, kind);
        auto rig = makeRig(kind);
        QVERIFY(rig);
        DriveController dc(rig->connection.get());
        QVERIFY(await(dc.enableOperation()).ok());
        PositionSetPoint sp { 720, 7200, 2000, 2000, false, true, {}, 0 };
        auto r = await(profilePosition(rig->connection.get(), sp, &dc)->start());
        QVERIFY2(r.ok(), qPrintable(r.error().toString()));
        // Handshake finished: bit 4 back to 0, bit 12 cleared.
        QCOMPARE(rig->drive().read({ 0x6040, 0 }).value().toUInt(), 0x0Fu);
        QTRY_VERIFY(rig->drive().statusword() & sw::TargetReached);
        QTRY_VERIFY(qAbs(rig->drive().axis().position() - 720) < 1);
        sp = { 100, 7200, 2000, 2000, true, true, {}, 0 }; // relative (bit 6): from the last target
        QVERIFY(await(profilePosition(rig->connection.get(), sp, &dc)->start()).ok());
        QTRY_VERIFY(qAbs(rig->drive().axis().position() - 820) < 1);
    }
    void homingSetsOffset_data() { transports(); }
    void homingSetsOffset()
    {
        QFETCH(QString, kind);
        auto rig = makeRig(kind);
        QVERIFY(rig);
        DriveController dc(rig->connection.get());
        QVERIFY(await(dc.enableOperation()).ok());
        HomingSetPoint sp;
        sp.method = 35;
        sp.speedFast = 90;
        sp.acceleration = 1000;
        sp.offset = 1234;
        auto r = await(homing(rig->connection.get(), sp, &dc)->start());
        QVERIFY2(r.ok(), qPrintable(r.error().toString()));
        QCOMPARE(qRound(rig->drive().axis().position()), 1234);
    }
    void stepTimesOutWhenTheDriveDoesNotFollow()
    {
        auto rig = makeRig(QStringLiteral("sim"));
        QVERIFY(rig);
        rig->sim->ignoreAllWrites = true;
        DriveController dc(rig->connection.get());
        auto r = await(dc.enableOperation(), 3000);
        QCOMPARE(r.error().kind(), Error::Kind::Timeout);
        QVERIFY2(r.error().message().contains(QLatin1String("Ready to switch on")),
                 qPrintable(r.error().message()));
    }
    // A wait step is judged by its own status read: one answered after the step's time (here
    // every answer takes 60 ms, the step allows 20) is an answer, not "no answer"; the state
    // it shows decides.
    void waitJudgedByItsOwnStatusRead()
    {
        auto rig = makeRig(QStringLiteral("sim"));
        QVERIFY(rig);
        rig->sim->immediate = false;
        rig->sim->replyDelayMs = 60;
        auto reached = [](quint16 word, QString &) {
            return (word & 0x4F) == 0x40 ? WaitVerdict::Reached : WaitVerdict::Pending;
        };
        auto *seq = new Sequence(rig->connection.get(), QStringLiteral("slow drive"));
        seq->waitFor(QStringLiteral("switch on disabled"), reached, 20);
        auto r = await(seq->start(), 5000);
        QVERIFY2(r.ok(), qPrintable(r.error().toString()));
        QCOMPARE(quint16(r->toUInt()) & 0x4F, 0x40);

        // Answered late and not there: the state is named, not a missing answer.
        auto *late = new Sequence(rig->connection.get(), QStringLiteral("slow drive"));
        late->waitFor(
            QStringLiteral("operation enabled"),
            [](quint16, QString &) { return WaitVerdict::Pending; }, 20);
        r = await(late->start(), 5000);
        QCOMPARE(r.error().kind(), Error::Kind::Timeout);
        QVERIFY2(r.error().message().contains(QLatin1String("operation enabled did not happen")),
                 qPrintable(r.error().message()));
        QVERIFY2(r.error().message().contains(QLatin1String("statusword 0x")),
                 qPrintable(r.error().message()));
    }
    // The same over RefGo and CANopen SDO, where requests go one at a time: a status read queued
    // behind an editor's reads (here 200, past the step's 1 ms) is an answer when it comes.
    void waitBehindQueuedReads_data()
    {
        QTest::addColumn<QString>("kind");
        QTest::newRow("refgo") << QStringLiteral("refgo");
        QTest::newRow("canopen") << QStringLiteral("canopen");
    }
    void waitBehindQueuedReads()
    {
        QFETCH(QString, kind);
        auto rig = makeRig(kind);
        QVERIFY(rig);
        QList<Reply *> ahead;
        for (int i = 0; i < 200; ++i)
            ahead.append(rig->connection->read({ 0x1000, 0 }));
        auto *seq = new Sequence(rig->connection.get(), QStringLiteral("queued"));
        seq->waitFor(QStringLiteral("switch on disabled"), bitsSet(0x40), 1);
        auto r = await(seq->start(), 10000);
        QVERIFY2(r.ok(), qPrintable(r.error().toString()));
        for (Reply *reply : ahead) {
            QVERIFY(reply->isFinished() && reply->ok());
            reply->deleteLater();
        }
    }
    // A status read that gets no answer: the step says so, with the read's own cause.
    void waitWithoutStatusAnswerSaysNoAnswer()
    {
        auto rig = makeRig(QStringLiteral("sim"));
        QVERIFY(rig);
        rig->sim->immediate = false;
        rig->connection->setRequestTimeoutMs(300);
        rig->sim->silent.insert(kStatusword);
        auto *seq = new Sequence(rig->connection.get(), QStringLiteral("silent drive"));
        seq->waitFor(
            QStringLiteral("switch on disabled"),
            [](quint16, QString &) { return WaitVerdict::Reached; }, 20);
        QElapsedTimer clock;
        clock.start();
        auto r = await(seq->start(), 5000);
        QCOMPARE(r.error().kind(), Error::Kind::Timeout);
        QVERIFY2(r.error().message().contains(QLatin1String("no answer")),
                 qPrintable(r.error().message()));
        QVERIFY2(r.error().message().startsWith(QLatin1String("silent drive: ")),
                 qPrintable(r.error().message()));
        QVERIFY2(clock.elapsed() >= 250, qPrintable(QString::number(clock.elapsed())));
    }
    // A drive that falls silent: the status cycle ends at its first unanswered read instead of
    // letting every read queued behind it wait out its own time limit, so the status (and a
    // command waiting for it) says "no answer" after one time limit, not one per object.
    void statusCycleEndsAtTheFirstUnansweredRead_data()
    {
        QTest::addColumn<QString>("kind");
        QTest::newRow("refgo") << QStringLiteral("refgo");
        QTest::newRow("canopen") << QStringLiteral("canopen");
    }
    void statusCycleEndsAtTheFirstUnansweredRead()
    {
        QFETCH(QString, kind);
        auto rig = makeRig(kind);
        QVERIFY(rig);
        // The product's time limit: the simulator answers in the test's own thread, which the
        // sanitizer build slows down enough for shorter limits to expire before its answers.
        rig->connection->setRequestTimeoutMs(1000);
        Cia402StatusSource source(rig->connection.get());
        QVERIFY(source.polledObjects().size() >= 6);
        source.setIntervalMs(20);
        source.acquire();
        QTRY_VERIFY_WITH_TIMEOUT(source.statusWordValue().fresh, 10000);
        int timeouts = 0;
        connect(
            rig->connection.get(), &DeviceConnection::requestFinished, this,
            [&](ObjectAddress, const Error &e) { timeouts += e.kind() == Error::Kind::Timeout; });
        QList<int> timeoutsAtUpdate;
        connect(&source, &StatusSource::updated, this, [&] { timeoutsAtUpdate.append(timeouts); });

        rig->demo->setSilent(true);
        const qsizetype start = timeoutsAtUpdate.size();
        QTRY_VERIFY_WITH_TIMEOUT(timeoutsAtUpdate.size() >= start + 3, 30000);
        // The first cycle may have been half answered; each later one met the silence at once.
        for (qsizetype i = start + 1; i < start + 3; ++i)
            QCOMPARE(timeoutsAtUpdate.at(i) - timeoutsAtUpdate.at(i - 1), 1);
        QVERIFY(!source.statusWordValue().fresh);
        for (const StatusValue &v : source.actualValues()) {
            QVERIFY2(!v.fresh, qPrintable(v.key));
            QVERIFY2(v.error.contains(QLatin1String("answer")), qPrintable(v.error));
        }

        // The withdrawn reads left nothing behind: it answers again, every value is fresh.
        rig->demo->setSilent(false);
        QTRY_VERIFY_WITH_TIMEOUT(source.statusWordValue().fresh, 20000);
        QTRY_VERIFY_WITH_TIMEOUT(std::ranges::all_of(source.actualValues(),
                                                     [](const StatusValue &v) { return v.fresh; }),
                                 10000);
    }
    void softwareEnableMissingFails()
    {
        // Input function 9 on IN1 (high required), IN1 low: switch-on raises FFF2h.
        auto rig = makeRig(QStringLiteral("sim"), { { { 0x3511, 1 }, 0x0900 } });
        QVERIFY(rig);
        DriveController dc(rig->connection.get());
        auto r = await(dc.enableOperation());
        QCOMPARE(r.error().kind(), Error::Kind::DeviceError);
        QVERIFY(r.error().message().contains(QLatin1String("fault")));
    }
    void newRequestSupersedesOlder()
    {
        auto rig = makeRig(QStringLiteral("sim"));
        QVERIFY(rig);
        DriveController dc(rig->connection.get());
        Reply *enable = dc.enableOperation();
        Reply *disable = dc.disableVoltage();
        QCOMPARE(await(enable).error().kind(), Error::Kind::Cancelled);
        QVERIFY(await(disable).ok());
        QCOMPARE(rig->drive().state(), State::SwitchOnDisabled);
    }
};

QTEST_GUILESS_MAIN(TestDriveController)
#include "tst_drivecontroller.moc"
