// Level 4: the Morse panel's live input offscreen, driven by a fake MorseLiveSource (no camera):
// samples go straight into the decoder, the IP and Connect come up while live, the plot
// scrolls, the preview shows the region, a drawn rectangle becomes the region, stopping keeps
// the result; no devices disable the camera controls with the reason; errors are shown.
// With DRIVEBENCH_SCREENSHOT_DIR set, the live panel is saved there as morse-live.png.
#include "ledvideo.h"
#include "widgets/common/plot.h"
#include "widgets/morse/morselivesource.h"
#include "widgets/morse/morsepanel.h"

#include <QComboBox>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>
#include <QToolButton>

#include <cmath>
#include <cstring>

using namespace db;
using db::widgets::MorseLiveSource;
using db::widgets::MorsePanel;

namespace {

// A scripted camera: start() succeeds or fails as told; the test emits the signals.
class FakeLiveSource : public MorseLiveSource
{
public:
    QStringList names;
    bool failStart = false;
    int started = -1;
    int stops = 0;
    QList<QRect> regions;

    QStringList devices() const override { return names; }
    bool start(int index) override
    {
        if (failStart) {
            Q_EMIT error(QStringLiteral("Camera \"%1\": Could not open device (busy)")
                             .arg(names.value(index)));
            return false;
        }
        started = index;
        return true;
    }
    void stop() override
    {
        ++stops;
        started = -1;
    }
    bool isActive() const override { return started >= 0; }
    void setRegion(const QRect &region) override { regions << region; }
};

morse::SignalOptions signal()
{
    return morsetest::ledSignal(QStringLiteral("MC+IP10+20+30+40:"), 30.0, 9, 0.3);
}

morsetest::LedScene scene()
{
    morsetest::LedScene s;
    s.width = 320;
    s.height = 240;
    s.led = QPoint(210, 90);
    s.radius = 7;
    return s;
}

// What a camera would send for frame f: its brightness sample (grey levels in the region) and
// every 8th frame a preview image with the region.
void emitFrame(FakeLiveSource &fake, morsetest::LedRenderer &renderer, int f)
{
    const morsetest::LedScene s = scene();
    const morse::Sample &x = renderer.signal().samples[std::size_t(f)];
    const double on = std::clamp(x.value, 0.0, 1.0);
    Q_EMIT fake.samples({ { x.t, s.background + s.ledOn * on * 0.6 } });
    if (f % 8 == 0 && on > 0.5) { // LED on: a telling picture
        QImage grey(s.width, s.height, QImage::Format_Grayscale8);
        std::vector<unsigned char> pixels(std::size_t(s.width * s.height));
        renderer.draw(f, pixels.data());
        for (int y = 0; y < s.height; ++y)
            std::memcpy(grey.scanLine(y), pixels.data() + y * s.width, std::size_t(s.width));
        Q_EMIT fake.preview(grey.convertToFormat(QImage::Format_RGB32),
                            QRect(s.led.x() - s.radius - 1, s.led.y() - s.radius - 1,
                                  2 * s.radius + 3, 2 * s.radius + 3));
    }
}

} // namespace

class TstMorsePanelLive : public QObject
{
    Q_OBJECT

private slots:
    void decodesLiveAndConnects()
    {
        FakeLiveSource fake;
        fake.names = QStringList { QStringLiteral("USB camera"), QStringLiteral("Laptop camera") };
        MorsePanel panel;
        panel.setLiveSource(&fake);
        panel.resize(1100, 440);
        panel.show();
        auto *cameras = panel.findChild<QComboBox *>(QStringLiteral("morseCameras"));
        auto *start = panel.findChild<QPushButton *>(QStringLiteral("morseStartCamera"));
        auto *stop = panel.findChild<QPushButton *>(QStringLiteral("morseStopCamera"));
        auto *connectButton = panel.findChild<QToolButton *>(QStringLiteral("morseConnect"));
        QCOMPARE(cameras->count(), 2);
        QVERIFY(cameras->isEnabled());
        QVERIFY(start->isEnabled());
        QVERIFY(!stop->isEnabled());
        cameras->setCurrentIndex(1);
        QTest::mouseClick(start, Qt::LeftButton);
        QCOMPARE(fake.started, 1);
        QVERIFY(panel.live());
        QVERIFY(!start->isEnabled());
        QVERIFY(stop->isEnabled());
        QVERIFY(!cameras->isEnabled());
        Q_EMIT fake.status(QStringLiteral("LED at 202,82 (17x17 px)"));
        QVERIFY(panel.findChild<QLabel *>(QStringLiteral("morseSource"))
                    ->text()
                    .contains(QLatin1String("Laptop camera\": LED at 202,82")));

        morsetest::LedRenderer renderer(signal(), scene());
        const auto &sig = renderer.signal();
        // Up to shortly after the second complete message: confident while live.
        const double until = sig.messageStarts.at(2) + 0.5;
        int f = 0;
        for (; f < renderer.frames() && sig.samples[std::size_t(f)].t < until; ++f)
            emitFrame(fake, renderer, f);
        QVERIFY(panel.live());
        QCOMPARE(panel.ipText(), QStringLiteral("10.20.30.40"));
        QVERIFY(panel.decoder().confident());
        QTRY_VERIFY(connectButton->isEnabled());
        QVERIFY(panel.findChild<QLabel *>(QStringLiteral("morseIp"))
                    ->text()
                    .contains(QLatin1String("10.20.30.40")));
        // The plot scrolls: the last 20 s.
        const QCPRange x = panel.plot()->xAxis->range();
        QVERIFY2(x.size() <= 20.01 && x.size() >= 19.0, qPrintable(QString::number(x.size())));
        QVERIFY(std::abs(x.upper - sig.samples[std::size_t(f - 1)].t) < 1e-9);
        QVERIFY(panel.plot()->graph(0)->dataCount() > 0);
        QVERIFY(!panel.findChild<QLabel *>(QStringLiteral("morseFrame"))->pixmap().isNull());
        if (const QByteArray dir = qgetenv("DRIVEBENCH_SCREENSHOT_DIR"); !dir.isEmpty()) {
            panel.plot()->replot();
            QVERIFY(panel.grab().save(QString::fromLocal8Bit(dir) + "/morse-live.png"));
        }

        // A rectangle dragged on the frame becomes the region, in preview pixels.
        auto *frame = panel.findChild<QLabel *>(QStringLiteral("morseFrame"));
        const QPoint centre = frame->contentsRect().center();
        QTest::mousePress(frame, Qt::LeftButton, {}, centre - QPoint(10, 10));
        QTest::mouseRelease(frame, Qt::LeftButton, {}, centre + QPoint(10, 10));
        QCOMPARE(fake.regions.size(), 1);
        QVERIFY(fake.regions.first().contains(QPoint(scene().width / 2, scene().height / 2)));
        QVERIFY(fake.regions.first().width() >= 10);
        QTest::mouseDClick(frame, Qt::LeftButton, {}, centre);
        QVERIFY(fake.regions.last().isEmpty()); // automatic again

        // Stop keeps the result; Connect asks for the decoded address.
        QTest::mouseClick(stop, Qt::LeftButton);
        QCOMPARE(fake.stops, 1);
        QVERIFY(!panel.live());
        QVERIFY(start->isEnabled());
        QCOMPARE(panel.ipText(), QStringLiteral("10.20.30.40"));
        QVERIFY(connectButton->isEnabled());
        const qsizetype fed = panel.plot()->graph(0)->dataCount();
        emitFrame(fake, renderer, f); // late samples after stop are ignored
        QCOMPARE(panel.plot()->graph(0)->dataCount(), fed);
        QSignalSpy spy(&panel, &MorsePanel::connectRequested);
        QTest::mouseClick(connectButton, Qt::LeftButton, {},
                          QPoint(8, connectButton->height() / 2));
        QCOMPARE(spy.size(), 1);
        QCOMPARE(spy.at(0).at(0).toString(), QStringLiteral("refgo://10.20.30.40"));
    }

    void liveHistoryIsBounded()
    {
        // A camera left running: the panel keeps only the last kLiveKeep s of samples (the
        // decoder keeps its own history), and decoding goes on.
        FakeLiveSource fake;
        fake.names = QStringList { QStringLiteral("USB camera") };
        MorsePanel panel;
        panel.setLiveSource(&fake);
        QVERIFY(panel.startLive(0));
        morsetest::LedRenderer renderer(signal(), scene());
        const auto &samples = renderer.signal().samples;
        const double length = samples.back().t + 1.0 / 30.0;
        const int loops = int(std::ceil(2.5 * MorsePanel::kLiveKeep / length));
        std::size_t sent = 0;
        double last = 0.0;
        for (int loop = 0; loop < loops; ++loop) {
            for (std::size_t i = 0; i < samples.size(); i += 10) {
                std::vector<morse::Sample> chunk;
                for (std::size_t k = i; k < std::min(samples.size(), i + 10); ++k) {
                    const double on = std::clamp(samples[k].value, 0.0, 1.0);
                    chunk.push_back({ samples[k].t + loop * length, 20.0 + 150.0 * on });
                }
                last = chunk.back().t;
                sent += chunk.size();
                Q_EMIT fake.samples(chunk);
            }
        }
        QVERIFY(last > 2.0 * MorsePanel::kLiveKeep);
        const auto &kept = panel.source().samples;
        QVERIFY(!kept.empty());
        QCOMPARE(kept.back().t, last);
        QVERIFY2(kept.front().t >= last - MorsePanel::kLiveKeep,
                 qPrintable(QString::number(kept.front().t)));
        QVERIFY(kept.size() < sent / 2);
        QVERIFY(kept.front().t - 1.0 / 30.0 < last - MorsePanel::kLiveKeep); // not more trimmed
        QCOMPARE(panel.ipText(), QStringLiteral("10.20.30.40"));
        QVERIFY(panel.decoder().confident());
    }

    void noCameraDisablesControls()
    {
        FakeLiveSource fake;
        MorsePanel panel;
        panel.setLiveSource(&fake);
        auto *cameras = panel.findChild<QComboBox *>(QStringLiteral("morseCameras"));
        auto *start = panel.findChild<QPushButton *>(QStringLiteral("morseStartCamera"));
        QVERIFY(!cameras->isEnabled());
        QVERIFY(!start->isEnabled());
        QCOMPARE(start->toolTip(), QStringLiteral("No camera found (Qt Multimedia lists none)"));
        QCOMPARE(cameras->placeholderText(), start->toolTip());
        if (const QByteArray dir = qgetenv("DRIVEBENCH_SCREENSHOT_DIR"); !dir.isEmpty()) {
            panel.resize(1100, 300);
            QVERIFY(panel.grab().save(QString::fromLocal8Bit(dir) + "/morse-nocamera.png"));
        }
        QVERIFY(!panel.startLive(0));
        QVERIFY(panel.statusText().contains(QLatin1String("No camera found")));
        QCOMPARE(fake.started, -1);

        // A camera plugged in later enables them.
        fake.names = QStringList { QStringLiteral("USB camera") };
        Q_EMIT fake.devicesChanged();
        QVERIFY(cameras->isEnabled());
        QVERIFY(start->isEnabled());

        MorsePanel bare; // no live source at all
        QVERIFY(!bare.findChild<QPushButton *>(QStringLiteral("morseStartCamera"))->isEnabled());
        QVERIFY(bare.findChild<QPushButton *>(QStringLiteral("morseStartCamera"))
                    ->toolTip()
                    .contains(QLatin1String("No camera input")));
        // As in the main window: the source is the panel's child and dies in its destructor.
        auto *child = new FakeLiveSource;
        child->setParent(&bare);
        bare.setLiveSource(child);
    }

    void errorsAreShown()
    {
        FakeLiveSource fake;
        fake.names = QStringList { QStringLiteral("USB camera") };
        MorsePanel panel;
        panel.setLiveSource(&fake);
        auto *start = panel.findChild<QPushButton *>(QStringLiteral("morseStartCamera"));

        // Refused at start.
        fake.failStart = true;
        QVERIFY(!panel.startLive(0));
        QVERIFY(!panel.live());
        QVERIFY2(panel.statusText().contains(QLatin1String("Could not open device (busy)")),
                 qPrintable(panel.statusText()));
        QVERIFY(start->isEnabled());

        // Failing while live: the panel stops and keeps the reason.
        fake.failStart = false;
        QVERIFY(panel.startLive(0));
        QVERIFY(!panel.statusText().contains(QLatin1String("busy"))); // cleared by the start
        Q_EMIT fake.error(QStringLiteral("Camera \"USB camera\" was disconnected"));
        QVERIFY(!panel.live());
        QVERIFY(start->isEnabled());
        QVERIFY(panel.statusText().contains(QLatin1String("was disconnected")));
    }
};

QTEST_MAIN(TstMorsePanelLive)
#include "tst_morsepanel_live.moc"
