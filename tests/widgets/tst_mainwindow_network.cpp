// Level 4: the main window's "CANopen Network" page against simulated CANopen nodes on one SLCAN
// link: the tab shows while a CANopen node is current and follows its network, Scan lists the
// other nodes, the PDO table of another node is read, the window still fits a laptop screen,
// and the tab goes when the connection is removed. With DRIVEBENCH_SCREENSHOT_DIR=DIR the page
// is saved as DIR/network-view.png (1366x768).
#include "canopen/cannetwork.h"
#include "common/protocols.h"
#include "common/simnodes.h"
#include "core/changelog.h"
#include "mainwindow.h"
#include "widgets/canopen/canmonitor.h"
#include "widgets/canopen/framesender.h"
#include "widgets/canopen/networkview.h"
#include "widgets/canopen/nodelist.h"
#include "widgets/canopen/nodelistmodel.h"
#include "widgets/canopen/pdopanel.h"
#include "widgets/connection/devicelist.h"

#include <QDockWidget>
#include <QFile>
#include <QSettings>
#include <QSignalSpy>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>

using namespace db;
using db::gui::MainWindow;

namespace {
constexpr int kTimeoutMs = 10000;
}

class TestMainWindowNetwork : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_settingsDir;
    QTemporaryDir m_library;

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_settingsDir.isValid());
        QVERIFY(m_library.isValid());
        QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_settingsDir.path());
        qputenv("DRIVEBENCH_DESCRIPTIONS", m_library.path().toLocal8Bit());
        // The nodes' description is in the library: names and units in the editor and monitor.
        QVERIFY(QFile::copy(
            QStringLiteral(DRIVEBENCH_SOURCE_DIR "/resources/devices/drivebench_testnode.json"),
            m_library.filePath(QStringLiteral("testnode.json"))));
    }

    void networkPageFollowsTheCanopenConnection()
    {
        app::SimNodes nodes;
        QVERIFY(nodes.create({ { 1, 2, 5 }, {}, {} }).ok());
        QVERIFY(nodes.startSlcan(0).ok());
        MainWindow window(app::protocolRegistry());
        window.setConfirmation([](const QString &) { return true; });
        window.resize(1366, 768);
        window.show();
        widgets::NetworkView *view = window.networkView();
        QTabWidget *pages = window.pages();
        QVERIFY(view);
        QVERIFY(!pages->isTabVisible(pages->indexOf(view))); // no CANopen connection yet

        const auto opened = window.openConnection(
            QStringLiteral("canopen+slcan://127.0.0.1:%1?node=1").arg(nodes.slcanPort()));
        QVERIFY2(opened.ok(), qPrintable(opened.error().toString()));
        DeviceConnection *connection = opened.value();
        QTRY_VERIFY_WITH_TIMEOUT(connection->isConnected(), kTimeoutMs);
        QVERIFY(pages->isTabVisible(pages->indexOf(view)));
        QCOMPARE(view->network(), canopen::networkNodeOf(connection).network);
        pages->setCurrentWidget(view);

        // The node dock and the page are one list: a scan started in the dock fills the page,
        // a node selected on the page is the dock's target, "All nodes" is one setting.
        widgets::NodeList *dock = window.nodeList();
        QCOMPARE(dock->model(), view->nodeList()->model());
        QSignalSpy scanned(view->nodeList(), &widgets::NodeList::scanFinished);
        QVERIFY(dock->scan());
        QVERIFY(dock->isScanning() && view->nodeList()->isScanning());
        QVERIFY(!view->nodeList()->scan()); // one scan at a time
        QVERIFY(scanned.wait(kTimeoutMs));
        QCOMPARE(view->nodeList()->model()->rowCount(), 3);
        view->nodeList()->selectNode(2);
        QCOMPARE(view->pdoPanel()->node(), canopen::NodeId(2));
        QCOMPARE(dock->targetNode(), 2);
        dock->selectNode(5);
        QCOMPARE(view->pdoPanel()->node(), canopen::NodeId(5));
        dock->setBroadcast(true);
        QCOMPARE(view->nodeList()->targetNode(), 0);
        dock->setBroadcast(false);
        view->nodeList()->selectNode(2);
        QCOMPARE(dock->targetNode(), 2);
        QSignalSpy read(view->pdoPanel(), &widgets::PdoPanel::readFinished);
        QVERIFY(view->pdoPanel()->read());
        QVERIFY(read.wait(kTimeoutMs));
        QVERIFY2(read.takeFirst().first().toBool(), qPrintable(view->pdoPanel()->status()));
        QCOMPARE(view->pdoPanel()->table()->rowCount(), 4);
        // A PDO write and an NMT command from the page go to the change log.
        ChangeLog *changes = window.changeLog();
        const int before = changes->count();
        QTableWidget *table = view->pdoPanel()->table();
        for (int row = 0; row < table->rowCount(); ++row) {
            if (table->item(row, widgets::PdoPanel::Pdo)->text() == QLatin1String("TPDO1"))
                table->item(row, widgets::PdoPanel::Event)->setText(QStringLiteral("300"));
        }
        QSignalSpy written(view->pdoPanel(), &widgets::PdoPanel::writeFinished);
        QVERIFY(view->pdoPanel()->write());
        QVERIFY(written.wait(kTimeoutMs));
        QVERIFY2(written.first().first().toBool(), qPrintable(view->pdoPanel()->status()));
        QVERIFY(view->nodeList()->sendCommand(canopen::NmtCommand::Start));
        QCOMPARE(changes->count(), before + 2);
        const ChangeLog::Entry &pdo = changes->entries().at(before);
        QCOMPARE(pdo.kind, ChangeLog::Kind::Write);
        QCOMPARE(pdo.object, QStringLiteral("TPDO1 of node 2"));
        QCOMPARE(pdo.outcome, ChangeLog::Outcome::Ok);
        QVERIFY2(pdo.newValue.contains(QStringLiteral("event 300 ms")), qPrintable(pdo.newValue));
        QVERIFY2(!pdo.oldValue.contains(QStringLiteral("event 300 ms")), qPrintable(pdo.oldValue));
        const ChangeLog::Entry &nmt = changes->entries().at(before + 1);
        QCOMPARE(nmt.kind, ChangeLog::Kind::Nmt);
        QCOMPARE(nmt.object, QStringLiteral("node 2"));
        QVERIFY(read.wait(kTimeoutMs)); // the panel reads back after writing

        view->setSyncPeriodMs(100);
        QVERIFY(view->setSync(true));

        // Still fits a laptop with the page and its tools.
        const QSize minimum = window.minimumSizeHint();
        QVERIFY2(minimum.width() <= 1366 && minimum.height() <= 740,
                 qPrintable(QStringLiteral("%1x%2").arg(minimum.width()).arg(minimum.height())));

        if (const QString dir = qEnvironmentVariable("DRIVEBENCH_SCREENSHOT_DIR"); !dir.isEmpty()) {
            // The page gets the room of the Motion dock and of the node dock it shares; the
            // CAN monitor at the bottom shows the bus, with a frame ready in the sender.
            for (const char *name : { "motionDock", "nodeListDock" })
                window.findChild<QDockWidget *>(QString::fromLatin1(name))->hide();
            window.showCanMonitor();
            window.canMonitor()->frameSender()->setFrameText(QStringLiteral("000"),
                                                             QStringLiteral("01 05"));
            QTest::qWait(1500); // heartbeats and SYNCs arrive, ages count
            QVERIFY(window.grab().save(dir + QStringLiteral("/network-view.png")));
        }

        view->setSync(false);
        Q_EMIT window.deviceList()->removeRequested(connection); // Remove in the device list
        QVERIFY(!pages->isTabVisible(pages->indexOf(view)));
        QVERIFY(!view->network());
    }
};

QTEST_MAIN(TestMainWindowNetwork)
#include "tst_mainwindow_network.moc"
