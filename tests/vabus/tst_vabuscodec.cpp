// VABus/TCP telegrams: every test vector of the protocol specification (T1-T34) byte-exact in
// both directions, the values they carry, and the framer over every split of the stream.
#include "vabus/vabuscodec.h"
#include "vabus/vabusframer.h"

#include <QTest>

using namespace db;
using namespace db::vabus;

namespace {

QByteArray bytes(const char *hexText)
{
    return QByteArray::fromHex(QByteArray(hexText).replace(' ', ""));
}

Telegram tg(bool write, bool error, quint8 sys, quint8 ds, quint16 parameter,
            const QByteArray &data = {})
{
    return Telegram { write, error, sys, ds, parameter, data };
}

struct Vector
{
    const char *name;
    const char *hex;
    Telegram telegram;
    DataType type; // how the data is read (Unsigned8 = no value check)
    QVariant value;
};

QList<Vector> allVectors()
{
    const auto s = [](const char *t) {
        return QByteArray(t);
    };
    const auto u = [](qulonglong v) {
        return QVariant::fromValue(v);
    };
    const auto i = [](qlonglong v) {
        return QVariant::fromValue(v);
    };
    const DataType none = DataType::Unsigned8;
    return {
        { "T1 read 372 DS2", "00 04 00 02 74 01", tg(false, false, 0, 2, 372), none, {} },
        { "T2 372 DS2 = 1390", "00 06 00 02 74 01 6E 05",
          tg(false, false, 0, 2, 372, bytes("6E05")), DataType::Unsigned16, u(1390) },
        { "T3 read 481 DS1", "00 04 00 01 E1 01", tg(false, false, 0, 1, 481), none, {} },
        { "T4 481 DS1 = 1000", "00 08 00 01 E1 01 E8 03 00 00",
          tg(false, false, 0, 1, 481, bytes("E8030000")), DataType::Integer32, i(1000) },
        { "T5 read 12", "00 04 00 00 0C 00", tg(false, false, 0, 0, 12), none, {} },
        { "T6 12 = 5.3.2 STO", "00 0D 00 00 0C 00 35 2E 33 2E 32 20 53 54 4F",
          tg(false, false, 0, 0, 12, s("5.3.2 STO")), DataType::VisibleString,
          QVariant(QStringLiteral("5.3.2 STO")) },
        { "T7 write 376 DS4 = 15", "80 06 00 04 78 01 0F 00",
          tg(true, false, 0, 4, 376, bytes("0F00")), DataType::Unsigned16, u(15) },
        { "T8 echo of T7", "80 06 00 04 78 01 0F 00", tg(true, false, 0, 4, 376, bytes("0F00")),
          DataType::Unsigned16, u(15) },
        { "T9 write 376 DS4 = 0", "80 06 00 04 78 01 00 00",
          tg(true, false, 0, 4, 376, bytes("0000")), DataType::Unsigned16, u(0) },
        { "T10 error 1",
          "C0 06 00 04 78 01 01 00",
          tg(true, true, 0, 4, 376, bytes("0100")),
          none,
          {} },
        { "T11 write 482 DS9 = 4450", "80 08 00 09 E2 01 62 11 00 00",
          tg(true, false, 0, 9, 482, bytes("62110000")), DataType::Integer32, i(4450) },
        { "T12 echo of T11", "80 08 00 09 E2 01 62 11 00 00",
          tg(true, false, 0, 9, 482, bytes("62110000")), DataType::Integer32, i(4450) },
        { "T13 write 482 DS9 = 200000", "80 08 00 09 E2 01 40 0D 03 00",
          tg(true, false, 0, 9, 482, bytes("400D0300")), DataType::Integer32, i(200000) },
        { "T14 error 1",
          "C0 06 00 09 E2 01 01 00",
          tg(true, true, 0, 9, 482, bytes("0100")),
          none,
          {} },
        { "T15 write 17 block definition",
          "80 13 00 00 11 00 30 30 32 31 30 30 30 32 31 31 30 30 32 31 33",
          tg(true, false, 0, 0, 17, s("002100021100213")), DataType::VisibleString,
          QVariant(QStringLiteral("002100021100213")) },
        { "T16 read 19", "00 04 00 00 13 00", tg(false, false, 0, 0, 19), none, {} },
        { "T17 19 = block values",
          "00 14 00 00 13 00 30 30 30 30 32 41 35 44 30 30 36 36 30 30 32 38",
          tg(false, false, 0, 0, 19, s("00002A5D00660028")), DataType::VisibleString,
          QVariant(QStringLiteral("00002A5D00660028")) },
        { "T18 write 17 = 0048100482", "80 0E 00 00 11 00 30 30 34 38 31 30 30 34 38 32",
          tg(true, false, 0, 0, 17, s("0048100482")), DataType::VisibleString,
          QVariant(QStringLiteral("0048100482")) },
        { "T19 write 18 block values",
          "80 14 00 00 12 00 30 30 30 30 33 30 33 45 30 30 30 30 31 30 46 39",
          tg(true, false, 0, 0, 18, s("0000303E000010F9")), DataType::VisibleString,
          QVariant(QStringLiteral("0000303E000010F9")) },
        { "T20 write 1200 = 34", "80 06 00 00 B0 04 22 00",
          tg(true, false, 0, 0, 1200, bytes("2200")), DataType::Unsigned16, u(34) },
        { "T21 write 1202 = 30000", "80 08 00 00 B2 04 30 75 00 00",
          tg(true, false, 0, 0, 1202, bytes("30750000")), DataType::Integer32, i(30000) },
        { "T22 write 1201 = 1", "80 06 00 00 B1 04 01 00",
          tg(true, false, 0, 0, 1201, bytes("0100")), DataType::Unsigned16, u(1) },
        { "T23 read 1202", "00 04 00 00 B2 04", tg(false, false, 0, 0, 1202), none, {} },
        { "T24 1202 = 123000", "00 08 00 00 B2 04 78 E0 01 00",
          tg(false, false, 0, 0, 1202, bytes("78E00100")), DataType::Integer32, i(123000) },
        { "T25 write 410 DS5 = 0x000F", "80 06 00 05 9A 01 0F 00",
          tg(true, false, 0, 5, 410, bytes("0F00")), DataType::Unsigned16, u(0x000F) },
        { "T26a read 411", "00 04 00 00 9B 01", tg(false, false, 0, 0, 411), none, {} },
        { "T26b 411 = 0x0237", "00 06 00 00 9B 01 37 02",
          tg(false, false, 0, 0, 411, bytes("3702")), DataType::Unsigned16, u(0x0237) },
        { "T27 write 1459 DS5 = -100", "80 06 00 05 B3 05 9C FF",
          tg(true, false, 0, 5, 1459, bytes("9CFF")), DataType::Integer16, i(-100) },
        { "T28 write 1455 DS5 = 30000", "80 08 00 05 AF 05 30 75 00 00",
          tg(true, false, 0, 5, 1455, bytes("30750000")), DataType::Integer32, i(30000) },
        { "T29 error 11",
          "40 06 00 00 3F 06 0B 00",
          tg(false, true, 0, 0, 1599, bytes("0B00")),
          none,
          {} },
        { "T30a write 2 bytes to 482", "80 06 00 09 E2 01 62 11",
          tg(true, false, 0, 9, 482, bytes("6211")), DataType::Unsigned16, u(4450) },
        { "T30b error 14",
          "C0 06 00 09 E2 01 0E 00",
          tg(true, true, 0, 9, 482, bytes("0E00")),
          none,
          {} },
        { "T31 error 4",
          "C0 06 00 00 9B 01 04 00",
          tg(true, true, 0, 0, 411, bytes("0400")),
          none,
          {} },
        { "T32a read 260", "00 04 00 00 04 01", tg(false, false, 0, 0, 260), none, {} },
        { "T32b 260 = F2714", "00 06 00 00 04 01 14 27", tg(false, false, 0, 0, 260, bytes("1427")),
          DataType::Unsigned16, u(0x2714) },
        { "T33a read 12 on node 7", "00 04 47 00 0C 00", tg(false, false, 0x47, 0, 12), none, {} },
        { "T33b error 20",
          "40 06 47 00 0C 00 14 00",
          tg(false, true, 0x47, 0, 12, bytes("1400")),
          none,
          {} },
        { "T34 write 1437 = 0", "80 06 00 00 9D 05 00 00",
          tg(true, false, 0, 0, 1437, bytes("0000")), DataType::Unsigned16, u(0) },
    };
}

QByteArray allVectorBytes()
{
    QByteArray all;
    for (const Vector &v : allVectors())
        all += bytes(v.hex);
    return all;
}

} // namespace

class TstVabusCodec : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void vectors_data()
    {
        QTest::addColumn<QByteArray>("wire");
        QTest::addColumn<int>("index");
        const QList<Vector> all = allVectors();
        for (int i = 0; i < all.size(); ++i)
            QTest::newRow(all.at(i).name) << bytes(all.at(i).hex) << i;
    }
    void vectors()
    {
        QFETCH(QByteArray, wire);
        QFETCH(int, index);
        const Vector v = allVectors().at(index);
        const auto decoded = decode(wire);
        QVERIFY2(decoded.ok(), qPrintable(decoded.error().message()));
        QCOMPARE(decoded.value(), v.telegram);
        const auto encoded = encode(v.telegram);
        QVERIFY(encoded.ok());
        QCOMPARE(encoded.value().toHex(' '), wire.toHex(' '));
        if (v.value.isValid()) {
            const auto value = decodeValue(v.type, v.telegram.data);
            QVERIFY2(value.ok(), qPrintable(value.error().message()));
            QCOMPARE(value.value(), v.value);
            const auto data = encodeValue(v.type, v.value);
            QVERIFY(data.ok());
            QCOMPARE(data.value(), v.telegram.data);
        }
    }

    void builders()
    {
        QCOMPARE(encode(Telegram::readRequest(372, 2)).value(), bytes("00 04 00 02 74 01"));
        QCOMPARE(encode(Telegram::writeRequest(376, 4, bytes("0F00"))).value(),
                 bytes("80 06 00 04 78 01 0F 00"));
        const Telegram t9 = Telegram::writeRequest(376, 4, bytes("0000"));
        QCOMPARE(encode(Telegram::errorAnswer(t9, InvalidValue)).value(),
                 bytes("C0 06 00 04 78 01 01 00"));
        QCOMPARE(encode(Telegram::errorAnswer(Telegram::readRequest(12, 0, 0x47), NodeNotAvailable))
                     .value(),
                 bytes("40 06 47 00 0C 00 14 00"));
        QCOMPARE(decode(bytes("C0 06 00 09 E2 01 01 00")).value().errorCode(), quint16(1));
    }

    // An empty string is a select telegram without data bytes (NoB = 4 + 0), distinct from an
    // enquiry by its R/W bit; its echo is the same frame.
    void emptyStringIsASelectWithoutData()
    {
        const auto data = encodeValue(DataType::VisibleString, QString());
        QVERIFY2(data.ok(), qPrintable(data.error().message()));
        QVERIFY(data.value().isEmpty());
        QCOMPARE(encode(Telegram::writeRequest(29, 0, data.value())).value(),
                 bytes("80 04 00 00 1D 00"));
        const auto echo = decode(bytes("80 04 00 00 1D 00"));
        QVERIFY(echo.ok());
        QVERIFY(echo.value().write && echo.value().data.isEmpty());
        QCOMPARE(decodeValue(DataType::VisibleString, {}).value(), QVariant(QString()));
    }

    void errorTexts()
    {
        QCOMPARE(errorText(1), QStringLiteral("invalid parameter value"));
        QCOMPARE(errorText(11), QStringLiteral("unknown parameter"));
        QCOMPARE(errorText(13), errorText(30));
        QCOMPARE(errorText(20), QStringLiteral("selected system bus node not available"));
        QVERIFY(errorText(77).contains(QLatin1String("77")));
        for (quint16 code = 0; code <= 30; ++code)
            QVERIFY(!errorText(code).isEmpty());
    }

    void rejectsBrokenTelegrams_data()
    {
        QTest::addColumn<QByteArray>("wire");
        QTest::newRow("short") << bytes("00 04 00 02 74");
        QTest::newRow("NoB too large") << bytes("00 06 00 02 74 01 6E");
        QTest::newRow("NoB too small") << bytes("00 04 00 02 74 01 6E 05");
        QTest::newRow("header bits 5..0") << bytes("01 04 00 02 74 01");
        QTest::newRow("error answer with NoB 8") << bytes("C0 08 00 09 E2 01 01 00 00 00");
    }
    void rejectsBrokenTelegrams()
    {
        QFETCH(QByteArray, wire);
        const auto decoded = decode(wire);
        QVERIFY(!decoded.ok());
        QCOMPARE(decoded.error().kind(), Error::Kind::Malformed);
    }

    void refusesWhatCannotBeSent()
    {
        QVERIFY(!encode(Telegram::writeRequest(12, 0, QByteArray(100, 'x'))).ok());
        QVERIFY(encode(Telegram::writeRequest(12, 0, QByteArray(99, 'x'))).ok());
        QVERIFY(!encode(Telegram::readRequest(1600, 0)).ok());
        QVERIFY(!encodeValue(DataType::Unsigned16, QVariant::fromValue<qlonglong>(70000)).ok());
        QVERIFY(!encodeValue(DataType::Integer16, QVariant::fromValue<qlonglong>(32768)).ok());
        QVERIFY(!encodeValue(DataType::Real32, 1.5).ok());
        QVERIFY(!encodeValue(DataType::VisibleString, QString(100, QLatin1Char('x'))).ok());
        QCOMPARE(decodeValue(DataType::Integer32, bytes("6211")).error().kind(),
                 Error::Kind::Malformed);
        QCOMPARE(typeForSize(2), DataType::Integer16);
        QCOMPARE(typeForSize(4), DataType::Integer32);
        QCOMPARE(typeForSize(9), DataType::VisibleString);
    }

    // The framer finds every vector's telegram wherever TCP splits the stream.
    void framerSplitsAnywhere()
    {
        const QByteArray all = allVectorBytes();
        const QList<Vector> expected = allVectors();
        for (int chunk = 1; chunk <= 23; ++chunk) {
            Framer framer;
            QList<Telegram> got;
            for (int i = 0; i < all.size(); i += chunk) {
                for (const auto &frame : framer.feed(all.mid(i, chunk))) {
                    QVERIFY(frame.ok());
                    QCOMPARE(frame.value().kind, Frame::Kind::Telegram);
                    got.append(frame.value().telegram);
                }
            }
            QCOMPARE(got.size(), expected.size());
            for (int i = 0; i < got.size(); ++i)
                QCOMPARE(got.at(i), expected.at(i).telegram);
            QCOMPARE(framer.bufferedBytes(), 0);
        }
    }

    void framerHoldsPartialTelegram()
    {
        Framer framer;
        QVERIFY(framer.feed(bytes("00 08 00 01 E1 01 E8")).empty());
        QCOMPARE(framer.bufferedBytes(), 7);
        framer.reset();
        QCOMPARE(framer.bufferedBytes(), 0);
        const auto frames = framer.feed(bytes("00 06 00 02 74 01 6E 05"));
        QCOMPARE(frames.size(), size_t(1));
        QCOMPARE(frames.front().value().telegram.parameter, quint16(372));
    }

    void framerReportsNakAndGarbage()
    {
        Framer framer;
        auto frames = framer.feed(bytes("15 00 06 00 02 74 01 6E 05"));
        QCOMPARE(frames.size(), size_t(2));
        QCOMPARE(frames.at(0).value().kind, Frame::Kind::Nak);
        QCOMPARE(frames.at(1).value().kind, Frame::Kind::Telegram);

        frames = framer.feed("hello\r\n");
        QCOMPARE(frames.size(), size_t(1));
        QCOMPARE(frames.at(0).value().kind, Frame::Kind::Garbage);
        QCOMPARE(framer.bufferedBytes(), 0);

        frames = framer.feed(bytes("00 02 00"));
        QCOMPARE(frames.size(), size_t(1));
        QCOMPARE(frames.at(0).value().kind, Frame::Kind::Garbage);
        QVERIFY(frames.at(0).value().problem.contains(QLatin1String("NoB 2")));

        frames = framer.feed(bytes("00 FF"));
        QCOMPARE(frames.at(0).value().kind, Frame::Kind::Garbage);

        frames = framer.feed(bytes("C0 08 00 09 E2 01 01 00 00 00"));
        QCOMPARE(frames.at(0).value().kind, Frame::Kind::Garbage);
        // After garbage the framer starts afresh.
        frames = framer.feed(bytes("00 06 00 02 74 01 6E 05"));
        QCOMPARE(frames.at(0).value().kind, Frame::Kind::Telegram);
    }
};

QTEST_GUILESS_MAIN(TstVabusCodec)
#include "tst_vabuscodec.moc"
