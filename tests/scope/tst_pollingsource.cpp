// Level 3: host polling against the in-process simulated MovingCap over loopback RefGo and
// SLCAN: every period gets its sample (zero lost at a modest rate), mixed rates account for every
// slot, one time base, failed reads
// count as lost samples with a gap, a lost connection stops the source with an error.
#include "common/demodrive.h"
#include "common/protocols.h"
#include "devices/movingcap/movingcapdrive.h"
#include "peers.h"
#include "scope/pollingsource.h"
#include "scope/recorder.h"

#include <QSignalSpy>
#include <QtTest>

using namespace db;
using namespace db::scope;

namespace {
constexpr int kConnectMs = 5000;

std::shared_ptr<DeviceConnection> connectTo(const QString &uri)
{
    auto made = app::protocolRegistry().create(uri);
    if (!made)
        return {};
    std::shared_ptr<DeviceConnection> c = *made;
    c->open();
    if (!QTest::qWaitFor([&] { return c->isConnected(); }, kConnectMs))
        return {};
    return c;
}
} // namespace

class TstPollingSource : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void init()
    {
        m_drive = std::make_unique<app::DemoDrive>();
        QVERIFY(m_drive->startRefgo(0).ok());
        QVERIFY(m_drive->startSlcan(0).ok());
    }
    void cleanup()
    {
        m_connection.reset();
        m_drive.reset();
    }

    void pollsAMoveWithoutLoss_data()
    {
        QTest::addColumn<bool>("slcan");
        QTest::newRow("refgo") << false;
        QTest::newRow("canopen+slcan") << true;
    }
    void pollsAMoveWithoutLoss()
    {
        QFETCH(bool, slcan);
        m_connection = connectTo(slcan ? m_drive->slcanUri() : m_drive->refgoUri());
        QVERIFY(m_connection);
        PollingSource source(m_connection.get());
        QVERIFY(source.addChannel({ 0x6064, 0 }, 20).ok());
        QVERIFY(source.addChannel({ 0x6078, 0 }, 20).ok());
        QCOMPARE(source.channels().at(0).name, QStringLiteral("Position actual value"));
        QCOMPARE(source.channels().at(0).device, slcan ? m_drive->slcanUri() : m_drive->refgoUri());

        Recorder recorder;
        recorder.addSource(&source);
        recorder.start();
        QVERIFY(source.isRunning());
        QVERIFY(m_drive->drive().go(20000).ok());
        // A running event loop, not QTRY's (it sleeps 10 ms between passes, and with the drive
        // in this process every hop of a read would wait for the next pass).
        QSignalSpy appended(&recorder, &Recorder::dataAppended);
        while (recorder.buffer(0).size() < 40)
            QVERIFY(appended.wait(10000));
        recorder.stop();
        QVERIFY(!source.isRunning());

        const TraceBuffer &pos = recorder.buffer(0);
        const TraceBuffer &cur = recorder.buffer(1);
        QCOMPARE(pos.lostAtSource(), 0);
        QCOMPARE(cur.lostAtSource(), 0);
        QCOMPARE(source.lostCount(), 0);
        QVERIFY(std::abs(pos.size() - cur.size()) <= 1);
        // ~20 ms apart on one time base, strictly later than the start.
        const double span = pos.lastTime() - pos.firstTime();
        QVERIFY(pos.firstTime() >= 0);
        QVERIFY2(std::abs(span / double(pos.size() - 1) - 0.020) < 0.005,
                 qPrintable(QString::number(span / double(pos.size() - 1))));
        // The axis moves: the position grows, the current is not constant.
        QVERIFY(pos.value(pos.size() - 1) > pos.value(0));
        double cmin = cur.value(0), cmax = cur.value(0);
        for (qint64 i = 0; i < cur.size(); ++i) {
            cmin = std::min(cmin, cur.value(i));
            cmax = std::max(cmax, cur.value(i));
        }
        QVERIFY(cmax > cmin);
    }

    // 16 channels at three rates over one link: every slot of every channel is accounted for,
    // as a sample or as a lost one, so a channel is neither starved by the others nor read
    // more often than its period.
    void mixedRatesAccountForEverySlot()
    {
        m_connection = connectTo(m_drive->slcanUri());
        QVERIFY(m_connection);
        PollingSource source(m_connection.get());
        const QList<quint16> objects { 0x6064, 0x6078, 0x606C, 0x6041,
                                       0x6061, 0x607A, 0x6081, 0x6083 };
        const QList<int> rates { 5, 10, 20, 10 };
        QList<int> channelRate;
        for (int i = 0; i < 16; ++i) {
            channelRate.append(rates.at(i % rates.size()));
            QVERIFY(
                source.addChannel({ objects.at(i % objects.size()), 0 }, channelRate.last()).ok());
        }
        Recorder recorder;
        recorder.addSource(&source);
        recorder.start();
        QTRY_VERIFY_WITH_TIMEOUT(
            recorder.buffer(2).size() + recorder.buffer(2).lostAtSource() >= 15, 10000);
        recorder.stop();
        const double t = recorder.stoppedAt();
        for (int i = 0; i < 16; ++i) {
            const qint64 begun = qint64(t * 1000 / channelRate.at(i)) + 1; // begun by the stop
            const qint64 accounted = recorder.buffer(i).size() + recorder.buffer(i).lostAtSource();
            // The slot running at the stop may be unread or its answer still on the way.
            QVERIFY2(accounted >= begun - 2 && accounted <= begun,
                     qPrintable(QStringLiteral("channel %1 (%2 ms): %3 of %4 slots in %5 s")
                                    .arg(i)
                                    .arg(channelRate.at(i))
                                    .arg(accounted)
                                    .arg(begun)
                                    .arg(t)));
        }
    }

    void asFastAsPossibleServesChannelsRoundRobin()
    {
        m_connection = connectTo(m_drive->refgoUri());
        QVERIFY(m_connection);
        PollingSource source(m_connection.get());
        for (quint16 index : { 0x6064, 0x606C, 0x6078, 0x6041 })
            QVERIFY(source.addChannel({ index, 0 }, 0).ok());
        QList<int> counts(4, 0);
        connect(&source, &TraceSource::samplesReady, this,
                [&](int channel, const TraceSamples &s) { counts[channel] += int(s.size()); });
        QElapsedTimer clock;
        clock.start();
        source.start(clock);
        QTRY_VERIFY(counts[3] >= 20);
        source.stop();
        for (int c : counts)
            QVERIFY(std::abs(c - counts[0]) <= 1);
        QCOMPARE(source.lostCount(), 0);
    }

    void failedReadIsALostSampleAndAGap()
    {
        m_connection = connectTo(m_drive->refgoUri());
        QVERIFY(m_connection);
        PollingSource source(m_connection.get());
        QVERIFY(source.addChannel({ 0x6064, 0 }, 0).ok());
        ChannelInfo missing;
        missing.id = QStringLiteral("2FFF:0");
        missing.address = { 0x2FFF, 0 }; // the drive answers with an error
        QVERIFY(source.addChannel(missing).ok());
        Recorder recorder;
        recorder.addSource(&source);
        QSignalSpy lost(&recorder, &Recorder::samplesLost);
        recorder.start();
        QTRY_VERIFY(recorder.buffer(0).size() >= 10);
        QCOMPARE(recorder.state(), Recorder::State::Recording); // keeps going
        recorder.stop();
        QVERIFY(recorder.buffer(1).lostAtSource() >= 9);
        QCOMPARE(recorder.buffer(1).size(), 0);
        QCOMPARE(recorder.buffer(0).lostAtSource(), 0);
        QVERIFY(lost.count() >= 9);
        QCOMPARE(lost.at(0).at(0).toInt(), 1);
        // Failed reads are told apart from periods missed on a slow link, with their cause.
        QCOMPARE(source.failedCount(), recorder.buffer(1).lostAtSource());
        QCOMPARE(source.lastReadError().kind(), Error::Kind::DeviceError);
        QVERIFY2(source.lastReadError().message().contains(QLatin1String("2FFF:0")),
                 qPrintable(source.lastReadError().toString()));
    }

    void unansweredReadCountsItsPeriodsAtStop()
    {
        // Accepts, never answers: the first read waits for its time limit.
        test::RawPeer silent(test::RawPeer::Behaviour::Silent);
        QVERIFY(silent.isListening());
        m_connection = connectTo(QStringLiteral("refgo://127.0.0.1:%1").arg(silent.serverPort()));
        QVERIFY(m_connection);
        PollingSource source(m_connection.get());
        QVERIFY(source.addChannel({ 0x6064, 0 }, 10).ok());
        Recorder recorder;
        recorder.addSource(&source);
        recorder.start();
        QElapsedTimer waiting;
        waiting.start();
        QTRY_VERIFY(waiting.elapsed() >= 200);
        recorder.stop();
        // 200 ms at 10 ms without a sample: not "zero lost".
        QVERIFY2(source.lostCount() >= 15, qPrintable(QString::number(source.lostCount())));
        QCOMPARE(recorder.buffer(0).lostAtSource(), source.lostCount());
        QCOMPARE(recorder.buffer(0).size(), 0);
        QCOMPARE(source.failedCount(), 0);
        QCOMPARE(source.unansweredAtStop().channel, 0);
        QVERIFY(source.unansweredAtStop().waitedS >= 0.19);
    }

    void rejectsWhatCannotBeSampled()
    {
        m_connection = connectTo(m_drive->refgoUri());
        QVERIFY(m_connection);
        PollingSource source(m_connection.get());
        QCOMPARE(source.addChannel({ 0x6064, 0 }, -1).error().kind(), Error::Kind::InvalidArgument);
        QCOMPARE(source.addChannel({ 0x1008, 0 }, 10).error().kind(), // device name (string)
                 Error::Kind::InvalidArgument);
        QCOMPARE(source.channels().size(), 0);
    }

    void connectionLossStopsWithError()
    {
        m_connection = connectTo(m_drive->refgoUri());
        QVERIFY(m_connection);
        PollingSource source(m_connection.get());
        QVERIFY(source.addChannel({ 0x6064, 0 }, 5).ok());
        Recorder recorder;
        recorder.addSource(&source);
        QSignalSpy errors(&recorder, &Recorder::errorOccurred);
        recorder.start();
        QTRY_VERIFY(recorder.buffer(0).size() >= 5);
        m_drive.reset(); // the simulated drive goes away: the server closes the socket
        QTRY_COMPARE_WITH_TIMEOUT(recorder.state(), Recorder::State::Stopped, 10000);
        QVERIFY(!source.isRunning());
        QCOMPARE(errors.count(), 1);
        QVERIFY(errors.at(0).at(0).value<Error>().isError());
        QVERIFY(recorder.buffer(0).size() >= 5); // the data stays
    }

    void connectionDeletedWhileSampling()
    {
        m_connection = connectTo(m_drive->refgoUri());
        QVERIFY(m_connection);
        PollingSource source(m_connection.get());
        QVERIFY(source.addChannel({ 0x6064, 0 }, 5).ok());
        QSignalSpy errors(&source, &TraceSource::errorOccurred);
        QElapsedTimer clock;
        clock.start();
        source.start(clock);
        QTRY_VERIFY(source.deliveredCount() >= 3);
        m_connection.reset();
        QVERIFY(!source.isRunning());
        QCOMPARE(errors.count(), 1);
        QCOMPARE(errors.at(0).at(0).value<Error>().kind(), Error::Kind::Disconnected);
    }

    void startOnClosedConnectionFails()
    {
        auto made = app::protocolRegistry().create(m_drive->refgoUri());
        QVERIFY(made.ok());
        std::shared_ptr<DeviceConnection> closed = *made;
        PollingSource source(closed.get());
        QVERIFY(source.addChannel({ 0x6064, 0 }, 10).ok());
        Recorder recorder;
        recorder.addSource(&source);
        QSignalSpy errors(&recorder, &Recorder::errorOccurred);
        recorder.start();
        QCOMPARE(recorder.state(), Recorder::State::Stopped);
        QCOMPARE(errors.count(), 1);
        QCOMPARE(errors.at(0).at(0).value<Error>().kind(), Error::Kind::Disconnected);
    }

private:
    std::unique_ptr<app::DemoDrive> m_drive;
    std::shared_ptr<DeviceConnection> m_connection;
};

QTEST_GUILESS_MAIN(TstPollingSource)
#include "tst_pollingsource.moc"
