// A corpus generated here (never tuned to one recording): random IPs, dit 60-400 ms
// (log-uniform), 15/25/30/60 fps and 1 kHz, random exposure, ambient, brightness scale, start
// position inside the message and repeat gap; 3 message periods per case, streamed in 0.25 s
// chunks. SNR as in signalgenerator.h: 10 log10(A^2 / (4 sigma^2)), A = on/off step,
// sigma = per-sample noise; 6 dB is sigma = A / 4.
//
// Decodability limit (see CorpusCondition::minSamplesPerUnit): the dit must span two sample
// periods for clean and mildly disturbed signals, three with +-30 % jitter. Per-frame noise of
// 6 dB at 15-30 fps is measured by bench/morse (morse_corpus) but only asserted at 60 fps and
// 1 kHz, where the targets hold; see the report there.
#include "morse/corpus.h"

#include <QTest>

#include <memory>

using namespace db::morse;
using CorpusConditionPtr = std::shared_ptr<CorpusCondition>;
Q_DECLARE_METATYPE(CorpusConditionPtr)

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
}

class TstMorseCorpus : public QObject
{
    Q_OBJECT

private slots:
    void corpus_data()
    {
        QTest::addColumn<CorpusConditionPtr>("condition");
        QTest::addColumn<int>("cases");
        QTest::addColumn<double>("minExact"); // share of cases with the exact IP at the end
        QTest::addColumn<double>("minWithinTwo"); // share confident within two repetitions
        auto row = [](const char *name, CorpusCondition c, int cases, double exact, double two) {
            c.name = QString::fromLatin1(name);
            QTest::newRow(name) << CorpusConditionPtr(new CorpusCondition(c)) << cases << exact
                                << two;
        };
        row("clean", { {}, 0.0, kInf, 0.0, 0.0, 0.0, 2.0 }, 60, 1.0, 1.0);
        row("jitter 15%", { {}, 0.15, kInf, 0.0, 0.0, 0.0, 2.0 }, 30, 0.95, 0.85);
        row("jitter 30%", { {}, 0.30, kInf, 0.0, 0.0, 0.0, 3.0 }, 40, 0.99, 0.85);
        row("noise 20 dB", { {}, 0.0, 20.0, 0.0, 0.0, 0.0, 2.0 }, 30, 1.0, 0.95);
        row("jitter 30% + noise 6 dB, 60 fps and 1 kHz",
            { {}, 0.30, 6.0, 0.0, 0.0, 0.0, 3.0, { 60.0, 1000.0 } }, 40, 0.95, 0.8);
        row("drift and auto exposure, 20 dB", { {}, 0.0, 20.0, 0.01, 0.3, 0.0, 2.0 }, 30, 0.95,
            0.85);
        row("duty error 0.3 units, 20 dB", { {}, 0.0, 20.0, 0.0, 0.0, 0.3, 3.0 }, 30, 1.0, 0.95);
    }
    void corpus()
    {
        QFETCH(CorpusConditionPtr, condition);
        QFETCH(int, cases);
        QFETCH(double, minExact);
        QFETCH(double, minWithinTwo);
        const std::vector<CorpusCase> corpus = makeCorpus(*condition, cases, 20240601u);
        int exact = 0;
        int withinTwo = 0;
        for (const CorpusCase &c : corpus) {
            const CaseOutcome o = runCase(c);
            exact += o.exact ? 1 : 0;
            withinTwo += o.repetitionsToConfident >= 0.0 && o.repetitionsToConfident <= 2.0;
            // Never confident in a wrong address.
            QVERIFY2(!o.wrongConfident,
                     qPrintable(QStringLiteral("%1 fps, %2 ms: %3 -> %4")
                                    .arg(c.signal.sampleRate)
                                    .arg(c.signal.unit * 1000.0)
                                    .arg(ipText(c.ip, QLatin1Char('.')), o.decoded)));
        }
        qInfo("%s: exact %d/%d, confident within two repetitions %d/%d",
              qPrintable(condition->name), exact, cases, withinTwo, cases);
        QVERIFY(exact >= minExact * cases);
        QVERIFY(withinTwo >= minWithinTwo * cases);
    }
};

QTEST_GUILESS_MAIN(TstMorseCorpus)
#include "tst_morsecorpus.moc"
