// Level 4: the scope plot and page offscreen, on synthetic recordings (Recorder::load) and on a
// FakeConnection for live polling and drops.
#include "canopen/canopenconnection.h"
#include "canopen/nmtmaster.h"
#include "canopen/nodemonitor.h"
#include "common/protocols.h"
#include "common/simnodes.h"
#include "fakeconnection.h"
#include "resources/builtindescriptions.h"
#include "scope/csv.h"
#include "scope/recorder.h"
#include "transport/canbus.h"
#include "widgets/common/plot.h"
#include "widgets/scope/scopeanalysisdialog.h"
#include "widgets/scope/scopechannelmodel.h"
#include "widgets/scope/scopecursors.h"
#include "widgets/scope/scopemeasurements.h"
#include "widgets/scope/scopepage.h"
#include "widgets/scope/scopeplot.h"

#include <QComboBox>
#include <QDir>
#include <QImage>
#include <QLabel>
#include <QMimeData>
#include <QSignalSpy>
#include <QTableView>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace db;
using namespace db::widgets;

namespace {

// Channel 0: "position" = 2 * t (inc); channel 1: "current" = 100 * sin(2 pi t) (mA); samples
// every 1 ms over [0, 10] s; the current has a gap (lost samples) at t = 5 s.
scope::Recording syntheticRecording(qint64 samples = 10001)
{
    scope::Recording rec;
    rec.device = QStringLiteral("fake://device");
    rec.startedAt = QDateTime::currentDateTimeUtc();
    scope::RecordedChannel position;
    position.info.id = QStringLiteral("6064:0");
    position.info.address = ObjectAddress(0x6064, 0);
    position.info.name = QStringLiteral("Position actual value");
    position.info.unit = QStringLiteral("inc");
    position.info.device = rec.device;
    position.buffer.setCapacity(samples);
    scope::RecordedChannel current;
    current.info.id = QStringLiteral("6078:0");
    current.info.address = ObjectAddress(0x6078, 0);
    current.info.name = QStringLiteral("Current actual value");
    current.info.unit = QStringLiteral("mA");
    current.info.device = rec.device;
    current.buffer.setCapacity(samples);
    for (qint64 i = 0; i < samples; ++i) {
        const double t = double(i) * 1e-3;
        position.buffer.append(t, 2.0 * t);
        if (i == samples / 2)
            current.buffer.markLost(10);
        current.buffer.append(t, std::round(100.0 * std::sin(2.0 * M_PI * t)));
    }
    rec.channels = { position, current };
    return rec;
}

double graphMax(const QCPGraph *g)
{
    double m = -INFINITY;
    for (auto it = g->data()->constBegin(); it != g->data()->constEnd(); ++it) {
        if (!std::isnan(it->value))
            m = std::max(m, it->value);
    }
    return m;
}

} // namespace

class TstScopeView : public QObject
{
    Q_OBJECT

private slots:
    void channelsAppearWithGapsAndDecimation()
    {
        ScopePage page;
        page.resize(1200, 700);
        page.recorder()->load(syntheticRecording(1'000'001)); // 1e6 samples per channel
        page.plot()->refreshNow();
        QCOMPARE(page.channelModel()->rowCount(), 2);
        QVERIFY(page.plot()->graph(0));
        QVERIFY(page.plot()->graph(1));
        QCOMPARE(page.plot()->lanes(), QList<int>({ 1, 2 })); // inc and mA: an axis each
        // Decimated to the pixels: about two points per column, not a million.
        const int points = page.plot()->graph(0)->data()->size();
        QVERIFY2(points > 100 && points < 5000, qPrintable(QString::number(points)));
        QCOMPARE(graphMax(page.plot()->graph(0)), 2.0 * 1000.0);
        // The lost samples of the current are a break (NaN) in its line.
        int breaks = 0;
        const QCPGraph *current = page.plot()->graph(1);
        for (auto it = current->data()->constBegin(); it != current->data()->constEnd(); ++it)
            breaks += std::isnan(it->value) ? 1 : 0;
        QCOMPARE(breaks, 1);
        // The whole recording is in view after loading.
        QCOMPARE(page.plot()->timeLower(), 0.0);
        QCOMPARE(page.plot()->timeUpper(), 1000.0);
    }

    void onlySparseLinesAreAntialiased()
    {
        // Antialiasing a dense line costs most of a frame (the stroker) and shows only where
        // samples lie pixels apart.
        ScopePage page;
        page.resize(1200, 700);
        page.show();
        QVERIFY(QTest::qWaitForWindowExposed(&page));
        page.recorder()->load(syntheticRecording());
        page.plot()->refreshNow();
        page.plot()->customPlot()->replot(); // lays the lanes out
        const QCPGraph *g = page.plot()->graph(0);
        const int columns = g->keyAxis()->axisRect()->width();
        QVERIFY(columns > 500);
        page.plot()->setTimeRange(1.0, 1.0 + columns * 1e-3); // a raw sample per column
        QVERIFY(g->data()->size() > columns / 2);
        QVERIFY(!g->antialiased());
        QCOMPARE(g->pen().widthF(), 1.0);
        page.plot()->setTimeRange(1.0, 1.0 + columns * 1e-4); // ten columns per sample
        QVERIFY(g->antialiased());
        QVERIFY(g->pen().widthF() > 1.0);
    }

    void separateLanesShareTheTimeAxis()
    {
        ScopePage page;
        page.recorder()->load(syntheticRecording());
        ScopeChannelModel *model = page.channelModel();
        // Merged into one axis by the user, then apart again.
        QVERIFY(model->setData(model->index(1, ScopeChannelModel::Lane), 1, Qt::EditRole));
        page.plot()->refreshNow();
        QCOMPARE(page.plot()->lanes(), QList<int>({ 1 }));
        QVERIFY(model->setData(model->index(1, ScopeChannelModel::Lane), 2, Qt::EditRole));
        QVERIFY(!model->setData(model->index(1, ScopeChannelModel::Lane), 9, Qt::EditRole));
        page.plot()->refreshNow();
        QCOMPARE(page.plot()->lanes(), QList<int>({ 1, 2 }));
        QCPAxisRect *lane2 = page.plot()->laneRect(2);
        QVERIFY(lane2);
        QCOMPARE(page.plot()->graph(1)->valueAxis(), lane2->axis(QCPAxis::atLeft));
        page.plot()->setTimeRange(2.0, 3.0);
        QCOMPARE(lane2->axis(QCPAxis::atBottom)->range().lower, 2.0);
        QCOMPARE(page.plot()->laneRect(1)->axis(QCPAxis::atBottom)->range().upper, 3.0);
        QVERIFY(!page.plot()->isFollowing());
        QVERIFY(lane2->axis(QCPAxis::atLeft)->label().contains(QStringLiteral("mA")));
    }

    void cursorsMeasureAKnownRecording()
    {
        ScopePage page;
        page.recorder()->load(syntheticRecording());
        page.plot()->refreshNow();
        page.setCursorsEnabled(true);
        page.plot()->cursors()->setPositions(2.0, 4.0);
        ScopeMeasurements *m = page.measurements();
        QTRY_COMPARE(m->table()->rowCount(), 2);
        QTRY_COMPARE(m->value(0, ScopeMeasurements::AtA), 4.0);
        QCOMPARE(m->value(0, ScopeMeasurements::AtB), 8.0);
        QCOMPARE(m->value(0, ScopeMeasurements::Dy), 4.0);
        QVERIFY(std::abs(m->value(0, ScopeMeasurements::Mean) - 6.0) < 1e-9);
        QCOMPARE(m->value(0, ScopeMeasurements::Min), 4.0);
        QCOMPARE(m->value(0, ScopeMeasurements::Max), 8.0);
        QCOMPARE(m->value(0, ScopeMeasurements::PeakToPeak), 4.0);
        // RMS of 2t over [2, 4] = sqrt(4 * (4^3 - 2^3) / 3 / 2) = 6.1101
        QVERIFY(std::abs(m->value(0, ScopeMeasurements::Rms) - std::sqrt(4.0 * 56.0 / 6.0)) < 1e-3);
        // The sine: two full periods between the cursors -> mean ~0, peak-peak 200.
        QVERIFY(std::abs(m->value(1, ScopeMeasurements::Mean)) < 0.5);
        QCOMPARE(m->value(1, ScopeMeasurements::PeakToPeak), 200.0);
        QVERIFY(m->summary()->text().contains(QStringLiteral("2 s")));
        QVERIFY(m->summary()->text().contains(QStringLiteral("0.5 Hz")));
    }

    void cursorIsDraggedWithTheMouse()
    {
        ScopePage page;
        page.resize(1200, 700);
        page.show();
        QVERIFY(QTest::qWaitForWindowExposed(&page));
        page.recorder()->load(syntheticRecording());
        page.plot()->refreshNow();
        page.setCursorsEnabled(true);
        page.plot()->cursors()->setPositions(2.0, 8.0);
        QCustomPlot *plot = page.plot()->customPlot();
        plot->replot();
        QCPAxisRect *rect = page.plot()->laneRect(1);
        QCPAxis *x = rect->axis(QCPAxis::atBottom);
        const int y = rect->center().y();
        const QPoint from(int(std::round(x->coordToPixel(2.0))), y);
        const QPoint to(int(std::round(x->coordToPixel(5.0))), y);
        QTest::mousePress(plot, Qt::LeftButton, {}, from);
        QTest::mouseMove(plot, to);
        QTest::mouseRelease(plot, Qt::LeftButton, {}, to);
        QVERIFY2(std::abs(page.plot()->cursors()->a() - 5.0) < 0.05,
                 qPrintable(QString::number(page.plot()->cursors()->a())));
        QCOMPARE(page.plot()->cursors()->b(), 8.0);
        // The drag moved the cursor, not the view.
        QCOMPARE(x->range().lower, 0.0);
    }

    void rubberBandAndWheelZoomTime()
    {
        ScopePage page;
        page.resize(1200, 700);
        page.show();
        QVERIFY(QTest::qWaitForWindowExposed(&page));
        page.recorder()->load(syntheticRecording());
        page.plot()->refreshNow();
        QCustomPlot *plot = page.plot()->customPlot();
        plot->replot();
        QCPAxisRect *rect = page.plot()->laneRect(1);
        QCPAxis *x = rect->axis(QCPAxis::atBottom);
        const QPoint from(int(x->coordToPixel(2.0)), rect->top() + 20);
        const QPoint to(int(x->coordToPixel(4.0)), rect->bottom() - 20);
        QTest::mousePress(plot, Qt::LeftButton, Qt::ShiftModifier, from);
        QTest::mouseMove(plot, to);
        QTest::mouseRelease(plot, Qt::LeftButton, Qt::ShiftModifier, to);
        QVERIFY2(std::abs(page.plot()->timeLower() - 2.0) < 0.05,
                 qPrintable(QString::number(page.plot()->timeLower())));
        QVERIFY(std::abs(page.plot()->timeUpper() - 4.0) < 0.05);
        QVERIFY(!page.plot()->isFollowing());
        // The zoomed view is decimated anew for its range (one sample beyond each edge).
        const double firstKey = page.plot()->graph(0)->data()->constBegin()->key;
        QVERIFY2(firstKey <= page.plot()->timeLower() && firstKey > page.plot()->timeLower() - 0.01,
                 qPrintable(QString::number(firstKey)));

        // Wheel: zooms time only, around the mouse.
        const double span = page.plot()->timeUpper() - page.plot()->timeLower();
        const std::pair<double, double> before(rect->axis(QCPAxis::atLeft)->range().lower,
                                               rect->axis(QCPAxis::atLeft)->range().upper);
        QWheelEvent wheel(QPointF(rect->center()), plot->mapToGlobal(QPointF(rect->center())),
                          QPoint(), QPoint(0, 120), Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase,
                          false);
        QCoreApplication::sendEvent(plot, &wheel);
        QVERIFY(page.plot()->timeUpper() - page.plot()->timeLower() < span * 0.95);
        QCOMPARE(rect->axis(QCPAxis::atLeft)->range().lower, before.first);

        // Autoscale brings the whole recording back and follows again.
        page.plot()->autoscale();
        QCOMPARE(page.plot()->timeLower(), 0.0);
        QVERIFY(page.plot()->isFollowing());
    }

    void visibilityAndScalingChangeTheView()
    {
        ScopePage page;
        page.recorder()->load(syntheticRecording());
        page.plot()->refreshNow();
        page.setCursorsEnabled(true);
        page.plot()->cursors()->setPositions(2.0, 4.0);
        ScopeChannelModel *model = page.channelModel();

        QVERIFY(model->setData(model->index(0, ScopeChannelModel::Name), Qt::Unchecked,
                               Qt::CheckStateRole));
        page.plot()->refreshNow();
        QVERIFY(!page.plot()->graph(0));
        QVERIFY(page.plot()->graph(1));
        QTRY_COMPARE(page.measurements()->table()->rowCount(), 1);
        QVERIFY(model->setData(model->index(0, ScopeChannelModel::Name), Qt::Checked,
                               Qt::CheckStateRole));

        // Display scaling after recording: raw values stay, the view and measurements change.
        QVERIFY(model->setData(model->index(0, ScopeChannelModel::Scale), 0.5, Qt::EditRole));
        QVERIFY(model->setData(model->index(0, ScopeChannelModel::Offset), 100.0, Qt::EditRole));
        QVERIFY(!model->setData(model->index(0, ScopeChannelModel::Scale), 0.0, Qt::EditRole));
        page.plot()->refreshNow();
        QCOMPARE(graphMax(page.plot()->graph(0)), 2.0 * 10.0 * 0.5 + 100.0);
        QCOMPARE(page.recorder()->buffer(0).value(1000), 2.0);
        QTRY_COMPARE(page.measurements()->value(0, ScopeMeasurements::AtA), 4.0 * 0.5 + 100.0);

        // Colour of a channel.
        ScopeChannelStyle style = page.plot()->channelStyle(1);
        style.color = QColor(Qt::magenta);
        page.plot()->setChannelStyle(1, style);
        page.plot()->refreshNow();
        QCOMPARE(page.plot()->graph(1)->pen().color(), QColor(Qt::magenta));
    }

    void analysisOfTheCursorRange()
    {
        ScopePage page;
        page.recorder()->load(syntheticRecording());
        page.plot()->refreshNow();
        auto *view = page.findChild<QTableView *>(QStringLiteral("scopeChannels"));
        QVERIFY(view);
        view->setCurrentIndex(page.channelModel()->index(1, 0));
        page.setCursorsEnabled(true);
        page.plot()->cursors()->setPositions(0.0, 4.0); // four periods of the 1 Hz sine
        page.showAnalysis();
        auto *dialog = page.findChild<ScopeAnalysisDialog *>();
        QVERIFY(dialog);
        QVERIFY2(dialog->spectrum().ok(), qPrintable(dialog->spectrum().error().toString()));
        QVERIFY2(std::abs(dialog->spectrum()->peakFrequency() - 1.0) < 0.3,
                 qPrintable(QString::number(dialog->spectrum()->peakFrequency())));
        QCOMPARE(dialog->statistics().count, 4001);
        QCOMPARE(dialog->statistics().max, 100.0);
        QVERIFY(dialog->spectrumPlot()->graphCount() == 1);
        dialog->close();
    }

    void replotsAreCoalesced()
    {
        ScopePage page;
        page.resize(1000, 600);
        page.show();
        QVERIFY(QTest::qWaitForWindowExposed(&page));
        page.recorder()->load(syntheticRecording());
        QSignalSpy replots(page.plot()->customPlot(), &QCustomPlot::afterReplot);
        QVERIFY(replots.wait(2000)); // the first frame after loading
        replots.clear();
        const int rounds = 5;
        for (int r = 0; r < rounds; ++r) {
            for (int i = 0; i < 500; ++i)
                Q_EMIT page.recorder()->dataAppended(); // a burst of batches
            QVERIFY(replots.wait(2000));
        }
        // One replot per frame, not per batch (2500 batches here).
        QVERIFY2(replots.size() <= rounds + 1, qPrintable(QString::number(replots.size())));

        // Hidden: no replot at all, whatever arrives, and no frame timer.
        QVERIFY(page.plot()->isRefreshing());
        page.hide();
        QVERIFY(!page.plot()->isRefreshing());
        replots.clear();
        for (int i = 0; i < 100; ++i)
            Q_EMIT page.recorder()->dataAppended();
        QVERIFY(!replots.wait(3 * 1000 / ScopePlot::kReplotHz + 100));
        // Shown again: it catches up.
        page.show();
        QVERIFY(replots.wait(2000));
    }

    void dropOfObjectsCreatesChannels()
    {
        test::FakeConnection connection;
        connection.setValue({ 0x6064, 0 }, qint64(1234));
        connection.setValue({ 0x6078, 0 }, qint64(-56));
        connection.open();
        QTRY_VERIFY(connection.isConnected());
        ScopePage page;
        page.setConnection(&connection);

        QMimeData mime;
        mime.setData(QString::fromLatin1(ScopePage::kObjectsMimeType), "6064:0\n6078:0\n");
        QDropEvent drop(QPointF(10, 10), Qt::CopyAction, &mime, Qt::LeftButton, {});
        QDragEnterEvent enter(QPoint(10, 10), Qt::CopyAction, &mime, Qt::LeftButton, {});
        QCoreApplication::sendEvent(&page, &enter);
        QVERIFY(enter.isAccepted());
        QCoreApplication::sendEvent(&page, &drop);
        QCOMPARE(page.recorder()->channelCount(), 2);
        QCOMPARE(page.recorder()->channelInfo(0).id, QStringLiteral("6064:0"));
        QCOMPARE(page.recorder()->channelInfo(1).id, QStringLiteral("6078:0"));

        // Again: already there, named in the status line; a bad line names itself.
        QDragEnterEvent enterAgain(QPoint(10, 10), Qt::CopyAction, &mime, Qt::LeftButton, {});
        QCoreApplication::sendEvent(&page, &enterAgain);
        QDropEvent again(QPointF(10, 10), Qt::CopyAction, &mime, Qt::LeftButton, {});
        QCoreApplication::sendEvent(&page, &again);
        QCOMPARE(page.recorder()->channelCount(), 2);
        QVERIFY2(page.statusText().contains(QStringLiteral("already")),
                 qPrintable(page.statusText()));
        QMimeData bad;
        bad.setData(QString::fromLatin1(ScopePage::kObjectsMimeType), "6064:0\nxyz:q\n");
        QVERIFY(!ScopePage::parseObjects(&bad));
        QVERIFY(ScopePage::parseObjects(&bad).error().message().contains(QStringLiteral("line 2")));

        // Record them live (Run mode), then stop: samples arrive and are drawn.
        page.start();
        QCOMPARE(page.recorder()->state(), scope::Recorder::State::Recording);
        QTRY_VERIFY_WITH_TIMEOUT(page.recorder()->buffer(1).size() >= 20, 10000);
        page.stop();
        QCOMPARE(page.recorder()->state(), scope::Recorder::State::Stopped);
        QCOMPARE(page.recorder()->buffer(0).value(0), 1234.0);
        page.plot()->refreshNow();
        QVERIFY(page.plot()->graph(1)->data()->size() > 0);
        QVERIFY(page.removeChannel(0));
        QCOMPARE(page.recorder()->channelCount(), 1);
    }

    void pdoChannelsFromASimulatedNode()
    {
        app::SimNodes sim;
        QVERIFY(sim.create({ { 5 }, {}, {} }).ok());
        QVERIFY(sim.startSlcan(0).ok());
        auto made = app::protocolRegistry().create(
            QStringLiteral("canopen+slcan://127.0.0.1:%1?node=5").arg(sim.slcanPort()));
        QVERIFY(made.ok());
        auto *connection = qobject_cast<canopen::CanopenConnection *>(made->get());
        QVERIFY(connection);
        connection->setDictionary(
            resources::builtinDescription(QStringLiteral("drivebench_testnode")).valueOr({}));
        connection->open();
        QTRY_VERIFY(connection->isConnected());
        // The device side, as a PLC would set it up: TPDO1 (6041:0, 6064:0) every 20 ms.
        QVERIFY(Reply::wait(connection->write({ 0x1800, 5 }, 20)).ok());
        QVERIFY(connection->nmt()->start(5));

        ScopePage page;
        page.setConnection(connection);
        auto *sourceBox = page.findChild<QComboBox *>(QStringLiteral("scopeSource"));
        QVERIFY(sourceBox && sourceBox->isVisibleTo(&page));
        page.setChannelSource(ScopePage::ChannelSource::Pdo);
        QSignalSpy looked(&page, &ScopePage::pdoLookupFinished);
        page.addPdoChannels({ ObjectAddress(0x6064, 0), ObjectAddress(0x2103, 0) });
        QVERIFY(looked.wait(5000));
        QCOMPARE(looked.takeFirst().at(0).toBool(), false); // 2103:0 is in no TPDO
        QVERIFY2(page.statusText().contains(
                     QStringLiteral("2103:0 Test integer32 is in no TPDO of node 5")),
                 qPrintable(page.statusText()));
        QCOMPARE(page.recorder()->channelCount(), 1);
        QCOMPARE(page.unmappedObjects(), QList<ObjectAddress> { ObjectAddress(0x2103, 0) });
        const auto mapping = page.pdoMapping(QStringLiteral("6064:0"));
        QVERIFY(mapping);
        QCOMPARE(mapping->cobId, 0x185u);
        QCOMPARE(mapping->byteOffset, 2);
        QCOMPARE(mapping->expectedPeriodMs, 20);
        auto *table = page.findChild<QTableView *>(QStringLiteral("scopeChannels"));
        QCOMPARE(table->model()->index(0, ScopeChannelModel::Rate).data().toString(),
                 QStringLiteral("PDO 0x185"));

        // Opt-in: TPDO2 now carries 2103:0 every 20 ms; it becomes a PDO channel.
        page.mapToTpdo(1, 20);
        QVERIFY(looked.wait(5000));
        QCOMPARE(looked.takeFirst().at(0).toBool(), true);
        QCOMPARE(page.recorder()->channelCount(), 2);
        QCOMPARE(page.pdoMapping(QStringLiteral("2103:0"))->cobId, 0x285u);
        QVERIFY(page.unmappedObjects().isEmpty());

        // Recording is passive: samples arrive and the page sends nothing.
        int sent = 0;
        connect(connection->bus(), &CanBus::frameSent, this, [&] { ++sent; });
        page.start();
        QCOMPARE(page.recorder()->state(), scope::Recorder::State::Recording);
        QTRY_VERIFY_WITH_TIMEOUT(page.recorder()->buffer(0).size() >= 10
                                     && page.recorder()->buffer(1).size() >= 10,
                                 10000);
        page.stop();
        QCOMPARE(sent, 0);
        QCOMPARE(page.recorder()->buffer(0).value(0), 1234.0);
        QCOMPARE(page.recorder()->buffer(1).value(0), -100000.0);
        QCOMPARE(page.recorder()->channelInfo(0).name, QStringLiteral("Position actual value"));

        // A pre-operational node sends no PDO: the page says why (from the node's heartbeat).
        QVERIFY(connection->nmt()->enterPreOperational(5));
        QTRY_COMPARE(connection->monitor()->state(5), canopen::NmtState::PreOperational);
        page.start();
        QTRY_VERIFY_WITH_TIMEOUT(page.statusText().contains(QStringLiteral(
                                     "node 5 is pre-operational (heartbeat), not operational: "
                                     "NMT start it")),
                                 5000);
        QVERIFY(page.statusText().contains(QStringLiteral("6064:0, 2103:0")));
        page.stop();
        connection->close();
    }

    // Two CANopen nodes on one bus, the same objects from each as PDO channels of one
    // recording: each channel samples its own node's PDO, is named with its node, and keeps
    // its own values and mapping in the page and in the file.
    void pdoChannelsFromTwoNodesSideBySide()
    {
        app::SimNodes sim;
        QVERIFY(sim.create({ { 5, 6 }, {}, {} }).ok());
        QVERIFY(sim.startSlcan(0).ok());
        const ObjectDictionary dict =
            resources::builtinDescription(QStringLiteral("drivebench_testnode")).valueOr({});
        std::vector<std::shared_ptr<DeviceConnection>> made;
        QList<canopen::CanopenConnection *> nodes;
        for (int node : { 5, 6 }) {
            auto c = app::protocolRegistry().create(QStringLiteral("canopen+slcan://127.0.0.1:%1"
                                                                   "?node=%2")
                                                        .arg(sim.slcanPort())
                                                        .arg(node));
            QVERIFY(c.ok());
            made.push_back(*c);
            auto *connection = qobject_cast<canopen::CanopenConnection *>(c->get());
            QVERIFY(connection);
            connection->setDictionary(dict);
            connection->open();
            QTRY_VERIFY(connection->isConnected());
            // The device side: TPDO1 (6041:0, 6064:0) every 20 ms; node 6's 2101:0 differs.
            QVERIFY(Reply::wait(connection->write({ 0x1800, 5 }, 20)).ok());
            QVERIFY(Reply::wait(connection->write({ 0x2101, 0 }, node == 6 ? 777 : -300)).ok());
            QVERIFY(connection->nmt()->start(quint8(node)));
            nodes.append(connection);
        }

        ScopePage page;
        QSignalSpy looked(&page, &ScopePage::pdoLookupFinished);
        for (canopen::CanopenConnection *connection : nodes) {
            page.setConnection(connection);
            page.setChannelSource(ScopePage::ChannelSource::Pdo);
            page.addPdoChannels({ ObjectAddress(0x6064, 0), ObjectAddress(0x2101, 0) });
            QVERIFY(looked.wait(5000));
            looked.clear();
            page.mapToTpdo(1, 20); // 2101:0 is in no TPDO yet
            QVERIFY(looked.wait(5000));
            QVERIFY2(looked.takeFirst().at(0).toBool(), qPrintable(page.statusText()));
        }
        QCOMPARE(page.recorder()->channelCount(), 4);
        page.setConnection(nodes[0]);
        QCOMPARE(page.pdoMapping(QStringLiteral("2101:0"))->cobId, 0x285u);
        page.setConnection(nodes[1]);
        QCOMPARE(page.pdoMapping(QStringLiteral("2101:0"))->cobId, 0x286u);
        QCOMPARE(page.pdoMapping(QStringLiteral("6064:0"))->cobId, 0x186u);

        page.start();
        QCOMPARE(page.recorder()->state(), scope::Recorder::State::Recording);
        QTRY_VERIFY_WITH_TIMEOUT(
            [&] {
                for (int i = 0; i < 4; ++i) {
                    if (page.recorder()->buffer(i).size() < 10)
                        return false;
                }
                return true;
            }(),
            10000);
        page.stop();
        // Channel order: node 5's 6064:0, 2101:0, then node 6's.
        const QList<double> expected { 1234, -300, 1234, 777 };
        for (int i = 0; i < 4; ++i) {
            const scope::ChannelInfo info = page.recorder()->channelInfo(i);
            QCOMPARE(info.device, nodes[i / 2]->uri().toString());
            QCOMPARE(page.recorder()->buffer(i).value(0), expected[i]);
        }
        QVERIFY(scopeChannelName(*page.recorder(), 1) != scopeChannelName(*page.recorder(), 3));
        auto *table = page.findChild<QTableView *>(QStringLiteral("scopeChannels"));
        for (int row = 0; row < 4; ++row)
            QVERIFY(table->model()
                        ->index(row, ScopeChannelModel::Rate)
                        .data()
                        .toString()
                        .startsWith(QLatin1String("PDO 0x")));

        // A second run rebuilds one PDO source per node and samples the same.
        page.start();
        QTRY_VERIFY_WITH_TIMEOUT(page.recorder()->buffer(3).size() >= 5, 10000);
        page.stop();
        QCOMPARE(page.recorder()->buffer(3).value(0), 777.0);
        QCOMPARE(page.recorder()->buffer(1).value(0), -300.0);

        const auto back = scope::csv::fromCsv(scope::csv::toCsv(page.recorder()->recording()));
        QVERIFY2(back.ok(), qPrintable(back.error().toString()));
        QCOMPARE(back->channels.size(), 4);
        QCOMPARE(back->channels[3].info.device, nodes[1]->uri().toString());
        QCOMPARE(back->channels[3].buffer.value(0), 777.0);

        // Node 5 pre-operational while node 6 is the page's device: the page names node 5 and
        // its channels, not the node it shows.
        QVERIFY(nodes[0]->nmt()->enterPreOperational(5));
        QTRY_COMPARE(nodes[0]->monitor()->state(5), canopen::NmtState::PreOperational);
        page.start();
        QTRY_VERIFY_WITH_TIMEOUT(page.statusText().contains(QStringLiteral(
                                     "node 5 is pre-operational (heartbeat), not operational: "
                                     "NMT start it")),
                                 5000);
        QVERIFY2(!page.statusText().contains(QStringLiteral("node 6")),
                 qPrintable(page.statusText()));
        page.stop();
        for (canopen::CanopenConnection *connection : nodes)
            connection->close();
    }

    void startWithoutDeviceIsRefusedWithAReason()
    {
        ScopePage page;
        page.recorder()->load(syntheticRecording(100));
        page.start();
        QVERIFY(!page.recorder()->isRunning());
        QVERIFY(page.statusText().contains(QStringLiteral("connect")));
        QVERIFY(!page.addChannels({ ObjectAddress(0x6064, 0) }));
    }

    void csvExportThenReopen()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        ScopePage page;
        page.recorder()->load(syntheticRecording());
        page.channelModel()->setData(page.channelModel()->index(1, ScopeChannelModel::Scale), 0.001,
                                     Qt::EditRole);
        const QString whole = dir.filePath(QStringLiteral("whole.csv"));
        const QString visible = dir.filePath(QStringLiteral("visible.csv"));
        QVERIFY(page.exportCsv(whole, false));
        page.plot()->refreshNow();
        page.plot()->setTimeRange(2.0, 3.0);
        QVERIFY(page.exportCsv(visible, true));
        QVERIFY(page.exportImage(dir.filePath(QStringLiteral("plot.png"))));
        QVERIFY(page.exportImage(dir.filePath(QStringLiteral("plot.pdf"))));
        QVERIFY(!page.exportImage(dir.filePath(QStringLiteral("plot.txt"))));
        // An export into a folder that cannot take it fails with the file named, and a
        // successful one over an existing image replaces it whole, leaving nothing behind.
        const Result<void> nowhere =
            page.exportImage(dir.filePath(QStringLiteral("missing/plot.png")));
        QVERIFY(!nowhere);
        QVERIFY(nowhere.error().message().contains(QStringLiteral("missing/plot.png")));
        const QString png = dir.filePath(QStringLiteral("plot.png"));
        QVERIFY(page.exportImage(png));
        QCOMPARE(QImage(png).isNull(), false);
        const QStringList files =
            QDir(dir.path()).entryList(QDir::Files | QDir::Hidden, QDir::Name);
        QCOMPARE(files, QStringList({ "plot.pdf", "plot.png", "visible.csv", "whole.csv" }));

        ScopePage reopened;
        const Result<void> r = reopened.openRecording(whole);
        QVERIFY2(r.ok(), qPrintable(r.error().toString()));
        QCOMPARE(reopened.recorder()->channelCount(), 2);
        QCOMPARE(reopened.recorder()->buffer(0).size(), page.recorder()->buffer(0).size());
        QCOMPARE(reopened.recorder()->channelInfo(1).scale, 0.001);
        QCOMPARE(reopened.recorder()->buffer(1).value(250), page.recorder()->buffer(1).value(250));
        reopened.plot()->refreshNow();
        QCOMPARE(reopened.plot()->timeUpper(), 10.0);

        QVERIFY(reopened.openRecording(visible));
        QVERIFY(std::abs(reopened.recorder()->buffer(0).size() - 1001) <= 1);
        QVERIFY(reopened.recorder()->buffer(0).firstTime() >= 2.0);
        QVERIFY(reopened.recorder()->buffer(0).lastTime() <= 3.0);

        const QString broken = dir.filePath(QStringLiteral("broken.csv"));
        QFile f(broken);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("time_s,a\n1,2\n0,x\n");
        f.close();
        const Result<void> bad = reopened.openRecording(broken);
        QVERIFY(!bad);
        QVERIFY(bad.error().message().contains(QStringLiteral("broken.csv")));
        QVERIFY(reopened.recorder()->buffer(0).lastTime() <= 3.0); // the old recording stays
    }
};

QTEST_MAIN(TstScopeView)
#include "tst_scopeview.moc"
