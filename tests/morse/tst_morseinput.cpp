// Morse inputs end to end (app/morse + protocols/morse): videos rendered here from synthetic LED
// recordings (libavcodec, MPEG-4) are read back with libavformat, the LED region is found, and
// the decoder must return the IP; CSV files; and a clear reason for each undecodable input.
// The CLI `drivebench-cli morse` is run on the same files.
#include "ledvideo.h"
#include "morse/decode/decoder.h"
#include "morse/input/morseinput.h"
#include "morse/synth/corpus.h"

#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <sys/resource.h>

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

// The CLI may use at most this much address space: a file must not be able to size its
// allocations (an exhausted limit aborts it with std::bad_alloc instead of swapping).
constexpr rlim_t kCliMemory = rlim_t(2) << 30;

Cli runCli(const QStringList &args)
{
    QProcess p;
#ifndef __SANITIZE_ADDRESS__
    // AddressSanitizer reserves terabytes of address space for its shadow memory, so the cap
    // cannot apply there; the normal build checks the bound.
    p.setChildProcessModifier([] {
        const rlimit limit { kCliMemory, kCliMemory };
        setrlimit(RLIMIT_AS, &limit);
    });
#endif
    p.start(QStringLiteral(DRIVEBENCH_CLI), QStringList { QStringLiteral("morse") } + args);
    if (!p.waitForFinished(60000))
        p.kill();
    if (p.exitStatus() != QProcess::NormalExit)
        return { -1,
                 {},
                 QStringLiteral("crashed: ") + QString::fromUtf8(p.readAllStandardError()) };
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

    // A recording with a long jump in time: read as two recordings, each decoded where it is
    // long enough, in bounded memory and time. The short file (72 rows) has nothing to decode
    // on either side and must say so, and why.
    void csvWithGapInTime_data()
    {
        QTest::addColumn<double>("jump");
        QTest::addColumn<int>("rows"); // per side; 0: the whole signal on each
        QTest::addColumn<bool>("lit"); // the jump inside a mark, else between two recordings
        for (const double jump : { 1e9, 1e8, 1e7 }) {
            QTest::addRow("%g s, two recordings", jump) << jump << 0 << false;
            QTest::addRow("%g s, inside a mark", jump) << jump << 0 << true;
            QTest::addRow("%g s, 72 rows", jump) << jump << 36 << false;
        }
    }
    void csvWithGapInTime()
    {
        QFETCH(double, jump);
        QFETCH(int, rows);
        QFETCH(bool, lit);
        SignalOptions o = ledSignal(30.0, 0.1, QStringLiteral("MC+IP10+0+7+42:"));
        std::vector<Sample> part = generateSignal(o).samples;
        std::vector<Sample> samples;
        if (lit) {
            // One recording whose clock jumps while the LED is on, in its second message.
            samples = part;
            std::size_t at = samples.size() / 2;
            while (samples[at].value < 1.0 || samples[at + 1].value < 1.0)
                ++at;
            part.resize(at + 1);
            for (std::size_t i = at + 1; i < samples.size(); ++i)
                samples[i].t += jump;
        } else {
            if (rows > 0)
                part.resize(std::size_t(rows));
            samples = part;
            const double shift = part.back().t + jump;
            for (const Sample &s : part)
                samples.push_back({ s.t + shift, s.value });
        }
        const bool longParts = rows == 0;
        const QString path = m_dir.filePath(QStringLiteral("gap%1.csv").arg(samples.size()));
        writeCsv(path, samples, true);
        const auto rec = readCsv(path);
        QVERIFY2(rec.ok(), qPrintable(rec.error().toString()));
        QCOMPARE(rec->samples.size(), samples.size());

        const QString note = QStringLiteral("the recording has a %1 s gap in time after sample %2")
                                 .arg(jump, 0, 'g', 3)
                                 .arg(part.size());
        const Cli cli = runCli({ path });
        QVERIFY2(cli.code >= 0, qPrintable(cli.err));
        if (longParts) {
            const auto r = decodeRecording(rec->samples);
            QVERIFY2(r.ok(), qPrintable(r.error().toString()));
            QCOMPARE(r->ip.toString(), QStringLiteral("10.0.7.42"));
            // Messages read on both sides of the cut.
            const QStringList parts = r->text.split(QStringLiteral(" | "));
            QCOMPARE(parts.size(), 2);
            // Cut inside its second message, the recording has a complete one only after the
            // cut; the part before ends with the start of the one cut.
            const QString before =
                lit ? QStringLiteral("MC+IP10+0+7+4") : QStringLiteral("MC+IP10+0+7+42:");
            QVERIFY2(parts[0].contains(before)
                         && parts[1].contains(QLatin1String("MC+IP10+0+7+42:")),
                     qPrintable(r->text));
            QCOMPARE(r->reason, Reason::None);
            QCOMPARE(cli.code, 0);
            QVERIFY2(cli.out.contains(QLatin1String("ip: 10.0.7.42 (confidence")),
                     qPrintable(cli.out + cli.err));
            QVERIFY2(cli.out.contains(QStringLiteral("note: ") + note), qPrintable(cli.out));
            QVERIFY(cli.out.contains(QLatin1String("read as 2 recordings")));
        } else {
            QCOMPARE(cli.code, 1);
            QVERIFY2(cli.err.contains(note) && cli.err.contains(QLatin1String("read as 2")),
                     qPrintable(cli.err));
        }
    }

    // Times the decoder cannot use: each refused with its row and what is wrong with it.
    void csvBadTimes_data()
    {
        QTest::addColumn<QByteArray>("rows");
        QTest::addColumn<QString>("message");
        QByteArray ordered;
        for (int i = 0; i < 15; ++i)
            ordered += QByteArray::number(0.1 * (i + 21), 'f', 1) + ",1\n";
        // Line 1 is the header; the 16th data row is line 17.
        QTest::newRow("out of order")
            << ordered + "3.2,1\n3.6,1\n"
            << "gap.csv:17: time 3.2 s is before the previous row's 3.5 s";
        QTest::newRow("repeated time") << ordered + "3.5,0\n"
                                       << "gap.csv:17: time 3.5 s repeats the previous row's time";
        QTest::newRow("time nan") << ordered + "nan,1\n"
                                  << "gap.csv:17: time \"nan\" is not a finite number";
        QTest::newRow("time inf") << ordered + "inf,1\n"
                                  << "gap.csv:17: time \"inf\" is not a finite number";
        QTest::newRow("brightness nan") << ordered + "3.6,nan\n"
                                        << "gap.csv:17: brightness \"nan\" is not a finite number";
        QTest::newRow("brightness -inf")
            << ordered + "3.6,-inf\n"
            << "gap.csv:17: brightness \"-inf\" is not a finite number";
        QTest::newRow("negative time")
            << QByteArray("-0.5,1\n") + ordered << "gap.csv:2: time -0.5 s is negative";
        QTest::newRow("line too long") << ordered + "3.6," + QByteArray(300, '1') + "\n"
                                       << "gap.csv:17: line longer than 256 characters";
    }
    void csvBadTimes()
    {
        QFETCH(QByteArray, rows);
        QFETCH(QString, message);
        const QString path = m_dir.filePath(QStringLiteral("gap.csv"));
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
        f.write("time_s,brightness\n" + rows);
        f.close();
        const auto rec = readCsv(path);
        QVERIFY(!rec.ok());
        QVERIFY2(rec.error().message().contains(message), qPrintable(rec.error().message()));
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
