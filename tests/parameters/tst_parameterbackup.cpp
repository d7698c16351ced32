// ParameterBackup when reads fail, and the rules that keep a partial read from passing for a
// backup: no complete set (result()) unless every object was read, the class of the failure
// from its most common cause, an identity that was not read is unknown (never 0 or the
// description's), and a restore of nothing never stores. Over a fake connection into the
// simulated MovingCap with per-object read failures.
#include "devices/movingcap/movingcapdrive.h"
#include "fakeconnection.h"
#include "parameters/parameterrunner.h"
#include "resources/builtindescriptions.h"
#include "wait.h"

#include <QSignalSpy>
#include <QTest>

using namespace db;
using db::test::FakeConnection;
using db::test::runToEnd;

namespace {

constexpr ObjectAddress kAcceleration { 0x6083, 0 };
constexpr ObjectAddress kDeceleration { 0x6084, 0 };
constexpr ObjectAddress kProductCode { 0x1018, 2 };

// The simulated MovingCap whose reads of the objects in `failures` fail with the error given.
struct Rig
{
    Rig()
        : drive(resources::movingCapDictionary())
    {
        connection.setModel(
            [this](ObjectAddress a) -> Result<QVariant> {
                if (const auto it = failures.find(a); it != failures.end())
                    return it.value();
                if (const auto it = answers.find(a); it != answers.end())
                    return it.value();
                return drive.read(a);
            },
            [this](ObjectAddress a, const QVariant &v) { return drive.write(a, v); });
        connection.setDictionary(drive.dictionary());
        connection.setCapabilities(DeviceConnection::Capability::StoreNonVolatile);
        connection.immediate = true;
        connection.open();
    }
    sim::MovingCapDrive drive;
    QHash<ObjectAddress, Error> failures;
    QHash<ObjectAddress, QVariant> answers; // answers instead of the drive's value
    FakeConnection connection;
};

Error malformed()
{
    return Error(Error::Kind::Malformed, QStringLiteral("answer does not belong to the request"));
}

} // namespace

class TestParameterBackup : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void oneFailedObjectMeansNoCompleteSet();
    void mostCommonCauseNamesTheClass();
    void nothingReadIsAFailure();
    void identityThatWasNotReadIsUnknown();
    void answerOutsideTheTypeIsMalformed();
    void linkLossListsEveryUnreadObject();
    void partialFileKeepsItsCommentsOutOfTheSet();
    void restoreOfNothingNeverStores_data();
    void restoreOfNothingNeverStores();
};

void TestParameterBackup::oneFailedObjectMeansNoCompleteSet()
{
    Rig rig;
    rig.failures.insert(kDeceleration,
                        Error(Error::Kind::DeviceError, QStringLiteral("SDO abort 06020000")));
    ParameterBackup backup(&rig.connection);
    QVERIFY(runToEnd(&backup));
    const auto result = backup.result();
    QVERIFY(!result);
    QCOMPARE(result.error().kind(), Error::Kind::DeviceError);
    QVERIFY2(result.error().message().startsWith(
                 QStringLiteral("1 of %1 objects could not be read").arg(backup.objectCount())),
             qPrintable(result.error().message()));
    QVERIFY(result.error().message().contains(QLatin1String("6084:0 Profile deceleration")));
    QVERIFY(!backup.error().isError()); // the run went to its end
    const ParameterSet partial = backup.partialSet();
    QCOMPARE(partial.size(),
             backup.objectCount() - 5); // identity reads (1018h.1-4) are not objects
    QVERIFY(!partial.contains(kDeceleration));
    QVERIFY(partial.contains(kAcceleration));
    QVERIFY(partial.productCodeKnown);
    QCOMPARE(backup.failures().size(), 1);
    QCOMPARE(backup.failures().first().address, kDeceleration);
    QCOMPARE(backup.failures().first().name, QStringLiteral("Profile deceleration"));
    QCOMPARE(backup.failures().first().error.kind(), Error::Kind::DeviceError);
}

void TestParameterBackup::mostCommonCauseNamesTheClass()
{
    Rig rig;
    rig.failures.insert(kAcceleration, Error(Error::Kind::DeviceError, QStringLiteral("ERROR")));
    rig.failures.insert(kDeceleration, malformed());
    rig.failures.insert({ 0x6085, 0 }, malformed());
    ParameterBackup backup(&rig.connection);
    QVERIFY(runToEnd(&backup));
    QCOMPARE(backup.result().error().kind(), Error::Kind::Malformed);
    QVERIFY(backup.result().error().message().contains(QLatin1String("first: 6083:0")));
    QCOMPARE(backup.failedAddresses(),
             (QList<ObjectAddress> { kAcceleration, kDeceleration, { 0x6085, 0 } }));
}

void TestParameterBackup::nothingReadIsAFailure()
{
    Rig rig;
    ParameterBackup backup(&rig.connection);
    backup.setAddresses({ kAcceleration, kDeceleration });
    rig.failures.insert(kAcceleration, malformed());
    rig.failures.insert(kDeceleration, malformed());
    QVERIFY(runToEnd(&backup));
    QVERIFY(!backup.result());
    QCOMPARE(backup.result().error().kind(), Error::Kind::Malformed);
    QVERIFY(backup.result().error().message().startsWith(QLatin1String("no object could be read")));
    QVERIFY(backup.partialSet().isEmpty());

    // A description without a readable object: nothing to back up is no backup either.
    FakeConnection bare;
    bare.setModel([](ObjectAddress) { return Result<QVariant>(0); },
                  [](ObjectAddress, const QVariant &) { return Result<void>(); });
    bare.setCapabilities(DeviceConnection::Capability::StoreNonVolatile);
    bare.immediate = true;
    bare.open();
    ParameterBackup none(&bare);
    QVERIFY(runToEnd(&none));
    QVERIFY(!none.result());
}

void TestParameterBackup::identityThatWasNotReadIsUnknown()
{
    Rig rig;
    rig.failures.insert(kProductCode, malformed());
    ParameterBackup backup(&rig.connection);
    QVERIFY(runToEnd(&backup));
    QCOMPARE(backup.result().error().kind(), Error::Kind::Malformed);
    QCOMPARE(backup.failedAddresses(), QList<ObjectAddress> { kProductCode });
    const ParameterSet partial = backup.partialSet();
    QVERIFY(!partial.productCodeKnown);
    QVERIFY(partial.vendorIdKnown);
    QCOMPARE(partial.identity.vendorId, 0x53Bu);
    const QByteArray text = partial.serialize();
    QVERIFY2(text.contains("\nproduct unknown \"MovingCap ETH\"\n"), text.left(300).constData());
    const auto loaded = ParameterSet::parse(text, QStringLiteral("identity.dbp"));
    QVERIFY2(loaded, qPrintable(loaded.error().toString()));
    QVERIFY(!loaded->productCodeKnown);
    QVERIFY(loaded->vendorIdKnown);
    QCOMPARE(loaded->size(), partial.size());
    // A set read completely knows its product code, and says so.
    rig.failures.clear();
    QVERIFY(runToEnd(&backup));
    QVERIFY(backup.result());
    QVERIFY(backup.result()->productCodeKnown);
    QVERIFY(!backup.result()->serialize().contains("unknown"));
}

void TestParameterBackup::answerOutsideTheTypeIsMalformed()
{
    Rig rig;
    rig.answers.insert(kAcceleration, QVariant::fromValue<qlonglong>(-5)); // UNSIGNED32
    rig.failures.insert(kDeceleration, Error(Error::Kind::OutOfRange, QStringLiteral("300")));
    rig.answers.insert(kProductCode, QVariant::fromValue<qulonglong>(0x1FFFFFFFFull));
    ParameterBackup backup(&rig.connection);
    QVERIFY(runToEnd(&backup));
    QCOMPARE(backup.failures().size(), 3);
    for (const BackupFailure &f : backup.failures())
        QVERIFY2(f.error.kind() == Error::Kind::Malformed, qPrintable(f.text()));
    QCOMPARE(backup.result().error().kind(), Error::Kind::Malformed);
    QVERIFY(!backup.partialSet().productCodeKnown);
}

void TestParameterBackup::linkLossListsEveryUnreadObject()
{
    Rig rig;
    ParameterBackup backup(&rig.connection);
    backup.setPipelineDepth(3);
    connect(&backup, &ParameterBackup::progress, this, [&](int done, int) {
        if (done == 10)
            rig.connection.goAway();
    });
    QVERIFY(runToEnd(&backup));
    QCOMPARE(backup.result().error().kind(), Error::Kind::Disconnected);
    QCOMPARE(backup.error().kind(), Error::Kind::Disconnected);
    const ParameterSet partial = backup.partialSet();
    QVERIFY(partial.size() >= 7);
    // Every object is either in the partial set or among the failures, with the cause.
    QCOMPARE(partial.size() + int(backup.failures().size()), backup.objectCount() - 4); // 1018h.1-4
    for (const BackupFailure &f : backup.failures())
        QCOMPARE(f.error.kind(), Error::Kind::Disconnected);
}

void TestParameterBackup::partialFileKeepsItsCommentsOutOfTheSet()
{
    ParameterSet set;
    set.insert({ kAcceleration, QStringLiteral("Profile acceleration"), DataType::Unsigned32,
                 QVariant::fromValue<qulonglong>(5), QString() });
    const QString evil = QStringLiteral("failed 6084:0: 12") + QChar(0) + QStringLiteral("34\nend");
    const QByteArray text = set.serialize({ QStringLiteral("partial backup"), evil });
    QVERIFY(!text.contains('\0'));
    QVERIFY2(text.contains("\n# failed 6084:0: 12\\x0034\\x0aend\n"), text.constData());
    const auto loaded = ParameterSet::parse(text, QStringLiteral("p.dbp"));
    QVERIFY2(loaded, qPrintable(loaded.error().toString()));
    QCOMPARE(loaded->entries(), set.entries());
}

void TestParameterBackup::restoreOfNothingNeverStores_data()
{
    QTest::addColumn<bool>("emptySet");
    QTest::newRow("empty set") << true;
    QTest::newRow("selection not in the set") << false;
}

void TestParameterBackup::restoreOfNothingNeverStores()
{
    QFETCH(bool, emptySet);
    Rig rig;
    ParameterSet set;
    if (!emptySet)
        set.insert({ kAcceleration, QStringLiteral("Profile acceleration"), DataType::Unsigned32,
                     QVariant::fromValue<qulonglong>(5), QString() });
    ParameterRestore restore(&rig.connection);
    restore.setParameterSet(set);
    if (!emptySet)
        restore.setSelection({ kDeceleration });
    restore.setStoreAfterwards(true);
    QVERIFY(runToEnd(&restore));
    const RestoreReport &report = restore.report();
    QVERIFY(!report.succeeded());
    QVERIFY(!report.stored);
    QCOMPARE(report.error.kind(), Error::Kind::InvalidArgument);
    QVERIFY(report.summary().contains(QLatin1String("nothing to restore")));
    QCOMPARE(rig.connection.writeCount, 0);
}

QTEST_GUILESS_MAIN(TestParameterBackup)
#include "tst_parameterbackup.moc"
