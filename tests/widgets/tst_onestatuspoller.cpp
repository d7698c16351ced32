// Level 4: the drive status panel, the motion dock's axis and the object editor on one
// connection read the drive's status through its one status source: the status word is read
// once per cycle, however many of them show it, and each of them sees what the others see.

#include "cia402/cia402statussource.h"
#include "devices/bonfiglioli/acuaxis.h"
#include "devices/bonfiglioli/acudescription.h"
#include "devices/bonfiglioli/acustatussource.h"
#include "fakeconnection.h"
#include "motion/cia402axis.h"
#include "resources/builtindescriptions.h"
#include "widgets/connection/drivestatuspanel.h"
#include "widgets/odeditor/odeditor.h"
#include "widgets/odeditor/odeditorfilter.h"
#include "widgets/odeditor/odeditormodel.h"
#include "widgets/odeditor/odeditorpoller.h"

#include <QTest>
#include <QTreeView>

#include <memory>

using namespace db;
using db::test::FakeConnection;
using db::widgets::DriveStatusPanel;
using db::widgets::OdEditor;
using db::widgets::OdEditorModel;

namespace {

// Every object of the description at its default (or 0).
void fillDefaults(FakeConnection &fake)
{
    for (const ObjectDef &def : fake.dictionary().objects()) {
        const QVariant raw = def.defaultValue.isValid() ? def.defaultValue
                                                        : codec::normalize(def.type, 0).valueOr({});
        fake.setValue(def.address, raw);
    }
}

// The three views of one drive, as the main window opens them.
struct Views
{
    std::unique_ptr<DriveStatusPanel> panel;
    std::unique_ptr<motion::AxisInterface> axis;
    std::unique_ptr<OdEditor> editor;
};

void openViews(Views &views, FakeConnection &fake, std::unique_ptr<motion::AxisInterface> axis,
               ObjectAddress statusWord)
{
    views.panel = std::make_unique<DriveStatusPanel>();
    views.panel->setConnection(&fake);
    views.panel->show();
    views.axis = std::move(axis);
    views.editor = std::make_unique<OdEditor>();
    views.editor->resize(1000, 600);
    views.editor->setConnection(&fake);
    views.editor->setRefreshPeriodMs(250);
    views.editor->show();
    // The status word's row is the current one: the editor refreshes it.
    const QModelIndex row = views.editor->filter()->mapFromSource(
        views.editor->model()->indexOf(statusWord, OdEditorModel::Name));
    QVERIFY(row.isValid());
    views.editor->view()->setCurrentIndex(row);
}

} // namespace

class TestOneStatusPoller : public QObject
{
    Q_OBJECT

private:
    // Status word reads while the three views are open for `cycles` cycles of the source,
    // after the editor's first read of every object.
    void countReads(FakeConnection &fake, Views &views, ObjectAddress statusWord)
    {
        auto reads = std::make_shared<int>(0); // counted as long as the connection lives
        connect(&fake, &DeviceConnection::requestFinished, &fake,
                [reads, statusWord](ObjectAddress address, const Error &) {
                    if (address == statusWord)
                        ++*reads;
                });
        fake.open();
        StatusSource *source = fake.statusSource();
        QVERIFY(source);
        QTRY_VERIFY(views.axis->status().valid);
        QTRY_VERIFY(views.editor->poller()->pending() == 0
                    && views.editor->poller()->inFlight() == 0);
        QTRY_VERIFY(views.editor->poller()->holdsStatusSource());
        QCOMPARE(source->effectiveIntervalMs(), motion::ConnectionAxis::kStatusPollMs);
        const int readsBefore = *reads;
        const quint64 cyclesBefore = source->serial();
        QTRY_VERIFY(source->serial() >= cyclesBefore + 30);
        const int statusReads = *reads - readsBefore;
        const int cycles = int(source->serial() - cyclesBefore);
        qInfo("%d status word reads in %d cycles of the shared source", statusReads, cycles);
        // One read per cycle (one more may be in flight): the axis and the editor add none.
        QVERIFY2(
            statusReads <= cycles + 1,
            qPrintable(
                QStringLiteral("%1 status word reads in %2 cycles").arg(statusReads).arg(cycles)));
    }

    // Status word reads while `command` waits for the drive, over `cycles` cycles of the
    // source: the command's procedure takes the status word from the source as well, so the
    // reads stay one per cycle (a procedure reading it itself every 10 ms would add dozens).
    void countReadsDuringCommand(FakeConnection &fake, Reply *command, ObjectAddress statusWord,
                                 int cycles)
    {
        auto reads = std::make_shared<int>(0);
        connect(&fake, &DeviceConnection::requestFinished, command,
                [reads, statusWord](ObjectAddress address, const Error &) {
                    if (address == statusWord)
                        ++*reads;
                });
        StatusSource *source = fake.statusSource();
        const quint64 cyclesBefore = source->serial();
        QTRY_VERIFY(source->serial() >= cyclesBefore + quint64(cycles));
        QVERIFY2(!command->isFinished(), qPrintable(command->error().toString()));
        const int counted = int(source->serial() - cyclesBefore);
        qInfo("%d status word reads in %d cycles while a command waits", *reads, counted);
        QVERIFY2(*reads <= counted + 1,
                 qPrintable(QStringLiteral("%1 status word reads in %2 cycles during a command")
                                .arg(*reads)
                                .arg(counted)));
    }

private Q_SLOTS:
    void cia402PanelAxisAndEditorReadTheStatusWordOnce()
    {
        constexpr ObjectAddress kStatusword { 0x6041, 0 };
        FakeConnection fake;
        fake.setDictionary(resources::movingCapDictionary());
        fillDefaults(fake);
        fake.setValue(kStatusword, QVariant::fromValue<qulonglong>(0x0427));
        Views views;
        openViews(views, fake, std::make_unique<motion::Cia402Axis>(&fake), kStatusword);
        countReads(fake, views, kStatusword);
        if (QTest::currentTestFailed())
            return;

        // A fault reaches all three from the same cycle.
        fake.setValue(kStatusword, QVariant::fromValue<qulonglong>(0x0008));
        QTRY_VERIFY(views.axis->status().fault);
        QTRY_COMPARE(views.editor->model()->value(kStatusword).toULongLong(), 0x0008ull);
        QCOMPARE(fake.statusSource()->state(), StatusSource::State::Fault);
        QVERIFY(fake.writes.isEmpty()); // nobody writes back what it read

        // A move waits for the set-point acknowledge (bit 12) while all three views are open.
        fake.setValue(kStatusword, QVariant::fromValue<qulonglong>(0x0427));
        QTRY_VERIFY(!views.axis->status().fault);
        motion::AxisInterface::Profile profile;
        profile.velocity = 1000;
        profile.acceleration = profile.deceleration = 10000;
        std::unique_ptr<Reply> move(views.axis->moveTo(5000, profile));
        QTRY_VERIFY(!fake.writes.isEmpty()); // the set-point is being written
        countReadsDuringCommand(fake, move.get(), kStatusword, 15);
        if (QTest::currentTestFailed())
            return;
        fake.setValue(kStatusword, QVariant::fromValue<qulonglong>(0x1427)); // acknowledged
        QTRY_COMPARE(fake.writes.last().second.toULongLong(), 0x000Full); // new set-point off
        fake.setValue(kStatusword, QVariant::fromValue<qulonglong>(0x0427));
        QTRY_VERIFY(move->isFinished());
        QVERIFY2(move->ok(), qPrintable(move->error().toString()));

        // The editor's refresh off: it lets go; the axis still holds the source.
        views.editor->setRefreshPeriodMs(0);
        QVERIFY(!views.editor->poller()->holdsStatusSource());
        views.panel->hide();
        QVERIFY(fake.statusSource()->users() == 1);
        views.axis.reset();
        QTRY_VERIFY(!fake.statusSource()->isPolling());
    }

    void acuPanelAxisAndEditorReadParameter411Once()
    {
        constexpr ObjectAddress k411 { 411, 0 };
        FakeConnection fake(QStringLiteral("vabus://127.0.0.1"));
        fake.setProtocolKey(QStringLiteral("vabus"));
        fake.setDictionary(bonfiglioli::acuDictionary());
        fillDefaults(fake);
        fake.setValue(k411, QVariant::fromValue<qulonglong>(0x0237));
        fake.setStatusSource(new bonfiglioli::AcuStatusSource(&fake));
        Views views;
        openViews(views, fake, std::make_unique<bonfiglioli::AcuAxis>(&fake), k411);
        countReads(fake, views, k411);
        if (QTest::currentTestFailed())
            return;
        // The axis's position (1108) comes with the source's cycles too.
        fake.setValue({ 1108, 0 }, QVariant::fromValue<qlonglong>(4321));
        QTRY_COMPARE(views.axis->status().position, 4321.0);
        QVERIFY(fake.statusSource()->cycleObjects().contains(ObjectAddress(1108, 0)));

        // Disabling waits for 'switch on disabled': 411 still only from the source.
        std::unique_ptr<Reply> off(views.axis->power(false));
        countReadsDuringCommand(fake, off.get(), k411, 15);
        if (QTest::currentTestFailed())
            return;
        fake.setValue(k411, QVariant::fromValue<qulonglong>(0x0040));
        QTRY_VERIFY(off->isFinished());
        QVERIFY2(off->ok(), qPrintable(off->error().toString()));

        views.axis.reset();
        QVERIFY(!fake.statusSource()->cycleObjects().contains(ObjectAddress(1108, 0)));
    }

    void refreshReadsAfterTheCall()
    {
        constexpr ObjectAddress kStatusword { 0x6041, 0 };
        FakeConnection fake;
        fake.setDictionary(resources::movingCapDictionary());
        fillDefaults(fake);
        fake.replyDelayMs = 20;
        fake.open();
        QTRY_VERIFY(fake.isConnected());
        StatusSource *source = cia402::Cia402StatusSource::sourceOf(&fake);
        QCOMPARE(cia402::Cia402StatusSource::sourceOf(&fake), source); // one per connection
        // Nobody holds the source: no cycle until someone asks for values.
        QTest::qWait(50); // a window in which nothing may happen
        QCOMPARE(source->serial(), quint64(0));
        const quint64 first = source->refresh();
        QCOMPARE(first, quint64(1));
        QTRY_VERIFY(fake.inFlight > 0); // the cycle's reads are out
        // Asked while a cycle runs: its reads may predate the caller's write, so the fresh
        // values are those of the cycle after it.
        const quint64 second = source->refresh();
        QCOMPARE(second, quint64(2));
        QTRY_COMPARE(source->serial(), second);
        QVERIFY(source->isFresh(kStatusword));
        QTRY_VERIFY(!source->isPolling()); // and no more cycles after it
        QCOMPARE(source->serial(), second);
    }
};

QTEST_MAIN(TestOneStatusPoller)
#include "tst_onestatuspoller.moc"
