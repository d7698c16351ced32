// Level 2: SlcanBus over a scripted byte stream (movingcap.md 4.2 tool recommendations).
#include "scriptedstream.h"
#include "transport/slcanbus.h"

#include <QSignalSpy>
#include <QTest>

using namespace db;

class TestSlcanBus : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void openSendsCloseBitrateOpen();
    void otherBitrate();
    void repliesAreIgnoredFramesDelivered();
    void bellAndGarbageAreWarnings();
    void sendWritesLineAndReportsFrameSent();
    void streamLossClosesBusWithError();
    void refusedStreamClosesBus();
    void closeSendsC();
};

namespace {
struct Fixture
{
    explicit Fixture(int bitrate = SlcanBus::kDefaultBitrate)
        : stream(new test::ScriptedStream)
        , bus(stream, bitrate)
    { }
    bool open()
    {
        QSignalSpy opened(&bus, &CanBus::opened);
        bus.open();
        return opened.wait(1000);
    }
    test::ScriptedStream *stream;
    SlcanBus bus;
};
} // namespace

void TestSlcanBus::openSendsCloseBitrateOpen()
{
    Fixture f;
    QVERIFY(f.open());
    QCOMPARE(f.stream->takeWritten(), QByteArray("C\rS4\rO\r"));
    QVERIFY(f.bus.isOpen());
    QCOMPARE(f.bus.name(), QStringLiteral("slcan scripted:0"));
}

void TestSlcanBus::otherBitrate()
{
    Fixture f(500000);
    QVERIFY(f.open());
    QCOMPARE(f.stream->takeWritten(), QByteArray("C\rS6\rO\r"));
    Fixture none(0);
    QVERIFY(none.open());
    QCOMPARE(none.stream->takeWritten(), QByteArray("C\rO\r"));
}

void TestSlcanBus::repliesAreIgnoredFramesDelivered()
{
    Fixture f;
    QVERIFY(f.open());
    QSignalSpy frames(&f.bus, &CanBus::frameReceived);
    QSignalSpy warnings(&f.bus, &CanBus::warning);
    f.stream->feed("\r\rz\rZ\rV1013\rt5B284B4160");
    QCOMPARE(frames.size(), 0);
    f.stream->feed("0027040000\r\nt732105\r");
    QCOMPARE(frames.size(), 2);
    const auto frame = frames.at(0).at(0).value<QCanBusFrame>();
    QCOMPARE(frame.frameId(), 0x5B2u);
    QCOMPARE(frame.payload(), QByteArray::fromHex("4B41600027040000"));
    QCOMPARE(warnings.size(), 0);
}

void TestSlcanBus::bellAndGarbageAreWarnings()
{
    Fixture f;
    QVERIFY(f.open());
    QSignalSpy frames(&f.bus, &CanBus::frameReceived);
    QSignalSpy warnings(&f.bus, &CanBus::warning);
    f.stream->feed("\a#garbage#\rt732105\r");
    QCOMPARE(warnings.size(), 2);
    QVERIFY(warnings.at(0).at(0).toString().contains(QStringLiteral("BEL")));
    QVERIFY(warnings.at(1).at(0).toString().contains(QStringLiteral("garbage")));
    QCOMPARE(frames.size(), 1);
}

void TestSlcanBus::sendWritesLineAndReportsFrameSent()
{
    Fixture f;
    QVERIFY(!f.bus.send(QCanBusFrame(0x632, QByteArray::fromHex("4041600000000000"))));
    QVERIFY(f.open());
    f.stream->takeWritten();
    QSignalSpy sent(&f.bus, &CanBus::frameSent);
    QVERIFY(f.bus.send(QCanBusFrame(0x632, QByteArray::fromHex("4041600000000000"))));
    QCOMPARE(f.stream->takeWritten(), QByteArray("t63284041600000000000\r"));
    QCOMPARE(sent.size(), 1);
}

void TestSlcanBus::streamLossClosesBusWithError()
{
    Fixture f;
    QVERIFY(f.open());
    QSignalSpy closed(&f.bus, &CanBus::closed);
    f.stream->drop(Error(Error::Kind::Disconnected, QStringLiteral("peer reset")));
    QCOMPARE(closed.size(), 1);
    QCOMPARE(closed.at(0).at(0).value<Error>().kind(), Error::Kind::Disconnected);
    QCOMPARE(f.bus.state(), CanBus::State::Closed);
}

void TestSlcanBus::refusedStreamClosesBus()
{
    Fixture f;
    f.stream->refuseNextOpen(Error(Error::Kind::ConnectionRefused, QStringLiteral("refused")));
    QSignalSpy closed(&f.bus, &CanBus::closed);
    f.bus.open();
    QVERIFY(closed.wait(1000));
    QCOMPARE(closed.at(0).at(0).value<Error>().kind(), Error::Kind::ConnectionRefused);
    QVERIFY(f.stream->takeWritten().isEmpty());
}

void TestSlcanBus::closeSendsC()
{
    Fixture f;
    QVERIFY(f.open());
    f.stream->takeWritten();
    QSignalSpy closed(&f.bus, &CanBus::closed);
    f.bus.close();
    QCOMPARE(f.stream->takeWritten(), QByteArray("C\r"));
    QCOMPARE(closed.size(), 1);
    QVERIFY(!closed.at(0).at(0).value<Error>().isError());
}

QTEST_GUILESS_MAIN(TestSlcanBus)
#include "tst_slcanbus.moc"
