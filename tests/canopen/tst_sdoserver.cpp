// Level 2: SdoServer byte-exact against hand-built client frames (CiA 301 7.2.4): expedited,
// segmented and block transfers, CRC, toggle and sequence errors, abort codes, timeout.
#include "canopen/device/sdoserver.h"
#include "canopen/device/simulatednode.h"
#include "canopen/sdoabort.h"
#include "canopen/sdocodec.h"
#include "objectdefs.h"

#include <QSignalSpy>
#include <QTest>
#include <QtEndian>

using namespace db;
using namespace db::canopen;

namespace {

using test::objectDef;

ObjectDictionary testDictionary()
{
    ObjectDictionary dict;
    dict.insert(objectDef(0x1000, 0, DataType::Unsigned32, Access::ReadOnly, 0x00020192u));
    dict.insert(objectDef(0x1008, 0, DataType::VisibleString, Access::Const,
                          QStringLiteral("Simulated node 1")));
    ObjectDef limited = objectDef(0x2000, 0, DataType::Unsigned16, Access::ReadWrite, 0u);
    limited.minimum = 10u;
    limited.maximum = 1000u;
    dict.insert(limited);
    dict.insert(objectDef(0x2001, 0, DataType::Integer32, Access::ReadWrite, 0));
    dict.insert(objectDef(0x2002, 0, DataType::Unsigned8, Access::WriteOnly, 0u));
    dict.insert(objectDef(0x2003, 1, DataType::Unsigned8, Access::ReadWrite, 0u));
    dict.insert(objectDef(0x2010, 0, DataType::Domain, Access::ReadWrite));
    dict.insert(objectDef(0x2011, 0, DataType::VisibleString, Access::ReadWrite));
    return dict;
}

QByteArray hex(const char *text)
{
    return QByteArray::fromHex(QByteArray(text).replace(' ', ""));
}

QByteArray abortFrame(const char *indexSub, quint32 code)
{
    QByteArray f = hex("80") + hex(indexSub);
    f.resize(8);
    qToLittleEndian(code, f.data() + 4);
    return f;
}

const QByteArray kData20 = "0123456789abcdefghij";

} // namespace

class TestSdoServer : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void init();
    void cleanup();
    void expeditedUpload_data();
    void expeditedUpload();
    void expeditedDownload();
    void aborts_data();
    void aborts();
    void segmentedUpload();
    void segmentedUploadToggleError();
    void segmentedDownload();
    void segmentedDownloadToggleError();
    void segmentedDownloadSizeMismatch();
    void blockDownload();
    void blockDownloadSmallBlocks();
    void blockDownloadBadCrc();
    void blockDownloadLostSegment();
    void blockUpload();
    void blockUploadRetransmit();
    void blockUploadProtocolSwitch();
    void blockUploadBadBlockSize();
    void timeoutAborts();
    void clientAbortEndsTransfer();
    void crcVector();

private:
    QList<QByteArray> request(const QByteArray &payload);

    ObjectValueStore *m_store = nullptr;
    SdoServer *m_server = nullptr;
};

void TestSdoServer::init()
{
    m_store = new ObjectValueStore(testDictionary());
    m_server = new SdoServer(m_store, 5);
}

void TestSdoServer::cleanup()
{
    delete m_server;
    delete m_store;
}

QList<QByteArray> TestSdoServer::request(const QByteArray &payload)
{
    QList<QByteArray> out;
    auto c = connect(m_server, &SdoServer::response, this, [&out](const QCanBusFrame &f) {
        QCOMPARE(f.frameId(), 0x585u);
        out.append(f.payload());
    });
    m_server->handleRequest(QCanBusFrame(0x605, payload));
    disconnect(c);
    return out;
}

void TestSdoServer::expeditedUpload_data()
{
    QTest::addColumn<QByteArray>("req");
    QTest::addColumn<QByteArray>("resp");
    QTest::newRow("u32") << hex("40 00 10 00 00000000") << hex("43 00 10 00 92010200");
    QTest::newRow("u16") << hex("40 00 20 00 00000000") << hex("4B 00 20 00 00000000");
    QTest::newRow("u8 short dlc") << hex("40 03 20 01") << hex("4F 03 20 01 00000000");
}

void TestSdoServer::expeditedUpload()
{
    QFETCH(QByteArray, req);
    QFETCH(QByteArray, resp);
    QCOMPARE(request(req), QList<QByteArray> { resp });
    QCOMPARE(m_server->state(), SdoServer::State::Idle);
}

void TestSdoServer::expeditedDownload()
{
    QSignalSpy finished(m_server, &SdoServer::transferFinished);
    QCOMPARE(request(hex("2B 00 20 00 40 01 00 00")),
             QList<QByteArray> { hex("60 00 20 00 00000000") });
    QCOMPARE(m_store->value({ 0x2000, 0 }).toUInt(), 320u);
    QCOMPARE(finished.size(), 1);
    QCOMPARE(finished.at(0).at(2).toUInt(), 0u);
    // Size not indicated (22h): the object's size decides.
    QCOMPARE(request(hex("22 00 20 00 41 01 FF FF")),
             QList<QByteArray> { hex("60 00 20 00 00000000") });
    QCOMPARE(m_store->value({ 0x2000, 0 }).toUInt(), 321u);
    QCOMPARE(request(hex("23 01 20 00 FE FF FF FF")).size(), 1);
    QCOMPARE(m_store->value({ 0x2001, 0 }).toLongLong(), -2);
}

void TestSdoServer::aborts_data()
{
    QTest::addColumn<QByteArray>("req");
    QTest::addColumn<QByteArray>("resp");
    QTest::newRow("no object") << hex("40 00 30 00 00000000")
                               << abortFrame("00 30 00", abort::NoSuchObject);
    QTest::newRow("no sub-index") << hex("40 03 20 05 00000000")
                                  << abortFrame("03 20 05", abort::NoSuchSubIndex);
    QTest::newRow("read-only") << hex("23 00 10 00 01000000")
                               << abortFrame("00 10 00", abort::ReadOnly);
    QTest::newRow("const") << hex("2F 08 10 00 41000000")
                           << abortFrame("08 10 00", abort::ReadOnly);
    QTest::newRow("write-only") << hex("40 02 20 00 00000000")
                                << abortFrame("02 20 00", abort::WriteOnly);
    QTest::newRow("too long") << hex("23 00 20 00 40010000")
                              << abortFrame("00 20 00", abort::LengthTooHigh);
    QTest::newRow("too short") << hex("2B 01 20 00 40010000")
                               << abortFrame("01 20 00", abort::LengthTooLow);
    QTest::newRow("segmented too long")
        << hex("21 00 20 00 05000000") << abortFrame("00 20 00", abort::LengthTooHigh);
    QTest::newRow("above max") << hex("2B 00 20 00 E9030000")
                               << abortFrame("00 20 00", abort::ValueTooHigh);
    QTest::newRow("below min") << hex("2B 00 20 00 09000000")
                               << abortFrame("00 20 00", abort::ValueTooLow);
    QTest::newRow("bad command") << hex("E0 00 20 00 00000000")
                                 << abortFrame("00 00 00", abort::InvalidCommand);
    QTest::newRow("segment when idle")
        << hex("60 00 00 00 00000000") << abortFrame("00 00 00", abort::InvalidCommand);
}

void TestSdoServer::aborts()
{
    QFETCH(QByteArray, req);
    QFETCH(QByteArray, resp);
    QCOMPARE(request(req), QList<QByteArray> { resp });
    QCOMPARE(m_server->state(), SdoServer::State::Idle);
}

void TestSdoServer::segmentedUpload()
{
    QCOMPARE(request(hex("40 08 10 00 00000000")),
             QList<QByteArray> { hex("41 08 10 00 10000000") });
    QCOMPARE(m_server->state(), SdoServer::State::UploadSegmented);
    QCOMPARE(request(hex("60 00000000000000")), QList<QByteArray> { hex("00") + "Simulat" });
    QCOMPARE(request(hex("70 00000000000000")), QList<QByteArray> { hex("10") + "ed node" });
    QCOMPARE(request(hex("60 00000000000000")),
             QList<QByteArray> { hex("0B") + " 1" + QByteArray(5, 0) });
    QCOMPARE(m_server->state(), SdoServer::State::Idle);
}

void TestSdoServer::segmentedUploadToggleError()
{
    request(hex("40 08 10 00 00000000"));
    QCOMPARE(request(hex("70 00000000000000")),
             QList<QByteArray> { abortFrame("08 10 00", abort::ToggleNotAlternated) });
    QCOMPARE(m_server->state(), SdoServer::State::Idle);
}

void TestSdoServer::segmentedDownload()
{
    QCOMPARE(request(hex("21 11 20 00 0C000000")),
             QList<QByteArray> { hex("60 11 20 00 00000000") });
    QCOMPARE(request(hex("00") + "hello w"), QList<QByteArray> { hex("20 00000000000000") });
    QCOMPARE(request(hex("15") + "orld!" + QByteArray(2, 0)),
             QList<QByteArray> { hex("30 00000000000000") });
    QCOMPARE(m_store->value({ 0x2011, 0 }).toString(), QStringLiteral("hello world!"));
    QCOMPARE(m_server->state(), SdoServer::State::Idle);
}

void TestSdoServer::segmentedDownloadToggleError()
{
    request(hex("21 11 20 00 0C000000"));
    request(hex("00") + "hello w");
    QCOMPARE(request(hex("05") + "orld!" + QByteArray(2, 0)),
             QList<QByteArray> { abortFrame("11 20 00", abort::ToggleNotAlternated) });
    QVERIFY(m_store->value({ 0x2011, 0 }).toString().isEmpty());
}

void TestSdoServer::segmentedDownloadSizeMismatch()
{
    request(hex("21 11 20 00 0C000000"));
    QCOMPARE(request(hex("05") + "hello" + QByteArray(2, 0)),
             QList<QByteArray> { abortFrame("11 20 00", abort::LengthMismatch) });
}

void TestSdoServer::blockDownload()
{
    QCOMPARE(request(hex("C6 10 20 00 14000000")),
             QList<QByteArray> { hex("A4 10 20 00 7F000000") });
    QVERIFY(request(hex("01") + kData20.mid(0, 7)).isEmpty());
    QVERIFY(request(hex("02") + kData20.mid(7, 7)).isEmpty());
    QCOMPARE(request(hex("83") + kData20.mid(14, 6) + QByteArray(1, 0)),
             QList<QByteArray> { hex("A2 03 7F 00 00000000") });
    QCOMPARE(m_server->state(), SdoServer::State::BlockDownloadEnd);
    QByteArray end = hex("C5 0000 0000000000"); // n = 1 byte unused in the last segment
    qToLittleEndian(sdocodec::crc16(kData20), end.data() + 1);
    QCOMPARE(request(end), QList<QByteArray> { hex("A1 00000000000000") });
    QCOMPARE(m_store->value({ 0x2010, 0 }).toByteArray(), kData20);
}

void TestSdoServer::blockDownloadSmallBlocks()
{
    m_server->setBlockSize(2);
    QCOMPARE(request(hex("C2 10 20 00 14000000")),
             QList<QByteArray> { hex("A4 10 20 00 02000000") });
    request(hex("01") + kData20.mid(0, 7));
    QCOMPARE(request(hex("02") + kData20.mid(7, 7)),
             QList<QByteArray> { hex("A2 02 02 00 00000000") });
    QCOMPARE(request(hex("81") + kData20.mid(14, 6) + QByteArray(1, 0)),
             QList<QByteArray> { hex("A2 01 02 00 00000000") });
    // Client without CRC support (cc = 0): the CRC bytes are not checked.
    QCOMPARE(request(hex("C5 0000 0000000000")), QList<QByteArray> { hex("A1 00000000000000") });
    QCOMPARE(m_store->value({ 0x2010, 0 }).toByteArray(), kData20);
}

void TestSdoServer::blockDownloadBadCrc()
{
    request(hex("C6 10 20 00 14000000"));
    request(hex("01") + kData20.mid(0, 7));
    request(hex("02") + kData20.mid(7, 7));
    request(hex("83") + kData20.mid(14, 6) + QByteArray(1, 0));
    QByteArray end = hex("C5 0000 0000000000");
    qToLittleEndian(quint16(sdocodec::crc16(kData20) ^ 1), end.data() + 1);
    QCOMPARE(request(end), QList<QByteArray> { abortFrame("10 20 00", abort::CrcError) });
    QVERIFY(m_store->value({ 0x2010, 0 }).toByteArray().isEmpty());
}

void TestSdoServer::blockDownloadLostSegment()
{
    request(hex("C6 10 20 00 14000000"));
    request(hex("01") + kData20.mid(0, 7));
    // Segment 2 lost: the last one arrives out of sequence; the ack names segment 1.
    QCOMPARE(request(hex("83") + kData20.mid(14, 6) + QByteArray(1, 0)),
             QList<QByteArray> { hex("A2 01 7F 00 00000000") });
    QCOMPARE(m_server->state(), SdoServer::State::BlockDownload);
    QVERIFY(request(hex("01") + kData20.mid(7, 7)).isEmpty());
    QCOMPARE(request(hex("82") + kData20.mid(14, 6) + QByteArray(1, 0)),
             QList<QByteArray> { hex("A2 02 7F 00 00000000") });
    QByteArray end = hex("C5 0000 0000000000");
    qToLittleEndian(sdocodec::crc16(kData20), end.data() + 1);
    QCOMPARE(request(end), QList<QByteArray> { hex("A1 00000000000000") });
    QCOMPARE(m_store->value({ 0x2010, 0 }).toByteArray(), kData20);
}

void TestSdoServer::blockUpload()
{
    m_store->set({ 0x2010, 0 }, kData20);
    QSignalSpy finished(m_server, &SdoServer::transferFinished);
    QCOMPARE(request(hex("A4 10 20 00 7F 00 0000")),
             QList<QByteArray> { hex("C6 10 20 00 14000000") });
    const QList<QByteArray> segments = request(hex("A3 00000000000000"));
    QCOMPARE(segments,
             (QList<QByteArray> { hex("01") + kData20.mid(0, 7), hex("02") + kData20.mid(7, 7),
                                  hex("83") + kData20.mid(14, 6) + QByteArray(1, 0) }));
    QByteArray end = hex("C5 0000 0000000000");
    qToLittleEndian(sdocodec::crc16(kData20), end.data() + 1);
    QCOMPARE(request(hex("A2 03 7F 0000000000")), QList<QByteArray> { end });
    QCOMPARE(m_server->state(), SdoServer::State::BlockUploadEnd);
    QVERIFY(request(hex("A1 00000000000000")).isEmpty());
    QCOMPARE(m_server->state(), SdoServer::State::Idle);
    QCOMPARE(finished.size(), 1);
    QCOMPARE(finished.at(0).at(2).toUInt(), 0u);
}

void TestSdoServer::blockUploadRetransmit()
{
    m_store->set({ 0x2010, 0 }, kData20);
    request(hex("A4 10 20 00 02 00 0000")); // two segments per block
    QCOMPARE(request(hex("A3 00000000000000")).size(), 2);
    // Client got only segment 1 and asks for blocks of 5: segments 2 and 3 come again as 1, 2.
    QCOMPARE(request(hex("A2 01 05 0000000000")),
             (QList<QByteArray> { hex("01") + kData20.mid(7, 7),
                                  hex("82") + kData20.mid(14, 6) + QByteArray(1, 0) }));
    QCOMPARE(request(hex("A2 02 05 0000000000")).at(0).at(0), char(0xC5));
    QCOMPARE(request(hex("A2 09 05 0000000000")),
             QList<QByteArray> { abortFrame("10 20 00", abort::InvalidCommand) });
}

void TestSdoServer::blockUploadProtocolSwitch()
{
    // Threshold 4: the 4-byte value comes as a normal expedited upload.
    QCOMPARE(request(hex("A4 00 10 00 7F 04 0000")),
             QList<QByteArray> { hex("43 00 10 00 92010200") });
    QCOMPARE(m_server->state(), SdoServer::State::Idle);
}

void TestSdoServer::blockUploadBadBlockSize()
{
    QCOMPARE(request(hex("A4 00 10 00 80 00 0000")),
             QList<QByteArray> { abortFrame("00 10 00", abort::InvalidBlockSize) });
}

void TestSdoServer::timeoutAborts()
{
    m_server->setTimeoutMs(50);
    QSignalSpy responses(m_server, &SdoServer::response);
    request(hex("40 08 10 00 00000000"));
    QVERIFY(responses.wait(1000));
    QCOMPARE(responses.last().at(0).value<QCanBusFrame>().payload(),
             abortFrame("08 10 00", abort::Timeout));
    QCOMPARE(m_server->state(), SdoServer::State::Idle);
}

void TestSdoServer::clientAbortEndsTransfer()
{
    QSignalSpy finished(m_server, &SdoServer::transferFinished);
    request(hex("C6 10 20 00 14000000"));
    QVERIFY(request(abortFrame("10 20 00", abort::General)).isEmpty());
    QCOMPARE(m_server->state(), SdoServer::State::Idle);
    QCOMPARE(finished.size(), 1);
    QCOMPARE(finished.at(0).at(2).toUInt(), abort::General);
}

void TestSdoServer::crcVector()
{
    QCOMPARE(sdocodec::crc16("123456789"), quint16(0x31C3));
    QCOMPARE(sdocodec::crc16("6789", sdocodec::crc16("12345")), quint16(0x31C3));
    QCOMPARE(sdocodec::crc16({}), quint16(0));
}

QTEST_GUILESS_MAIN(TestSdoServer)
#include "tst_sdoserver.moc"
