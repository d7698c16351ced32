// Level 1: Morse table (ITU-R M.1677-1, movingcap.md 2.4), element classification and the
// "MC+IP...:" parser and voter.
#include "morse/decode/ipvoter.h"
#include "morse/decode/morsecode.h"
#include "morse/decode/symbolizer.h"

#include <QTest>

#include <map>

using namespace db::morse;

class TstMorseCode : public QObject
{
    Q_OBJECT

private slots:
    void specTable_data()
    {
        QTest::addColumn<QChar>("ch");
        QTest::addColumn<QString>("code");
        const char *table[][2] = { { "M", "--" },     { "C", "-.-." },  { "I", ".." },
                                   { "P", ".--." },   { "+", ".-.-." }, { ":", "---..." },
                                   { ".", ".-.-.-" }, { "0", "-----" }, { "1", ".----" },
                                   { "2", "..---" },  { "3", "...--" }, { "4", "....-" },
                                   { "5", "....." },  { "6", "-...." }, { "7", "--..." },
                                   { "8", "---.." },  { "9", "----." }, { "A", ".-" },
                                   { "Z", "--.." } };
        for (const auto &row : table)
            QTest::newRow(row[0]) << QChar::fromLatin1(row[0][0]) << QString::fromLatin1(row[1]);
    }
    void specTable()
    {
        QFETCH(QChar, ch);
        QFETCH(QString, code);
        QCOMPARE(codeFor(ch), code);
        QCOMPARE(charFor(code), ch);
    }

    void allLettersAndDigitsRoundTrip()
    {
        const QString chars = QStringLiteral("ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789");
        for (QChar c : chars) {
            QVERIFY2(!codeFor(c).isEmpty(), qPrintable(QString(c)));
            QCOMPARE(charFor(codeFor(c)), c);
        }
        QCOMPARE(codeFor(QLatin1Char('m')), QStringLiteral("--"));
        QVERIFY(codeFor(QLatin1Char('#')).isEmpty());
        QVERIFY(charFor(u"......-").isNull());
    }

    void classify_data()
    {
        QTest::addColumn<bool>("on");
        QTest::addColumn<double>("units");
        QTest::addColumn<ElementKind>("kind");
        // Nominal lengths and +-30 % jitter around them.
        QTest::newRow("dit") << true << 1.0 << ElementKind::Dit;
        QTest::newRow("dit -30%") << true << 0.7 << ElementKind::Dit;
        QTest::newRow("dit +30%") << true << 1.3 << ElementKind::Dit;
        QTest::newRow("dah") << true << 3.0 << ElementKind::Dah;
        QTest::newRow("dah -30%") << true << 2.1 << ElementKind::Dah;
        QTest::newRow("dah +30%") << true << 3.9 << ElementKind::Dah;
        // Two dahs whose gap noise filled (3 + 1 + 3 units, 9.1 with +30 % jitter): still a
        // mark for the sequence decoder, which reads it with one edit.
        QTest::newRow("two dahs merged") << true << 7.0 << ElementKind::Dah;
        QTest::newRow("two dahs merged +30%") << true << 9.1 << ElementKind::Dah;
        QTest::newRow("steady on") << true << 12.0 << ElementKind::LongMark;
        QTest::newRow("intra") << false << 1.0 << ElementKind::IntraGap;
        QTest::newRow("intra -30%") << false << 0.7 << ElementKind::IntraGap;
        QTest::newRow("intra +30%") << false << 1.3 << ElementKind::IntraGap;
        QTest::newRow("letter") << false << 3.0 << ElementKind::LetterGap;
        QTest::newRow("letter -30%") << false << 2.1 << ElementKind::LetterGap;
        QTest::newRow("letter +30%") << false << 3.9 << ElementKind::LetterGap;
        QTest::newRow("word") << false << 7.0 << ElementKind::WordGap;
        QTest::newRow("word -25%") << false << 5.25 << ElementKind::WordGap;
        QTest::newRow("word +30%") << false << 9.1 << ElementKind::WordGap;
        QTest::newRow("repeat pause") << false << 30.0 << ElementKind::WordGap;
    }
    void classify()
    {
        QFETCH(bool, on);
        QFETCH(double, units);
        QFETCH(ElementKind, kind);
        QCOMPARE(db::morse::classify(on, units), kind);
    }

    void voting()
    {
        IpVoter voter;
        IpObservation a;
        a.octets = { 192, 168, 2, 150 };
        a.complete = true;
        voter.add(a);
        QCOMPARE(voter.estimate().confidence, 0.5); // one reading is not enough
        QVERIFY(voter.estimate().confidence < IpVoter::kConfident);
        voter.add(a);
        QCOMPARE(voter.estimate().confidence, 1.0);
        QCOMPARE(voter.estimate().messages, 2);
        IpObservation wrong = a;
        wrong.octets[3] = 158;
        voter.add(wrong);
        QCOMPARE(voter.estimate().toString(), QStringLiteral("192.168.2.150"));
        QVERIFY(voter.estimate().confidence < IpVoter::kConfident); // 2:1 is not yet enough
        voter.add(a);
        QVERIFY(voter.estimate().confidence >= IpVoter::kConfident); // 3:1
    }

    // Soft readings: each says how much worse every other value of an octet explains the marks.
    // `rival` of octet `octet` costs `nats` more than the value read; every other value is far.
    static IpObservation soft(std::array<int, 4> octets, int octet = -1, int rival = -1,
                              double nats = 0.0)
    {
        IpObservation o;
        o.octets = octets;
        o.complete = true;
        if (octet >= 0)
            o.cost[std::size_t(octet)][rival] = nats;
        for (std::size_t k = 0; k < 4; ++k)
            o.cost[k][octets[k]] = 0.0;
        return o;
    }

    // Two agreeing readings of "168", each unsure against a different rival: 169 and 178 each
    // lose clearly to the other reading, so 168 is confident. Unsure against the same rival
    // twice, it is not.
    void votingWithSoftEvidence()
    {
        IpVoter voter;
        voter.add(soft({ 10, 168, 0, 1 }, 1, 169, 0.8));
        voter.add(soft({ 10, 168, 0, 1 }, 1, 178, 0.8));
        QCOMPARE(voter.estimate().toString(), QStringLiteral("10.168.0.1"));
        QVERIFY(voter.estimate().confidence >= IpVoter::kConfident);

        IpVoter same;
        same.add(soft({ 10, 168, 0, 1 }, 1, 169, 0.8));
        same.add(soft({ 10, 168, 0, 1 }, 1, 169, 0.8));
        QCOMPARE(same.estimate().toString(), QStringLiteral("10.168.0.1"));
        QVERIFY(same.estimate().confidence < IpVoter::kConfident);
        // A third, clear reading settles it.
        same.add(soft({ 10, 168, 0, 1 }));
        QVERIFY(same.estimate().confidence >= IpVoter::kConfident);
    }

    // Noise merges the two dits of a '2' (..---) in one message: "----" is also an '8' with its
    // last two dits merged, at the same cost, and the reading names whichever its parse found
    // first. It reads both: with a clear second reading of 181 that is two readings for 181 and
    // a confident address (and two messages reporting it); had the tie gone the other way, 181
    // would have been read twice anyway. A reading that merely prefers 121 (by a nat) does not
    // read 181.
    void tiedReadingReadsBoth()
    {
        IpVoter voter;
        voter.add(soft({ 10, 121, 0, 1 }, 1, 181, 0.0));
        voter.add(soft({ 10, 181, 0, 1 }));
        QCOMPARE(voter.estimate().toString(), QStringLiteral("10.181.0.1"));
        QVERIFY2(voter.estimate().confidence >= IpVoter::kConfident,
                 qPrintable(QString::number(voter.estimate().confidence)));
        QCOMPARE(voter.estimate().messages, 2); // both read 10.181.0.1

        IpVoter unsure;
        unsure.add(soft({ 10, 121, 0, 1 }, 1, 181, 1.0));
        unsure.add(soft({ 10, 181, 0, 1 }));
        QVERIFY(unsure.estimate().confidence < IpVoter::kConfident);
        QCOMPARE(unsure.estimate().messages, 1);
    }

    // A message garbled by noise disagrees in several octets. It costs every address at most
    // IpVoter::kMessageCap, so it does not outvote a clean reading octet by octet once a third
    // reading confirms the clean one where they differ; the octets only the clean reading read
    // are not confident on that one reading.
    void garbledReadingDoesNotOutvote()
    {
        IpVoter voter;
        voter.add(soft({ 169, 91, 212, 115 }));
        voter.add(soft({ 6, 135, 241, 5 }));
        IpObservation partial; // "MC+IP6+1" of a third message
        partial.octets = { 6, -1, -1, -1 };
        partial.cost[0] = { { 6, 0.0 } };
        voter.add(partial);
        const IpEstimate e = voter.estimate();
        QCOMPARE(e.toString(), QStringLiteral("6.135.241.5"));
        QVERIFY(e.confidence < IpVoter::kConfident);
        voter.add(soft({ 6, 135, 241, 5 }));
        QVERIFY(voter.estimate().confidence >= IpVoter::kConfident);
        QCOMPARE(voter.estimate().messages, 2);
    }
};

QTEST_GUILESS_MAIN(TstMorseCode)
#include "tst_morsecode.moc"
