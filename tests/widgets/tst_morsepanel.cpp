// Level 4: the Morse panel offscreen. A video of a simulated LED is rendered (libavcodec), read
// through the same loader the main window injects (app/morse), played, and the panel must show
// the frame, the plot with threshold and timeline, the text and the IP; "Connect" asks for
// refgo://IP and its menu for canopen+slcan://IP?node=50. Undecodable input shows its reason.
#include "ledvideo.h"
#include "morse/input/morseinput.h"
#include "widgets/common/plot.h"
#include "widgets/morse/morsepanel.h"

#include <QLabel>
#include <QMenu>
#include <QPlainTextEdit>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QToolButton>

using namespace db;
using db::widgets::MorsePanel;
using db::widgets::MorseSource;

namespace {

Result<MorseSource> load(const QString &path)
{
    auto rec = morseio::readRecording(path);
    if (!rec)
        return rec.error();
    return MorseSource { rec->samples, rec->region, rec->frame, rec->frameSize.width(),
                         rec->source };
}

morse::SignalOptions signal(const QString &text)
{
    return morsetest::ledSignal(text, 25.0, 5);
}

} // namespace

class TstMorsePanel : public QObject
{
    Q_OBJECT

private slots:
    void decodesVideoAndConnects()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("led.mp4"));
        QVERIFY(morsetest::renderLedVideo(path, signal(QStringLiteral("MC+IP10+20+30+40:"))).ok());
        MorsePanel panel;
        panel.setLoader(load);
        panel.resize(1000, 420);
        panel.show();
        QVERIFY(panel.openFile(path));
        QVERIFY(panel.playing());
        // Live: the plot fills while playing.
        QTRY_VERIFY(panel.plot()->graph(0)->dataCount() > 50);
        panel.finishPlayback();
        QVERIFY(!panel.playing());
        QCOMPARE(panel.ipText(), QStringLiteral("10.20.30.40"));
        QVERIFY(panel.decoder().confident());
        QVERIFY(panel.findChild<QPlainTextEdit *>(QStringLiteral("morseText"))
                    ->toPlainText()
                    .contains(QLatin1String("MC+IP10+20+30+40:")));
        QVERIFY(panel.findChild<QLabel *>(QStringLiteral("morseIp"))
                    ->text()
                    .contains(QLatin1String("10.20.30.40")));
        QVERIFY(!panel.findChild<QLabel *>(QStringLiteral("morseFrame"))->pixmap().isNull());
        QVERIFY(panel.plot()->graph(1)->dataCount() > 0); // threshold
        QVERIFY(panel.plot()->graph(2)->dataCount() > 0); // dits
        QVERIFY(panel.plot()->graph(3)->dataCount() > 0); // dahs

        QSignalSpy spy(&panel, &MorsePanel::connectRequested);
        auto *button = panel.findChild<QToolButton *>(QStringLiteral("morseConnect"));
        QVERIFY(button->isEnabled());
        QTest::mouseClick(button, Qt::LeftButton, {}, QPoint(8, button->height() / 2));
        QCOMPARE(spy.size(), 1);
        QCOMPARE(spy.at(0).at(0).toString(), QStringLiteral("refgo://10.20.30.40"));
        button->menu()->actions().at(1)->trigger();
        QCOMPARE(spy.at(1).at(0).toString(), QStringLiteral("canopen+slcan://10.20.30.40?node=50"));
    }

    // A drive that loops its message without a pause (only a letter gap after ':'): the video
    // decodes in the panel as with a pause. With DRIVEBENCH_SCREENSHOT_DIR set, the panel is
    // saved there as morse-back-to-back.png.
    void decodesMessagesSentBackToBack()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("led.mp4"));
        morse::SignalOptions o = signal(QStringLiteral("MC+IP192+168+100+200:"));
        o.repeatGap = 3.0;
        o.repetitions = 4;
        QVERIFY(morsetest::renderLedVideo(path, o).ok());
        MorsePanel panel;
        panel.setLoader(load);
        panel.resize(1000, 420);
        panel.show();
        QVERIFY(panel.openFile(path));
        panel.finishPlayback();
        QCOMPARE(panel.ipText(), QStringLiteral("192.168.100.200"));
        QVERIFY(panel.decoder().confident());
        const QString text =
            panel.findChild<QPlainTextEdit *>(QStringLiteral("morseText"))->toPlainText();
        // Shown with a break opportunity (zero-width space) after every ':'.
        QVERIFY2(text.contains(QStringLiteral(":\u200BMC+IP192+168+100+200:\u200BMC+IP")),
                 qPrintable(text));
        QCoreApplication::processEvents(); // the plot's queued replot
        if (const QByteArray shots = qgetenv("DRIVEBENCH_SCREENSHOT_DIR"); !shots.isEmpty())
            QVERIFY(panel.grab().save(QString::fromLocal8Bit(shots)
                                      + QStringLiteral("/morse-back-to-back.png")));
    }

    // A gap of hours between the samples of a file: playback skips it (at 8x it would wait for
    // years), and the status names the cut as the CLI does. Decoded on both sides.
    void gapInTimeIsSkippedAndNamed()
    {
        const std::vector<morse::Sample> part =
            morse::generateSignal(signal(QStringLiteral("MC+IP10+0+7+42:"))).samples;
        std::vector<morse::Sample> samples = part;
        for (const morse::Sample &s : part)
            samples.push_back({ s.t + part.back().t + 1e9, s.value });
        MorsePanel panel;
        panel.resize(1000, 420);
        panel.show();
        panel.setSource({ samples, {}, {}, 0, QStringLiteral("test") });
        QVERIFY(panel.playing());
        // Into the second part: played, not waited for.
        QTRY_VERIFY_WITH_TIMEOUT(panel.statusText().contains(QLatin1String("read as 2 recordings")),
                                 30000);
        panel.finishPlayback();
        QCOMPARE(panel.ipText(), QStringLiteral("10.0.7.42"));
        QVERIFY2(panel.statusText().startsWith(QLatin1String("Confident:"))
                     && panel.statusText().contains(
                         QStringLiteral("the recording has a 1e+09 s gap in time after sample %1")
                             .arg(part.size())),
                 qPrintable(panel.statusText()));
    }

    void failedOpenClearsThePreviousResult()
    {
        MorsePanel panel;
        panel.setLoader(load);
        morse::SignalOptions o = signal(QStringLiteral("MC+IP10+20+30+40:"));
        o.sampleRate = 60.0;
        panel.setSource({ morse::generateSignal(o).samples, {}, {}, 0, QStringLiteral("test") });
        panel.finishPlayback();
        QCOMPARE(panel.ipText(), QStringLiteral("10.20.30.40"));
        auto *connectButton = panel.findChild<QToolButton *>(QStringLiteral("morseConnect"));
        QVERIFY(connectButton->isEnabled());
        // A file that cannot be read: nothing of the previous decode is left to act on.
        QVERIFY(!panel.openFile(QStringLiteral("/nonexistent/led.mp4")));
        QVERIFY(panel.ipText().isEmpty());
        QVERIFY(!connectButton->isEnabled());
        QVERIFY(panel.findChild<QPlainTextEdit *>(QStringLiteral("morseText"))
                    ->toPlainText()
                    .isEmpty());
        QVERIFY(!panel.findChild<QLabel *>(QStringLiteral("morseIp"))
                     ->text()
                     .contains(QLatin1String("10.20.30.40")));
        QVERIFY2(panel.statusText().contains(QLatin1String("no such file")),
                 qPrintable(panel.statusText()));
    }

    void undecodableShowsReason()
    {
        MorsePanel panel;
        panel.setLoader(load);
        QVERIFY(!panel.openFile(QStringLiteral("/nonexistent/led.mp4")));
        QVERIFY(panel.statusText().contains(QLatin1String("no such file")));

        morse::SignalOptions o = signal(QStringLiteral("ST+OK+TEMP+45:"));
        o.sampleRate = 60.0;
        panel.setSource({ morse::generateSignal(o).samples, {}, {}, 0, QStringLiteral("test") });
        panel.finishPlayback();
        QVERIFY(panel.ipText().isEmpty());
        QVERIFY(!panel.findChild<QToolButton *>(QStringLiteral("morseConnect"))->isEnabled());
        QVERIFY2(panel.statusText().contains(QLatin1String("without a valid")),
                 qPrintable(panel.statusText()));

        // Only the end of the message readable: the label and the status name the octets read
        // so far.
        o.text = QStringLiteral("ST+7+42:");
        panel.setSource({ morse::generateSignal(o).samples, {}, {}, 0, QStringLiteral("test") });
        panel.finishPlayback();
        QVERIFY(!panel.findChild<QToolButton *>(QStringLiteral("morseConnect"))->isEnabled());
        QVERIFY2(panel.statusText().contains(QLatin1String("octets read so far: ?.?.7.42")),
                 qPrintable(panel.statusText()));
        const QString label = panel.findChild<QLabel *>(QStringLiteral("morseIp"))->text();
        QVERIFY2(label.contains(QLatin1String("?.?.7.42"))
                     && label.contains(QLatin1String("partly")),
                 qPrintable(label));
        QVERIFY(panel.ipText().isEmpty()); // nothing to connect to
        // Decoded at once, the threshold still is a curve (a point per 0.25 s), not one point.
        QVERIFY2(panel.plot()->graph(1)->dataCount() > 20,
                 qPrintable(QString::number(panel.plot()->graph(1)->dataCount())));
    }
};

QTEST_MAIN(TstMorsePanel)
#include "tst_morsepanel.moc"
