// Level 2: SDO block download and upload (CiA 301 7.2.4.3.9 - 7.2.4.3.16) over a scripted CAN
// bus: byte-exact sequences, CRC, block size negotiation, lost segments, CRC mismatch.

#include "canopen/sdoabort.h"
#include "canopen/sdoblocktransfer.h"
#include "canopen/sdoclient.h"
#include "canopen/sdocodec.h"
#include "scriptedcanbus.h"

#include <QtTest>

using namespace db;
using namespace db::canopen;
using db::test::ScriptedCanBus;

namespace {
constexpr int kWaitMs = 5000;
constexpr NodeId kNode = 5;

QByteArray h(const char *hex)
{
    return QByteArray::fromHex(QByteArray(hex).replace(' ', ""));
}
ScriptedCanBus::Line tx(const char *hex)
{
    return ScriptedCanBus::tx(0x600 + kNode, hex);
}
ScriptedCanBus::Line rx(const char *hex)
{
    return ScriptedCanBus::rx(0x580 + kNode, hex);
}
QByteArray pattern(int size)
{
    QByteArray data(size, '\0');
    for (int i = 0; i < size; ++i)
        data[i] = char((i * 7 + 3) & 0xFF);
    return data;
}
} // namespace

class TstSdoBlock : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void init();
    void cleanup();

    void blockDownloadByteExact();
    void blockDownloadHonoursServerBlockSize();
    void blockDownloadResendsAfterLostSegment();
    void blockDownloadAckBeyondSentAborts();
    void blockUploadByteExact();
    void blockUploadAcksShortOnLostSegmentAndTakesRetransmission();
    void blockUploadCrcMismatchAborts();
    void blockUploadWithoutServerCrcSkipsCheck();
    void blockUploadServerAbortGivesText();
    void autoModeChoosesBlockOnlyWhenEnabledAndLarge();
    void largeBlockRoundTripThroughStateMachines();

private:
    Result<QVariant> run(Reply *reply) { return Reply::wait(reply, kWaitMs); }
    void checkScript()
    {
        QVERIFY2(m_bus->scriptErrors().isEmpty(),
                 qPrintable(m_bus->scriptErrors().join(QLatin1Char('\n'))));
        QVERIFY(m_bus->scriptDone());
    }

    ScriptedCanBus *m_bus = nullptr;
    SdoClient *m_sdo = nullptr;
};

void TstSdoBlock::init()
{
    m_bus = new ScriptedCanBus;
    m_bus->open();
    m_sdo = new SdoClient(m_bus);
}

void TstSdoBlock::cleanup()
{
    delete m_sdo;
    delete m_bus;
}

void TstSdoBlock::blockDownloadByteExact()
{
    // "123456789" (CRC 31C3h) as two segments: 7 + 2 bytes, n = 5 in the end frame.
    m_bus->play({
        tx("C6 00 2F 01 09 00 00 00"),
        rx("A4 00 2F 01 7F 00 00 00"),
        tx("01 31 32 33 34 35 36 37"),
        tx("82 38 39 00 00 00 00 00"),
        rx("A2 02 7F 00 00 00 00 00"),
        tx("D5 C3 31 00 00 00 00 00"),
        rx("A1 00 00 00 00 00 00 00"),
    });
    const auto r = run(m_sdo->download(kNode, { 0x2F00, 1 }, "123456789", SdoClient::Mode::Block));
    QVERIFY2(r.ok(), qPrintable(r.error().toString()));
    checkScript();
}

void TstSdoBlock::blockDownloadHonoursServerBlockSize()
{
    // The server takes 2 segments per block, then 1; without CRC support (sc = 0).
    m_bus->play({
        tx("C6 00 2F 01 10 00 00 00"),
        rx("A0 00 2F 01 02 00 00 00"),
        tx("01 41 42 43 44 45 46 47"),
        tx("02 48 49 4A 4B 4C 4D 4E"),
        rx("A2 02 01 00 00 00 00 00"),
        tx("81 4F 50 00 00 00 00 00"),
        rx("A2 01 7F 00 00 00 00 00"),
        tx("D5 00 00 00 00 00 00 00"),
        rx("A1 00 00 00 00 00 00 00"),
    });
    const auto r =
        run(m_sdo->download(kNode, { 0x2F00, 1 }, "ABCDEFGHIJKLMNOP", SdoClient::Mode::Block));
    QVERIFY2(r.ok(), qPrintable(r.error().toString()));
    checkScript();
}

void TstSdoBlock::blockDownloadResendsAfterLostSegment()
{
    // Segment 2 of 3 lost: the server acks 1; segments 2 and 3 go again as 1 and 2.
    const quint16 crc = sdocodec::crc16("ABCDEFGHIJKLMNOP");
    QByteArray endFrame = h("D5 00 00 00 00 00 00 00");
    endFrame[1] = char(crc & 0xFF);
    endFrame[2] = char(crc >> 8);
    m_bus->play({
        tx("C6 00 2F 01 10 00 00 00"),
        rx("A4 00 2F 01 7F 00 00 00"),
        tx("01 41 42 43 44 45 46 47"),
        tx("02 48 49 4A 4B 4C 4D 4E"),
        tx("83 4F 50 00 00 00 00 00"),
        rx("A2 01 7F 00 00 00 00 00"),
        tx("01 48 49 4A 4B 4C 4D 4E"),
        tx("82 4F 50 00 00 00 00 00"),
        rx("A2 02 7F 00 00 00 00 00"),
        { true, QCanBusFrame(0x605, endFrame) },
        rx("A1 00 00 00 00 00 00 00"),
    });
    const auto r =
        run(m_sdo->download(kNode, { 0x2F00, 1 }, "ABCDEFGHIJKLMNOP", SdoClient::Mode::Block));
    QVERIFY2(r.ok(), qPrintable(r.error().toString()));
    checkScript();
}

void TstSdoBlock::blockDownloadAckBeyondSentAborts()
{
    m_bus->play({
        tx("C6 00 2F 01 05 00 00 00"),
        rx("A4 00 2F 01 7F 00 00 00"),
        tx("81 41 42 43 44 45 00 00"),
        rx("A2 05 7F 00 00 00 00 00"),
        tx("80 00 2F 01 03 00 04 05"),
    });
    const auto r = run(m_sdo->download(kNode, { 0x2F00, 1 }, "ABCDE", SdoClient::Mode::Block));
    QCOMPARE(r.error().kind(), Error::Kind::Malformed);
    QCOMPARE(r.error().deviceCode(), abort::InvalidSequence);
    checkScript();
}

void TstSdoBlock::blockUploadByteExact()
{
    m_sdo->setBlockSize(4);
    // 9 bytes "123456789", CRC 31C3h.
    m_bus->play({
        tx("A4 08 10 00 04 00 00 00"),
        rx("C6 08 10 00 09 00 00 00"),
        tx("A3 00 00 00 00 00 00 00"),
        rx("01 31 32 33 34 35 36 37"),
        rx("82 38 39 00 00 00 00 00"),
        tx("A2 02 04 00 00 00 00 00"),
        rx("D5 C3 31 00 00 00 00 00"),
        tx("A1 00 00 00 00 00 00 00"),
    });
    const auto r = run(m_sdo->upload(kNode, { 0x1008, 0 }, SdoClient::Mode::Block));
    QVERIFY2(r.ok(), qPrintable(r.error().toString()));
    QCOMPARE(r->toByteArray(), QByteArray("123456789"));
    checkScript();
}

void TstSdoBlock::blockUploadAcksShortOnLostSegmentAndTakesRetransmission()
{
    m_sdo->setBlockSize(3);
    // 16 bytes in 3 segments; segment 2 is lost on the first try.
    const QByteArray data = "ABCDEFGHIJKLMNOP";
    const quint16 crc = sdocodec::crc16(data);
    QByteArray end = h("D5 00 00 00 00 00 00 00");
    end[1] = char(crc & 0xFF);
    end[2] = char(crc >> 8);
    m_bus->play({
        tx("A4 08 10 00 03 00 00 00"),
        rx("C6 08 10 00 10 00 00 00"),
        tx("A3 00 00 00 00 00 00 00"),
        rx("01 41 42 43 44 45 46 47"),
        rx("83 4F 50 00 00 00 00 00"),
        tx("A2 01 03 00 00 00 00 00"),
        rx("01 48 49 4A 4B 4C 4D 4E"),
        rx("82 4F 50 00 00 00 00 00"),
        tx("A2 02 03 00 00 00 00 00"),
        { false, QCanBusFrame(0x585, end) },
        tx("A1 00 00 00 00 00 00 00"),
    });
    const auto r = run(m_sdo->upload(kNode, { 0x1008, 0 }, SdoClient::Mode::Block));
    QVERIFY2(r.ok(), qPrintable(r.error().toString()));
    QCOMPARE(r->toByteArray(), data);
    checkScript();
}

void TstSdoBlock::blockUploadCrcMismatchAborts()
{
    m_bus->play({
        tx("A4 08 10 00 7F 00 00 00"),
        rx("C6 08 10 00 09 00 00 00"),
        tx("A3 00 00 00 00 00 00 00"),
        rx("01 31 32 33 34 35 36 37"),
        rx("82 38 39 00 00 00 00 00"),
        tx("A2 02 7F 00 00 00 00 00"),
        rx("D5 C4 31 00 00 00 00 00"),
        tx("80 08 10 00 04 00 04 05"),
    });
    const auto r = run(m_sdo->upload(kNode, { 0x1008, 0 }, SdoClient::Mode::Block));
    QCOMPARE(r.error().kind(), Error::Kind::Malformed);
    QCOMPARE(r.error().deviceCode(), abort::CrcError);
    QVERIFY2(r.error().message().contains(QLatin1String("CRC")), qPrintable(r.error().message()));
    checkScript();
}

void TstSdoBlock::blockUploadWithoutServerCrcSkipsCheck()
{
    m_bus->play({
        tx("A4 08 10 00 7F 00 00 00"),
        rx("C2 08 10 00 02 00 00 00"),
        tx("A3 00 00 00 00 00 00 00"),
        rx("81 4F 4B 00 00 00 00 00"),
        tx("A2 01 7F 00 00 00 00 00"),
        rx("D5 00 00 00 00 00 00 00"),
        tx("A1 00 00 00 00 00 00 00"),
    });
    const auto r = run(m_sdo->upload(kNode, { 0x1008, 0 }, SdoClient::Mode::Block));
    QCOMPARE(r.valueOr({}).toByteArray(), QByteArray("OK"));
    checkScript();
}

void TstSdoBlock::blockUploadServerAbortGivesText()
{
    m_bus->play({ tx("A4 08 10 00 7F 00 00 00"), rx("80 08 10 00 01 00 04 05") });
    const auto r = run(m_sdo->upload(kNode, { 0x1008, 0 }, SdoClient::Mode::Block));
    QCOMPARE(r.error().kind(), Error::Kind::DeviceError);
    QCOMPARE(r.error().message(), abortText(abort::InvalidCommand));
    checkScript();
}

void TstSdoBlock::autoModeChoosesBlockOnlyWhenEnabledAndLarge()
{
    const QByteArray big(100, 'x');
    delete m_sdo->download(kNode, { 0x2F00, 1 }, big);
    QCOMPARE(quint8(m_bus->takeSent().at(0).payload().at(0)), quint8(0x21)); // segmented
    m_sdo->cancelAll(Error(Error::Kind::Cancelled, QStringLiteral("test")));
    m_sdo->setBlockEnabled(true);
    delete m_sdo->download(kNode, { 0x2F00, 1 }, big);
    QCOMPARE(quint8(m_bus->takeSent().at(0).payload().at(0)), quint8(0xC6)); // block
    m_sdo->cancelAll(Error(Error::Kind::Cancelled, QStringLiteral("test")));
    delete m_sdo->download(kNode, { 0x2F00, 1 }, QByteArray(10, 'x'));
    QCOMPARE(quint8(m_bus->takeSent().at(0).payload().at(0)), quint8(0x21)); // small: segmented
    m_sdo->cancelAll(Error(Error::Kind::Cancelled, QStringLiteral("test")));
    delete m_sdo->upload(kNode, { 0x6041, 0 }, SdoClient::Mode::Auto, 2);
    QCOMPARE(quint8(m_bus->takeSent().at(0).payload().at(0)), quint8(0x40)); // known small
    m_sdo->cancelAll(Error(Error::Kind::Cancelled, QStringLiteral("test")));
    delete m_sdo->upload(kNode, { 0x1008, 0 });
    QCOMPARE(quint8(m_bus->takeSent().at(0).payload().at(0)), quint8(0xA4)); // unknown size
    m_sdo->cancelAll(Error(Error::Kind::Cancelled, QStringLiteral("test")));
}

// The two state machines against each other's frames through a tiny in-test block server, for
// a 100 kB domain: what the other side would see, without a bus.
void TstSdoBlock::largeBlockRoundTripThroughStateMachines()
{
    const QByteArray data = pattern(100 * 1024 + 3);
    SdoBlockDownload down({ 0x2F00, 1 }, data);
    SdoStep step = down.start();
    QCOMPARE(quint8(step.frames.at(0).at(0)), quint8(0xC6));
    QCOMPARE(sdocodec::u32(step.frames.at(0), 4), quint32(data.size()));
    step = down.onFrame(h("A4 00 2F 01 7F 00 00 00"));
    QByteArray received;
    int blocks = 1;
    const auto isEnd = [](const SdoStep &s) {
        return s.frames.size() == 1 && (quint8(s.frames.at(0).at(0)) & 0xE3) == 0xC1;
    };
    while (step.outcome == SdoStep::Outcome::Continue && !isEnd(step)) {
        for (const QByteArray &f : step.frames)
            received += f.mid(1);
        QByteArray ack = h("A2 00 7F 00 00 00 00 00");
        ack[1] = char(step.frames.size());
        step = down.onFrame(ack);
        ++blocks;
    }
    // The end frame: n and CRC.
    QCOMPARE(step.frames.size(), 1);
    const QByteArray end = step.frames.at(0);
    received.chop(sdocodec::endUnused(end));
    QCOMPARE(received, data);
    QCOMPARE(sdocodec::endCrc(end), sdocodec::crc16(data));
    QCOMPARE(blocks, int((data.size() + 7 * 127 - 1) / (7 * 127)) + 1);
    QCOMPARE(down.onFrame(h("A1 00 00 00 00 00 00 00")).outcome, SdoStep::Outcome::Done);
}

QTEST_GUILESS_MAIN(TstSdoBlock)
#include "tst_sdoblock.moc"
