// NM17x process data: the RxPDO1/RxPDO2/TxPDO codecs and the control words the displays accept.
#include "devices/nm17x/nm17xpdo.h"

#include <QTest>

using namespace db;
using namespace db::nm17x;

Q_DECLARE_METATYPE(db::nm17x::Command)

class TstNm17xPdo : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void broadcastFrames_data();
    void broadcastFrames();
    void broadcastObjects();
    void positionCommandRoundTrip();
    void tpdoDecoders();
    void shortPayloadsAreMalformed();
    void allowedWords_data();
    void allowedWords();
    void forbiddenWords_data();
    void forbiddenWords();
    void builder_data();
    void builder();
    void builderRefusesWrongSpeed();
};

void TstNm17xPdo::broadcastFrames_data()
{
    QTest::addColumn<quint16>("index");
    QTest::addColumn<quint8>("sub");
    QTest::addColumn<quint32>("data");
    QTest::addColumn<QByteArray>("frame");
    QTest::newRow("inch") << quint16(0x2001) << quint8(0) << 1u
                          << QByteArray::fromHex("0001200001000000");
    QTest::newRow("start group 1")
        << quint16(0x204D) << quint8(1) << 1u << QByteArray::fromHex("004D200101000000");
    QTest::newRow("stop all") << quint16(0x204D) << quint8(1) << 0u
                              << QByteArray::fromHex("004D200100000000");
    QTest::newRow("preset 0") << quint16(0x6003) << quint8(0) << 0u
                              << QByteArray::fromHex("0003600000000000");
    QTest::newRow("show id") << quint16(0x2008) << quint8(0) << 1u
                             << QByteArray::fromHex("0008200001000000");
}

void TstNm17xPdo::broadcastFrames()
{
    QFETCH(quint16, index);
    QFETCH(quint8, sub);
    QFETCH(quint32, data);
    QFETCH(QByteArray, frame);
    const Broadcast b { 0, index, sub, data };
    QCOMPARE(encodeBroadcast(b), frame);
    QCOMPARE(decodeBroadcast(frame).value(), b);
    QVERIFY(isBroadcastObject(index, sub));
}

void TstNm17xPdo::broadcastObjects()
{
    QVERIFY(!isBroadcastObject(0x2020, 1));
    QVERIFY(!isBroadcastObject(0x204D, 3)); // Tippen is not broadcast
    QVERIFY(!isBroadcastObject(0x2001, 1));
}

void TstNm17xPdo::positionCommandRoundTrip()
{
    // 262.50 mm, correction -62.50 mm, standard setpoint with release
    const PositionCommand c { 26250, -6250, 0x0003 };
    const QByteArray frame = encodePositionCommand(c);
    QCOMPARE(frame, QByteArray::fromHex("8A66000096E70300"));
    QCOMPARE(decodePositionCommand(frame).value(), c);
    const PositionCommand keep { -99999, kKeepCorrection, 0x4000 };
    QCOMPARE(decodePositionCommand(encodePositionCommand(keep)).value(), keep);
}

void TstNm17xPdo::tpdoDecoders()
{
    // position 500000 (5000.00 mm), status Moving + In Position, errors Er 8
    const auto t1 = decodeTpdo1(QByteArray::fromHex("20A1070001800001"));
    QVERIFY(t1);
    QCOMPARE(t1->position, 500000);
    QCOMPARE(t1->status, quint16(0x8001));
    QCOMPARE(t1->errors, quint16(0x0100));
    const auto t2 = decodeTpdo2(QByteArray::fromHex("FFFFFFFF0080"
                                                    "0040"));
    QVERIFY(t2);
    QCOMPARE(t2->position, -1);
    QCOMPARE(t2->correction, qint16(-32768));
    QCOMPARE(t2->status, quint16(0x4000));
    QCOMPARE(encodeTpdo2(t2.value()), QByteArray::fromHex("FFFFFFFF00800040"));
}

void TstNm17xPdo::shortPayloadsAreMalformed()
{
    const QByteArray seven = QByteArray::fromHex("00000000000000");
    QCOMPARE(decodeTpdo1(seven).error().kind(), Error::Kind::Malformed);
    QCOMPARE(decodeTpdo2(seven).error().kind(), Error::Kind::Malformed);
    QCOMPARE(decodeBroadcast(seven).error().kind(), Error::Kind::Malformed);
    QCOMPARE(decodePositionCommand(seven).error().kind(), Error::Kind::Malformed);
}

void TstNm17xPdo::allowedWords_data()
{
    QTest::addColumn<quint16>("word");
    QTest::addColumn<Command>("command");
    QTest::addColumn<int>("speed"); // 0 = none
    // The 22 combinations with every "X" bit 0 ...
    QTest::newRow("0 none") << quint16(0x0000) << Command::None << 0;
    QTest::newRow("1 D3") << quint16(0x0021) << Command::WriteD3 << 0;
    QTest::newRow("2 reserved") << quint16(0x0041) << Command::Reserved << 0;
    QTest::newRow("3 reserved") << quint16(0x0061) << Command::Reserved << 0;
    QTest::newRow("4 SEF") << quint16(0x0007) << Command::SetpointDirect << 0;
    QTest::newRow("5 S") << quint16(0x0001) << Command::Setpoint << 0;
    QTest::newRow("6 SF") << quint16(0x0003) << Command::SetpointRelease << 0;
    QTest::newRow("7 SL slow") << quint16(0x0009) << Command::Einsaegen << 1;
    QTest::newRow("8 SL medium") << quint16(0x0011) << Command::Einsaegen << 2;
    QTest::newRow("9 SL fast") << quint16(0x0019) << Command::Einsaegen << 3;
    QTest::newRow("10 SLF slow") << quint16(0x000B) << Command::EinsaegenRelease << 1;
    QTest::newRow("11 SLF medium") << quint16(0x0013) << Command::EinsaegenRelease << 2;
    QTest::newRow("12 SLF fast") << quint16(0x001B) << Command::EinsaegenRelease << 3;
    QTest::newRow("13 right slow") << quint16(0x0089) << Command::JogRight << 1;
    QTest::newRow("14 right medium") << quint16(0x0091) << Command::JogRight << 2;
    QTest::newRow("15 right fast") << quint16(0x0099) << Command::JogRight << 3;
    QTest::newRow("16 left slow") << quint16(0x0109) << Command::JogLeft << 1;
    QTest::newRow("17 left medium") << quint16(0x0111) << Command::JogLeft << 2;
    QTest::newRow("18 left fast") << quint16(0x0119) << Command::JogLeft << 3;
    QTest::newRow("19 clamp open") << quint16(0x0201) << Command::ClampOpen << 0;
    QTest::newRow("20 clamp close") << quint16(0x0203) << Command::ClampClose << 0;
    QTest::newRow("21 stop") << quint16(0x4000) << Command::Stop << 0;
    // ... and with "X" bits set: the toggle bit, bits 10..13, the free bits of rows 1, 4, 21.
    QTest::newRow("toggle only") << quint16(0x8000) << Command::None << 0;
    QTest::newRow("SF toggled") << quint16(0x8003) << Command::SetpointRelease << 0;
    QTest::newRow("SF bits 10-13") << quint16(0x3C03) << Command::SetpointRelease << 0;
    QTest::newRow("D3 free bits") << quint16(0x003F) << Command::WriteD3 << 0;
    QTest::newRow("SEF with speed bits") << quint16(0x001F) << Command::SetpointDirect << 0;
    QTest::newRow("stop with anything") << quint16(0xFFFF) << Command::Stop << 0;
}

void TstNm17xPdo::allowedWords()
{
    QFETCH(quint16, word);
    QFETCH(Command, command);
    QFETCH(int, speed);
    const auto c = classify(word);
    QVERIFY2(c, qPrintable(c ? QString() : c.error().message()));
    QCOMPARE(c->command, command);
    QCOMPARE(c->speed ? int(*c->speed) : 0, speed);
}

void TstNm17xPdo::forbiddenWords_data()
{
    QTest::addColumn<quint16>("word");
    QTest::newRow("no loop without release") << quint16(0x0005);
    QTest::newRow("release without enable") << quint16(0x0002);
    QTest::newRow("jog without speed") << quint16(0x0081);
    QTest::newRow("jog left without speed") << quint16(0x0101);
    QTest::newRow("both jog directions") << quint16(0x0189);
    QTest::newRow("clamp with speed") << quint16(0x0209);
    QTest::newRow("clamp without enable") << quint16(0x0200);
    QTest::newRow("jog with release") << quint16(0x008B);
    QTest::newRow("jog and D3") << quint16(0x00A9);
    QTest::newRow("setpoint and clamp and jog") << quint16(0x0289);
    QTest::newRow("speed without enable") << quint16(0x0018);
}

void TstNm17xPdo::forbiddenWords()
{
    QFETCH(quint16, word);
    const auto c = classify(word);
    QVERIFY(!c);
    QCOMPARE(c.error().kind(), Error::Kind::InvalidArgument);
    QVERIFY(
        c.error().message().contains(QStringLiteral("0x%1").arg(word, 4, 16, QLatin1Char('0'))));
    QVERIFY(c.error().message().contains(QLatin1String("8230")));
}

void TstNm17xPdo::builder_data()
{
    QTest::addColumn<Command>("command");
    QTest::addColumn<int>("speed");
    QTest::addColumn<quint16>("word");
    QTest::newRow("setpoint") << Command::Setpoint << 0 << quint16(0x0001);
    QTest::newRow("release") << Command::SetpointRelease << 0 << quint16(0x0003);
    QTest::newRow("direct") << Command::SetpointDirect << 0 << quint16(0x0007);
    QTest::newRow("D3") << Command::WriteD3 << 0 << quint16(0x0021);
    QTest::newRow("Einsaegen fast") << Command::Einsaegen << 3 << quint16(0x0019);
    QTest::newRow("Einsaegen release slow") << Command::EinsaegenRelease << 1 << quint16(0x000B);
    QTest::newRow("right medium") << Command::JogRight << 2 << quint16(0x0091);
    QTest::newRow("left fast") << Command::JogLeft << 3 << quint16(0x0119);
    QTest::newRow("clamp open") << Command::ClampOpen << 0 << quint16(0x0201);
    QTest::newRow("clamp close") << Command::ClampClose << 0 << quint16(0x0203);
    QTest::newRow("stop") << Command::Stop << 0 << quint16(0x4000);
}

void TstNm17xPdo::builder()
{
    QFETCH(Command, command);
    QFETCH(int, speed);
    QFETCH(quint16, word);
    const auto built = controlWord(command, speed ? std::optional(Speed(speed)) : std::nullopt);
    QVERIFY(built);
    QCOMPARE(built.value(), word);
    // Whatever the builder makes, the device takes as the same command.
    QCOMPARE(classify(built.value())->command, command);
}

void TstNm17xPdo::builderRefusesWrongSpeed()
{
    const auto noSpeed = controlWord(Command::JogLeft);
    QVERIFY(!noSpeed);
    QVERIFY(noSpeed.error().message().contains(QLatin1String("needs a speed")));
    const auto extraSpeed = controlWord(Command::Setpoint, Speed::Fast);
    QVERIFY(!extraSpeed);
    QVERIFY(extraSpeed.error().message().contains(QLatin1String("takes no speed")));
    QVERIFY(!controlWord(Command::Reserved));
    QCOMPARE(parseSpeed(QStringLiteral("Medium")), std::optional(Speed::Medium));
    QVERIFY(!parseSpeed(QStringLiteral("turbo")));
}

QTEST_GUILESS_MAIN(TstNm17xPdo)
#include "tst_nm17xpdo.moc"
