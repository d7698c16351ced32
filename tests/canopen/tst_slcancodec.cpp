// Level 1: the slcan ASCII codec (movingcap.md 4.2, 4.3): line tables, split input, CRLF,
// garbage, BEL, timestamps, encoding.
#include "transport/slcancodec.h"

#include <QTest>

using namespace db;
using Kind = slcan::Message::Kind;

Q_DECLARE_METATYPE(slcan::Message::Kind)

class TestSlcanCodec : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void parseFrames_data();
    void parseFrames();
    void parseOther_data();
    void parseOther();
    void splitInputAnywhere();
    void crlfAndLoneLf();
    void bellInsideStream();
    void overlongGarbageIsOneUnknownLine();
    void linesAtTheLengthLimit();
    void feedEachStopsWhenTheReceiverSaysSo();
    void encodeFrames_data();
    void encodeFrames();
    void encodeRejectsFd();
    void encodeIntoReusesItsLine();
    void bitrateCodes();
};

void TestSlcanCodec::parseFrames_data()
{
    QTest::addColumn<QByteArray>("line");
    QTest::addColumn<quint32>("id");
    QTest::addColumn<bool>("extended");
    QTest::addColumn<bool>("remote");
    QTest::addColumn<QByteArray>("payload");
    QTest::addColumn<int>("timestamp"); // -1 = none

    // Spec 4.3 example frames.
    QTest::newRow("sdo read 6041") << QByteArray("t63284041600000000000") << 0x632u << false
                                   << false << QByteArray::fromHex("4041600000000000") << -1;
    QTest::newRow("sdo answer 6041") << QByteArray("t5B284B41600027040000") << 0x5B2u << false
                                     << false << QByteArray::fromHex("4B41600027040000") << -1;
    QTest::newRow("emcy undervolt") << QByteArray("t0B282132050000000000") << 0x0B2u << false
                                    << false << QByteArray::fromHex("2132050000000000") << -1;
    QTest::newRow("nmt start 50") << QByteArray("t00020132") << 0u << false << false
                                  << QByteArray::fromHex("0132") << -1;
    QTest::newRow("heartbeat") << QByteArray("t732105") << 0x732u << false << false
                               << QByteArray::fromHex("05") << -1;
    QTest::newRow("lowercase hex")
        << QByteArray("t5b2243ab") << 0x5B2u << false << false << QByteArray::fromHex("43ab") << -1;
    QTest::newRow("dlc 0") << QByteArray("t0800") << 0x080u << false << false << QByteArray() << -1;
    QTest::newRow("timestamp") << QByteArray("t7321051A2B") << 0x732u << false << false
                               << QByteArray::fromHex("05") << 0x1A2B;
    QTest::newRow("extended") << QByteArray("T1FFFFFFF2ABCD") << 0x1FFFFFFFu << true << false
                              << QByteArray::fromHex("ABCD") << -1;
    QTest::newRow("remote") << QByteArray("r7324") << 0x732u << false << true << QByteArray(4, 0)
                            << -1;
    QTest::newRow("remote ext ts")
        << QByteArray("R0000012310001") << 0x123u << true << true << QByteArray(1, 0) << 1;
}

void TestSlcanCodec::parseFrames()
{
    QFETCH(QByteArray, line);
    QFETCH(quint32, id);
    QFETCH(bool, extended);
    QFETCH(bool, remote);
    QFETCH(QByteArray, payload);
    QFETCH(int, timestamp);
    const slcan::Message m = slcan::parseLine(line);
    QCOMPARE(m.kind, Kind::Frame);
    QCOMPARE(m.frame.frameId(), id);
    QCOMPARE(m.frame.hasExtendedFrameFormat(), extended);
    QCOMPARE(m.frame.frameType() == QCanBusFrame::RemoteRequestFrame, remote);
    QCOMPARE(m.frame.payload(), payload);
    QCOMPARE(m.timestamp.has_value(), timestamp >= 0);
    if (timestamp >= 0)
        QCOMPARE(int(*m.timestamp), timestamp);
}

void TestSlcanCodec::parseOther_data()
{
    QTest::addColumn<QByteArray>("line");
    QTest::addColumn<Kind>("kind");
    QTest::addColumn<char>("command");
    QTest::addColumn<QByteArray>("argument");

    QTest::newRow("ack") << QByteArray() << Kind::Ack << char(0) << QByteArray();
    QTest::newRow("z") << QByteArray("z") << Kind::TransmitAck << 'z' << QByteArray();
    QTest::newRow("Z") << QByteArray("Z") << Kind::TransmitAck << 'Z' << QByteArray();
    QTest::newRow("open") << QByteArray("O") << Kind::Command << 'O' << QByteArray();
    QTest::newRow("close") << QByteArray("C") << Kind::Command << 'C' << QByteArray();
    QTest::newRow("listen") << QByteArray("L") << Kind::Command << 'L' << QByteArray();
    QTest::newRow("S4") << QByteArray("S4") << Kind::Command << 'S' << QByteArray("4");
    QTest::newRow("btr") << QByteArray("s031C") << Kind::Command << 's' << QByteArray("031C");
    QTest::newRow("version?") << QByteArray("V") << Kind::Command << 'V' << QByteArray();
    QTest::newRow("version") << QByteArray("V1013") << Kind::Command << 'V' << QByteArray("1013");
    QTest::newRow("serial") << QByteArray("NA123") << Kind::Command << 'N' << QByteArray("A123");
    QTest::newRow("flags") << QByteArray("F00") << Kind::Command << 'F' << QByteArray("00");
    QTest::newRow("Z1") << QByteArray("Z1") << Kind::Command << 'Z' << QByteArray("1");
    // Garbage and near misses.
    QTest::newRow("id too big") << QByteArray("t8001AA") << Kind::Unknown << char(0)
                                << QByteArray();
    QTest::newRow("dlc 9") << QByteArray("t1239") << Kind::Unknown << char(0) << QByteArray();
    QTest::newRow("short data") << QByteArray("t1232AA") << Kind::Unknown << char(0)
                                << QByteArray();
    QTest::newRow("bad hex") << QByteArray("t1231G0") << Kind::Unknown << char(0) << QByteArray();
    QTest::newRow("3 extra") << QByteArray("t1231AA123") << Kind::Unknown << char(0)
                             << QByteArray();
    QTest::newRow("ext too big") << QByteArray("T200000000") << Kind::Unknown << char(0)
                                 << QByteArray();
    QTest::newRow("S bad") << QByteArray("Sx") << Kind::Unknown << char(0) << QByteArray();
    QTest::newRow("O arg") << QByteArray("Ox") << Kind::Unknown << char(0) << QByteArray();
    QTest::newRow("Z2") << QByteArray("Z2") << Kind::Unknown << char(0) << QByteArray();
    QTest::newRow("text") << QByteArray("hello") << Kind::Unknown << char(0) << QByteArray();
}

void TestSlcanCodec::parseOther()
{
    QFETCH(QByteArray, line);
    QFETCH(Kind, kind);
    QFETCH(char, command);
    QFETCH(QByteArray, argument);
    const slcan::Message m = slcan::parseLine(line);
    QCOMPARE(m.kind, kind);
    if (kind == Kind::Command || kind == Kind::TransmitAck) {
        QCOMPARE(m.command, command);
        QCOMPARE(m.argument, argument);
    }
    if (kind == Kind::Unknown)
        QCOMPARE(m.line, line);
}

void TestSlcanCodec::splitInputAnywhere()
{
    const QByteArray stream = "z\rt5B284B41600027040000\r\rt732105\r";
    for (int cut = 0; cut <= stream.size(); ++cut) {
        slcan::Decoder decoder;
        QList<slcan::Message> all = decoder.feed(stream.left(cut));
        all += decoder.feed(stream.mid(cut));
        QCOMPARE(all.size(), 4);
        QCOMPARE(all.at(0).kind, Kind::TransmitAck);
        QCOMPARE(all.at(1).kind, Kind::Frame);
        QCOMPARE(all.at(1).frame.payload(), QByteArray::fromHex("4B41600027040000"));
        QCOMPARE(all.at(2).kind, Kind::Ack);
        QCOMPARE(all.at(3).frame.frameId(), 0x732u);
        QCOMPARE(decoder.pendingBytes(), 0);
    }
    slcan::Decoder bytewise;
    QList<slcan::Message> all;
    for (const char c : stream)
        all += bytewise.feed(QByteArray(1, c));
    QCOMPARE(all.size(), 4);
}

void TestSlcanCodec::crlfAndLoneLf()
{
    slcan::Decoder decoder;
    const auto messages = decoder.feed("t732105\r\nt73217F\n\n\r\n");
    QCOMPARE(messages.size(), 3); // two frames and the one empty "\r" line
    QCOMPARE(messages.at(0).kind, Kind::Frame);
    QCOMPARE(messages.at(1).frame.payload(), QByteArray::fromHex("7F"));
    QCOMPARE(messages.at(2).kind, Kind::Ack);
}

void TestSlcanCodec::bellInsideStream()
{
    slcan::Decoder decoder;
    const auto messages = decoder.feed("\at7321");
    QCOMPARE(messages.size(), 1);
    QCOMPARE(messages.at(0).kind, Kind::Bell);
    const auto rest = decoder.feed("05\r\a");
    QCOMPARE(rest.size(), 2);
    QCOMPARE(rest.at(0).kind, Kind::Frame);
    QCOMPARE(rest.at(1).kind, Kind::Bell);
}

void TestSlcanCodec::overlongGarbageIsOneUnknownLine()
{
    slcan::Decoder decoder;
    const QByteArray junk(1000, 'x');
    QVERIFY(decoder.feed(junk).isEmpty());
    QCOMPARE(decoder.pendingBytes(), slcan::kMaxLineLength);
    const auto messages = decoder.feed("\rt732105\r");
    QCOMPARE(messages.size(), 2);
    QCOMPARE(messages.at(0).kind, Kind::Unknown);
    QCOMPARE(messages.at(1).kind, Kind::Frame);
}

void TestSlcanCodec::linesAtTheLengthLimit()
{
    // Whole lines in one chunk are parsed where they lie; the limit must hold there too.
    const QByteArray atLimit(slcan::kMaxLineLength, 'x');
    const QByteArray overLimit(slcan::kMaxLineLength + 1, 'x');
    slcan::Decoder decoder;
    const auto messages = decoder.feed(atLimit + "\r" + overLimit + "\rz\r");
    QCOMPARE(messages.size(), 3);
    QCOMPARE(messages.at(0).kind, Kind::Unknown);
    QCOMPARE(messages.at(0).line, atLimit);
    QCOMPARE(messages.at(1).kind, Kind::Unknown);
    QCOMPARE(messages.at(1).line, overLimit.left(slcan::kMaxLineLength));
    QCOMPARE(messages.at(2).kind, Kind::TransmitAck);
    QCOMPARE(messages.at(2).line, QByteArray("z"));
    QCOMPARE(decoder.pendingBytes(), 0);
}

void TestSlcanCodec::feedEachStopsWhenTheReceiverSaysSo()
{
    const QByteArray stream = "z\rt732105\r\at73217F\rt7321";
    slcan::Decoder all;
    QList<Kind> kinds;
    all.feedEach(stream, [&](const slcan::Message &m) {
        kinds.append(m.kind);
        return true;
    });
    QCOMPARE(kinds, (QList<Kind> { Kind::TransmitAck, Kind::Frame, Kind::Bell, Kind::Frame }));
    QCOMPARE(all.pendingBytes(), 5); // "t7321" waits for the rest of its line

    slcan::Decoder stopping;
    QList<quint32> ids;
    stopping.feedEach(stream, [&](const slcan::Message &m) {
        if (m.kind != Kind::Frame)
            return true;
        ids.append(m.frame.frameId());
        return false; // e.g. the receiver closed the bus
    });
    QCOMPARE(ids, QList<quint32> { 0x732 });
    QCOMPARE(stopping.pendingBytes(), 0); // the rest is discarded, no partial line kept
    const auto next = stopping.feed("t73217F\r");
    QCOMPARE(next.size(), 1);
    QCOMPARE(next.at(0).frame.payload(), QByteArray::fromHex("7F"));
}

void TestSlcanCodec::encodeFrames_data()
{
    QTest::addColumn<quint32>("id");
    QTest::addColumn<bool>("extended");
    QTest::addColumn<bool>("remote");
    QTest::addColumn<QByteArray>("payload");
    QTest::addColumn<int>("timestamp");
    QTest::addColumn<QByteArray>("line");

    QTest::newRow("sdo write 6040")
        << 0x632u << false << false << QByteArray::fromHex("2B4060000F000000") << -1
        << QByteArray("t63282B4060000F000000\r");
    QTest::newRow("save") << 0x632u << false << false << QByteArray::fromHex("2310100173617665")
                          << -1 << QByteArray("t63282310100173617665\r");
    QTest::newRow("nmt") << 0x000u << false << false << QByteArray::fromHex("0132") << -1
                         << QByteArray("t00020132\r");
    QTest::newRow("ts") << 0x732u << false << false << QByteArray::fromHex("05") << 0xEA5F
                        << QByteArray("t732105EA5F\r");
    QTest::newRow("ext") << 0x1234567u << true << false << QByteArray::fromHex("00") << -1
                         << QByteArray("T01234567100\r");
    QTest::newRow("rtr") << 0x732u << false << true << QByteArray(1, 0) << -1
                         << QByteArray("r7321\r");
}

void TestSlcanCodec::encodeFrames()
{
    QFETCH(quint32, id);
    QFETCH(bool, extended);
    QFETCH(bool, remote);
    QFETCH(QByteArray, payload);
    QFETCH(int, timestamp);
    QFETCH(QByteArray, line);
    QCanBusFrame frame(id, payload);
    frame.setExtendedFrameFormat(extended);
    if (remote)
        frame.setFrameType(QCanBusFrame::RemoteRequestFrame);
    const auto stamp = timestamp >= 0 ? std::optional<quint16>(quint16(timestamp)) : std::nullopt;
    QCOMPARE(slcan::encodeFrame(frame, stamp), line);
    // Round trip through the decoder.
    slcan::Decoder decoder;
    const auto back = decoder.feed(line);
    QCOMPARE(back.size(), 1);
    QCOMPARE(back.at(0).frame.frameId(), id);
    QCOMPARE(back.at(0).frame.payload(), payload);
}

void TestSlcanCodec::encodeRejectsFd()
{
    QCanBusFrame fd(0x123, QByteArray(12, 'a'));
    fd.setFlexibleDataRateFormat(true);
    QVERIFY(slcan::encodeFrame(fd).isEmpty());
    QCOMPARE(slcan::encodeCommand('S', "4"), QByteArray("S4\r"));
}

// The sender encodes every frame into the same line: a shorter frame after a longer one must not
// keep the longer one's tail, a copy someone kept must stay as it was, and a frame that cannot be
// sent leaves the line empty.
void TestSlcanCodec::encodeIntoReusesItsLine()
{
    QByteArray line;
    QVERIFY(slcan::encodeFrameInto(QCanBusFrame(0x632, QByteArray::fromHex("4041600000000000")),
                                   line, quint16(0x1234)));
    QCOMPARE(line, QByteArray("t632840416000000000001234\r"));
    const QByteArray kept = line;
    QVERIFY(slcan::encodeFrameInto(QCanBusFrame(0x080, QByteArray()), line));
    QCOMPARE(line, QByteArray("t0800\r"));
    QCOMPARE(kept, QByteArray("t632840416000000000001234\r"));
    QCanBusFrame fd(0x123, QByteArray(12, 'a'));
    fd.setFlexibleDataRateFormat(true);
    QVERIFY(!slcan::encodeFrameInto(fd, line));
    QVERIFY(line.isEmpty());
}

void TestSlcanCodec::bitrateCodes()
{
    QCOMPARE(slcan::bitrateCode(125000), std::optional<int>(4));
    QCOMPARE(slcan::bitrateCode(1000000), std::optional<int>(8));
    QCOMPARE(slcan::bitrateCode(10000), std::optional<int>(0));
    QVERIFY(!slcan::bitrateCode(123456));
    QCOMPARE(slcan::bitrateForCode(6), std::optional<int>(500000));
    QVERIFY(!slcan::bitrateForCode(9));
}

QTEST_GUILESS_MAIN(TestSlcanCodec)
#include "tst_slcancodec.moc"
