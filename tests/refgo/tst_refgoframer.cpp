// Level 1: splitting the drive's bytes into answers (movingcap.md 3.1, 3.8; 1.3 for the LF CR
// line ends).

#include "refgo/refgoframer.h"

#include <QtTest>

using namespace db;
using namespace db::refgo;

namespace {

// Every answer and error the framer produces for bytes fed in the given chunks.
std::vector<Result<Answer>> feedAll(Framer &framer, const QByteArrayList &chunks)
{
    std::vector<Result<Answer>> all;
    for (const QByteArray &chunk : chunks) {
        auto out = framer.feed(chunk);
        for (auto &r : out)
            all.push_back(std::move(r));
    }
    return all;
}

} // namespace

class TstRefgoFramer : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void docklightAnswerSplitAtEveryBytePosition_data();
    void docklightAnswerSplitAtEveryBytePosition();
    void docklightAnswerFedByteByByte_data();
    void docklightAnswerFedByteByByte();
    void anyLineEndIsAccepted_data();
    void anyLineEndIsAccepted();
    void whitespaceBeforeEchoIsSkipped();
    void promptWithoutEchoIsSkipped();
    void twoAnswersInOneChunk();
    void garbageLineBecomesTheEcho();
    void answerWithoutPromptIsNotComplete();
    void oversizeAnswerWithoutPromptIsAnError();
    void resetForgetsPartialAnswer();
    void promptInsideLineIsText();
};

void TstRefgoFramer::docklightAnswerSplitAtEveryBytePosition_data()
{
    QTest::addColumn<QByteArray>("bytes");
    QTest::addColumn<QString>("echo");
    QTest::addColumn<QStringList>("lines");
    // movingcap.md 3.8, rows 1-14 (duplicates left out).
    QTest::newRow("1 REF35") << QByteArray("REF35\r\n>") << "REF35" << QStringList();
    QTest::newRow("2 SP720") << QByteArray("SP720\r\n>") << "SP720" << QStringList();
    QTest::newRow("3 AC5000") << QByteArray("AC5000\r\n>") << "AC5000" << QStringList();
    QTest::newRow("4 DE1000") << QByteArray("DE1000\r\n>") << "DE1000" << QStringList();
    QTest::newRow("5 G360") << QByteArray("G360\r\n>") << "G360" << QStringList();
    QTest::newRow("6 G-7200") << QByteArray("G-7200\r\n>") << "G-7200" << QStringList();
    QTest::newRow("7 TPSR") << QByteArray("TPSR\r\n00000006\r\n>") << "TPSR"
                            << QStringList { "00000006" };
    QTest::newRow("8 TP") << QByteArray("TP\r\n-3658\r\n>") << "TP" << QStringList { "-3658" };
    QTest::newRow("9 TPSR") << QByteArray("TPSR\r\n0000000a\r\n>") << "TPSR"
                            << QStringList { "0000000a" };
    QTest::newRow("10 TP") << QByteArray("TP\r\n-7200\r\n>") << "TP" << QStringList { "-7200" };
    QTest::newRow("11 PQ") << QByteArray("PQ\r\n>") << "PQ" << QStringList();
    QTest::newRow("12 OR") << QByteArray("OR3511,8\r\nOR3511,8,110\r\n>") << "OR3511,8"
                           << QStringList { "OR3511,8,110" };
    QTest::newRow("13 OW") << QByteArray("OW3511,8,120\r\nOW3511,8,120,OK\r\n>") << "OW3511,8,120"
                           << QStringList { "OW3511,8,120,OK" };
    QTest::newRow("14 OR") << QByteArray("OR3511,8\r\nOR3511,8,120\r\n>") << "OR3511,8"
                           << QStringList { "OR3511,8,120" };
    QTest::newRow("two result lines")
        << QByteArray("X\r\na\r\nb\r\n>") << "X" << QStringList { "a", "b" };
}

void TstRefgoFramer::docklightAnswerSplitAtEveryBytePosition()
{
    QFETCH(QByteArray, bytes);
    QFETCH(QString, echo);
    QFETCH(QStringList, lines);
    for (qsizetype split = 0; split <= bytes.size(); ++split) {
        Framer framer;
        const auto out = feedAll(framer, { bytes.left(split), bytes.mid(split) });
        QVERIFY2(out.size() == 1, qPrintable(QStringLiteral("split at %1").arg(split)));
        QVERIFY(out.front().ok());
        QCOMPARE(out.front()->echo, echo);
        QCOMPARE(out.front()->lines, lines);
        QVERIFY(framer.isIdle());
    }
}

void TstRefgoFramer::docklightAnswerFedByteByByte_data()
{
    docklightAnswerSplitAtEveryBytePosition_data();
}

void TstRefgoFramer::docklightAnswerFedByteByByte()
{
    QFETCH(QByteArray, bytes);
    QFETCH(QString, echo);
    QFETCH(QStringList, lines);
    Framer framer;
    QByteArrayList chunks;
    for (char c : bytes)
        chunks.append(QByteArray(1, c));
    const auto out = feedAll(framer, chunks);
    QCOMPARE(out.size(), size_t(1));
    QCOMPARE(out.front()->echo, echo);
    QCOMPARE(out.front()->lines, lines);
}

void TstRefgoFramer::anyLineEndIsAccepted_data()
{
    QTest::addColumn<QByteArray>("bytes");
    QTest::newRow("CR LF") << QByteArray("TP\r\n-3658\r\n>");
    QTest::newRow("LF CR") << QByteArray("TP\n\r-3658\n\r>");
    QTest::newRow("lone CR") << QByteArray("TP\r-3658\r>");
    QTest::newRow("lone LF") << QByteArray("TP\n-3658\n>");
    QTest::newRow("mixed") << QByteArray("TP\n\r-3658\r\n>");
    QTest::newRow("blank lines") << QByteArray("TP\r\n\r\n-3658\r\n\r\n>");
}

void TstRefgoFramer::anyLineEndIsAccepted()
{
    QFETCH(QByteArray, bytes);
    for (qsizetype split = 0; split <= bytes.size(); ++split) {
        Framer framer;
        const auto out = feedAll(framer, { bytes.left(split), bytes.mid(split) });
        QCOMPARE(out.size(), size_t(1));
        QCOMPARE(out.front()->echo, QStringLiteral("TP"));
        QCOMPARE(out.front()->lines, QStringList { "-3658" });
    }
}

void TstRefgoFramer::whitespaceBeforeEchoIsSkipped()
{
    Framer framer;
    const auto out = framer.feed("\r\n \t\n\rTP\r\n-3658\r\n>");
    QCOMPARE(out.size(), size_t(1));
    QCOMPARE(out.front()->echo, QStringLiteral("TP"));
}

void TstRefgoFramer::promptWithoutEchoIsSkipped()
{
    Framer framer;
    QVERIFY(framer.feed(">\r\n").empty());
    const auto out = framer.feed("TS\r\n2\r\n>");
    QCOMPARE(out.size(), size_t(1));
    QCOMPARE(out.front()->echo, QStringLiteral("TS"));
    QCOMPARE(out.front()->lines, QStringList { "2" });
}

void TstRefgoFramer::twoAnswersInOneChunk()
{
    Framer framer;
    const auto out = framer.feed("TP\r\n-3658\r\n>TS\r\n2\r\n>G360\r\n>");
    QCOMPARE(out.size(), size_t(3));
    QCOMPARE(out.at(0)->echo, QStringLiteral("TP"));
    QCOMPARE(out.at(1)->lines, QStringList { "2" });
    QCOMPARE(out.at(2)->echo, QStringLiteral("G360"));
    QVERIFY(out.at(2)->lines.isEmpty());
}

void TstRefgoFramer::garbageLineBecomesTheEcho()
{
    // The framer does not judge content: the client rejects this by its echo.
    Framer framer;
    const auto out = framer.feed(QByteArray("\x07\x01zz#\r\n>", 8));
    QCOMPARE(out.size(), size_t(1));
    QCOMPARE(out.front()->echo, QString::fromLatin1("\x07\x01zz#"));
}

void TstRefgoFramer::answerWithoutPromptIsNotComplete()
{
    Framer framer;
    QVERIFY(framer.feed("TP\r\n-3658\r\n").empty());
    QVERIFY(!framer.isIdle());
    const auto out = framer.feed(">");
    QCOMPARE(out.size(), size_t(1));
    QVERIFY(framer.isIdle());
}

void TstRefgoFramer::oversizeAnswerWithoutPromptIsAnError()
{
    Framer framer;
    const QByteArray junk(Framer::kMaxAnswerBytes + 10, 'A');
    auto out = framer.feed(junk);
    QCOMPARE(out.size(), size_t(1));
    QVERIFY(!out.front().ok());
    QCOMPARE(out.front().error().kind(), Error::Kind::Malformed);
    QVERIFY(out.front().error().message().contains(QLatin1String("too long without prompt")));
    // The rest of the oversize answer up to its prompt is discarded, then framing resumes.
    QVERIFY(framer.feed("more junk\r\nand more\r\n>").empty());
    out = framer.feed("TP\r\n1\r\n>");
    QCOMPARE(out.size(), size_t(1));
    QCOMPARE(out.front()->echo, QStringLiteral("TP"));
}

void TstRefgoFramer::resetForgetsPartialAnswer()
{
    Framer framer;
    QVERIFY(framer.feed("TP\r\n-36").empty());
    framer.reset();
    QVERIFY(framer.isIdle());
    const auto out = framer.feed("TS\r\n2\r\n>");
    QCOMPARE(out.size(), size_t(1));
    QCOMPARE(out.front()->echo, QStringLiteral("TS"));
    QCOMPARE(out.front()->lines, QStringList { "2" });
}

void TstRefgoFramer::promptInsideLineIsText()
{
    Framer framer;
    const auto out = framer.feed("X\r\na>b\r\n>");
    QCOMPARE(out.size(), size_t(1));
    QCOMPARE(out.front()->lines, QStringList { "a>b" });
}

QTEST_GUILESS_MAIN(TstRefgoFramer)
#include "tst_refgoframer.moc"
