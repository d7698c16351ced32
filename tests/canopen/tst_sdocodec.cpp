// Level 1: the pure SDO frame builders and readers (CiA 301 7.2.4.3) against hand-built frames,
// the spec vectors (movingcap.md 4.3, nm170_canopen.md 3.3.5) and the CRC of 7.2.4.3.16.

#include "canopen/sdocodec.h"

#include <QtTest>

using namespace db;
using namespace db::canopen;

namespace {
QByteArray h(const char *hex)
{
    return QByteArray::fromHex(QByteArray(hex).replace(' ', ""));
}
} // namespace

class TstSdoCodec : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void builders_data();
    void builders();
    void initiateUploadResponse_data();
    void initiateUploadResponse();
    void uploadSegment();
    void crc16_data();
    void crc16();
    void crcChainsOverPieces();
    void readersNeverReadPastShortFrames();
};

void TstSdoCodec::builders_data()
{
    QTest::addColumn<QByteArray>("built");
    QTest::addColumn<QByteArray>("expected");
    const ObjectAddress statusword(0x6041, 0);
    QTest::newRow("movingcap 4.3 read 6041")
        << sdocodec::initiateUpload(statusword) << h("40 41 60 00 00 00 00 00");
    QTest::newRow("movingcap 4.3 write 6040=000F")
        << sdocodec::initiateDownloadExpedited({ 0x6040, 0 }, h("0F 00"))
        << h("2B 40 60 00 0F 00 00 00");
    QTest::newRow("movingcap 4.3 save")
        << sdocodec::initiateDownloadExpedited({ 0x1010, 1 }, "save")
        << h("23 10 10 01 73 61 76 65");
    QTest::newRow("nm170 SDO-2") << sdocodec::initiateDownloadExpedited({ 0x2003, 0 },
                                                                        h("40 01 00 00"))
                                 << h("23 03 20 00 40 01 00 00");
    QTest::newRow("1 byte") << sdocodec::initiateDownloadExpedited({ 0x2101, 0 }, h("7F"))
                            << h("2F 01 21 00 7F 00 00 00");
    QTest::newRow("3 bytes") << sdocodec::initiateDownloadExpedited({ 0x2000, 1 }, h("01 02 03"))
                             << h("27 00 20 01 01 02 03 00");
    QTest::newRow("segmented initiate")
        << sdocodec::initiateDownloadSegmented({ 0x2007, 0 }, 12) << h("21 07 20 00 0C 00 00 00");
    QTest::newRow("segment t0 7 bytes")
        << sdocodec::downloadSegment(false, "ABCDEFG", false) << h("00 41 42 43 44 45 46 47");
    QTest::newRow("segment t1 last 5")
        << sdocodec::downloadSegment(true, "HIJKL", true) << h("15 48 49 4A 4B 4C 00 00");
    QTest::newRow("upload segment t1")
        << sdocodec::uploadSegmentRequest(true) << h("70 00 00 00 00 00 00 00");
    QTest::newRow("abort timeout")
        << sdocodec::abort(statusword, 0x05040000) << h("80 41 60 00 00 00 04 05");
    QTest::newRow("block download initiate")
        << sdocodec::initiateBlockDownload({ 0x2F00, 2 }, 100) << h("C6 00 2F 02 64 00 00 00");
    QTest::newRow("block segment 3")
        << sdocodec::blockSegment(3, "1234567", false) << h("03 31 32 33 34 35 36 37");
    QTest::newRow("block segment last")
        << sdocodec::blockSegment(127, "12", true) << h("FF 31 32 00 00 00 00 00");
    QTest::newRow("block download end")
        << sdocodec::endBlockDownload(5, 0x31C3) << h("D5 C3 31 00 00 00 00 00");
    QTest::newRow("block upload initiate")
        << sdocodec::initiateBlockUpload({ 0x1008, 0 }, 127) << h("A4 08 10 00 7F 00 00 00");
    QTest::newRow("block upload start")
        << sdocodec::startBlockUpload() << h("A3 00 00 00 00 00 00 00");
    QTest::newRow("block upload ack")
        << sdocodec::blockUploadAck(5, 127) << h("A2 05 7F 00 00 00 00 00");
    QTest::newRow("block upload end response")
        << sdocodec::endBlockUploadResponse() << h("A1 00 00 00 00 00 00 00");
}

void TstSdoCodec::builders()
{
    QFETCH(QByteArray, built);
    QFETCH(QByteArray, expected);
    QCOMPARE(sdocodec::hex(built), sdocodec::hex(expected));
}

void TstSdoCodec::initiateUploadResponse_data()
{
    QTest::addColumn<QByteArray>("frame");
    QTest::addColumn<bool>("expedited");
    QTest::addColumn<QByteArray>("data");
    QTest::addColumn<int>("size");
    QTest::newRow("movingcap 6041=0427") << h("4B 41 60 00 27 04 00 00") << true << h("27 04") << 2;
    QTest::newRow("nm170 SDO-1") << h("43 04 60 00 20 A1 07 00") << true << h("20 A1 07 00") << 4;
    QTest::newRow("nm170 SDO-3") << h("4F 01 21 00 7F 00 00 00") << true << h("7F") << 1;
    QTest::newRow("3 bytes") << h("47 00 20 00 01 02 03 00") << true << h("01 02 03") << 3;
    QTest::newRow("size not indicated")
        << h("42 00 20 00 01 02 03 04") << true << h("01 02 03 04") << 4;
    QTest::newRow("segmented 14") << h("41 08 10 00 0E 00 00 00") << false << QByteArray() << 14;
}

void TstSdoCodec::initiateUploadResponse()
{
    QFETCH(QByteArray, frame);
    QFETCH(bool, expedited);
    QFETCH(QByteArray, data);
    QFETCH(int, size);
    const auto r = sdocodec::parseInitiateUpload(frame);
    QCOMPARE(r.expedited, expedited);
    QCOMPARE(r.data, data);
    QCOMPARE(int(r.size), size);
}

void TstSdoCodec::uploadSegment()
{
    const auto s = sdocodec::parseUploadSegment(h("19 45 54 48 00 00 00 00"));
    QVERIFY(s.toggle);
    QVERIFY(s.last);
    QCOMPARE(s.data, QByteArray("ETH"));
    const auto full = sdocodec::parseUploadSegment(h("00 4D 6F 76 69 6E 67 43"));
    QVERIFY(!full.toggle);
    QVERIFY(!full.last);
    QCOMPARE(full.data, QByteArray("MovingC"));
}

void TstSdoCodec::crc16_data()
{
    QTest::addColumn<QByteArray>("data");
    QTest::addColumn<int>("crc");
    // CRC-16/XMODEM parameters (poly 1021h, init 0, no reflection), as CiA 301 defines it.
    QTest::newRow("check string") << QByteArray("123456789") << 0x31C3;
    QTest::newRow("empty") << QByteArray() << 0x0000;
    QTest::newRow("one zero byte") << h("00") << 0x0000;
    QTest::newRow("A") << QByteArray("A") << 0x58E5;
}

void TstSdoCodec::crc16()
{
    QFETCH(QByteArray, data);
    QFETCH(int, crc);
    QCOMPARE(int(sdocodec::crc16(data)), crc);
}

void TstSdoCodec::crcChainsOverPieces()
{
    QCOMPARE(sdocodec::crc16("6789", sdocodec::crc16("12345")), sdocodec::crc16("123456789"));
}

void TstSdoCodec::readersNeverReadPastShortFrames()
{
    QCOMPARE(sdocodec::address(h("40 41")), ObjectAddress());
    QCOMPARE(sdocodec::u32(h("80 41 60 00 30"), 4), 0x30u);
    QCOMPARE(sdocodec::specifier(QByteArray()), quint8(0xFF));
    QCOMPARE(sdocodec::parseUploadSegment(h("00")).data, QByteArray());
}

QTEST_GUILESS_MAIN(TstSdoCodec)
#include "tst_sdocodec.moc"
