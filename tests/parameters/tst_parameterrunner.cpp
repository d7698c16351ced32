// ParameterBackup / ParameterRestore over in-process connections: the simulated MovingCap (the
// RefGo object model) and a simulated CANopen node (PDO objects), with the failure modes
// named in each test.
#include "canopen/device/simulatednode.h"
#include "canopen/storesignatures.h"
#include "devices/movingcap/movingcapdrive.h"
#include "fakeconnection.h"
#include "parameters/parameterrunner.h"
#include "resources/builtindescriptions.h"
#include "wait.h"

#include <QSignalSpy>
#include <QTest>

#include <memory>

using namespace db;
using db::test::FakeConnection;
using db::test::runToEnd;

namespace {

QVariant u32(quint32 v)
{
    return QVariant::fromValue<qulonglong>(v);
}

// The simulated MovingCap behind a fake connection that answers at once, connected; it stores
// and restores defaults as a CiA 301 device does (1010h / 1011h).
void attach(FakeConnection &connection, const ObjectDictionary &dictionary)
{
    connection.setDictionary(dictionary);
    connection.setCapabilities(DeviceConnection::Capability::StoreNonVolatile);
    connection.immediate = true;
    connection.open();
}

struct MovingCapRig
{
    MovingCapRig()
        : drive(resources::movingCapDictionary())
    {
        connection.setModel(&drive);
        attach(connection, drive.dictionary());
    }
    sim::MovingCapDrive drive;
    FakeConnection connection;
};

// A CANopen node with the built-in test description (PDO objects 1400h-1A01h); every write
// that reaches it is recorded in order.
struct NodeRig
{
    NodeRig()
        : node(resources::builtinDescription(QStringLiteral("drivebench_testnode")).value(), 5)
    {
        connection.setModel(&node);
        QObject::connect(&node, &canopen::SimulatedNode::objectWritten,
                         [this](ObjectAddress a, const QVariant &v) {
                             written.append(QStringLiteral("%1=%2").arg(
                                 a.toString(), QString::number(v.toULongLong(), 16)));
                         });
        attach(connection, node.dictionary());
    }
    canopen::SimulatedNode node;
    FakeConnection connection;
    QStringList written;
};

} // namespace

class TestParameterRunner : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void backupReadsEveryStorableObject();
    void pipelinedBackupGivesTheSameSet();
    void backupSkipsObjectsThatFail();
    void oneTimeoutIsSkippedTwoInARowAreFatal();
    void cancelDuringBackupGivesNoSet();
    void linkLossDuringBackupIsFatal();
    void backupRestoreRoundTrip();
    void restoreAgainstADriveThatRejectsSomeWrites();
    void restoreReportsAMismatch();
    void cancelDuringRestoreSkipsTheRest();
    void restoreFollowsThePdoSafeOrder();
    void pdoThatCannotBeDisabledIsLeftAlone();
    void cancelInsideAPdoGroupIsReported();
    void linkLossDuringRestoreStopsAndReports();
    void writeOnlyRowIsWrittenNotVerified();
    void storeAndFactoryDefaults();
};

void TestParameterRunner::backupReadsEveryStorableObject()
{
    MovingCapRig rig;
    ParameterBackup backup(&rig.connection);
    QSignalSpy progress(&backup, &ParameterBackup::progress);
    QVERIFY(runToEnd(&backup));
    const auto set = backup.result();
    QVERIFY2(set, qPrintable(set.error().toString()));
    int storable = 0;
    for (const ObjectDef &def : rig.drive.dictionary().objects())
        storable += def.storable && def.readable() ? 1 : 0;
    QVERIFY(storable > 100);
    QCOMPARE(set->size(), storable);
    QVERIFY(backup.warnings().isEmpty());
    QCOMPARE(set->identity.productName, QStringLiteral("MovingCap ETH"));
    QCOMPARE(set->find({ 0x6083, 0 })->raw, rig.drive.read({ 0x6083, 0 }).value());
    QVERIFY(!set->contains({ 0x6041, 0 })); // a process value, not a parameter
    // Four more reads: 1018h.1-.4 give the identity the device reports, serial number included.
    QCOMPARE(progress.last().at(0).toInt(), storable + 4);
    QCOMPARE(progress.last().at(1).toInt(), storable + 4);
    QCOMPARE(set->serialNumber,
             ParameterSet::identityNumber(rig.drive.read({ 0x1018, 4 }).value().toUInt()));
    QCOMPARE(set->identity.productCode, rig.drive.read({ 0x1018, 2 }).value().toUInt());
    QCOMPARE(set->identity.vendorId, 0x53Bu);
    QVERIFY(!set->contains({ 0x1018, 2 }));
}

void TestParameterRunner::pipelinedBackupGivesTheSameSet()
{
    MovingCapRig rig;
    ParameterBackup one(&rig.connection);
    ParameterBackup four(&rig.connection);
    four.setPipelineDepth(4);
    QVERIFY(runToEnd(&one));
    QVERIFY(runToEnd(&four));
    QCOMPARE(four.result()->entries(), one.result()->entries());
}

void TestParameterRunner::backupSkipsObjectsThatFail()
{
    MovingCapRig rig;
    ParameterBackup backup(&rig.connection);
    backup.setAddresses({ { 0x6083, 0 }, { 0x5555, 0 }, { 0x6084, 0 } });
    QVERIFY(runToEnd(&backup));
    QVERIFY(!backup.result()); // not the complete set
    const ParameterSet set = backup.partialSet();
    QCOMPARE(set.addresses(), (QList<ObjectAddress> { { 0x6083, 0 }, { 0x6084, 0 } }));
    QCOMPARE(backup.failedAddresses(), QList<ObjectAddress> { ObjectAddress(0x5555, 0) });
    QCOMPARE(backup.warnings().size(), 1);
    QVERIFY2(backup.warnings().first().startsWith(QLatin1String("5555:0")),
             qPrintable(backup.warnings().first()));
}

void TestParameterRunner::oneTimeoutIsSkippedTwoInARowAreFatal()
{
    MovingCapRig rig;
    rig.connection.silent.insert({ 0x6084, 0 });
    ParameterBackup backup(&rig.connection);
    backup.setAddresses({ { 0x6083, 0 }, { 0x6084, 0 }, { 0x6085, 0 } });
    QVERIFY(runToEnd(&backup));
    QCOMPARE(backup.result().error().kind(), Error::Kind::Timeout);
    QCOMPARE(backup.partialSet().size(), 2);
    QCOMPARE(backup.failedAddresses(), QList<ObjectAddress> { ObjectAddress(0x6084, 0) });

    rig.connection.silent.insert({ 0x6085, 0 }); // a device that stopped answering
    const int readsBefore = rig.connection.readCount;
    ParameterBackup dead(&rig.connection);
    dead.setAddresses({ { 0x6083, 0 }, { 0x6084, 0 }, { 0x6085, 0 }, { 0x6098, 0 } });
    QVERIFY(runToEnd(&dead));
    QCOMPARE(dead.result().error().kind(), Error::Kind::Timeout);
    QVERIFY(dead.result().error().message().contains(QLatin1String("stopped answering")));
    QCOMPARE(rig.connection.readCount - readsBefore, 3); // 6098:0 never asked
}

void TestParameterRunner::cancelDuringBackupGivesNoSet()
{
    MovingCapRig rig;
    ParameterBackup backup(&rig.connection);
    QSignalSpy finished(&backup, &ParameterBackup::finished);
    int readsAtCancel = -1;
    connect(&backup, &ParameterBackup::progress, this, [&](int done, int) {
        if (done == 20) {
            readsAtCancel = rig.connection.readCount;
            backup.cancel();
        }
    });
    backup.start();
    QTRY_COMPARE(finished.size(), 1);
    QVERIFY(!backup.isRunning());
    const auto set = backup.result();
    QVERIFY(!set);
    QCOMPARE(set.error().kind(), Error::Kind::Cancelled);
    QVERIFY(set.error().message().contains(QLatin1String("20 of")));
    QTest::qWait(50); // nothing more may be sent or finish after a cancel
    QCOMPARE(rig.connection.readCount, readsAtCancel);
    QCOMPARE(finished.size(), 1);
}

void TestParameterRunner::linkLossDuringBackupIsFatal()
{
    MovingCapRig rig;
    ParameterBackup backup(&rig.connection);
    backup.setPipelineDepth(3);
    connect(&backup, &ParameterBackup::progress, this, [&](int done, int) {
        if (done == 10)
            rig.connection.goAway();
    });
    QVERIFY(runToEnd(&backup));
    const auto set = backup.result();
    QVERIFY(!set);
    QCOMPARE(set.error().kind(), Error::Kind::Disconnected);
}

void TestParameterRunner::backupRestoreRoundTrip()
{
    MovingCapRig rig;
    ParameterBackup backup(&rig.connection);
    QVERIFY(runToEnd(&backup));
    const ParameterSet saved = backup.result().value();
    QVERIFY(rig.drive.write({ 0x6083, 0 }, u32(4321)));
    QVERIFY(rig.drive.write({ 0x3511, 8 }, QVariant::fromValue<qlonglong>(-77)));

    ParameterRestore restore(&rig.connection);
    restore.setParameterSet(saved);
    QVERIFY(runToEnd(&restore));
    const RestoreReport &report = restore.report();
    QVERIFY2(report.succeeded(), qPrintable(report.summary()));
    QCOMPARE(report.count(RestoreOutcome::Verified), saved.size());
    QCOMPARE(rig.drive.read({ 0x6083, 0 }).value(), saved.find({ 0x6083, 0 })->raw);
    QCOMPARE(rig.drive.read({ 0x3511, 8 }).value(), saved.find({ 0x3511, 8 })->raw);
    QVERIFY(!report.stored);
}

void TestParameterRunner::restoreAgainstADriveThatRejectsSomeWrites()
{
    MovingCapRig rig;
    rig.drive.setRejectedWrites({ ObjectAddress(0x6084, 0) });
    ParameterSet set;
    set.insert({ { 0x6083, 0 },
                 QStringLiteral("Profile acceleration"),
                 DataType::Unsigned32,
                 u32(1500),
                 QString() });
    set.insert({ { 0x6084, 0 },
                 QStringLiteral("Profile deceleration"),
                 DataType::Unsigned32,
                 u32(1600),
                 QString() });
    set.insert({ { 0x6085, 0 },
                 QStringLiteral("Quick stop deceleration"),
                 DataType::Unsigned32,
                 u32(1700),
                 QString() });
    set.insert(
        { { 0x6041, 0 }, QStringLiteral("Statusword"), DataType::Unsigned16, u32(0), QString() });
    set.insert(
        { { 0x5555, 1 }, QStringLiteral("Not there"), DataType::Unsigned8, u32(1), QString() });
    set.insert({ { 0x6098, 0 },
                 QStringLiteral("Homing method"),
                 DataType::Integer8,
                 QVariant::fromValue<qlonglong>(17),
                 QString() });

    ParameterRestore restore(&rig.connection);
    restore.setParameterSet(set);
    // 6098:0 is not selected: it must stay as it was.
    restore.setSelection(
        { { 0x5555, 1 }, { 0x6041, 0 }, { 0x6083, 0 }, { 0x6084, 0 }, { 0x6085, 0 } });
    restore.setStoreAfterwards(true);
    const QVariant homingBefore = rig.drive.read({ 0x6098, 0 }).value();
    QVERIFY(runToEnd(&restore));
    const RestoreReport &report = restore.report();
    QCOMPARE(report.rows.size(), 5);
    const QList<RestoreOutcome> expected { RestoreOutcome::Skipped, RestoreOutcome::Skipped,
                                           RestoreOutcome::Verified, RestoreOutcome::Failed,
                                           RestoreOutcome::Verified };
    for (int i = 0; i < 5; ++i)
        QCOMPARE(report.rows.at(i).outcome, expected.at(i));
    QCOMPARE(report.rows.at(0).reason, QStringLiteral("not in the device description"));
    QCOMPARE(report.rows.at(1).reason, QStringLiteral("ro object"));
    QVERIFY(report.rows.at(3).reason.contains(QLatin1String("present device state")));
    QCOMPARE(rig.drive.read({ 0x6083, 0 }).value(), u32(1500));
    QCOMPARE(rig.drive.read({ 0x6085, 0 }).value(), u32(1700));
    QCOMPARE(rig.drive.read({ 0x6098, 0 }).value(), homingBefore);
    QVERIFY(!report.succeeded());
    QVERIFY(!report.error.isError());
    QVERIFY(report.storeRequested);
    QVERIFY(!report.stored); // never store a half-restored set
    QCOMPARE(report.storeReason, QStringLiteral("not stored: 3 row(s) did not succeed"));
    const QString summary = report.summary();
    QVERIFY2(summary.startsWith(
                 QLatin1String("restore: 2 verified, 0 written, 1 failed, 0 mismatch, 2 skipped")),
             qPrintable(summary));
    QVERIFY(summary.contains(QLatin1String("verified  6083:0 Profile acceleration")));
    QVERIFY(summary.contains(QLatin1String("failed    6084:0 Profile deceleration: ")));
    QVERIFY(summary.contains(QLatin1String("skipped   6041:0 Statusword: ro object")));
    QVERIFY(summary.contains(QLatin1String("not stored: 3 row(s) did not succeed")));
}

void TestParameterRunner::restoreReportsAMismatch()
{
    MovingCapRig rig;
    rig.connection.ignoreWrites.insert({ 0x6083, 0 }); // accepted, never applied
    ParameterSet set;
    set.insert({ { 0x6083, 0 }, QString(), DataType::Unsigned32, u32(2500), QString() });
    ParameterRestore restore(&rig.connection);
    restore.setParameterSet(set);
    QVERIFY(runToEnd(&restore));
    const RestoreRow &row = restore.report().rows.first();
    QCOMPARE(row.outcome, RestoreOutcome::Mismatch);
    QCOMPARE(row.readBack, rig.drive.read({ 0x6083, 0 }).value());
    QVERIFY2(row.reason.contains(QLatin1String("expected 2500")), qPrintable(row.reason));

    // Without verification the same row is only "written".
    ParameterRestore blind(&rig.connection);
    blind.setParameterSet(set);
    blind.setVerify(false);
    QVERIFY(runToEnd(&blind));
    QCOMPARE(blind.report().rows.first().outcome, RestoreOutcome::Written);
}

void TestParameterRunner::cancelDuringRestoreSkipsTheRest()
{
    MovingCapRig rig;
    ParameterBackup backup(&rig.connection);
    QVERIFY(runToEnd(&backup));
    ParameterRestore restore(&rig.connection);
    restore.setParameterSet(backup.result().value());
    connect(&restore, &ParameterRestore::progress, this, [&](int done, int) {
        if (done == 3)
            restore.cancel();
    });
    QVERIFY(runToEnd(&restore));
    const RestoreReport &report = restore.report();
    QCOMPARE(report.error.kind(), Error::Kind::Cancelled);
    QCOMPARE(report.count(RestoreOutcome::Verified), 3);
    QCOMPARE(report.count(RestoreOutcome::Skipped), report.rows.size() - 3);
    QCOMPARE(report.rows.last().reason, QStringLiteral("not attempted: restore cancelled"));
    QVERIFY(!report.succeeded());
}

void TestParameterRunner::restoreFollowsThePdoSafeOrder()
{
    NodeRig rig;
    ParameterSet set;
    auto add = [&](ObjectAddress a, quint32 v) {
        set.insert({ a, QString(), rig.node.dictionary().find(a)->type, u32(v), QString() });
    };
    add({ 0x1017, 0 }, 100);
    add({ 0x1600, 1 }, 0x60400010); // RPDO 1: one mapping entry only
    add({ 0x1800, 1 }, 0x40000190); // TPDO 1: new COB-ID, type, mapping
    add({ 0x1800, 2 }, 1);
    add({ 0x1A00, 0 }, 1);
    add({ 0x1A00, 1 }, 0x60410010);
    ParameterRestore restore(&rig.connection);
    restore.setParameterSet(set);
    QVERIFY(runToEnd(&restore));
    QVERIFY2(restore.report().succeeded(), qPrintable(restore.report().summary()));
    // CiA 301: disable (bit 31), mapping count 0, entries, count, re-enable.
    const QStringList expected {
        QStringLiteral("1400:1=80000200"), QStringLiteral("1600:0=0"),
        QStringLiteral("1600:1=60400010"), QStringLiteral("1600:0=1"),
        QStringLiteral("1400:1=200"),      QStringLiteral("1800:1=c0000180"),
        QStringLiteral("1800:2=1"),        QStringLiteral("1A00:0=0"),
        QStringLiteral("1A00:1=60410010"), QStringLiteral("1A00:0=1"),
        QStringLiteral("1800:1=40000190"), QStringLiteral("1017:0=64"),
    };
    QCOMPARE(rig.written, expected);
    QList<ObjectAddress> order;
    for (const RestoreRow &row : restore.report().rows)
        order.append(row.address);
    QCOMPARE(order,
             (QList<ObjectAddress> { { 0x1600, 1 },
                                     { 0x1800, 2 },
                                     { 0x1A00, 1 },
                                     { 0x1A00, 0 },
                                     { 0x1800, 1 },
                                     { 0x1017, 0 } }));
    QVERIFY(restore.report().notes.isEmpty());
}

void TestParameterRunner::pdoThatCannotBeDisabledIsLeftAlone()
{
    NodeRig rig;
    rig.connection.rejectWrites.insert({ 0x1800, 1 });
    ParameterSet set;
    set.insert({ { 0x1017, 0 }, QString(), DataType::Unsigned16, u32(100), QString() });
    set.insert({ { 0x1A00, 1 }, QString(), DataType::Unsigned32, u32(0x60410010), QString() });
    ParameterRestore restore(&rig.connection);
    restore.setParameterSet(set);
    QVERIFY(runToEnd(&restore));
    const RestoreReport &report = restore.report();
    QCOMPARE(report.rows.size(), 2);
    QCOMPARE(report.rows.at(0).address, ObjectAddress(0x1A00, 1));
    QCOMPARE(report.rows.at(0).outcome, RestoreOutcome::Skipped);
    QVERIFY2(report.rows.at(0).reason.startsWith(QLatin1String("PDO 1800h could not be disabled")),
             qPrintable(report.rows.at(0).reason));
    QCOMPARE(report.rows.at(1).outcome, RestoreOutcome::Verified);
    QCOMPARE(rig.written, QStringList { QStringLiteral("1017:0=64") }); // mapping untouched
}

void TestParameterRunner::storeAndFactoryDefaults()
{
    MovingCapRig rig;
    ParameterSet set;
    set.insert({ { 0x6083, 0 }, QString(), DataType::Unsigned32, u32(3333), QString() });
    ParameterRestore restore(&rig.connection);
    restore.setParameterSet(set);
    restore.setStoreAfterwards(true);
    QVERIFY(runToEnd(&restore));
    QVERIFY2(restore.report().succeeded(), qPrintable(restore.report().summary()));
    QVERIFY(restore.report().stored);
    rig.drive.powerCycle();
    QCOMPARE(rig.drive.read({ 0x6083, 0 }).value(), u32(3333)); // survived: stored by 1010h

    QVERIFY(Reply::wait(rig.connection.restoreFactoryDefaults()));
    QCOMPARE(rig.drive.read({ 0x6083, 0 }).value(), u32(1000)); // description default
    QVERIFY(rig.drive.write({ 0x6083, 0 }, u32(4444)));
    QVERIFY(Reply::wait(rig.connection.storeNonVolatile()));
    rig.drive.powerCycle();
    QCOMPARE(rig.drive.read({ 0x6083, 0 }).value(), u32(4444));
}

void TestParameterRunner::cancelInsideAPdoGroupIsReported()
{
    NodeRig rig;
    ParameterSet set;
    set.insert({ { 0x1A00, 1 }, QString(), DataType::Unsigned32, u32(0x60410010), QString() });
    ParameterRestore restore(&rig.connection);
    restore.setParameterSet(set);
    // Steps: read 1800:1, disable, read 1A00:0, clear, 1A00:1, count back, re-enable.
    connect(&restore, &ParameterRestore::progress, this, [&](int done, int) {
        if (done == 2)
            restore.cancel();
    });
    QVERIFY(runToEnd(&restore));
    const RestoreReport &report = restore.report();
    QCOMPARE(report.error.kind(), Error::Kind::Cancelled);
    QCOMPARE(report.rows.first().outcome, RestoreOutcome::Skipped);
    QCOMPARE(report.notes,
             QStringList { QStringLiteral("PDO 1800h left disabled (COB-ID bit 31 set)") });
    QVERIFY(report.summary().contains(QLatin1String("note: PDO 1800h left disabled")));
    QCOMPARE(rig.written, QStringList { QStringLiteral("1800:1=c0000180") });
}

void TestParameterRunner::linkLossDuringRestoreStopsAndReports()
{
    MovingCapRig rig;
    ParameterBackup backup(&rig.connection);
    QVERIFY(runToEnd(&backup));
    ParameterRestore restore(&rig.connection);
    restore.setParameterSet(backup.result().value());
    restore.setStoreAfterwards(true);
    connect(&restore, &ParameterRestore::progress, this, [&](int done, int) {
        if (done == 5)
            rig.connection.goAway();
    });
    const int writesBefore = rig.connection.writeCount;
    QVERIFY(runToEnd(&restore));
    const RestoreReport &report = restore.report();
    QCOMPARE(report.error.kind(), Error::Kind::Disconnected);
    QCOMPARE(report.count(RestoreOutcome::Verified), 5);
    QCOMPARE(report.count(RestoreOutcome::Skipped), report.rows.size() - 5);
    QVERIFY(report.rows.at(5).reason.startsWith(QLatin1String("not attempted: ")));
    QCOMPARE(rig.connection.writeCount - writesBefore, 5);
    QVERIFY(!report.stored);
    QCOMPARE(report.storeReason, QStringLiteral("not stored: the restore stopped"));
}

void TestParameterRunner::writeOnlyRowIsWrittenNotVerified()
{
    MovingCapRig rig;
    QVERIFY(rig.drive.write({ 0x6083, 0 }, u32(2100)));
    ParameterSet set;
    set.insert({ canopen::store::kStoreAll, QStringLiteral("Store parameters"),
                 DataType::Unsigned32, u32(canopen::store::kSaveSignature), QString() });
    ParameterRestore restore(&rig.connection);
    restore.setParameterSet(set);
    QVERIFY(runToEnd(&restore));
    const RestoreRow &row = restore.report().rows.first();
    QCOMPARE(row.outcome, RestoreOutcome::Written);
    QCOMPARE(row.reason, QStringLiteral("write-only: not read back"));
    QVERIFY(restore.report().succeeded());
    rig.drive.powerCycle(); // the write reached the drive: 6083h was stored
    QCOMPARE(rig.drive.read({ 0x6083, 0 }).value(), u32(2100));
}

QTEST_GUILESS_MAIN(TestParameterRunner)
#include "tst_parameterrunner.moc"
