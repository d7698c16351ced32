// The test support itself: every failure mode of the fake connection does what tests rely on,
// and the wait helpers give up when nothing happens.
#include "fakeconnection.h"
#include "wait.h"

#include <QtTest>

using namespace db;
using db::test::await;
using db::test::FakeConnection;

namespace {

constexpr ObjectAddress kStatus { 0x6041, 0 };
constexpr ObjectAddress kControl { 0x6040, 0 };

QVariant u16(quint16 v)
{
    return QVariant::fromValue<qulonglong>(v);
}

// A value store with read/write functions, as the simulated drives have them.
struct Model
{
    QHash<ObjectAddress, QVariant> values;
    Result<QVariant> read(ObjectAddress a)
    {
        if (!values.contains(a))
            return Error(Error::Kind::DeviceError, QStringLiteral("no such object"));
        return values.value(a);
    }
    Result<void> write(ObjectAddress a, const QVariant &v)
    {
        values.insert(a, v);
        return {};
    }
};

bool openFake(FakeConnection &c)
{
    c.open();
    return test::waitUntil(&c, &DeviceConnection::stateChanged, [&c] { return c.isConnected(); });
}

} // namespace

class TstFakeConnection : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void tableAnswersFromTheEventLoop()
    {
        FakeConnection c;
        c.setValue(kStatus, u16(0x237));
        QVERIFY(openFake(c));
        Reply *reply = c.read(kStatus);
        QVERIFY(!reply->isFinished());
        QCOMPARE(await(reply).value(), u16(0x237));
        QCOMPARE(c.readCount, 1);
        QCOMPARE(await(c.read(kControl)).error().kind(), Error::Kind::DeviceError);
    }

    void immediateAnswersInsideTheCall()
    {
        FakeConnection c;
        c.immediate = true;
        c.setValue(kStatus, u16(0x237));
        c.open();
        QVERIFY(c.isConnected());
        Reply *reply = c.read(kStatus);
        QVERIFY(reply->isFinished());
        QCOMPARE(await(reply).value(), u16(0x237));
    }

    void modelTakesReadsAndWrites()
    {
        Model model;
        FakeConnection c;
        c.setModel(&model);
        QVERIFY(openFake(c));
        QVERIFY(await(c.write(kControl, u16(6))).ok());
        QCOMPARE(model.values.value(kControl), u16(6));
        QCOMPARE(await(c.read(kControl)).value(), u16(6));
        QCOMPARE(c.writes.size(), 1);
        QCOMPARE(await(c.read(kStatus)).error().message(), QStringLiteral("no such object"));
    }

    void failureFailsEveryRequestUntilCleared()
    {
        FakeConnection c;
        c.setValue(kStatus, u16(1));
        QVERIFY(openFake(c));
        const Error abort(Error::Kind::DeviceError, QStringLiteral("SDO abort 06020000"));
        c.setFailure(kStatus, abort);
        QCOMPARE(await(c.read(kStatus)).error().message(), abort.message());
        QCOMPARE(await(c.write(kStatus, u16(2))).error().kind(), Error::Kind::DeviceError);
        QCOMPARE(c.value(kStatus), u16(1));
        c.clearFailure(kStatus);
        QCOMPARE(await(c.read(kStatus)).value(), u16(1));
    }

    void silentObjectTimesOutAtTheRequestTimeout()
    {
        FakeConnection c;
        c.setValue(kStatus, u16(1));
        c.setRequestTimeoutMs(40);
        c.silent.insert(kStatus);
        QVERIFY(openFake(c));
        const auto r = await(c.read(kStatus));
        QCOMPARE(r.error().kind(), Error::Kind::Timeout);
        QCOMPARE(r.error().message(), QStringLiteral("no answer within 40 ms"));
    }

    void refusedWriteIsADeviceErrorAndChangesNothing()
    {
        FakeConnection c;
        c.setValue(kControl, u16(0));
        c.rejectWrites.insert(kControl);
        QVERIFY(openFake(c));
        const auto r = await(c.write(kControl, u16(6)));
        QCOMPARE(r.error().kind(), Error::Kind::DeviceError);
        QCOMPARE(r.error().deviceCode(), quint32(0x08000022));
        QCOMPARE(c.value(kControl), u16(0));
        QCOMPARE(c.writeCount, 1);
        QVERIFY(c.writes.isEmpty());
    }

    void ignoredWriteIsAcknowledgedButNotApplied()
    {
        FakeConnection c;
        c.setValue(kControl, u16(0));
        c.ignoreAllWrites = true;
        QVERIFY(openFake(c));
        QVERIFY(await(c.write(kControl, u16(6))).ok());
        QCOMPARE(c.value(kControl), u16(0));
    }

    void linkBreaksDuringTheNthRequest()
    {
        FakeConnection c;
        c.setValue(kStatus, u16(1));
        QVERIFY(openFake(c));
        c.goAwayDuringRequest(2);
        QVERIFY(await(c.read(kStatus)).ok());
        const auto r = await(c.read(kStatus));
        QCOMPARE(r.error().kind(), Error::Kind::Disconnected);
        QCOMPARE(c.state(), DeviceConnection::State::Disconnected);
    }

    void slowAnswersAreInFlightTogether()
    {
        FakeConnection c;
        c.setValue(kStatus, u16(1));
        c.replyDelayMs = 30;
        QVERIFY(openFake(c));
        Reply *a = c.read(kStatus);
        Reply *b = c.read(kStatus);
        QCOMPARE(c.inFlight, 2);
        QVERIFY(await(a).ok());
        QVERIFY(await(b).ok());
        QCOMPARE(c.maxInFlight, 2);
        QCOMPARE(c.inFlight, 0);
    }

    void refusedOpenEndsDisconnectedWithTheError()
    {
        FakeConnection c;
        c.refuseNextOpen(
            Error(Error::Kind::ConnectionRefused, QStringLiteral("connection refused")));
        QSignalSpy errors(&c, &DeviceConnection::errorOccurred);
        c.open();
        QVERIFY(test::waitUntil(&c, &DeviceConnection::stateChanged, [&c] {
            return c.state() == DeviceConnection::State::Disconnected;
        }));
        QCOMPARE(errors.size(), 1);
        QCOMPARE(c.lastError().message(), QStringLiteral("connection refused"));
    }

    void storingWritesTheSignatureOnlyWithTheCapability()
    {
        FakeConnection c;
        QVERIFY(openFake(c));
        QCOMPARE(await(c.storeNonVolatile()).error().kind(), Error::Kind::NotSupported);
        c.setCapabilities(DeviceConnection::Capability::StoreNonVolatile);
        QVERIFY(await(c.storeNonVolatile()).ok());
        QCOMPARE(c.value({ 0x1010, 1 }), QVariant::fromValue<qulonglong>(0x65766173));
    }

    void waitsGiveUpWhenNothingHappens()
    {
        Reply never(kStatus);
        QVERIFY(!test::waitForSignal(&never, &Reply::finished, 1, 30));
        QVERIFY(!test::waitUntil(
            &never, &Reply::finished, [&never] { return never.isFinished(); }, 30));
        const auto r = await(new Reply(kStatus), 30);
        QCOMPARE(r.error().kind(), Error::Kind::Timeout);
    }
};

QTEST_GUILESS_MAIN(TstFakeConnection)
#include "tst_fakeconnection.moc"
