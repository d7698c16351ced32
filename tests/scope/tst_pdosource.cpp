// PDO sampling: the pure decode (level 1); passive sampling, loss and bus loss over a scripted
// bus (level 2); and end to end against a simulated CANopen node over SLCAN on loopback with a
// TPDO configured by the opt-in helper (level 3).
#include "canopen/canopenconnection.h"
#include "canopen/nmtmaster.h"
#include "canopen/pdoclient.h"
#include "common/protocols.h"
#include "common/simnodes.h"
#include "resources/builtindescriptions.h"
#include "scope/pdosource.h"
#include "scope/recorder.h"
#include "scriptedcanbus.h"

#include <QSignalSpy>
#include <QtTest>

using namespace db;
using namespace db::scope;
using Mapping = PdoSource::Mapping;

namespace {
ObjectDictionary testDictionary()
{
    return resources::builtinDescription(QStringLiteral("drivebench_testnode")).valueOr({});
}

ChannelInfo info(const char *id)
{
    ChannelInfo c;
    c.id = QString::fromLatin1(id);
    c.address = *ObjectAddress::parse(c.id);
    return c;
}
} // namespace

class TstPdoSource : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void decodesValues_data()
    {
        QTest::addColumn<QByteArray>("payload");
        QTest::addColumn<int>("offset");
        QTest::addColumn<DataType>("type");
        QTest::addColumn<bool>("ok");
        QTest::addColumn<double>("value");
        const QByteArray p = QByteArray::fromHex("D4FE6079FEFF0000");
        QTest::newRow("int16 at 0") << p << 0 << DataType::Integer16 << true << -300.0;
        QTest::newRow("uint16 at 0") << p << 0 << DataType::Unsigned16 << true << 65236.0;
        QTest::newRow("int32 at 2") << p << 2 << DataType::Integer32 << true << -100000.0;
        QTest::newRow("uint8 at 7") << p << 7 << DataType::Unsigned8 << true << 0.0;
        QTest::newRow("int24 at 2") << p << 2 << DataType::Integer24 << true << -100000.0;
        QTest::newRow("bool") << QByteArray::fromHex("02") << 0 << DataType::Boolean << true << 1.0;
        QTest::newRow("real32") << QByteArray::fromHex("0000C03F") << 0 << DataType::Real32 << true
                                << 1.5;
        QTest::newRow("int64") << QByteArray::fromHex("FEFFFFFFFFFFFFFF") << 0
                               << DataType::Integer64 << true << -2.0;
        QTest::newRow("too short")
            << QByteArray::fromHex("0102") << 1 << DataType::Integer16 << false << 0.0;
        QTest::newRow("string") << p << 0 << DataType::VisibleString << false << 0.0;
    }
    void decodesValues()
    {
        QFETCH(QByteArray, payload);
        QFETCH(int, offset);
        QFETCH(DataType, type);
        QFETCH(bool, ok);
        const auto v = PdoSource::decodeValue(payload, { 0x181, offset, type, 0 });
        QCOMPARE(v.has_value(), ok);
        if (ok)
            QTEST(*v, "value");
    }

    void samplesPassivelyFromTheBus()
    {
        test::ScriptedCanBus bus;
        bus.open();
        PdoSource source(&bus);
        QVERIFY(source.addChannel(info("2101:0"), { 0x185, 0, DataType::Integer16, 0 }).ok());
        QVERIFY(source.addChannel(info("2103:0"), { 0x185, 2, DataType::Integer32, 0 }).ok());
        QVERIFY(source.addChannel(info("6041:0"), { 0x285, 0, DataType::Unsigned16, 0 }).ok());
        QCOMPARE(
            source.addChannel(info("2000:0"), { 0x185, 6, DataType::Integer32, 0 }).error().kind(),
            Error::Kind::InvalidArgument); // bytes 6..9 do not fit
        Recorder recorder;
        recorder.addSource(&source);
        recorder.start();
        bus.feed(0x185, "D4 FE 60 79 FE FF");
        bus.feed(0x186, "01 02"); // another node: ignored
        QCanBusFrame rtr(0x185, {});
        rtr.setFrameType(QCanBusFrame::RemoteRequestFrame);
        bus.feed(rtr); // remote request: ignored
        bus.feed(0x285, "27 06");
        bus.feed(0x185, "D5 FE 61 79 FE FF");
        QCOMPARE(recorder.buffer(0).size(), 2);
        QCOMPARE(recorder.buffer(0).value(0), -300.0);
        QCOMPARE(recorder.buffer(0).value(1), -299.0);
        QCOMPARE(recorder.buffer(1).value(0), -100000.0);
        QCOMPARE(recorder.buffer(2).value(0), double(0x0627));
        QVERIFY(recorder.buffer(0).time(1) >= recorder.buffer(0).time(0));
        QCOMPARE(source.framesSeen(), 3);
        // Passive: nothing was sent on the bus.
        QVERIFY(bus.sent().isEmpty());
        recorder.stop();
        bus.feed(0x185, "00 00 00 00 00 00");
        QCOMPARE(recorder.buffer(0).size(), 2);
    }

    void shortPdoIsALostSample()
    {
        test::ScriptedCanBus bus;
        bus.open();
        PdoSource source(&bus);
        QVERIFY(source.addChannel(info("2103:0"), { 0x185, 2, DataType::Integer32, 0 }).ok());
        Recorder recorder;
        recorder.addSource(&source);
        recorder.start();
        bus.feed(0x185, "00 00 01 00 00 00");
        bus.feed(0x185, "00 00 01");
        bus.feed(0x185, "00 00 02 00 00 00");
        const TraceBuffer &b = recorder.buffer(0);
        QCOMPARE(b.size(), 2);
        QCOMPARE(b.lostAtSource(), 1);
        QVERIFY(b.startsGap(1));
    }

    void missedPeriodsAreCounted()
    {
        test::ScriptedCanBus bus;
        bus.open();
        PdoSource source(&bus);
        QVERIFY(source.addChannel(info("2101:0"), { 0x185, 0, DataType::Integer16, 5 }).ok());
        Recorder recorder;
        recorder.addSource(&source);
        recorder.start();
        bus.feed(0x185, "01 00");
        QElapsedTimer clock;
        clock.start();
        QTRY_VERIFY(clock.elapsed() >= 40); // >= 7 periods without a frame
        bus.feed(0x185, "02 00");
        const TraceBuffer &b = recorder.buffer(0);
        QCOMPARE(b.size(), 2);
        QVERIFY2(b.lostAtSource() >= 6, qPrintable(QString::number(b.lostAtSource())));
        QVERIFY(b.startsGap(1));
    }

    void busLossStopsTheSource()
    {
        test::ScriptedCanBus bus;
        bus.open();
        PdoSource source(&bus);
        QVERIFY(source.addChannel(info("2101:0"), { 0x185, 0, DataType::Integer16, 0 }).ok());
        Recorder recorder;
        recorder.addSource(&source);
        QSignalSpy errors(&recorder, &Recorder::errorOccurred);
        recorder.start();
        bus.feed(0x185, "01 00");
        bus.drop(Error(Error::Kind::Disconnected, QStringLiteral("adapter unplugged")));
        QCOMPARE(recorder.state(), Recorder::State::Stopped);
        QCOMPARE(errors.count(), 1);
        QVERIFY(errors.at(0).at(0).value<Error>().message().contains(
            QStringLiteral("adapter unplugged")));
        QCOMPARE(recorder.buffer(0).size(), 1);
    }

    void tpdoConfiguration()
    {
        const ObjectDictionary dict = testDictionary();
        const auto c = tpdoConfigFor(5, 0, { { 0x2101, 0 }, { 0x2103, 0 } }, dict, 10);
        QVERIFY2(c.ok(), qPrintable(c.error().toString()));
        QCOMPARE(c->canId(), 0x185u);
        QCOMPARE(c->entries.size(), 2);
        QCOMPARE(c->entries[1].toRaw(), 0x21030020u);
        QCOMPARE(c->eventTimer, std::optional<quint16>(10));
        QCOMPARE(tpdoConfigFor(5, 1, { { 0x2101, 0 } }, dict, 10)->canId(), 0x285u);
        QCOMPARE(tpdoConfigFor(5, 0, { { 0x2103, 0 }, { 0x2102, 0 }, { 0x2100, 0 } }, dict, 10)
                     .error()
                     .kind(),
                 Error::Kind::InvalidArgument); // 72 bits
        QCOMPARE(tpdoConfigFor(5, 0, { { 0x2FFF, 0 } }, dict, 10).error().kind(),
                 Error::Kind::InvalidArgument); // unknown object
        QCOMPARE(tpdoConfigFor(5, 4, { { 0x2101, 0 } }, dict, 10).error().kind(),
                 Error::Kind::InvalidArgument); // TPDO5 has no predefined COB-ID
    }

    void endToEndOverSlcan()
    {
        app::SimNodes sim;
        QVERIFY(sim.create({ { 5 }, {}, {} }).ok());
        QVERIFY(sim.startSlcan(0).ok());
        auto made = app::protocolRegistry().create(
            QStringLiteral("canopen+slcan://127.0.0.1:%1?node=5").arg(sim.slcanPort()));
        QVERIFY(made.ok());
        auto *connection = qobject_cast<canopen::CanopenConnection *>(made->get());
        QVERIFY(connection);
        connection->open();
        QTRY_VERIFY(connection->isConnected());
        const ObjectDictionary dict = testDictionary();

        // Opt-in: make the node send 2101h and 2103h every 10 ms on TPDO1, then start it.
        canopen::PdoClient client(connection->sdo());
        const auto written =
            Reply::wait(configureTpdo(&client, 5, 0, { { 0x2101, 0 }, { 0x2103, 0 } }, dict, 10));
        QVERIFY2(written.ok(), qPrintable(written.error().toString()));
        const auto config = written->value<canopen::PdoConfig>();
        QVERIFY(connection->nmt()->start(5));

        PdoSource source(connection);
        const auto channels = source.addPdo(config, dict, {});
        QVERIFY(channels.ok());
        QCOMPARE(channels->size(), 2);
        QCOMPARE(source.channels().at(0).name, QStringLiteral("Test integer16"));
        QCOMPARE(source.channels().at(0).device, connection->uri().toString());

        Recorder recorder;
        recorder.addSource(&source);
        int sent = 0;
        connect(connection->bus(), &CanBus::frameSent, this, [&] { ++sent; });
        recorder.start();
        QTRY_VERIFY_WITH_TIMEOUT(recorder.buffer(1).size() >= 20, 10000);
        recorder.stop();
        QCOMPARE(sent, 0); // sampling sent nothing
        QCOMPARE(recorder.buffer(0).value(0), -300.0);
        QCOMPARE(recorder.buffer(1).value(0), -100000.0);
        QCOMPARE(recorder.buffer(0).lostAtSource(), 0);
        const TraceBuffer &b = recorder.buffer(1);
        const double period = (b.lastTime() - b.firstTime()) / double(b.size() - 1);
        QVERIFY2(period > 0.005 && period < 0.05, qPrintable(QString::number(period)));
        connection->close();
    }
};

QTEST_GUILESS_MAIN(TstPdoSource)
#include "tst_pdosource.moc"
