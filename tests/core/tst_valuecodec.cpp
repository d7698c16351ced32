// Level 1: the value codec for every CiA 301 basic type (bytes <-> raw <-> text <-> physical).
#include "core/valuecodec.h"

#include <QTest>

using namespace db;

Q_DECLARE_METATYPE(db::Error::Kind)

class TestValueCodec : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void roundTrip_data();
    void roundTrip();
    void decodeRejectsWrongSize_data();
    void decodeRejectsWrongSize();
    void textRejectsBadInput_data();
    void textRejectsBadInput();
    void hexText_data();
    void hexText();
    void typeLimits();
    void limitsOfTheObject();
    void physicalScaling();
    void visibleStringStopsAtNul();
    void unicodeStringIsUcs2LittleEndian();
    void everyTypeHasAName();
};

void TestValueCodec::roundTrip_data()
{
    QTest::addColumn<DataType>("type");
    QTest::addColumn<QString>("text");
    QTest::addColumn<QByteArray>("bytes");
    QTest::addColumn<QString>("canonical"); // toText() of the decoded value

    auto row = [](const char *name, DataType t, const char *text, const char *hex,
                  const char *canonical) {
        QTest::newRow(name) << t << QString::fromUtf8(text) << QByteArray::fromHex(hex)
                            << QString::fromUtf8(canonical);
    };
    row("bool true", DataType::Boolean, "true", "01", "1");
    row("bool 0", DataType::Boolean, "0", "00", "0");
    row("i8 min", DataType::Integer8, "-128", "80", "-128");
    row("i8 max", DataType::Integer8, "127", "7f", "127");
    row("i8 hex bit pattern", DataType::Integer8, "0x80", "80", "-128");
    row("i16 -2", DataType::Integer16, "-2", "feff", "-2");
    row("i24 min", DataType::Integer24, "-8388608", "000080", "-8388608");
    row("i24 max", DataType::Integer24, "8388607", "ffff7f", "8388607");
    row("i32 -7200", DataType::Integer32, "-7200", "e0e3ffff", "-7200");
    row("i40 min", DataType::Integer40, "-549755813888", "0000000080", "-549755813888");
    row("i48 -1", DataType::Integer48, "-1", "ffffffffffff", "-1");
    row("i56 max", DataType::Integer56, "36028797018963967", "ffffffffffff7f", "36028797018963967");
    row("i64 min", DataType::Integer64, "-9223372036854775808", "0000000000000080",
        "-9223372036854775808");
    row("i64 max", DataType::Integer64, "9223372036854775807", "ffffffffffffff7f",
        "9223372036854775807");
    row("u8 hex", DataType::Unsigned8, "0xff", "ff", "255");
    row("u16 statusword", DataType::Unsigned16, "0x0427", "2704", "1063");
    row("u16 h suffix", DataType::Unsigned16, "427h", "2704", "1063");
    row("u24 max", DataType::Unsigned24, "16777215", "ffffff", "16777215");
    row("u32 save", DataType::Unsigned32, "1702257011", "73617665", "1702257011");
    row("u32 binary", DataType::Unsigned32, "0b101", "05000000", "5");
    row("u40 max", DataType::Unsigned40, "0xFFFFFFFFFF", "ffffffffff", "1099511627775");
    row("u48", DataType::Unsigned48, "1", "010000000000", "1");
    row("u56 max", DataType::Unsigned56, "72057594037927935", "ffffffffffffff",
        "72057594037927935");
    row("u64 max", DataType::Unsigned64, "18446744073709551615", "ffffffffffffffff",
        "18446744073709551615");
    row("real32", DataType::Real32, "1.5", "0000c03f", "1.5");
    row("real32 negative", DataType::Real32, "-2e3", "0000fac4", "-2000");
    row("real64", DataType::Real64, "0.1", "9a9999999999b93f", "0.10000000000000001");
    row("real32 negative zero", DataType::Real32, "-0", "00000080", "-0");
    row("real64 negative zero", DataType::Real64, "-0.0", "0000000000000080", "-0");
    row("visible string", DataType::VisibleString, "MovingCap ETH", "4d6f76696e6743617020455448",
        "MovingCap ETH");
    row("empty string", DataType::VisibleString, "", "", "");
    row("octet string", DataType::OctetString, "01 02 ff", "0102ff", "01 02 FF");
    row("domain", DataType::Domain, "0xDEADBEEF", "deadbeef", "DE AD BE EF");
    row("unicode", DataType::UnicodeString, "Ä1", "c4003100", "Ä1");
}

void TestValueCodec::roundTrip()
{
    QFETCH(DataType, type);
    QFETCH(QString, text);
    QFETCH(QByteArray, bytes);
    QFETCH(QString, canonical);

    const auto raw = codec::fromText(type, text);
    QVERIFY2(raw.ok(), qPrintable(raw.error().toString()));
    const auto encoded = codec::encode(type, raw.value());
    QVERIFY2(encoded.ok(), qPrintable(encoded.error().toString()));
    QCOMPARE(encoded.value().toHex(), bytes.toHex());
    const auto decoded = codec::decode(type, bytes);
    QVERIFY2(decoded.ok(), qPrintable(decoded.error().toString()));
    QCOMPARE(codec::toText(type, decoded.value()), canonical);
    QCOMPARE(decoded.value(), raw.value());
}

void TestValueCodec::decodeRejectsWrongSize_data()
{
    QTest::addColumn<DataType>("type");
    QTest::addColumn<QByteArray>("bytes");
    QTest::newRow("u16 from 1 byte") << DataType::Unsigned16 << QByteArray(1, '\0');
    QTest::newRow("i32 from 5 bytes") << DataType::Integer32 << QByteArray(5, '\0');
    QTest::newRow("i24 from 4 bytes") << DataType::Integer24 << QByteArray(4, '\0');
    QTest::newRow("bool byte 2") << DataType::Boolean << QByteArray(1, '\2');
    QTest::newRow("unicode odd length") << DataType::UnicodeString << QByteArray(3, 'a');
}

void TestValueCodec::decodeRejectsWrongSize()
{
    QFETCH(DataType, type);
    QFETCH(QByteArray, bytes);
    const auto decoded = codec::decode(type, bytes);
    QVERIFY(!decoded.ok());
    QCOMPARE(decoded.error().kind(), Error::Kind::Malformed);
}

void TestValueCodec::textRejectsBadInput_data()
{
    QTest::addColumn<DataType>("type");
    QTest::addColumn<QString>("text");
    QTest::addColumn<Error::Kind>("kind");
    QTest::newRow("u8 256") << DataType::Unsigned8 << "256" << Error::Kind::OutOfRange;
    QTest::newRow("u16 negative") << DataType::Unsigned16 << "-1" << Error::Kind::OutOfRange;
    QTest::newRow("i8 -129") << DataType::Integer8 << "-129" << Error::Kind::OutOfRange;
    QTest::newRow("i24 overflow") << DataType::Integer24 << "8388608" << Error::Kind::OutOfRange;
    QTest::newRow("i64 overflow") << DataType::Integer64 << "9223372036854775808"
                                  << Error::Kind::OutOfRange;
    QTest::newRow("u64 overflow") << DataType::Unsigned64 << "18446744073709551616"
                                  << Error::Kind::InvalidArgument;
    QTest::newRow("i16 hex too wide")
        << DataType::Integer16 << "0x10000" << Error::Kind::OutOfRange;
    QTest::newRow("letters") << DataType::Integer32 << "12ab" << Error::Kind::InvalidArgument;
    QTest::newRow("empty integer") << DataType::Integer32 << "" << Error::Kind::InvalidArgument;
    QTest::newRow("bool 2") << DataType::Boolean << "2" << Error::Kind::InvalidArgument;
    QTest::newRow("real words") << DataType::Real32 << "fast" << Error::Kind::InvalidArgument;
    QTest::newRow("real32 overflow") << DataType::Real32 << "1e39" << Error::Kind::OutOfRange;
    QTest::newRow("odd hex bytes")
        << DataType::OctetString << "0102f" << Error::Kind::InvalidArgument;
    QTest::newRow("non-hex bytes") << DataType::Domain << "zz" << Error::Kind::InvalidArgument;
    QTest::newRow("non-ascii visible string")
        << DataType::VisibleString << "Grüße" << Error::Kind::InvalidArgument;
}

void TestValueCodec::textRejectsBadInput()
{
    QFETCH(DataType, type);
    QFETCH(QString, text);
    QFETCH(Error::Kind, kind);
    const auto raw = codec::fromText(type, text);
    QVERIFY(!raw.ok());
    QCOMPARE(raw.error().kind(), kind);
    QVERIFY(!raw.error().message().isEmpty());
}

void TestValueCodec::hexText_data()
{
    QTest::addColumn<DataType>("type");
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("hex");
    QTest::newRow("statusword") << DataType::Unsigned16 << "1063"
                                << "0x0427";
    QTest::newRow("negative i16") << DataType::Integer16 << "-1"
                                  << "0xFFFF";
    QTest::newRow("i24") << DataType::Integer24 << "-2"
                         << "0xFFFFFE";
    QTest::newRow("u32 inputs") << DataType::Unsigned32 << "327680"
                                << "0x00050000";
}

void TestValueCodec::hexText()
{
    QFETCH(DataType, type);
    QFETCH(QString, text);
    QFETCH(QString, hex);
    const auto raw = codec::fromText(type, text);
    QVERIFY(raw.ok());
    QCOMPARE(codec::toText(type, raw.value(), codec::TextFormat::Hex), hex);
    QCOMPARE(codec::fromText(type, hex).value(), raw.value());
}

void TestValueCodec::typeLimits()
{
    QCOMPARE(codec::typeMinimum(DataType::Integer24).toLongLong(), -8388608LL);
    QCOMPARE(codec::typeMaximum(DataType::Unsigned40).toULongLong(), 0xFFFFFFFFFFULL);
    QCOMPARE(codec::typeMaximum(DataType::Unsigned64).toULongLong(), ~0ULL);
    QVERIFY(!codec::typeMaximum(DataType::VisibleString).isValid());
    // normalize converts between QVariant types and refuses what does not fit
    QCOMPARE(codec::normalize(DataType::Unsigned16, 42).value(), QVariant::fromValue(42ULL));
    QVERIFY(!codec::normalize(DataType::Unsigned16, -1).ok());
    QVERIFY(!codec::normalize(DataType::Integer8, 1.5).ok());
    QCOMPARE(codec::normalize(DataType::Integer8, 3.0).value(), QVariant::fromValue(3LL));
    QVERIFY(!codec::normalize(DataType::Integer64, QVariant::fromValue(~0ULL)).ok());
}

void TestValueCodec::limitsOfTheObject()
{
    const QVariant min = QVariant::fromValue(1ULL);
    const QVariant max = QVariant::fromValue(20000ULL);
    QVERIFY(codec::checkLimits(DataType::Unsigned32, QVariant::fromValue(1000ULL), min, max).ok());
    const auto low = codec::checkLimits(DataType::Unsigned32, QVariant::fromValue(0ULL), min, max);
    QCOMPARE(low.error().kind(), Error::Kind::OutOfRange);
    QVERIFY(low.error().message().contains(QLatin1String("1 .. 20000")));
    QVERIFY(!codec::checkLimits(DataType::Integer16, QVariant::fromValue(181LL),
                                QVariant::fromValue(-180LL), QVariant::fromValue(180LL))
                 .ok());
    QVERIFY(codec::checkLimits(DataType::Integer16, QVariant::fromValue(5LL), {}, {}).ok());
}

void TestValueCodec::physicalScaling()
{
    // 6078h current: 0.1 % of rated per digit
    QCOMPARE(codec::toPhysical(QVariant::fromValue(902LL), 0.1, 0.0), 90.2);
    const auto raw = codec::fromPhysical(DataType::Integer16, -10.3, 0.1, 0.0);
    QVERIFY(raw.ok());
    QCOMPARE(raw.value().toLongLong(), -103LL);
    QCOMPARE(codec::fromPhysical(DataType::Integer8, 20.0, 0.1, 0.0).error().kind(),
             Error::Kind::OutOfRange);
    QCOMPARE(codec::fromPhysical(DataType::Unsigned8, 1.0, 0.0, 0.0).error().kind(),
             Error::Kind::InvalidArgument);
    QCOMPARE(codec::fromPhysical(DataType::Real32, 25.0, 0.5, 5.0).value().toDouble(), 40.0);
}

void TestValueCodec::visibleStringStopsAtNul()
{
    const auto decoded = codec::decode(DataType::VisibleString, QByteArray("MC349\0junk", 10));
    QCOMPARE(decoded.value().toString(), QStringLiteral("MC349"));
}

void TestValueCodec::unicodeStringIsUcs2LittleEndian()
{
    const auto bytes = codec::encode(DataType::UnicodeString, QStringLiteral("µ"));
    QCOMPARE(bytes.value(), QByteArray::fromHex("b500"));
}

void TestValueCodec::everyTypeHasAName()
{
    for (DataType t : datatype::all()) {
        const QString name = datatype::name(t);
        QVERIFY(name != QLatin1String("UNKNOWN"));
        QCOMPARE(datatype::fromName(name), std::optional<DataType>(t));
        QCOMPARE(datatype::fromCode(static_cast<quint32>(t)), std::optional<DataType>(t));
    }
    QCOMPARE(datatype::fromName(QStringLiteral("uint16")), std::optional(DataType::Unsigned16));
    QCOMPARE(datatype::fromName(QStringLiteral("0x0007")), std::optional(DataType::Unsigned32));
    QVERIFY(!datatype::fromName(QStringLiteral("quaternion")));
    QCOMPARE(datatype::all().size(), 23);
}

QTEST_GUILESS_MAIN(TestValueCodec)
#include "tst_valuecodec.moc"
