// Live camera input without a camera: synthetic QVideoFrames of a blinking LED (the renderer
// of ledvideo.h, 30 fps, pixel noise) are pushed into CameraSource's QVideoSink. The LED must
// be found where it is, its samples must decode to the sent IP, static scenes must give nothing,
// a lost LED must be found again where it went, and broken frames must not crash.
#include "ledvideo.h"
#include "morse/decode/decoder.h"
#include "morse/input/camerasource.h"

#include <QSignalSpy>
#include <QTest>
#include <QVideoFrame>
#include <QVideoFrameFormat>
#include <QVideoSink>

#include <cstring>

using namespace db;
using morseio::CameraSource;
using morseio::LiveLedTracker;

namespace {

morse::SignalOptions signal(const QString &text, unsigned seed = 3)
{
    return morsetest::ledSignal(text, 30.0, seed);
}

morsetest::LedScene scene(QPoint led)
{
    morsetest::LedScene s;
    s.width = 320; // larger than the analysis width: the frames are scaled down
    s.height = 240;
    s.led = led;
    s.radius = 6;
    return s;
}

// One synthetic frame in `format` (Y8: the grey bytes; YUYV/UYVY: grey luma, neutral chroma;
// XRGB8888: grey in all channels) with its start time in microseconds.
QVideoFrame makeFrame(morsetest::LedRenderer &renderer, const morsetest::LedScene &s, int f,
                      QVideoFrameFormat::PixelFormat format)
{
    std::vector<unsigned char> grey(std::size_t(s.width * s.height));
    renderer.draw(f, grey.data());
    QVideoFrame frame(QVideoFrameFormat(QSize(s.width, s.height), format));
    if (!frame.map(QVideoFrame::WriteOnly))
        return {};
    const int stride = frame.bytesPerLine(0);
    for (int y = 0; y < s.height; ++y) {
        uchar *row = frame.bits(0) + qint64(y) * stride;
        const unsigned char *src = grey.data() + std::size_t(y * s.width);
        if (format == QVideoFrameFormat::Format_Y8) {
            std::memcpy(row, src, std::size_t(s.width));
        } else if (format == QVideoFrameFormat::Format_YUYV
                   || format == QVideoFrameFormat::Format_UYVY) {
            const int luma = format == QVideoFrameFormat::Format_UYVY ? 1 : 0;
            for (int x = 0; x < s.width; ++x) {
                row[2 * x + luma] = src[x];
                row[2 * x + 1 - luma] = 128; // no colour
            }
        } else {
            for (int x = 0; x < s.width; ++x)
                std::memset(row + 4 * x, src[x], 4);
        }
    }
    frame.unmap();
    frame.setStartTime(qint64(renderer.signal().samples[std::size_t(f)].t * 1e6));
    return frame;
}

struct Collected
{
    std::vector<morse::Sample> samples;
    std::vector<QRect> previewRegions;
    QStringList statuses;
    QStringList errors;
};

void collect(CameraSource &source, Collected &c)
{
    QObject::connect(&source, &CameraSource::samplesReady, &source,
                     [&c](const std::vector<morse::Sample> &s) {
                         c.samples.insert(c.samples.end(), s.begin(), s.end());
                     });
    QObject::connect(&source, &CameraSource::previewReady, &source,
                     [&c](const QImage &image, const QRect &r) {
                         QVERIFY(!image.isNull());
                         QVERIFY(image.width() <= CameraSource::kPreviewWidth);
                         c.previewRegions.push_back(r);
                     });
    QObject::connect(&source, &CameraSource::statusChanged, &source,
                     [&c](const QString &s) { c.statuses << s; });
    QObject::connect(&source, &CameraSource::errorOccurred, &source,
                     [&c](const QString &s) { c.errors << s; });
}

QRect ledRect(const morsetest::LedScene &s)
{
    return QRect(s.led.x() - s.radius, s.led.y() - s.radius, 2 * s.radius + 1, 2 * s.radius + 1);
}

} // namespace

class TstCameraSource : public QObject
{
    Q_OBJECT

private slots:
    void decodesBlinkingLed_data()
    {
        QTest::addColumn<int>("format");
        QTest::newRow("Y8") << int(QVideoFrameFormat::Format_Y8);
        QTest::newRow("XRGB8888") << int(QVideoFrameFormat::Format_XRGB8888);
        QTest::newRow("YUYV") << int(QVideoFrameFormat::Format_YUYV);
        QTest::newRow("UYVY") << int(QVideoFrameFormat::Format_UYVY);
    }

    void decodesBlinkingLed()
    {
        QFETCH(int, format);
        const morsetest::LedScene s = scene(QPoint(236, 70));
        morsetest::LedRenderer renderer(signal(QStringLiteral("MC+IP10+20+30+40:")), s);
        CameraSource source;
        Collected c;
        collect(source, c);
        for (int f = 0; f < renderer.frames(); ++f) {
            const QVideoFrame frame =
                makeFrame(renderer, s, f, QVideoFrameFormat::PixelFormat(format));
            QVERIFY(frame.isValid());
            source.videoSink()->setVideoFrame(frame);
            // Nothing before the search window is full.
            if (f < int(LiveLedTracker::kWindow * 30.0) - 2)
                QVERIFY(c.samples.empty());
        }
        QVERIFY2(c.errors.isEmpty(), qPrintable(c.errors.join(QLatin1Char('\n'))));
        QCOMPARE(source.state(), LiveLedTracker::State::Tracking);
        QCOMPARE(source.frameSize(), QSize(s.width, s.height));
        QVERIFY2(source.region().intersects(ledRect(s)),
                 qPrintable(QStringLiteral("%1,%2 %3x%4")
                                .arg(source.region().x())
                                .arg(source.region().y())
                                .arg(source.region().width())
                                .arg(source.region().height())));
        QVERIFY(source.region().width() < s.width / 4);
        // Every frame is a sample, the search window included.
        QCOMPARE(int(c.samples.size()), renderer.frames());
        for (std::size_t i = 1; i < c.samples.size(); ++i)
            QVERIFY(c.samples[i].t > c.samples[i - 1].t);
        QCOMPARE(c.samples.front().t, 0.0);

        morse::Decoder decoder;
        decoder.feed(c.samples);
        decoder.finish();
        QCOMPARE(decoder.ip().toString(), QStringLiteral("10.20.30.40"));
        QVERIFY(decoder.confident());

        // Previews at <= kPreviewHz of frame time, the later ones with the region.
        const double seconds = c.samples.back().t;
        QVERIFY(int(c.previewRegions.size()) <= int(seconds * CameraSource::kPreviewHz) + 2);
        QVERIFY(c.previewRegions.size() > 10);
        QVERIFY(c.previewRegions.front().isEmpty());
        QVERIFY(!c.previewRegions.back().isEmpty());
        QVERIFY(c.statuses.first().contains(QLatin1String("Searching")));
        QVERIFY(c.statuses.last().contains(QLatin1String("LED at")));
    }

    void staticSceneGivesNoRegion()
    {
        morsetest::LedScene s = scene(QPoint(236, 70));
        s.ledVisible = false;
        morse::SignalOptions o = signal(QStringLiteral("MC+IP1+2+3+4:"));
        o.repetitions = 1;
        morsetest::LedRenderer renderer(o, s);
        CameraSource source;
        Collected c;
        collect(source, c);
        for (int f = 0; f < std::min(renderer.frames(), 20 * 30); ++f)
            source.consumeFrame(makeFrame(renderer, s, f, QVideoFrameFormat::Format_Y8));
        QVERIFY(c.samples.empty());
        QVERIFY(source.region().isEmpty());
        QCOMPARE(source.state(), LiveLedTracker::State::Searching);
        QVERIFY(!c.previewRegions.empty());
        QVERIFY(c.errors.isEmpty());
    }

    void userRegionSamplesAtOnce()
    {
        const morsetest::LedScene s = scene(QPoint(60, 180));
        morsetest::LedRenderer renderer(signal(QStringLiteral("MC+IP1+2+3+4:")), s);
        CameraSource source;
        Collected c;
        collect(source, c);
        source.setRegion(ledRect(s));
        for (int f = 0; f < 10; ++f)
            source.consumeFrame(makeFrame(renderer, s, f, QVideoFrameFormat::Format_Y8));
        QCOMPARE(int(c.samples.size()), 10);
        QVERIFY(source.region().intersects(ledRect(s)));
        QVERIFY(c.statuses.last().contains(QLatin1String("your region")));

        // A region outside the frame is refused with its reason in the status; the camera keeps
        // running and the search takes over, then finds the LED by itself.
        source.setRegion(QRect(1000, 1000, 10, 10));
        QVERIFY2(c.errors.isEmpty(), qPrintable(c.errors.join(QLatin1Char('\n'))));
        QVERIFY2(c.statuses.last().contains(QLatin1String("outside the 320x240")),
                 qPrintable(c.statuses.last()));
        QCOMPARE(source.state(), LiveLedTracker::State::Searching);
        const int reasons = int(c.statuses.size());
        source.consumeFrame(makeFrame(renderer, s, 10, QVideoFrameFormat::Format_Y8));
        QCOMPARE(int(c.statuses.size()), reasons); // the reason is not replaced at once
        for (int f = 11; f < 11 + int(LiveLedTracker::kWindow * 30.0) + 30; ++f)
            source.consumeFrame(makeFrame(renderer, s, f, QVideoFrameFormat::Format_Y8));
        QCOMPARE(source.state(), LiveLedTracker::State::Tracking);
        QVERIFY(source.region().intersects(ledRect(s)));
        QVERIFY(c.errors.isEmpty());
    }

    void lostLedIsFoundAgain()
    {
        // The camera moves: the LED blinks at one spot, then at another. The old region goes
        // flat, is dropped after kDeadAfter s, and the new spot is found.
        morsetest::LedScene a = scene(QPoint(40, 40));
        morsetest::LedScene b = scene(QPoint(270, 200));
        a.width = b.width = 160;
        a.height = b.height = 120;
        a.led = QPoint(30, 30);
        b.led = QPoint(130, 90);
        morse::SignalOptions o = signal(QStringLiteral("MC+IP10+20+30+40:"));
        o.repetitions = 4;
        morsetest::LedRenderer ra(o, a);
        morsetest::LedRenderer rb(o, b);
        CameraSource source;
        Collected c;
        collect(source, c);
        const int switchAt = 12 * 30;
        bool sawLost = false;
        for (int f = 0; f < ra.frames(); ++f) {
            const QVideoFrame fa = makeFrame(ra, a, f, QVideoFrameFormat::Format_Y8);
            const QVideoFrame fb = makeFrame(rb, b, f, QVideoFrameFormat::Format_Y8);
            source.consumeFrame(f < switchAt ? fa : fb);
            if (f == switchAt - 1)
                QVERIFY(source.region().intersects(ledRect(a)));
            sawLost = sawLost || source.state() == LiveLedTracker::State::Lost;
        }
        QVERIFY(sawLost);
        QVERIFY(c.statuses.join(QLatin1Char('|')).contains(QLatin1String("LED lost")));
        QCOMPARE(source.state(), LiveLedTracker::State::Tracking);
        QVERIFY(source.region().intersects(ledRect(b)));
        for (std::size_t i = 1; i < c.samples.size(); ++i)
            QVERIFY(c.samples[i].t > c.samples[i - 1].t);
    }

    void brokenFramesDoNotCrash()
    {
        CameraSource source;
        Collected c;
        collect(source, c);
        source.consumeFrame(QVideoFrame()); // what the sink sends when a camera stops
        source.videoSink()->setVideoFrame(QVideoFrame());
        // JPEG frames with garbage: mappable, not decodable; reported once after a run of them.
        for (int i = 0; i < CameraSource::kBadFramesForError + 5; ++i) {
            QVideoFrame jpeg(QVideoFrameFormat(QSize(64, 48), QVideoFrameFormat::Format_Jpeg));
            if (jpeg.map(QVideoFrame::WriteOnly)) {
                std::memset(jpeg.bits(0), 0x5a, std::size_t(jpeg.mappedBytes(0)));
                jpeg.unmap();
            }
            source.consumeFrame(jpeg);
        }
        QVERIFY(c.samples.empty());
        QCOMPARE(c.errors.size(), 1);
        QVERIFY2(c.errors.first().contains(QLatin1String("cannot be read")),
                 qPrintable(c.errors.first()));
        // Frames going back in time are dropped, not passed on as non-increasing samples.
        const morsetest::LedScene s = scene(QPoint(100, 100));
        morsetest::LedRenderer renderer(signal(QStringLiteral("MC+IP1+2+3+4:")), s);
        source.reset();
        source.setRegion(ledRect(s));
        QVideoFrame f1 = makeFrame(renderer, s, 5, QVideoFrameFormat::Format_Y8);
        QVideoFrame f0 = makeFrame(renderer, s, 4, QVideoFrameFormat::Format_Y8);
        source.consumeFrame(f1);
        source.consumeFrame(f0);
        source.consumeFrame(f1);
        QCOMPARE(int(c.samples.size()), 1);
    }

    void noCameraIsAnError()
    {
        CameraSource source;
        QSignalSpy errors(&source, &CameraSource::errorOccurred);
        (void)CameraSource::devices(); // lists without a camera, without crashing
        QVERIFY(!source.start(QCameraDevice()));
        QCOMPARE(errors.size(), 1);
        QVERIFY(errors.first().first().toString().contains(QLatin1String("No camera found")));
        QVERIFY(!source.isActive());
        source.stop(); // idempotent
    }
};

QTEST_MAIN(TstCameraSource)
#include "tst_camerasource.moc"
