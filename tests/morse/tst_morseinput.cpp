// Morse inputs end to end (app/morse + protocols/morse): videos rendered here from synthetic LED
// recordings (libavcodec, MPEG-4) are read back with libavformat, the LED region is found, and
// the decoder must return the IP; CSV files; and a clear reason for each undecodable input.
// The CLI `drivebench-cli morse` is run on the same files.
#include "ledvideo.h"
#include "morse/corpus.h"
#include "morse/decoder.h"
#include "morse/morseinput.h"

#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

using namespace db::morse;
using namespace db::morseio;

namespace {

SignalOptions ledSignal(double fps, double unit, const QString &text)
{
    SignalOptions o = morsetest::ledSignal(text, fps, 11, 0.3);
    o.unit = unit;
    o.exposure = 0.5;
    return o;
}

void writeCsv(const QString &path, const std::vector<Sample> &samples, bool header)
{
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Text));
    if (header)
        f.write("time_s,brightness\n");
    for (const Sample &s : samples)
        f.write(QByteArray::number(s.t, 'f', 6) + ',' + QByteArray::number(s.value, 'g', 9) + '\n');
}

struct Cli
{
    int code;
    QString out;
    QString err;
};

Cli runCli(const QStringList &args)
{
    QProcess p;
    p.start(QStringLiteral(DRIVEBENCH_CLI), QStringList { QStringLiteral("morse") } + args);
    p.waitForFinished(60000);
    return { p.exitCode(), QString::fromUtf8(p.readAllStandardOutput()),
             QString::fromUtf8(p.readAllStandardError()) };
}

} // namespace

class TstMorseInput : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase() { QVERIFY(m_dir.isValid()); }

    void videoEndToEnd_data()
    {
        QTest::addColumn<double>("fps");
        QTest::addColumn<double>("unit");
        QTest::addColumn<QString>("ip");
        QTest::newRow("25 fps, 120 ms") << 25.0 << 0.12 << "192.168.2.150";
        QTest::newRow("30 fps, 90 ms") << 30.0 << 0.09 << "10.0.7.42";
    }
    void videoEndToEnd()
    {
        QFETCH(double, fps);
        QFETCH(double, unit);
        QFETCH(QString, ip);
        QString text = ip;
        text.replace(QLatin1Char('.'), QLatin1Char('+'));
        const QString path = m_dir.filePath(QStringLiteral("led%1.mp4").arg(int(fps)));
        morsetest::LedScene scene;
        const auto written = morsetest::renderLedVideo(
            path, ledSignal(fps, unit, QStringLiteral("MC+IP%1:").arg(text)), scene);
        QVERIFY2(written.ok(), qPrintable(written.error().toString()));

        const auto rec = readVideo(path);
        QVERIFY2(rec.ok(), qPrintable(rec.error().toString()));
        QVERIFY(std::abs(rec->frameRate - fps) < 0.5);
        QVERIFY2(rec->region.contains(scene.led),
                 qPrintable(QStringLiteral("%1,%2 %3x%4")
                                .arg(rec->region.x())
                                .arg(rec->region.y())
                                .arg(rec->region.width())
                                .arg(rec->region.height())));
        QVERIFY(rec->region.width() <= 4 * scene.radius
                && rec->region.height() <= 4 * scene.radius);
        QVERIFY(!rec->frame.isNull());
        const auto r = decodeRecording(rec->samples);
        QVERIFY2(r.ok(), qPrintable(r.error().toString()));
        QCOMPARE(r->ip.toString(), ip);
        QCOMPARE(r->reason, Reason::None);

        // The user's region gives the same; the CLI prints the IP.
        const auto given = readVideo(path, QRect(scene.led.x() - 3, scene.led.y() - 3, 7, 7));
        QVERIFY(given.ok());
        QCOMPARE(decodeRecording(given->samples)->ip.toString(), ip);
        const Cli cli = runCli({ path });
        QCOMPARE(cli.code, 0);
        QVERIFY2(cli.out.contains(QStringLiteral("ip: %1 (confidence").arg(ip)),
                 qPrintable(cli.out));
        QVERIFY(cli.out.contains(QStringLiteral("MC+IP%1:").arg(text)));
    }

    void videoWithoutLed()
    {
        const QString path = m_dir.filePath(QStringLiteral("noled.mp4"));
        morsetest::LedScene scene;
        scene.ledVisible = false;
        SignalOptions o = ledSignal(25.0, 0.12, QStringLiteral("MC+IP1+2+3+4:"));
        o.repetitions = 1;
        QVERIFY(morsetest::renderLedVideo(path, o, scene).ok());
        const auto rec = readVideo(path);
        QVERIFY(rec.ok());
        QVERIFY(rec->region.isEmpty());
        const Cli cli = runCli({ path });
        QCOMPARE(cli.code, 1);
        QVERIFY2(cli.err.contains(QLatin1String("no LED found")), qPrintable(cli.err));
    }

    void csvWithHeader()
    {
        SignalOptions o = ledSignal(30.0, 0.1, QStringLiteral("MC+IP172+16+0+9:"));
        o.snrDb = 12.0;
        o.ambient = 40.0;
        o.amplitude = 3.0;
        const QString path = m_dir.filePath(QStringLiteral("led.csv"));
        writeCsv(path, generateSignal(o).samples, true);
        const auto rec = readCsv(path);
        QVERIFY2(rec.ok(), qPrintable(rec.error().toString()));
        QCOMPARE(decodeRecording(rec->samples)->ip.toString(), QStringLiteral("172.16.0.9"));
        const Cli cli = runCli({ path });
        QCOMPARE(cli.code, 0);
        QVERIFY(cli.out.contains(QLatin1String("ip: 172.16.0.9")));
    }

    // The CLI on the generated corpus (tst_morsecorpus streams the same cases through the
    // library): every file of a clean and of a jittered, noisy condition, and of messages sent
    // back to back, gives its exact IP.
    void cliDecodesTheCorpus_data()
    {
        QTest::addColumn<double>("jitter");
        QTest::addColumn<double>("snrDb");
        QTest::addColumn<int>("cases");
        QTest::addColumn<double>("pause"); // CorpusCondition::repeatGap
        const double inf = std::numeric_limits<double>::infinity();
        QTest::newRow("clean") << 0.0 << inf << 10 << 0.0;
        QTest::newRow("jitter 30% + noise 6 dB") << 0.3 << 6.0 << 20 << 0.0;
        QTest::newRow("back to back") << 0.0 << inf << 5 << 3.0;
    }
    void cliDecodesTheCorpus()
    {
        QFETCH(double, jitter);
        QFETCH(double, snrDb);
        QFETCH(int, cases);
        QFETCH(double, pause);
        CorpusCondition condition;
        condition.jitter = jitter;
        condition.snrDb = snrDb;
        condition.repeatGap = pause;
        condition.minSamplesPerUnit = jitter > 0.0 ? 3.0 : 2.0;
        const std::vector<CorpusCase> corpus = makeCorpus(condition, cases, 20240601u);
        int exact = 0;
        for (std::size_t k = 0; k < corpus.size(); ++k) {
            const QString path = m_dir.filePath(QStringLiteral("corpus%1.csv").arg(k));
            writeCsv(path, generateSignal(corpus[k].signal).samples, k % 2 == 0);
            const Cli cli = runCli({ path });
            const QString ip = ipText(corpus[k].ip, QLatin1Char('.'));
            const bool ok =
                cli.code == 0 && cli.out.contains(QStringLiteral("ip: %1 (confidence").arg(ip));
            if (!ok)
                qWarning("case %zu (%g fps, %.0f ms): %s: %s%s", k, corpus[k].signal.sampleRate,
                         corpus[k].signal.unit * 1000.0, qPrintable(ip), qPrintable(cli.out),
                         qPrintable(cli.err));
            exact += ok ? 1 : 0;
        }
        QCOMPARE(exact, cases);
    }

    // Undecodable input: each gets its reason, from the library and from the CLI.
    void undecodable_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<double>("periods");
        QTest::addColumn<int>("reason");
        QTest::addColumn<QString>("message");
        QTest::newRow("too short")
            << "MC+IP192+168+2+150:" << 0.4 << int(Reason::TooShort) << "too short";
        QTest::newRow("wrong message")
            << "ST+OK+TEMP+45:" << 3.0 << int(Reason::NoValidIp) << "without a valid";
        QTest::newRow("octet above 255")
            << "MC+IP192+168+2+350:" << 3.0 << int(Reason::NoValidIp) << "without a valid";
    }
    void undecodable()
    {
        QFETCH(QString, text);
        QFETCH(double, periods);
        QFETCH(int, reason);
        QFETCH(QString, message);
        SignalOptions o = ledSignal(30.0, 0.1, text);
        o.startOffset = 0.0;
        Signal sig = generateSignal(o);
        sig.samples.resize(std::size_t(periods / 3.0 * double(sig.samples.size())));
        const QString path = m_dir.filePath(QStringLiteral("bad%1.csv").arg(reason));
        writeCsv(path, sig.samples, false);
        const auto r = decodeRecording(sig.samples);
        const Reason got = r.ok() ? r->reason : Reason(r.error().deviceCode());
        QCOMPARE(int(got), reason);
        const Cli cli = runCli({ path });
        QCOMPARE(cli.code, 1);
        QVERIFY2(cli.err.contains(message), qPrintable(cli.err));
    }

    void badFiles()
    {
        const QString path = m_dir.filePath(QStringLiteral("broken.csv"));
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("t,v\n0.0,1\n0.1,oops\n");
        f.close();
        const auto rec = readCsv(path);
        QVERIFY(!rec.ok());
        QVERIFY2(rec.error().message().contains(QLatin1String(":3:")),
                 qPrintable(rec.error().message()));
        QVERIFY(!readVideo(m_dir.filePath(QStringLiteral("missing.mp4"))).ok());
        QVERIFY(!readVideo(path).ok()); // not a video
        QCOMPARE(runCli({ path }).code, 1);
        QCOMPARE(runCli({ path, QStringLiteral("1,2,3") }).code, 2);
        QCOMPARE(parseRegion(QStringLiteral("4, 5, 6, 7")), QRect(4, 5, 6, 7));
    }

private:
    QTemporaryDir m_dir;
};

QTEST_GUILESS_MAIN(TstMorseInput)
#include "tst_morseinput.moc"
