// Level 1: block definitions (parameter 17) and block answers (parameter 19) with the
// specification's block vectors (T15, T17, T18) and their limits.

#include "vabus/vabusblock.h"

#include <QtTest>

using namespace db;
using namespace db::vabus;

class TstVabusBlock : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void definitionOfTheExample()
    {
        // T15: 210 (Long), 211 and 213 (Int), data set 0.
        const QList<BlockItem> items = { { { 210, 0 }, DataType::Integer32 },
                                         { { 211, 0 }, DataType::Integer16 },
                                         { { 213, 0 }, DataType::Integer16 } };
        const auto text = blockDefinition(items);
        QVERIFY2(text.ok(), qPrintable(text.error().toString()));
        QCOMPARE(text.value(), QByteArray("002100021100213"));
        // T18: 481 and 482.
        const auto second = blockDefinition(
            { { { 481, 0 }, DataType::Integer32 }, { { 482, 0 }, DataType::Integer32 } });
        QCOMPARE(second.value(), QByteArray("0048100482"));
        // The data set digit.
        QCOMPARE(blockDefinition({ { { 412, 3 }, DataType::Unsigned16 } }).value(),
                 QByteArray("03412"));
    }

    void answerOfTheExample()
    {
        // T17: 108.45 Hz, 10.2 A, 4.0 kW as raw values.
        const QList<BlockItem> items = { { { 210, 0 }, DataType::Integer32 },
                                         { { 211, 0 }, DataType::Integer16 },
                                         { { 213, 0 }, DataType::Integer16 } };
        const auto values = decodeBlock("00002A5D00660028", items);
        QVERIFY2(values.ok(), qPrintable(values.error().toString()));
        QCOMPARE(values.value().size(), 3);
        QCOMPARE(values.value().at(0).toLongLong(), 10845);
        QCOMPARE(values.value().at(1).toLongLong(), 102);
        QCOMPARE(values.value().at(2).toLongLong(), 40);
    }

    void signedAndUnsignedWords()
    {
        const QList<BlockItem> items = { { { 411, 0 }, DataType::Unsigned16 },
                                         { { 240, 0 }, DataType::Integer32 },
                                         { { 213, 0 }, DataType::Integer16 } };
        const auto values = decodeBlock("8237FFFFFF9CFFFF", items);
        QVERIFY(values.ok());
        QCOMPARE(values.value().at(0).toULongLong(), 0x8237ull);
        QCOMPARE(values.value().at(1).toLongLong(), -100);
        QCOMPARE(values.value().at(2).toLongLong(), -1);
    }

    void badAnswersAreMalformed()
    {
        const QList<BlockItem> items = { { { 411, 0 }, DataType::Unsigned16 } };
        QCOMPARE(decodeBlock("123", items).error().kind(), Error::Kind::Malformed);
        QCOMPARE(decodeBlock("12345", items).error().kind(), Error::Kind::Malformed);
        const auto notHex = decodeBlock("12G4", items);
        QCOMPARE(notHex.error().kind(), Error::Kind::Malformed);
        QVERIFY(notHex.error().message().contains(QStringLiteral("hexadecimal")));
    }

    void parametersThatCannotBeInABlock()
    {
        // Four-digit numbers, strings, RAM data sets.
        QVERIFY(!fitsBlock({ { 1108, 0 }, DataType::Integer32 }));
        QVERIFY(!fitsBlock({ { 12, 0 }, DataType::VisibleString }));
        QVERIFY(!fitsBlock({ { 481, 6 }, DataType::Integer32 }));
        const auto refused = blockDefinition({ { { 1108, 0 }, DataType::Integer32 } });
        QCOMPARE(refused.error().kind(), Error::Kind::InvalidArgument);
        QVERIFY(refused.error().message().contains(QStringLiteral("1108:0")));
        QCOMPARE(blockDefinition({}).error().kind(), Error::Kind::InvalidArgument);
    }

    void packingStaysWithin64Characters()
    {
        // 20 double words would need 160 answer characters: only 8 fit (64 / 8); 13 words fit
        // the answer (52) but only 12 groups fit the definition (60).
        QList<BlockItem> longs;
        QList<BlockItem> words;
        for (quint16 p = 200; p < 220; ++p) {
            longs.append({ { p, 0 }, DataType::Integer32 });
            words.append({ { p, 0 }, DataType::Unsigned16 });
        }
        QCOMPARE(packBlock(longs).size(), 8);
        QCOMPARE(packBlock(words).size(), 12);
        QVERIFY(blockDefinition(packBlock(words)).ok());
        // Items that do not fit are skipped, not the ones after them.
        QList<BlockItem> mixed = { { { 1108, 0 }, DataType::Integer32 },
                                   { { 411, 0 }, DataType::Unsigned16 } };
        QCOMPARE(packBlock(mixed).size(), 1);
        QCOMPARE(packBlock(mixed).first().address, ObjectAddress(411, 0));
    }
};

QTEST_GUILESS_MAIN(TstVabusBlock)
#include "tst_vabusblock.moc"
