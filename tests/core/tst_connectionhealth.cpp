// ConnectionHealth beyond the main window: pollers back off while a device does not answer, and
// the optional automatic reconnect (attempts after a loss, never after the user's own close,
// giving up after its window).
#include "core/autoreconnect.h"
#include "core/connectionhealth.h"
#include "core/statussource.h"
#include "fakeconnection.h"

#include <QSignalSpy>
#include <QTest>

using namespace db;

namespace {
constexpr ObjectAddress kStatusword(0x6041, 0);
constexpr int kWaitMs = 10000;

// The smallest status source: the status word, every cycle.
class WordSource : public StatusSource
{
public:
    using StatusSource::StatusSource;
    QString statusWordLabel() const override { return QStringLiteral("Statusword"); }
    QList<StatusLamp> lamps() const override { return {}; }
    QList<ObjectAddress> polledObjects() const override { return { kStatusword }; }
    QList<StatusValue> actualValues() const override { return {}; }
    StatusValue fault() const override { return {}; }
    QString faultText() const override { return {}; }
    bool faultActive() const override { return false; }
    QStringList warnings() const override { return {}; }

protected:
    void poll() override { readEach({ kStatusword }); }
};
} // namespace

class TestConnectionHealth : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void pollersBackOffWhileTheDeviceIsSilent()
    {
        test::FakeConnection c;
        c.setRequestTimeoutMs(20);
        c.setValue(kStatusword, 0x0237);
        c.setValue(ObjectAddress(0x1000, 0), 0x20192);
        auto *health = new ConnectionHealth(&c);
        auto *source = new WordSource(&c, &c);
        source->setIntervalMs(10);
        source->acquire();
        c.open();
        QTRY_COMPARE(health->status(), ConnectionHealth::Status::Responding);
        QCOMPARE(ConnectionHealth::pollIntervalMs(&c, 10), 10);

        c.silent = { kStatusword, ObjectAddress(0x1000, 0) };
        QTRY_COMPARE_WITH_TIMEOUT(health->status(), ConnectionHealth::Status::NotResponding,
                                  kWaitMs);
        QVERIFY(ConnectionHealth::isSilent(&c));
        QCOMPARE(ConnectionHealth::pollIntervalMs(&c, 10), ConnectionHealth::kSilentPollIntervalMs);
        // The next cycle waits kSilentPollIntervalMs, not 10 ms (at 10 ms plus a 20 ms timeout,
        // 1.5 s would be ~50 cycles).
        QSignalSpy updated(source, &StatusSource::updated);
        const int readsBefore = c.readCount;
        QVERIFY(!updated.wait(1500));
        QVERIFY2(c.readCount - readsBefore <= 1, qPrintable(QString::number(c.readCount)));

        // It answers again: the probe notices, polling goes back to its interval.
        c.silent.clear();
        QTRY_COMPARE_WITH_TIMEOUT(health->status(), ConnectionHealth::Status::Responding, kWaitMs);
        QTRY_VERIFY_WITH_TIMEOUT(updated.size() >= 5, kWaitMs);
    }

    void reconnectsAfterALossAndSaysSo()
    {
        test::FakeConnection c;
        c.setValue(ObjectAddress(0x1000, 0), 0x20192);
        auto *health = new ConnectionHealth(&c);
        auto *reconnect = new AutoReconnect(health, 20, kWaitMs);
        QCOMPARE(AutoReconnect::of(&c), reconnect);
        QSignalSpy attempts(reconnect, &AutoReconnect::attemptStarted);
        QSignalSpy back(reconnect, &AutoReconnect::reconnected);
        c.open();
        QTRY_VERIFY(c.isConnected());

        // The device restarts: two refused attempts, then it is back.
        c.refuseNextOpen(Error(Error::Kind::ConnectionRefused, QStringLiteral("refused")));
        c.goAway();
        QCOMPARE(health->status(), ConnectionHealth::Status::Lost);
        QVERIFY(reconnect->isActive());
        QSignalSpy failed(health, &ConnectionHealth::statusChanged);
        QTRY_VERIFY_WITH_TIMEOUT(c.isConnected(), kWaitMs); // the second attempt
        QVERIFY(failed.contains(QVariantList {
            QVariant::fromValue(ConnectionHealth::Status::Failed) })); // the first one was refused
        QCOMPARE(attempts.size(), 2);
        QCOMPARE(attempts.at(1).at(0).toInt(), 2);
        QCOMPARE(back.size(), 1);
        QCOMPARE(back.at(0).at(0).toInt(), 2);
        QVERIFY(!reconnect->isActive());
        QTRY_COMPARE_WITH_TIMEOUT(health->status(), ConnectionHealth::Status::Responding, kWaitMs);
    }

    void neverAfterTheUsersOwnClose()
    {
        test::FakeConnection c;
        auto *health = new ConnectionHealth(&c);
        auto *reconnect = new AutoReconnect(health, 10, kWaitMs);
        QSignalSpy attempts(reconnect, &AutoReconnect::attemptStarted);
        c.open();
        QTRY_VERIFY(c.isConnected());
        c.close();
        QTRY_COMPARE(health->status(), ConnectionHealth::Status::ClosedByUser);
        QVERIFY(!reconnect->isActive());
        QVERIFY(!attempts.wait(200));
        QCOMPARE(c.state(), DeviceConnection::State::Disconnected);
    }

    void givesUpAfterItsWindow()
    {
        test::FakeConnection c;
        auto *health = new ConnectionHealth(&c);
        auto *reconnect = new AutoReconnect(health, 20, 300);
        QSignalSpy attempts(reconnect, &AutoReconnect::attemptStarted);
        QSignalSpy gaveUp(reconnect, &AutoReconnect::gaveUp);
        c.open();
        QTRY_VERIFY(c.isConnected());
        // Every attempt is refused (FakeConnection refuses one open per call).
        connect(reconnect, &AutoReconnect::attemptStarted, &c, [&c] {
            c.refuseNextOpen(Error(Error::Kind::ConnectionRefused, QStringLiteral("refused")));
        });
        c.refuseNextOpen(Error(Error::Kind::ConnectionRefused, QStringLiteral("refused")));
        c.goAway();
        QVERIFY(gaveUp.wait(kWaitMs));
        QVERIFY(attempts.size() >= 2);
        QCOMPARE(gaveUp.at(0).at(0).toInt(), attempts.size());
        QVERIFY(!reconnect->isActive());
        const int made = int(attempts.size());
        QVERIFY(!attempts.wait(200)); // no attempt after giving up
        QCOMPARE(attempts.size(), made);
        QCOMPARE(c.state(), DeviceConnection::State::Disconnected);
    }

    void firstAttemptThatFailsIsNotRetried()
    {
        test::FakeConnection c;
        auto *health = new ConnectionHealth(&c);
        auto *reconnect = new AutoReconnect(health, 10, kWaitMs);
        QSignalSpy attempts(reconnect, &AutoReconnect::attemptStarted);
        c.refuseNextOpen(Error(Error::Kind::ConnectionRefused, QStringLiteral("refused")));
        c.open();
        QTRY_COMPARE(health->status(), ConnectionHealth::Status::Failed);
        QVERIFY(!reconnect->isActive());
        QVERIFY(!attempts.wait(200));
    }
};

QTEST_GUILESS_MAIN(TestConnectionHealth)
#include "tst_connectionhealth.moc"
