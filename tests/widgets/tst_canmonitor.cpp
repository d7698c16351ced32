#include "canopen/canopenconnection.h"
#include "common/demodrive.h"
#include "common/protocols.h"
#include "core/changelog.h"
#include "core/reply.h"
#include "resources/builtindescriptions.h"
#include "scriptedcanbus.h"
#include "widgets/canopen/canmonitor.h"
#include "widgets/canopen/canmonitorlog.h"
#include "widgets/canopen/framesender.h"

#include <QCheckBox>
#include <QComboBox>
#include <QElapsedTimer>
#include <QFile>
#include <QLineEdit>
#include <QSignalSpy>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <QToolButton>
#include <QVBoxLayout>

using namespace db;
using db::test::ScriptedCanBus;
using db::widgets::CanMonitor;
using db::widgets::CanMonitorModel;
using db::widgets::FrameSender;

namespace {
// Counts the events of one type a watched object receives.
class EventCounter : public QObject
{
public:
    EventCounter(QObject *watched, QEvent::Type type, int *count)
        : m_type(type)
        , m_count(count)
    {
        watched->installEventFilter(this);
    }

protected:
    bool eventFilter(QObject *, QEvent *event) override
    {
        if (event->type() == m_type)
            ++*m_count;
        return false;
    }

private:
    QEvent::Type m_type;
    int *m_count;
};
} // namespace

// Level 4: the CAN monitor offscreen against a ScriptedCanBus (frames of movingcap.md 4.3) and,
// end to end, against the demo drive's SLCAN door.
class TestCanMonitor : public QObject
{
    Q_OBJECT

private:
    // RX and TX traffic of node 50: read 6041h, write 6040h, EMCY, heartbeat, NMT.
    static void playTraffic(ScriptedCanBus &bus)
    {
        bus.send(ScriptedCanBus::frame(0x632, "40 41 60 00 00 00 00 00"));
        bus.feed(0x5B2, "4B 41 60 00 27 04 00 00");
        bus.send(ScriptedCanBus::frame(0x632, "2B 40 60 00 0F 00 00 00"));
        bus.feed(0x5B2, "60 40 60 00 00 00 00 00");
        bus.feed(0x0B2, "21 32 05 00 00 00 00 00");
        bus.feed(0x732, "05");
        bus.send(ScriptedCanBus::frame(0x000, "01 32"));
    }

    static QString cell(CanMonitor &m, int row, int column)
    {
        return m.view()->model()->index(row, column).data().toString();
    }

    static void setUp(CanMonitor &monitor, ScriptedCanBus &bus)
    {
        bus.open();
        monitor.setBus(&bus);
        monitor.model()->decoder().setDictionary(50, resources::movingCapDictionary());
    }

private Q_SLOTS:
    void framesAppearDecodedInOneBatch()
    {
        ScriptedCanBus bus;
        CanMonitor monitor;
        setUp(monitor, bus);
        QSignalSpy inserted(monitor.model(), &QAbstractItemModel::rowsInserted);
        playTraffic(bus);
        QCOMPARE(monitor.model()->rowCount(), 0); // not per frame: at the next tick
        QTRY_COMPARE(monitor.model()->rowCount(), 7);
        QCOMPARE(inserted.count(), 1);

        QCOMPARE(cell(monitor, 0, CanMonitorModel::Direction), QStringLiteral("TX"));
        QCOMPARE(cell(monitor, 0, CanMonitorModel::Id), QStringLiteral("632"));
        QCOMPARE(cell(monitor, 0, CanMonitorModel::Length), QStringLiteral("8"));
        QCOMPARE(cell(monitor, 1, CanMonitorModel::Direction), QStringLiteral("RX"));
        QCOMPARE(cell(monitor, 1, CanMonitorModel::Data),
                 QStringLiteral("4B 41 60 00 27 04 00 00"));
        QCOMPARE(cell(monitor, 1, CanMonitorModel::Service), QStringLiteral("SDO tx"));
        QCOMPARE(cell(monitor, 1, CanMonitorModel::Node), QStringLiteral("50"));
        QCOMPARE(cell(monitor, 1, CanMonitorModel::Decoded),
                 QStringLiteral("upload 6041:0 Statusword → 0x0427"));
        QCOMPARE(cell(monitor, 4, CanMonitorModel::Decoded),
                 QStringLiteral("3221 ERROR_UNDER_VOLT (voltage), reg 0x05"));
        QCOMPARE(cell(monitor, 5, CanMonitorModel::Decoded), QStringLiteral("operational"));
        QCOMPARE(cell(monitor, 6, CanMonitorModel::Decoded), QStringLiteral("NMT start node 50"));
        QVERIFY(cell(monitor, 6, CanMonitorModel::Time).toDouble() >= 0.0);
        QCOMPARE(cell(monitor, 6, CanMonitorModel::Node), QStringLiteral("50"));
        QCOMPARE(monitor.model()->entry(1).decoded.text,
                 QStringLiteral("SDO tx node 50: upload 6041:0 Statusword → 0x0427"));
    }

    // New frames scroll the table and change the frame count; the count repaints itself but
    // lays out nothing (a label's new text used to lay out the whole window at every batch).
    void newFramesDoNotLayOutTheWindow()
    {
        ScriptedCanBus bus;
        QWidget window;
        auto *layout = new QVBoxLayout(&window);
        auto *monitor = new CanMonitor(&window);
        layout->addWidget(monitor);
        setUp(*monitor, bus);
        window.resize(800, 400);
        window.show();
        playTraffic(bus);
        playTraffic(bus);
        QTRY_COMPARE(monitor->model()->rowCount(), 14);
        QCoreApplication::processEvents();
        int layouts = 0;
        auto *counter = new EventCounter(monitor, QEvent::LayoutRequest, &layouts);
        playTraffic(bus);
        QTRY_COMPARE(monitor->model()->rowCount(), 21);
        QCoreApplication::processEvents();
        QCOMPARE(layouts, 0);
        delete counter;
    }

    void answersSentFromAReceiveHandlerComeAfterTheirCause()
    {
        ScriptedCanBus bus;
        // A protocol engine connected before the monitor answers inside frameReceived(), as the
        // SDO client does when it sends the next request of its queue.
        connect(&bus, &CanBus::frameReceived, &bus, [&bus](const QCanBusFrame &f) {
            if (f.frameId() == 0x5B2)
                bus.send(ScriptedCanBus::frame(0x632, "40 64 60 00 00 00 00 00"));
        });
        CanMonitor monitor;
        setUp(monitor, bus);
        bus.feed(0x5B2, "4B 41 60 00 27 04 00 00");
        monitor.model()->flush();
        QCOMPARE(monitor.model()->rowCount(), 2);
        QCOMPARE(cell(monitor, 0, CanMonitorModel::Direction), QStringLiteral("RX"));
        QCOMPARE(cell(monitor, 1, CanMonitorModel::Direction), QStringLiteral("TX"));
    }

    void filtersNarrowTheTable()
    {
        ScriptedCanBus bus;
        CanMonitor monitor;
        setUp(monitor, bus);
        playTraffic(bus);
        monitor.model()->flush();
        auto *ids = monitor.findChild<QLineEdit *>(QStringLiteral("idFilter"));
        auto *object = monitor.findChild<QLineEdit *>(QStringLiteral("objectFilter"));
        auto *data = monitor.findChild<QLineEdit *>(QStringLiteral("dataFilter"));
        auto *text = monitor.findChild<QLineEdit *>(QStringLiteral("textFilter"));
        auto *direction = monitor.findChild<QComboBox *>(QStringLiteral("directionFilter"));
        QAbstractItemModel *shown = monitor.view()->model();

        QTest::keyClicks(ids, QStringLiteral("580-5FF"));
        QCOMPARE(shown->rowCount(), 2);
        ids->clear();
        QTest::keyClicks(ids, QStringLiteral("81-ff, 700-77F"));
        QCOMPARE(shown->rowCount(), 2); // EMCY and heartbeat: Kickdrive's "id = 81-ff" and more
        ids->clear();

        direction->setCurrentIndex(direction->findText(QStringLiteral("TX")));
        QCOMPARE(shown->rowCount(), 3);
        direction->setCurrentIndex(0);

        QTest::keyClicks(object, QStringLiteral("6041"));
        QCOMPARE(shown->rowCount(), 2); // request and response
        object->clear();

        QTest::keyClicks(data, QStringLiteral("?? 4? 60 00"));
        QCOMPARE(shown->rowCount(), 4); // the four SDO frames
        data->clear();
        QTest::keyClicks(data, QStringLiteral("4B 41 60 ?? 27"));
        QCOMPARE(shown->rowCount(), 1);
        data->clear();

        QTest::keyClicks(text, QStringLiteral("heartbeat"));
        QCOMPARE(shown->rowCount(), 1);
        text->clear();
        QCOMPARE(shown->rowCount(), 7);

        // Bad input is marked and the last valid filter stays.
        QTest::keyClicks(ids, QStringLiteral("732"));
        QCOMPARE(shown->rowCount(), 1);
        QTest::keyClicks(ids, QStringLiteral("-zz"));
        QCOMPARE(shown->rowCount(), 1);
        QVERIFY(ids->toolTip().contains(QStringLiteral("not a hex id")));
    }

    void filterParsersRejectNonsense()
    {
        using widgets::CanFrameFilter;
        QVERIFY(!CanFrameFilter::parseIds(QStringLiteral("5FF-580")));
        QVERIFY(!CanFrameFilter::parseIds(QStringLiteral("1-2-3")));
        QCOMPARE(CanFrameFilter::parseIds(QStringLiteral("0x580-0x5ff")).value().first().last,
                 0x5FFu);
        CanFrameFilter f;
        QVERIFY(!f.setDataPattern(QStringLiteral("4B 4")));
        QVERIFY(!f.setDataPattern(QStringLiteral("00 11 22 33 44 55 66 77 88")));
        QVERIFY(f.setDataPattern(QStringLiteral("4?")));
        QCOMPARE(f.mask, QByteArray(1, char(0xF0)));
        QVERIFY(!f.setObject(QStringLiteral("xyz")));
        QVERIFY(f.setObject(QStringLiteral("6041:0")));
        QCOMPARE(*f.subIndex, quint8(0));
    }

    void pauseHoldsFramesUntilResume()
    {
        ScriptedCanBus bus;
        CanMonitor monitor;
        setUp(monitor, bus);
        bus.feed(0x732, "05");
        monitor.model()->flush();
        QTest::mouseClick(monitor.findChild<QToolButton *>(QStringLiteral("pause")),
                          Qt::LeftButton);
        QVERIFY(monitor.isPaused());
        bus.feed(0x732, "05");
        bus.feed(0x732, "05");
        QSignalSpy flushed(monitor.model(), &CanMonitorModel::flushed);
        QVERIFY(!flushed.wait(3 * CanMonitorModel::kFlushIntervalMs)); // no batch while paused
        QCOMPARE(monitor.model()->rowCount(), 1);
        QCOMPARE(monitor.model()->pendingCount(), 2); // captured while paused
        QTest::mouseClick(monitor.findChild<QToolButton *>(QStringLiteral("pause")),
                          Qt::LeftButton);
        QCOMPARE(monitor.model()->rowCount(), 3);
    }

    void bufferIsBoundedAndDropsTheOldest()
    {
        ScriptedCanBus bus;
        CanMonitor monitor;
        setUp(monitor, bus);
        monitor.model()->setCapacity(10);
        for (int i = 0; i < 7; ++i)
            bus.feed(QCanBusFrame(0x181, QByteArray(1, char(i))));
        monitor.model()->flush();
        for (int i = 7; i < 25; ++i)
            bus.feed(QCanBusFrame(0x181, QByteArray(1, char(i))));
        monitor.model()->flush();
        QCOMPARE(monitor.model()->rowCount(), 10);
        QCOMPARE(monitor.model()->droppedCount(), 15);
        QCOMPARE(monitor.model()->entry(0).frame.payload(), QByteArray(1, char(15)));
        QCOMPARE(monitor.model()->entry(9).frame.payload(), QByteArray(1, char(24)));
        for (int i = 25; i < 28; ++i)
            bus.feed(QCanBusFrame(0x181, QByteArray(1, char(i))));
        monitor.model()->flush();
        QCOMPARE(monitor.model()->entry(0).frame.payload(), QByteArray(1, char(18)));
        QCOMPARE(monitor.model()->entry(9).frame.payload(), QByteArray(1, char(27)));
        QCOMPARE(CanMonitorModel::kDefaultCapacity, 100000);
    }

    void savesAndReadsBackACandumpLog()
    {
        ScriptedCanBus bus;
        CanMonitor monitor;
        setUp(monitor, bus);
        playTraffic(bus);
        QCanBusFrame remote(0x732, QByteArray());
        remote.setFrameType(QCanBusFrame::RemoteRequestFrame);
        bus.feed(remote);
        QCanBusFrame extended(0x18FF0032, QByteArray::fromHex("0102"));
        bus.feed(extended);
        monitor.model()->flush();
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("traffic.log"));
        const auto saved = monitor.saveLog(path);
        QVERIFY2(saved.ok(), qPrintable(saved.error().toString()));

        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly | QIODevice::Text));
        const QStringList lines =
            QString::fromLatin1(file.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 9);
        QVERIFY(
            QRegularExpression(QStringLiteral(R"(^\(\d{10}\.\d{6}\) can0 5B2#4B41600027040000$)"))
                .match(lines.at(1))
                .hasMatch());
        QVERIFY(lines.at(7).endsWith(QStringLiteral(" can0 732#R")));
        QVERIFY(lines.at(8).endsWith(QStringLiteral(" can0 18FF0032#0102")));
        for (int i = 0; i < lines.size(); ++i) {
            const auto line = widgets::candump::parseLine(lines.at(i));
            QVERIFY2(line, qPrintable(lines.at(i)));
            const CanMonitorModel::Entry &e = monitor.model()->entry(i);
            QCOMPARE(line->frame.frameId(), e.frame.frameId());
            QCOMPARE(line->frame.payload(), e.frame.payload());
            QCOMPARE(line->frame.frameType(), e.frame.frameType());
            QCOMPARE(line->frame.hasExtendedFrameFormat(), e.frame.hasExtendedFrameFormat());
            QCOMPARE(line->epochUs, e.epochUs);
        }

        // Only what the filters show is saved.
        QTest::keyClicks(monitor.findChild<QLineEdit *>(QStringLiteral("idFilter")),
                         QStringLiteral("B2"));
        QVERIFY(monitor.saveLog(path, QStringLiteral("vcan0")));
        file.close();
        QVERIFY(file.open(QIODevice::ReadOnly | QIODevice::Text));
        const QString only = QString::fromLatin1(file.readAll()).trimmed();
        QVERIFY2(only.endsWith(QStringLiteral(" vcan0 0B2#2132050000000000")), qPrintable(only));
        QVERIFY(!only.contains(QLatin1Char('\n')));
        QVERIFY(!monitor.saveLog(dir.filePath(QStringLiteral("missing/dir/x.log"))));
    }

    void clearEmptiesAndDetachStopsRecording()
    {
        ScriptedCanBus bus;
        CanMonitor monitor;
        setUp(monitor, bus);
        playTraffic(bus);
        monitor.model()->flush();
        QTest::mouseClick(monitor.findChild<QToolButton *>(QStringLiteral("clear")),
                          Qt::LeftButton);
        QCOMPARE(monitor.model()->rowCount(), 0);
        monitor.setBus(nullptr);
        bus.feed(0x732, "05");
        monitor.model()->flush();
        QCOMPARE(monitor.model()->rowCount(), 0);
    }

    void senderSendsOnceAndPeriodically()
    {
        ScriptedCanBus bus;
        CanMonitor monitor;
        setUp(monitor, bus);
        FrameSender *sender = monitor.frameSender();
        QVERIFY(sender);
        // Bad input names the cause and sends nothing.
        sender->setFrameText(QStringLiteral("6G1"), QStringLiteral("01"));
        QVERIFY(!sender->sendOnce());
        QVERIFY2(sender->status().contains(QStringLiteral("6G1")), qPrintable(sender->status()));
        sender->setFrameText(QStringLiteral("601"), QStringLiteral("00 11 22 33 44 55 66 77 88"));
        QVERIFY(!sender->sendOnce());
        QVERIFY2(sender->status().contains(QStringLiteral("at most 8")),
                 qPrintable(sender->status()));
        QVERIFY(bus.takeSent().isEmpty());

        // NMT start node 5, from the fields with the Send button.
        sender->setFrameText(QStringLiteral("000"), QStringLiteral("0105"));
        QTest::mouseClick(sender->findChild<QToolButton *>(QStringLiteral("send")), Qt::LeftButton);
        QList<QCanBusFrame> sent = bus.takeSent();
        QCOMPARE(sent.size(), 1);
        QCOMPARE(test::describe(sent.first()), QStringLiteral("000 [2] 01 05"));
        // The monitor shows what the sender sent.
        monitor.model()->flush();
        QCOMPARE(monitor.model()->rowCount(), 1);

        // Periodic: every 20 ms until switched off; a closed bus stops it.
        sender->setFrameText(QStringLiteral("080"), QString());
        sender->setPeriodMs(20);
        QTest::mouseClick(sender->findChild<QToolButton *>(QStringLiteral("sendPeriodic")),
                          Qt::LeftButton);
        QVERIFY(sender->isPeriodic());
        QTRY_VERIFY(bus.sent().size() >= 4);
        for (const QCanBusFrame &f : bus.takeSent())
            QCOMPARE(test::describe(f).trimmed(), QStringLiteral("080 [0]"));
        sender->setPeriodic(false);
        QVERIFY(!sender->isPeriodic());
        QVERIFY(sender->setPeriodic(true));
        bus.close();
        QTRY_VERIFY(!sender->isPeriodic());
        QVERIFY2(sender->status().contains(QStringLiteral("not open")),
                 qPrintable(sender->status()));
    }

    void senderRunsAMacroOfSendAndWait()
    {
        const auto bad = FrameSender::parseMacro(QStringLiteral("send 000 01 05\nsleep 10"));
        QVERIFY(!bad);
        QVERIFY2(bad.error().message().contains(QStringLiteral("line 2")),
                 qPrintable(bad.error().message()));
        QVERIFY(!FrameSender::parseMacro(QStringLiteral("wait -1")));
        QVERIFY(!FrameSender::parseMacro(QStringLiteral("send")));
        const auto steps = FrameSender::parseMacro(
            QStringLiteral("# start node 5, then SYNC\n\nsend 000 01 05\nwait 60 # settle\n"
                           "SEND 18FF0001 AA"));
        QVERIFY2(steps, qPrintable(steps.error().toString()));
        QCOMPARE(steps->size(), 3);
        QVERIFY(steps->at(2).frame.hasExtendedFrameFormat());

        ScriptedCanBus bus;
        CanMonitor monitor;
        setUp(monitor, bus);
        FrameSender *sender = monitor.frameSender();
        sender->setMacroText(QStringLiteral("send 000 01 05\nwait 60\nsend 080\nsend 18FF0001 AA"));
        QSignalSpy finished(sender, &FrameSender::macroFinished);
        QElapsedTimer clock;
        clock.start();
        QVERIFY(sender->runMacro());
        QCOMPARE(bus.sent().size(), 1); // the first frame at once, then the wait
        QVERIFY(finished.wait(5000));
        QVERIFY(clock.elapsed() >= 55); // the wait, less a timer that may fire a little early
        QCOMPARE(finished.first().first().toBool(), true);
        const QList<QCanBusFrame> sent = bus.takeSent();
        QCOMPARE(sent.size(), 3);
        QCOMPARE(test::describe(sent.at(0)), QStringLiteral("000 [2] 01 05"));
        QCOMPARE(test::describe(sent.at(1)).trimmed(), QStringLiteral("080 [0]"));
        QCOMPARE(sent.at(2).frameId(), 0x18FF0001u);
        QCOMPARE(sender->sentCount(), 3);

        // Stop in the middle of a wait: nothing more goes out.
        sender->setMacroText(QStringLiteral("send 080\nwait 10000\nsend 080"));
        QVERIFY(sender->runMacro());
        sender->stopMacro();
        QVERIFY(!sender->isMacroRunning());
        QCOMPARE(bus.takeSent().size(), 1);
    }

    // One change-log entry per send action: a frame sent once, the start and the stop of a
    // periodic sending (not one per frame), a macro from its start to its end; input refused
    // before anything is sent makes none.
    void senderActionsGoToTheChangeLog()
    {
        ScriptedCanBus bus;
        CanMonitor monitor;
        setUp(monitor, bus);
        ChangeLog log;
        FrameSender *sender = monitor.frameSender();
        sender->setChangeLog(&log, QStringLiteral("canopen+slcan://bus"));

        sender->setFrameText(QStringLiteral("6G1"), QStringLiteral("01"));
        QVERIFY(!sender->sendOnce());
        QCOMPARE(log.count(), 0);

        sender->setFrameText(QStringLiteral("000"), QStringLiteral("0105"));
        QVERIFY(sender->sendOnce());
        QCOMPARE(log.count(), 1);
        ChangeLog::Entry e = log.entries().at(0);
        QCOMPARE(e.kind, ChangeLog::Kind::Frame);
        QCOMPARE(e.device, QStringLiteral("canopen+slcan://bus"));
        QCOMPARE(e.object, QStringLiteral("000 01 05"));
        QCOMPARE(e.outcome, ChangeLog::Outcome::Ok);

        sender->setFrameText(QStringLiteral("080"), QString());
        sender->setPeriodMs(20);
        QVERIFY(sender->setPeriodic(true));
        QTRY_VERIFY(bus.sent().size() >= 5);
        sender->setPeriodic(false);
        const int periodic = int(bus.takeSent().size()) - 1;
        QCOMPARE(log.count(), 3); // start and stop, not one per frame
        QCOMPARE(log.entries().at(1).object, QStringLiteral("080"));
        QVERIFY2(log.entries().at(1).newValue.contains(QStringLiteral("20 ms")),
                 qPrintable(log.entries().at(1).newValue));
        const ChangeLog::Entry stop = log.entries().at(2);
        QVERIFY2(stop.newValue.contains(QStringLiteral("after %1 frame").arg(periodic)),
                 qPrintable(stop.newValue));
        QCOMPARE(stop.outcome, ChangeLog::Outcome::Ok);

        // A closed bus ends the periodic sending: the stop says why.
        QVERIFY(sender->setPeriodic(true));
        bus.close();
        QTRY_VERIFY(!sender->isPeriodic());
        QCOMPARE(log.count(), 5);
        QCOMPARE(log.entries().at(4).outcome, ChangeLog::Outcome::Failed);
        QVERIFY2(log.entries().at(4).message.contains(QStringLiteral("not open")),
                 qPrintable(log.entries().at(4).message));

        // A macro: one entry, pending while it runs, done at its end; stopped: aborted.
        bus.open();
        sender->setMacroText(QStringLiteral("send 000 01 05\nwait 30\nsend 080"));
        QSignalSpy finished(sender, &FrameSender::macroFinished);
        QVERIFY(sender->runMacro());
        QCOMPARE(log.count(), 6);
        QCOMPARE(log.entries().at(5).outcome, ChangeLog::Outcome::Pending);
        QVERIFY2(log.entries().at(5).newValue.contains(QStringLiteral("send 000 01 05; wait 30")),
                 qPrintable(log.entries().at(5).newValue));
        QVERIFY(finished.wait(5000));
        QCOMPARE(log.count(), 6);
        QCOMPARE(log.entries().at(5).outcome, ChangeLog::Outcome::Ok);
        sender->setMacroText(QStringLiteral("send 080\nwait 10000\nsend 080"));
        QVERIFY(sender->runMacro());
        sender->stopMacro();
        QCOMPARE(log.count(), 7);
        QCOMPARE(log.entries().at(6).outcome, ChangeLog::Outcome::Aborted);
    }

    void showsTheDemoDriveOverSlcan()
    {
        app::DemoDrive demo;
        QVERIFY(demo.startSlcan(0).ok());
        auto created = app::protocolRegistry().create(demo.slcanUri());
        QVERIFY2(created.ok(), qPrintable(created.error().toString()));
        auto *connection = qobject_cast<canopen::CanopenConnection *>(created.value().get());
        QVERIFY(connection);
        CanMonitor monitor;
        monitor.setConnection(connection);
        connection->open();
        QTRY_COMPARE_WITH_TIMEOUT(connection->state(), DeviceConnection::State::Connected, 5000);
        std::unique_ptr<Reply> reply(connection->read(ObjectAddress(0x6041, 0)));
        QSignalSpy finished(reply.get(), &Reply::finished);
        QVERIFY(finished.wait(5000));
        const auto has = [&monitor](const QString &prefix) {
            for (int row = 0; row < monitor.model()->rowCount(); ++row) {
                if (monitor.model()->entry(row).decoded.text.startsWith(prefix))
                    return true;
            }
            return false;
        };
        QTRY_VERIFY(has(QStringLiteral("SDO rx node 50: upload 6041:0 Statusword")));
        QTRY_VERIFY(has(QStringLiteral("SDO tx node 50: upload 6041:0 Statusword → 0x")));
        connection->close();
    }
};

QTEST_MAIN(TestCanMonitor)
#include "tst_canmonitor.moc"
