// Level 4: what the scope shows people, offscreen: time from the trigger, an axis per unit, the
// trigger channel chosen for them, channels of two devices side by side, the cursor table's
// units and decimals, "not a step", and the image export's header.
#include "core/objectdictionary.h"
#include "fakeconnection.h"
#include "scope/csv.h"
#include "scope/recorder.h"
#include "widgets/common/plot.h"
#include "widgets/scope/scopeanalysisdialog.h"
#include "widgets/scope/scopechannelmodel.h"
#include "widgets/scope/scopecursors.h"
#include "widgets/scope/scopemeasurements.h"
#include "widgets/scope/scopepage.h"
#include "widgets/scope/scopeplot.h"

#include <QComboBox>
#include <QImage>
#include <QLabel>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace db;
using namespace db::widgets;

namespace {

scope::RecordedChannel channel(const QString &id, const QString &name, const QString &unit,
                               const QString &device = QStringLiteral("fake://device"))
{
    scope::RecordedChannel c;
    c.info.id = id;
    c.info.address = *AddressFormat::canopen().parse(id);
    c.info.name = name;
    c.info.unit = unit;
    c.info.device = device;
    c.buffer.setCapacity(20000);
    return c;
}

// Velocity (rpm, a ramp from t = 4 s), position (inc) and a second velocity, 1 ms apart over
// [0, 10] s; triggered at 5 s when `triggerAt` is set.
scope::Recording recording(double triggerAt = NAN)
{
    scope::Recording rec;
    rec.device = QStringLiteral("fake://device");
    rec.startedAt = QDateTime(QDate(2026, 11, 26), QTime(14, 30, 5), Qt::UTC);
    scope::RecordedChannel velocity = channel(QStringLiteral("606C:0"), "Velocity", "rpm");
    scope::RecordedChannel position = channel(QStringLiteral("6064:0"), "Position", "inc");
    scope::RecordedChannel demand = channel(QStringLiteral("606B:0"), "Velocity demand", "rpm");
    for (int i = 0; i <= 10000; ++i) {
        const double t = i * 1e-3;
        velocity.buffer.append(t, t < 4 ? 0 : 100 * (t - 4));
        position.buffer.append(t, std::round(1000 * std::sin(t)));
        demand.buffer.append(t, 50);
    }
    rec.channels = { velocity, position, demand };
    if (std::isfinite(triggerAt)) {
        rec.trigger.channel = 0;
        rec.trigger.kind = scope::Trigger::Kind::RisingEdge;
        rec.trigger.level = 100;
        rec.trigger.preTriggerS = 5;
        rec.trigger.postTriggerS = 5;
        rec.triggerTime = triggerAt;
        rec.mode = QStringLiteral("single");
    }
    return rec;
}

// The tick labels of the bottom time axis after a replot, by tick position.
QMap<double, QString> timeTicks(ScopePage &page)
{
    page.plot()->refreshNow();
    page.plot()->customPlot()->replot();
    const QList<int> lanes = page.plot()->lanes();
    QCPAxis *axis = page.plot()->laneRect(lanes.last())->axis(QCPAxis::atBottom);
    QMap<double, QString> ticks;
    const QVector<double> at = axis->tickVector();
    const QVector<QString> labels = axis->tickVectorLabels();
    for (int i = 0; i < at.size() && i < labels.size(); ++i)
        ticks.insert(at[i], labels[i]);
    return ticks;
}

ObjectDictionary driveDictionary(const QString &product)
{
    ObjectDictionary d;
    d.identity.productName = product;
    ObjectDef frequency;
    frequency.address = ObjectAddress(0x2100, 0);
    frequency.name = QStringLiteral("Actual frequency");
    frequency.type = DataType::Integer32;
    frequency.unit = QStringLiteral("Hz");
    frequency.factor = 0.01;
    d.insert(frequency);
    ObjectDef position;
    position.address = ObjectAddress(0x6064, 0);
    position.name = QStringLiteral("Position actual value");
    position.type = DataType::Integer32;
    position.unit = QStringLiteral("inc");
    d.insert(position);
    return d;
}

} // namespace

class TstScopeDetails : public QObject
{
    Q_OBJECT

private slots:
    void triggeredTimeCountsFromTheTrigger()
    {
        ScopePage page;
        page.resize(1200, 700);
        page.recorder()->load(recording(5.0));
        const QMap<double, QString> ticks = timeTicks(page);
        QStringList shown;
        for (auto it = ticks.cbegin(); it != ticks.cend(); ++it)
            shown.append(QStringLiteral("%1=%2").arg(it.key(), 0, 'g', 17).arg(it.value()));
        QVERIFY2(ticks.contains(5.0), qPrintable(shown.join(' ')));
        QCOMPARE(ticks.value(5.0), QStringLiteral("0"));
        QVERIFY(ticks.contains(3.0) || ticks.contains(4.0));
        QCOMPARE(ticks.value(4.0, QStringLiteral("-1")), QStringLiteral("-1"));
        QVERIFY(ticks.first().startsWith(QLatin1Char('-'))); // the pre-trigger is negative
        const QList<int> lanes = page.plot()->lanes();
        QVERIFY(page.plot()
                    ->laneRect(lanes.last())
                    ->axis(QCPAxis::atBottom)
                    ->label()
                    .contains(QStringLiteral("trigger")));
        // The cursor readout counts from the trigger too.
        page.setCursorsEnabled(true);
        page.plot()->cursors()->setPositions(4.0, 6.5);
        QTRY_VERIFY(page.measurements()->summary()->text().contains(QStringLiteral("-1 s")));
        QVERIFY(page.measurements()->summary()->text().contains(QStringLiteral("1.5 s")));

        // Free-running: absolute time from the start.
        ScopePage free;
        free.resize(1200, 700);
        free.recorder()->load(recording());
        const QMap<double, QString> absolute = timeTicks(free);
        QCOMPARE(absolute.value(4.0, QStringLiteral("4")), QStringLiteral("4"));
        QCOMPARE(absolute.firstKey() >= 0, true);
        QVERIFY(!absolute.first().startsWith(QLatin1Char('-')));
    }

    void eachUnitHasItsOwnAxis()
    {
        ScopePage page;
        page.recorder()->load(recording());
        page.plot()->refreshNow();
        // rpm, inc, rpm: two axes, the velocities share one, labelled with the unit.
        QCOMPARE(page.plot()->lanes(), QList<int>({ 1, 2 }));
        QCOMPARE(page.plot()->channelStyle(0).lane, page.plot()->channelStyle(2).lane);
        QVERIFY(page.plot()->channelStyle(1).lane != page.plot()->channelStyle(0).lane);
        const int rpmLane = page.plot()->channelStyle(0).lane;
        QCOMPARE(page.plot()->laneRect(rpmLane)->axis(QCPAxis::atLeft)->label(),
                 QStringLiteral("rpm"));
        // The user can still put them on one axis.
        ScopeChannelModel *model = page.channelModel();
        QVERIFY(model->setData(model->index(1, ScopeChannelModel::Lane), rpmLane, Qt::EditRole));
        page.plot()->refreshNow();
        QCOMPARE(page.plot()->lanes().size(), 1);
    }

    void triggerChannelIsPreselected()
    {
        test::FakeConnection connection;
        connection.setValue({ 0x6064, 0 }, qint64(1));
        connection.setValue({ 0x606C, 0 }, qint64(2));
        connection.setValue({ 0x6041, 0 }, qint64(3));
        connection.open();
        QTRY_VERIFY(connection.isConnected());
        ScopePage page;
        page.setConnection(&connection);
        page.setMode(int(scope::Recorder::Mode::Single));
        QVERIFY(page.addChannels({ ObjectAddress(0x6064, 0) }));
        QCOMPARE(page.triggerSettings().channel, 0); // the first channel, ready to trigger
        QVERIFY(page.addChannels({ ObjectAddress(0x606C, 0), ObjectAddress(0x6041, 0) }));
        QCOMPARE(page.triggerSettings().channel, 0);

        // The user picks 606C; after removing and adding channels it is still the one chosen.
        auto *box = page.findChild<QComboBox *>(QStringLiteral("scopeTriggerChannel"));
        QVERIFY(box);
        box->setCurrentIndex(1);
        Q_EMIT box->activated(1);
        QVERIFY(page.removeChannel(1));
        QCOMPARE(page.triggerSettings().channel, 0);
        QVERIFY(page.addChannels({ ObjectAddress(0x606C, 0) }));
        QCOMPARE(page.recorder()->channelInfo(page.triggerSettings().channel).id,
                 QStringLiteral("606C:0"));
    }

    void theSameObjectOfTwoDrivesSideBySide()
    {
        test::FakeConnection left(QStringLiteral("fake://127.0.0.1:10001"));
        test::FakeConnection right(QStringLiteral("fake://127.0.0.1:10002"));
        for (test::FakeConnection *c : { &left, &right }) {
            c->setDictionary(driveDictionary(QStringLiteral("ACTIVE Cube ACU (VABus/TCP)")));
            c->open();
        }
        left.setValue({ 0x2100, 0 }, qint64(5000));
        right.setValue({ 0x2100, 0 }, qint64(-1234));
        QTRY_VERIFY(left.isConnected() && right.isConnected());
        ScopePage page;
        page.setConnection(&left);
        QVERIFY(page.addChannels({ ObjectAddress(0x2100, 0) }));
        page.setConnection(&right);
        QVERIFY(page.addChannels({ ObjectAddress(0x2100, 0) }));
        QCOMPARE(page.recorder()->channelCount(), 2);
        // Refused only from the same device.
        QVERIFY(!page.addChannels({ ObjectAddress(0x2100, 0) }));

        page.start();
        QCOMPARE(page.recorder()->state(), scope::Recorder::State::Recording);
        // Selecting another device does not stop the recording.
        page.setConnection(&left);
        QVERIFY(page.recorder()->isRunning());
        QTRY_VERIFY(page.recorder()->buffer(0).size() >= 5
                    && page.recorder()->buffer(1).size() >= 5);
        page.stop();
        const scope::ChannelInfo a = page.recorder()->channelInfo(0);
        const scope::ChannelInfo b = page.recorder()->channelInfo(1);
        QCOMPARE(a.device, left.uri().toString());
        QCOMPARE(b.device, right.uri().toString());
        QCOMPARE(page.recorder()->buffer(0).value(0), 5000.0);
        QCOMPARE(page.recorder()->buffer(1).value(0), -1234.0);
        // Named with their device, told apart by the port.
        const QString nameA = scopeChannelName(*page.recorder(), 0);
        const QString nameB = scopeChannelName(*page.recorder(), 1);
        QCOMPARE(nameA, QStringLiteral("ACTIVE Cube ACU 127.0.0.1:10001: 2100:0 Actual frequency"));
        QCOMPARE(nameB, QStringLiteral("ACTIVE Cube ACU 127.0.0.1:10002: 2100:0 Actual frequency"));
        page.plot()->refreshNow();
        QVERIFY(page.plot()->graph(0)->name().startsWith(nameA));
        QCOMPARE(
            page.channelModel()->data(page.channelModel()->index(1, 0), Qt::DisplayRole).toString(),
            nameB);

        // A file keeps which channel came from which device.
        const scope::Recording back =
            *scope::csv::fromCsv(scope::csv::toCsv(page.recorder()->recording()));
        QCOMPARE(back.channels.size(), 2);
        QCOMPARE(back.channels[0].info.device, a.device);
        QCOMPARE(back.channels[1].info.device, b.device);
        QCOMPARE(back.channels[1].info.deviceName, b.deviceName);
        QCOMPARE(back.channels[1].info.decimals, 2);
    }

    void cursorTableHasUnitsAndTheChannelsDecimals()
    {
        scope::Recording rec;
        rec.device = QStringLiteral("fake://device");
        scope::RecordedChannel frequency = channel(QStringLiteral("2100:0"), "Frequency", "Hz");
        frequency.info.scale = 0.01;
        frequency.info.decimals = 2;
        scope::RecordedChannel count = channel(QStringLiteral("6064:0"), "Position", "inc");
        count.info.decimals = 0;
        scope::RecordedChannel real = channel(QStringLiteral("2200:0"), "Torque", "Nm");
        for (int i = 0; i <= 1000; ++i) {
            frequency.buffer.append(i * 1e-3, 1000 + i); // 10.00 .. 20.00 Hz
            count.buffer.append(i * 1e-3, 3 * i);
            real.buffer.append(i * 1e-3, 0.123456 * i);
        }
        rec.channels = { frequency, count, real };
        ScopePage page;
        page.recorder()->load(rec);
        page.plot()->refreshNow();
        page.setCursorsEnabled(true);
        page.plot()->cursors()->setPositions(0.25, 0.5);
        QTableWidget *table = page.measurements()->table();
        QTRY_COMPARE(table->rowCount(), 3);
        QTRY_COMPARE(table->item(0, ScopeMeasurements::AtA)->text(), QStringLiteral("12.50"));
        const auto cell = [table](int row, ScopeMeasurements::Column c) {
            return table->item(row, c)->text();
        };
        QCOMPARE(cell(0, ScopeMeasurements::Unit), QStringLiteral("Hz"));
        QCOMPARE(cell(0, ScopeMeasurements::AtA), QStringLiteral("12.50"));
        QCOMPARE(cell(0, ScopeMeasurements::AtB), QStringLiteral("15.00"));
        QCOMPARE(cell(0, ScopeMeasurements::Dy), QStringLiteral("2.50"));
        QCOMPARE(cell(0, ScopeMeasurements::Min), QStringLiteral("12.50"));
        QCOMPARE(cell(1, ScopeMeasurements::Unit), QStringLiteral("inc"));
        QCOMPARE(cell(1, ScopeMeasurements::AtA), QStringLiteral("750"));
        QCOMPARE(cell(1, ScopeMeasurements::Max), QStringLiteral("1500"));
        // Floating point: one number of decimals for all of the channel's figures.
        const QStringList figures = { cell(2, ScopeMeasurements::AtA),
                                      cell(2, ScopeMeasurements::AtB),
                                      cell(2, ScopeMeasurements::Dy),
                                      cell(2, ScopeMeasurements::Max) };
        const qsizetype decimals = figures.first().size() - figures.first().indexOf('.') - 1;
        QVERIFY2(decimals >= 2, qPrintable(figures.join(' ')));
        for (const QString &f : figures)
            QCOMPARE(f.size() - f.indexOf('.') - 1, decimals);
    }

    void analysisSaysNotAStep()
    {
        scope::RecordedChannel sine = channel(QStringLiteral("6064:0"), "Position", "inc");
        for (int i = 0; i < 3000; ++i)
            sine.buffer.append(i * 1e-3, 100 * std::sin(2 * M_PI * 2 * i * 1e-3));
        ScopeAnalysisDialog dialog(sine.info, sine.buffer, 0, 3);
        bool said = false;
        bool riseTime = false;
        for (const QLabel *label : dialog.findChildren<QLabel *>()) {
            said = said || label->text().contains(QStringLiteral("not a step"));
            riseTime = riseTime || label->text().contains(QStringLiteral("Rise time"));
        }
        QStringList texts;
        for (const QLabel *label : dialog.findChildren<QLabel *>())
            texts.append(label->text());
        QVERIFY2(said, qPrintable(texts.join(" | ")));
        QVERIFY(!riseTime);
    }

    void imageExportHasAHeader()
    {
        scope::Recording rec = recording(5.0);
        for (scope::RecordedChannel &c : rec.channels)
            c.info.deviceName = QStringLiteral("MovingCap ETH 127.0.0.1");
        ScopePage page;
        page.resize(1000, 600);
        page.recorder()->load(rec);
        const QStringList header = page.exportHeader();
        const QString text = header.join('\n');
        QVERIFY2(text.contains(QStringLiteral("MovingCap ETH 127.0.0.1")), qPrintable(text));
        const QString local =
            rec.startedAt.toLocalTime().toString(QStringLiteral("yyyy-MM-dd HH:mm"));
        QVERIFY2(text.contains(local), qPrintable(text));
        QVERIFY2(text.contains(QStringLiteral("606C:0 Velocity")), qPrintable(text));
        QVERIFY2(text.contains(QStringLiteral("rising edge 100 rpm")), qPrintable(text));
        QVERIFY2(text.contains(QStringLiteral("5 s before")), qPrintable(text));

        QTemporaryDir dir;
        const QString png = dir.filePath(QStringLiteral("plot.png"));
        QVERIFY(page.exportImage(png));
        QVERIFY(page.exportImage(dir.filePath(QStringLiteral("plot.pdf"))));
        // Text in the band above the plot, where the page itself shows nothing.
        const QImage image(png);
        QVERIFY(!image.isNull());
        int dark = 0;
        for (int y = 0; y < 24; ++y) {
            for (int x = 0; x < image.width() / 2; ++x)
                dark += qGray(image.pixel(x, y)) < 100 ? 1 : 0;
        }
        QVERIFY2(dark > 50, qPrintable(QString::number(dark)));
        // The page's own plot has no header afterwards.
        QCOMPARE(page.plot()->customPlot()->plotLayout()->elementCount(),
                 page.plot()->lanes().size());

        ScopePage untriggered;
        untriggered.recorder()->load(recording());
        QVERIFY(untriggered.exportHeader().join('\n').contains(QStringLiteral("No trigger")));
    }
};

QTEST_MAIN(TstScopeDetails)
#include "tst_scopedetails.moc"
