// Level 1/2: the recorder with a scripted source: every trigger kind with its pre/post window,
// modes run/roll/single/normal, a run that ends after its duration, loss counting and gaps, bounded
// memory, source failure.
#include "fakesource.h"
#include "scope/recorder.h"

#include <QSignalSpy>
#include <QtTest>

using namespace db;
using namespace db::scope;
using db::test::FakeSource;

namespace {
// Binary-exact times so window bounds compare exactly.
constexpr double kDt = 0.125;

QList<QPair<double, double>> series(const QList<double> &values, double t0 = 0)
{
    QList<QPair<double, double>> out;
    for (int i = 0; i < values.size(); ++i)
        out.append({ t0 + i * kDt, values[i] });
    return out;
}
} // namespace

class TstRecorder : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void init()
    {
        m_source = new FakeSource({ test::channel(0x6064, 0, QStringLiteral("Position")),
                                    test::channel(0x6041, 0, QStringLiteral("Statusword")) });
        m_recorder = new Recorder;
        QCOMPARE(m_recorder->addSource(m_source), QList<int>({ 0, 1 }));
    }
    void cleanup()
    {
        delete m_recorder;
        delete m_source;
    }

    void triggerKinds_data()
    {
        QTest::addColumn<Trigger::Kind>("kind");
        QTest::addColumn<double>("level");
        QTest::addColumn<double>("level2");
        QTest::addColumn<int>("bit");
        QTest::addColumn<QList<double>>("values");
        QTest::addColumn<int>("firesAt"); // sample index, -1 = never
        using K = Trigger::Kind;
        const QList<double> up { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14 };
        const QList<double> down { 14, 13, 12, 11, 10, 9, 8, 7, 6, 5, 4, 3, 2, 1, 0 };
        QTest::newRow("rising") << K::RisingEdge << 5.0 << 0.0 << 0 << up << 5;
        QTest::newRow("rising needs a crossing")
            << K::RisingEdge << 5.0 << 0.0 << 0 << QList<double>(15, 7.0) << -1;
        QTest::newRow("falling") << K::FallingEdge << 5.0 << 0.0 << 0 << down << 9;
        QTest::newRow("falling not on rise") << K::FallingEdge << 5.0 << 0.0 << 0 << up << -1;
        QTest::newRow("above") << K::LevelAbove << 5.0 << 0.0 << 0 << up << 6;
        QTest::newRow("above at once")
            << K::LevelAbove << 5.0 << 0.0 << 0 << QList<double>(15, 7.0) << 0;
        QTest::newRow("below") << K::LevelBelow << 5.0 << 0.0 << 0 << down << 10;
        QTest::newRow("inside") << K::WindowInside << 4.0 << 6.0 << 0 << down << 8;
        QTest::newRow("outside") << K::WindowOutside << -1.0 << 1.0 << 0
                                 << QList<double> { 0, 0, 0, 0, 0, 0, 2, 0, 0, 0, 0, 0 } << 6;
        QTest::newRow("bit3 set (fault)")
            << K::BitSet << 0.0 << 0.0 << 3
            << QList<double> { 0x27, 0x27, 0x27, 0x27, 0x27, 0x08, 0x08, 0x08, 0x08, 0x08 } << 5;
        QTest::newRow("bit3 clear") << K::BitClear << 0.0 << 0.0 << 3
                                    << QList<double> { 8, 8, 8, 8, 0, 0, 0, 0, 0, 0, 0 } << 4;
        QTest::newRow("negative int16 statusword bit")
            << K::BitSet << 0.0 << 0.0 << 15 << QList<double> { 1, 1, 1, -32768, 0, 0, 0, 0 } << 3;
    }
    void triggerKinds()
    {
        QFETCH(Trigger::Kind, kind);
        QFETCH(double, level);
        QFETCH(double, level2);
        QFETCH(int, bit);
        QFETCH(QList<double>, values);
        QFETCH(int, firesAt);

        Trigger trigger;
        trigger.channel = 0;
        trigger.kind = kind;
        trigger.level = level;
        trigger.level2 = level2;
        trigger.bit = bit;
        trigger.preTriggerS = 2 * kDt;
        trigger.postTriggerS = 3 * kDt;
        m_recorder->setMode(Recorder::Mode::Single);
        m_recorder->setTrigger(trigger);
        QSignalSpy completed(m_recorder, &Recorder::captureCompleted);
        m_recorder->start();
        QCOMPARE(m_recorder->state(), Recorder::State::Armed);
        // The other channel is sampled in between, at other times.
        for (int i = 0; i < values.size(); ++i) {
            m_source->push(1, { { i * kDt - kDt / 2, 100 + i } });
            m_source->push(0, { { i * kDt, values[i] } });
        }
        if (firesAt < 0) {
            QCOMPARE(m_recorder->state(), Recorder::State::Armed);
            QVERIFY(std::isnan(m_recorder->triggerTime()));
            QCOMPARE(completed.count(), 0);
            // Pre-trigger memory is bounded to the pre window.
            QVERIFY(m_recorder->buffer(0).size() <= 3);
            return;
        }
        const double tt = firesAt * kDt;
        QCOMPARE(m_recorder->triggerTime(), tt);
        QCOMPARE(m_recorder->state(), Recorder::State::Stopped);
        QCOMPARE(completed.count(), 1);
        QVERIFY(!m_source->isRunning());
        const TraceBuffer &b = m_recorder->buffer(0);
        QVERIFY(b.firstTime() >= tt - 2 * kDt);
        QVERIFY(b.lastTime() <= tt + 3 * kDt);
        // Full pre window when there was history, always the full post window.
        const qint64 expected = std::min(firesAt, 2) + 1 + 3;
        QCOMPARE(b.size(), expected);
        const TraceBuffer &other = m_recorder->buffer(1);
        QVERIFY(other.firstTime() >= tt - 2 * kDt);
        QVERIFY(other.lastTime() <= tt + 3 * kDt);
    }

    void scalingAppliesToTheLevel()
    {
        m_recorder->setScaling(0, 0.5, 0); // display = raw / 2
        Trigger trigger;
        trigger.channel = 0;
        trigger.level = 5;
        trigger.postTriggerS = kDt;
        m_recorder->setMode(Recorder::Mode::Single);
        m_recorder->setTrigger(trigger);
        m_recorder->start();
        m_source->push(0, series({ 0, 4, 8, 12, 16, 20 }));
        QCOMPARE(m_recorder->triggerTime(), 3 * kDt); // raw 12 = displayed 6 >= 5
    }

    void singleWithoutTriggerIsRefused()
    {
        QSignalSpy errors(m_recorder, &Recorder::errorOccurred);
        m_recorder->setMode(Recorder::Mode::Single);
        m_recorder->start();
        QCOMPARE(errors.count(), 1);
        QCOMPARE(errors.at(0).at(0).value<Error>().kind(), Error::Kind::InvalidArgument);
        QCOMPARE(m_recorder->state(), Recorder::State::Idle);
        QVERIFY(!m_source->isRunning());
    }

    void postWindowEndsWithoutFurtherSamples()
    {
        Trigger trigger;
        trigger.channel = 0;
        trigger.kind = Trigger::Kind::LevelAbove;
        trigger.level = 1;
        trigger.postTriggerS = 0.2;
        m_recorder->setMode(Recorder::Mode::Single);
        m_recorder->setTrigger(trigger);
        m_recorder->start();
        m_source->push(0, { { m_recorder->now(), 5 } });
        QCOMPARE(m_recorder->state(), Recorder::State::Triggered);
        QTRY_COMPARE(m_recorder->state(), Recorder::State::Stopped);
        QCOMPARE(m_recorder->buffer(0).size(), 1);
    }

    void runEndsAfterItsDuration()
    {
        m_recorder->setDurationS(0.05);
        m_recorder->start();
        QVERIFY(std::isnan(m_recorder->stoppedAt()));
        // A sample stamped after the end (its answer came before the end timer's turn) is not
        // part of the recording.
        m_source->push(0, { { 0.01, 1 }, { 0.0625, 2 } });
        QCOMPARE(m_recorder->buffer(0).size(), 1);
        QTRY_COMPARE(m_recorder->state(), Recorder::State::Stopped);
        QVERIFY(!m_source->isRunning());
        QVERIFY2(m_recorder->stoppedAt() >= 0.05,
                 qPrintable(QString::number(m_recorder->stoppedAt())));
        // Without a duration the recording runs until stop().
        m_recorder->setDurationS(0);
        m_recorder->start();
        m_source->push(0, { { 0.0625, 2 } });
        QCOMPARE(m_recorder->buffer(0).size(), 1);
        QVERIFY(m_recorder->isRunning());
        m_recorder->stop();
    }

    void normalModeKeepsTheLastCapture()
    {
        Trigger trigger;
        trigger.channel = 0;
        trigger.level = 5;
        trigger.preTriggerS = kDt;
        trigger.postTriggerS = kDt;
        m_recorder->setMode(Recorder::Mode::Normal);
        m_recorder->setTrigger(trigger);
        QSignalSpy completed(m_recorder, &Recorder::captureCompleted);
        m_recorder->start();
        QCOMPARE(m_recorder->buffer(0).size(), 0);
        m_source->push(0, series({ 0, 4, 6, 7, 8, 0, 0, 0 }));
        QCOMPARE(completed.count(), 1);
        QCOMPARE(m_recorder->state(), Recorder::State::Armed);
        QCOMPARE(m_recorder->buffer(0).size(), 3); // 4, 6, 7
        QCOMPARE(m_recorder->buffer(0).value(1), 6.0);
        // Acquisition goes on out of sight; the shown capture stays until the next one.
        m_source->push(0, series({ 1, 2, 3, 1, 2 }, 10));
        QCOMPARE(m_recorder->buffer(0).value(1), 6.0);
        m_source->push(0, series({ 3, 9, 1, 3 }, 11));
        QCOMPARE(completed.count(), 2);
        QCOMPARE(m_recorder->triggerTime(), 11 + kDt);
        QCOMPARE(m_recorder->buffer(0).value(1), 9.0);
        m_recorder->stop();
        QCOMPARE(m_recorder->state(), Recorder::State::Stopped);
        QCOMPARE(m_recorder->buffer(0).value(1), 9.0);
    }

    void runModeIsBoundedByCapacity()
    {
        m_recorder->setCapacity(100);
        m_recorder->setMode(Recorder::Mode::Run);
        QSignalSpy data(m_recorder, &Recorder::dataAppended);
        m_recorder->start();
        QCOMPARE(m_recorder->state(), Recorder::State::Recording);
        QList<double> values;
        for (int i = 0; i < 500; ++i)
            values.append(i);
        m_source->push(0, series(values));
        QCOMPARE(m_recorder->buffer(0).size(), 100);
        QCOMPARE(m_recorder->buffer(0).droppedOverwritten(), 400);
        QCOMPARE(m_recorder->buffer(0).value(0), 400.0);
        QVERIFY(data.count() >= 500);
        m_recorder->stop();
        QCOMPARE(m_recorder->state(), Recorder::State::Stopped);
        QCOMPARE(m_recorder->buffer(0).size(), 100);
        m_source->push(0, series({ 1, 2 }, 1000)); // stopped: ignored
        QCOMPARE(m_recorder->buffer(0).size(), 100);
    }

    void rollModeKeepsTheWindow()
    {
        m_recorder->setMode(Recorder::Mode::Roll);
        m_recorder->setRollWindowS(1.0);
        m_recorder->start();
        QList<double> values(41, 1.0); // 0 .. 5 s
        m_source->push(0, series(values));
        const TraceBuffer &b = m_recorder->buffer(0);
        QCOMPARE(b.lastTime(), 5.0);
        QCOMPARE(b.firstTime(), 4.0);
        QCOMPARE(b.size(), 9);
    }

    void lossIsCountedAndMarkedAsGap()
    {
        QSignalSpy lost(m_recorder, &Recorder::samplesLost);
        m_recorder->start();
        m_source->push(0, series({ 1, 2 }));
        m_source->lose(0, 3);
        m_source->push(0, series({ 3, 4 }, 1));
        const TraceBuffer &b = m_recorder->buffer(0);
        QCOMPARE(b.size(), 4);
        QVERIFY(!b.startsGap(1));
        QVERIFY(b.startsGap(2));
        QVERIFY(!b.startsGap(3));
        QCOMPARE(b.lostAtSource(), 3);
        QCOMPARE(lost.count(), 1);
        QCOMPARE(lost.at(0).at(0).toInt(), 0);
        QCOMPARE(lost.at(0).at(1).toLongLong(), 3);
        QCOMPARE(m_recorder->buffer(1).dropped(), 0);
    }

    void sourceErrorStopsAndKeepsData()
    {
        QSignalSpy errors(m_recorder, &Recorder::errorOccurred);
        m_recorder->start();
        m_source->push(0, series({ 1, 2, 3 }));
        m_source->failWith(Error(Error::Kind::Disconnected, QStringLiteral("link lost")));
        QCOMPARE(m_recorder->state(), Recorder::State::Stopped);
        QCOMPARE(errors.count(), 1);
        QCOMPARE(m_recorder->buffer(0).size(), 3);
    }

    void restartClearsAndChannelsAreFrozenWhileRunning()
    {
        m_recorder->start();
        m_source->push(0, series({ 1, 2, 3 }));
        QCOMPARE(m_recorder->addChannel(m_source, 0), -1);
        QVERIFY(!m_recorder->removeChannel(0));
        m_recorder->stop();
        m_recorder->start();
        QCOMPARE(m_recorder->buffer(0).size(), 0);
        QCOMPARE(m_source->starts, 2);
        m_recorder->stop();
        QVERIFY(m_recorder->removeChannel(0));
        QCOMPARE(m_recorder->channelCount(), 1);
        QCOMPARE(m_recorder->channelInfo(0).id, QStringLiteral("6041:0"));
    }

    void deletedSourceLeavesOrphanChannels()
    {
        m_recorder->start();
        m_source->push(0, series({ 1, 2, 3 }));
        delete m_source;
        m_source = nullptr;
        m_recorder->stop();
        QCOMPARE(m_recorder->channelCount(), 2);
        QCOMPARE(m_recorder->buffer(0).size(), 3);
        QSignalSpy errors(m_recorder, &Recorder::errorOccurred);
        m_recorder->start();
        QCOMPARE(errors.count(), 1);
        QVERIFY(errors.at(0).at(0).value<Error>().message().contains(QStringLiteral("6064:0")));
    }

    void recordingValueAndLoad()
    {
        Trigger trigger;
        trigger.channel = 1;
        trigger.kind = Trigger::Kind::BitSet;
        trigger.bit = 3;
        trigger.preTriggerS = kDt;
        trigger.postTriggerS = kDt;
        m_recorder->setMode(Recorder::Mode::Single);
        m_recorder->setTrigger(trigger);
        m_recorder->start();
        m_source->push(0, series({ 10, 11, 12, 13, 14 }));
        m_source->push(1, series({ 0, 0, 8, 8, 8 }));
        QCOMPARE(m_recorder->state(), Recorder::State::Stopped);
        const Recording rec = m_recorder->recording();
        QCOMPARE(rec.channels.size(), 2);
        QCOMPARE(rec.trigger, trigger);
        QCOMPARE(rec.triggerTime, 2 * kDt);
        QCOMPARE(rec.mode, QStringLiteral("single"));
        QCOMPARE(rec.device, QStringLiteral("refgo://127.0.0.1:1"));

        Recorder other;
        other.load(rec);
        QCOMPARE(other.state(), Recorder::State::Stopped);
        QCOMPARE(other.channelCount(), 2);
        QCOMPARE(other.buffer(1).size(), rec.channels[1].buffer.size());
        QCOMPARE(other.triggerTime(), 2 * kDt);
        QSignalSpy errors(&other, &Recorder::errorOccurred);
        other.start(); // loaded channels have no source
        QCOMPARE(errors.count(), 1);
    }

    void triggerSpecParsing_data()
    {
        QTest::addColumn<QString>("spec");
        QTest::addColumn<bool>("ok");
        QTest::addColumn<int>("channel");
        QTest::addColumn<Trigger::Kind>("kind");
        QTest::addColumn<double>("level");
        QTest::addColumn<int>("bit");
        using K = Trigger::Kind;
        QTest::newRow("rising") << "6064:0,rising,100" << true << 0 << K::RisingEdge << 100.0 << 0;
        QTest::newRow("falling neg")
            << "6064,falling,-5.5" << true << 0 << K::FallingEdge << -5.5 << 0;
        QTest::newRow("bit set") << "6041:0,bit3,set" << true << 1 << K::BitSet << 0.0 << 3;
        QTest::newRow("bit default set") << "6041:00,bit10" << true << 1 << K::BitSet << 0.0 << 10;
        QTest::newRow("bit clear") << "6041:0,BIT3,clear" << true << 1 << K::BitClear << 0.0 << 3;
        QTest::newRow("inside") << "6064:0,inside,0,1000" << true << 0 << K::WindowInside << 0.0
                                << 0;
        QTest::newRow("unknown channel")
            << "6078:0,above,5" << false << 0 << K::LevelAbove << 0.0 << 0;
        QTest::newRow("no level") << "6064:0,rising" << false << 0 << K::RisingEdge << 0.0 << 0;
        QTest::newRow("bad number")
            << "6064:0,above,abc" << false << 0 << K::LevelAbove << 0.0 << 0;
        QTest::newRow("bad kind") << "6064:0,sideways,1" << false << 0 << K::LevelAbove << 0.0 << 0;
        QTest::newRow("bit 64") << "6041:0,bit64,set" << false << 0 << K::BitSet << 0.0 << 0;
        QTest::newRow("window reversed")
            << "6064:0,outside,5,1" << false << 0 << K::BitSet << 0.0 << 0;
    }
    void triggerSpecParsing()
    {
        QFETCH(QString, spec);
        QFETCH(bool, ok);
        const auto t = Trigger::parse(spec, { QStringLiteral("6064:0"), QStringLiteral("6041:0") });
        QCOMPARE(t.ok(), ok);
        if (!ok) {
            QCOMPARE(t.error().kind(), Error::Kind::InvalidArgument);
            QVERIFY(t.error().message().contains(spec));
            return;
        }
        QTEST(t->channel, "channel");
        QTEST(t->kind, "kind");
        QTEST(t->level, "level");
        QTEST(t->bit, "bit");
        // The text form parses back to the same trigger.
        const QString ids[] = { QStringLiteral("6064:0"), QStringLiteral("6041:0") };
        const auto again = Trigger::parse(ids[t->channel] + QLatin1Char(',') + t->conditionText(),
                                          { ids[0], ids[1] });
        QVERIFY(again.ok());
        QCOMPARE(*again, *t);
    }

private:
    FakeSource *m_source = nullptr;
    Recorder *m_recorder = nullptr;
};

QTEST_GUILESS_MAIN(TstRecorder)
#include "tst_recorder.moc"
