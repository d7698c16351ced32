#include "canopen/framedecoder.h"
#include "canopen/sdoabort.h"
#include "resources/builtindescriptions.h"
#include "translations/language.h"

#include <QTest>

using namespace db;
using namespace db::canopen;

namespace {

QCanBusFrame frame(quint32 id, const QString &hex)
{
    return QCanBusFrame(id, QByteArray::fromHex(hex.toLatin1()));
}

// A node whose TPDO1 carries 6041h (16 bits) and 6064h (32 bits), as in a CiA 402 drive.
ObjectDictionary pdoDictionary()
{
    ObjectDictionary d;
    ObjectDef count;
    count.address = { 0x1A00, 0 };
    count.name = QStringLiteral("Number of mapped objects");
    count.type = DataType::Unsigned8;
    count.defaultValue = 2;
    d.insert(count);
    ObjectDef first = count;
    first.address = { 0x1A00, 1 };
    first.type = DataType::Unsigned32;
    first.defaultValue = 0x60410010u;
    d.insert(first);
    ObjectDef second = first;
    second.address = { 0x1A00, 2 };
    second.defaultValue = 0x60640020u;
    d.insert(second);
    ObjectDef status;
    status.address = { 0x6041, 0 };
    status.name = QStringLiteral("Statusword");
    status.type = DataType::Unsigned16;
    d.insert(status);
    ObjectDef position;
    position.address = { 0x6064, 0 };
    position.name = QStringLiteral("Position actual value");
    position.localNames.insert(QStringLiteral("de"), QStringLiteral("Lageistwert"));
    position.type = DataType::Integer32;
    d.insert(position);
    return d;
}

} // namespace

// Level 1: frames of movingcap.md 4.3 (CANopen on node 50 over SLCAN) and 7.1 (EMCY list), plus
// the remaining CiA 301 services.
class TestFrameDecoder : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void decodesSingleFrames_data()
    {
        QTest::addColumn<uint>("id");
        QTest::addColumn<QString>("hex");
        QTest::addColumn<bool>("withDictionary");
        QTest::addColumn<int>("service");
        QTest::addColumn<int>("node");
        QTest::addColumn<QString>("text");

        const auto row = [](const char *name, uint id, const char *hex, bool dict, Service s,
                            int node, const QString &text) {
            QTest::newRow(name) << id << QString::fromLatin1(hex) << dict << int(s) << node << text;
        };
        // movingcap.md 4.3
        row("read 6041", 0x632, "4041600000000000", true, Service::SdoRequest, 50,
            QStringLiteral("SDO rx node 50: upload 6041:0 Statusword"));
        row("6041 = 0427", 0x5B2, "4B41600027040000", true, Service::SdoResponse, 50,
            QStringLiteral("SDO tx node 50: upload 6041:0 Statusword → 0x0427"));
        row("6041 without dictionary", 0x5B2, "4B41600027040000", false, Service::SdoResponse, 50,
            QStringLiteral("SDO tx node 50: upload 6041:0 → 0x0427"));
        row("write 6040", 0x632, "2B4060000F000000", true, Service::SdoRequest, 50,
            QStringLiteral("SDO rx node 50: download 6040:0 Controlword ← 0x000F"));
        row("write ack", 0x5B2, "6040600000000000", true, Service::SdoResponse, 50,
            QStringLiteral("SDO tx node 50: download 6040:0 Controlword ok"));
        row("save", 0x632, "2310100173617665", false, Service::SdoRequest, 50,
            QStringLiteral("SDO rx node 50: download 1010:1 ← 0x65766173"));
        row("under-voltage", 0x0B2, "2132050000000000", true, Service::Emcy, 50,
            QStringLiteral("EMCY node 50: 3221 ERROR_UNDER_VOLT (voltage), reg 0x05"));
        row("start node 50", 0x000, "0132", false, Service::Nmt, 50,
            QStringLiteral("NMT start node 50"));
        row("heartbeat operational", 0x732, "05", false, Service::Heartbeat, 50,
            QStringLiteral("Heartbeat node 50: operational"));
        // movingcap.md 7.1
        row("over-temperature", 0x0B2, "1042090000000000", true, Service::Emcy, 50,
            QStringLiteral("EMCY node 50: 4210 ERROR_OVER_TEMP (temperature), reg 0x09"));
        row("stroke", 0x0B2, "2171100000000000", true, Service::Emcy, 50,
            QStringLiteral("EMCY node 50: 7121 ERROR_STROKE (additional modules), reg 0x10"));
        row("emcy without dictionary", 0x0B2, "2132050000000000", false, Service::Emcy, 50,
            QStringLiteral("EMCY node 50: 3221 (voltage), reg 0x05"));
        row("emcy reset", 0x0B2, "0000000000000000", false, Service::Emcy, 50,
            QStringLiteral("EMCY node 50: 0000 error reset, reg 0x00"));
        row("emcy device specific", 0x0B2, "F1FF100000000000", true, Service::Emcy, 50,
            QStringLiteral("EMCY node 50: FFF1 ERROR_SENSOR_1 (device specific), reg 0x10"));
        row("emcy manufacturer data", 0x081, "1042090102030405", false, Service::Emcy, 1,
            QStringLiteral("EMCY node 1: 4210 (temperature), reg 0x09, data 01 02 03 04 05"));
        row("emcy too short", 0x0B2, "2132", false, Service::Emcy, 50,
            QStringLiteral("EMCY node 50: malformed (2 bytes)"));
        // CiA 301 others
        row("nmt reset all", 0x000, "8100", false, Service::Nmt, 0,
            QStringLiteral("NMT reset all nodes"));
        row("nmt reset comm", 0x000, "8205", false, Service::Nmt, 5,
            QStringLiteral("NMT reset communication node 5"));
        row("nmt preop", 0x000, "8032", false, Service::Nmt, 50,
            QStringLiteral("NMT pre-operational node 50"));
        row("sync", 0x080, "", false, Service::Sync, 0, QStringLiteral("SYNC"));
        row("sync counter", 0x080, "07", false, Service::Sync, 0, QStringLiteral("SYNC counter 7"));
        row("boot-up", 0x732, "00", false, Service::BootUp, 50, QStringLiteral("Boot-up node 50"));
        row("pre-operational", 0x705, "7F", false, Service::Heartbeat, 5,
            QStringLiteral("Heartbeat node 5: pre-operational"));
        row("stopped, guarding toggle", 0x705, "84", false, Service::Heartbeat, 5,
            QStringLiteral("Heartbeat node 5: stopped"));
        row("time", 0x100, "000000000000", false, Service::Time, 0,
            QStringLiteral("TIME 1984-01-01 00:00:00.000"));
        row("tpdo2 unmapped", 0x2B2, "0102", false, Service::Tpdo, 50,
            QStringLiteral("TPDO2 node 50: 2 bytes"));
        row("rpdo4", 0x532, "01", false, Service::Rpdo, 50,
            QStringLiteral("RPDO4 node 50: 1 bytes"));
        row("abort", 0x5B2, "8000200000000206", true, Service::SdoResponse, 50,
            QStringLiteral("SDO tx node 50: abort 2000:0: 0x06020000 ") + abortText(0x06020000));
        row("segmented upload", 0x5B2, "4108100014000000", true, Service::SdoResponse, 50,
            QStringLiteral("SDO tx node 50: upload 1008:0 Manufacturer device name, 20 bytes"));
        row("lss switch global", 0x7E5, "0401000000000000", false, Service::Lss, 0,
            QStringLiteral("LSS master: switch state global"));
        row("unassigned", 0x7F0, "01", false, Service::Other, 0, QString());
    }

    void decodesSingleFrames()
    {
        QFETCH(uint, id);
        QFETCH(QString, hex);
        QFETCH(bool, withDictionary);
        QFETCH(int, service);
        QFETCH(int, node);
        QFETCH(QString, text);

        FrameDecoder decoder;
        if (withDictionary)
            decoder.setDictionary(50, resources::movingCapDictionary());
        const DecodedFrame d = decoder.decode(frame(id, hex));
        QCOMPARE(d.text, text);
        QVERIFY(text.endsWith(d.detail));
        QCOMPARE(int(d.service), service);
        QCOMPARE(int(d.node), node);
    }

    void sdoFramesCarryTheirObject()
    {
        FrameDecoder decoder;
        const DecodedFrame request = decoder.decode(frame(0x632, "4041600000000000"));
        QVERIFY(request.hasAddress);
        QCOMPARE(request.address, ObjectAddress(0x6041, 0));
        QVERIFY(!decoder.decode(frame(0x732, "05")).hasAddress);
    }

    void segmentsNameTheObjectOfTheTransfer()
    {
        FrameDecoder decoder;
        decoder.setDictionary(50, resources::movingCapDictionary());
        decoder.decode(frame(0x632, "4008100000000000"));
        decoder.decode(frame(0x5B2, "410810000D000000"));
        const DecodedFrame request = decoder.decode(frame(0x632, "6000000000000000"));
        QCOMPARE(request.address, ObjectAddress(0x1008, 0));
        QCOMPARE(request.text,
                 QStringLiteral("SDO rx node 50: upload segment request 1008:0 Manufacturer "
                                "device name t=0"));
        const DecodedFrame segment = decoder.decode(frame(0x5B2, "004D6F76696E6743"));
        QCOMPARE(segment.text,
                 QStringLiteral("SDO tx node 50: upload segment 1008:0 Manufacturer device name "
                                "t=0: \"MovingC\""));
        const DecodedFrame last = decoder.decode(frame(0x5B2, "1361702045544800"));
        QVERIFY(last.text.endsWith(QStringLiteral("t=1 last: \"ap ETH\"")));
    }

    void blockDownloadSegmentsAreRecognised()
    {
        FrameDecoder decoder;
        decoder.decode(frame(0x605, "C600200109000000")); // 2000:1, 9 bytes
        decoder.decode(frame(0x585, "A400200107000000")); // ok, blksize 7
        const DecodedFrame s1 = decoder.decode(frame(0x605, "0101020304050607"));
        QCOMPARE(s1.text,
                 QStringLiteral("SDO rx node 5: block segment 1 2000:1: 01 02 03 04 05 06 07"));
        const DecodedFrame s2 = decoder.decode(frame(0x605, "8208090000000000"));
        QVERIFY(s2.text.startsWith(QStringLiteral("SDO rx node 5: block segment 2 last 2000:1")));
        QVERIFY(decoder.decode(frame(0x585, "A202070000000000"))
                    .text.startsWith(QStringLiteral("SDO tx node 5: block download ack 2000:1")));
        const DecodedFrame end = decoder.decode(frame(0x605, "D534120000000000"));
        QCOMPARE(end.text,
                 QStringLiteral("SDO rx node 5: block download end 2000:1, 5 unused, crc 0x1234"));
        QCOMPARE(decoder.decode(frame(0x585, "A100000000000000")).text,
                 QStringLiteral("SDO tx node 5: block download end 2000:1 ok"));
    }

    void pdosAreDecodedWithTheMappingOfTheDictionary()
    {
        FrameDecoder decoder;
        decoder.setDictionary(3, pdoDictionary());
        const DecodedFrame d = decoder.decode(frame(0x183, "2704E8030000"));
        QCOMPARE(d.service, Service::Tpdo);
        QCOMPARE(d.pdoNumber, 1);
        QCOMPARE(d.text,
                 QStringLiteral("TPDO1 node 3: 6041:0 Statusword = 0x0427, "
                                "6064:0 Position actual value = 1000"));
        decoder.removeDictionary(3);
        QCOMPARE(decoder.decode(frame(0x183, "2704E8030000")).text,
                 QStringLiteral("TPDO1 node 3: 6 bytes"));
    }

    // With the German translation the monitor's words are German, the device's names those of
    // its German manual, and CANopen's own terms, numbers and the "service: detail" form stay.
    void decodesInGerman()
    {
        QVERIFY(i18n::installTranslations(*QCoreApplication::instance(), QStringLiteral("de")));
        FrameDecoder decoder;
        decoder.setDictionary(3, pdoDictionary());
        const DecodedFrame pdo = decoder.decode(frame(0x183, "2704E8030000"));
        const DecodedFrame nmt = decoder.decode(frame(0x000, "0100"));
        const DecodedFrame heartbeat = decoder.decode(frame(0x703, "7F"));
        const DecodedFrame emcy = decoder.decode(frame(0x083, "2132050000000000"));
        QVERIFY(i18n::installTranslations(*QCoreApplication::instance(), QStringLiteral("en")));
        QCOMPARE(pdo.text,
                 QStringLiteral("TPDO1 Knoten 3: 6041:0 Statusword = 0x0427, "
                                "6064:0 Lageistwert = 1000"));
        QCOMPARE(pdo.detail,
                 QStringLiteral("6041:0 Statusword = 0x0427, 6064:0 Lageistwert = 1000"));
        QCOMPARE(nmt.text, QStringLiteral("NMT Start alle Knoten"));
        QCOMPARE(heartbeat.text, QStringLiteral("Heartbeat Knoten 3: pre-operational"));
        QCOMPARE(emcy.text, QStringLiteral("EMCY Knoten 3: 3221 (Spannung), Reg. 0x05"));
        QCOMPARE(decoder.decode(frame(0x000, "0100")).text, QStringLiteral("NMT start all nodes"));
    }

    void extendedAndErrorFramesAreNotCanopen()
    {
        FrameDecoder decoder;
        QCanBusFrame extended(0x18FF0032, QByteArray(2, '\0'));
        extended.setExtendedFrameFormat(true);
        QCOMPARE(decoder.decode(extended).service, Service::Other);
        QCanBusFrame error;
        error.setFrameType(QCanBusFrame::ErrorFrame);
        QCOMPARE(decoder.decode(error).text, QStringLiteral("error frame"));
    }
};

QTEST_GUILESS_MAIN(TestFrameDecoder)
#include "tst_framedecoder.moc"
