// Level 4: the CANopen network page offscreen against simulated CANopen nodes (our test node's
// description, SLCAN on loopback): scan with names from 1008h, the heartbeat consumer time per
// node, the SYNC switch, the PDO table read-edit-write in the safe order, LSS inquire and node id
// assignment, and the CAN monitor's frame sender starting a node.
#include "canopen/cannetwork.h"
#include "canopen/device/lssslave.h"
#include "canopen/lssmaster.h"
#include "canopen/nmtmaster.h"
#include "canopen/nodemonitor.h"
#include "canopen/pdoclient.h"
#include "canopen/syncproducer.h"
#include "common/protocols.h"
#include "common/simnodes.h"
#include "core/reply.h"
#include "scriptedcanbus.h"
#include "transport/canbus.h"
#include "widgets/canopen/canmonitor.h"
#include "widgets/canopen/framesender.h"
#include "widgets/canopen/lsspanel.h"
#include "widgets/canopen/networkview.h"
#include "widgets/canopen/nodelist.h"
#include "widgets/canopen/nodelistmodel.h"
#include "widgets/canopen/pdopanel.h"

#include <QCheckBox>
#include <QCoreApplication>
#include <QPushButton>
#include <QSignalSpy>
#include <QTableView>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QToolButton>
#include <QtEndian>

using namespace db;
using db::widgets::NetworkView;
using db::widgets::NodeListModel;
using db::widgets::PdoPanel;

namespace {

constexpr int kTimeoutMs = 10000;

// Simulated nodes on one SLCAN link and a connection to the first of them.
struct Bus
{
    app::SimNodes nodes;
    std::shared_ptr<DeviceConnection> connection;
    canopen::CanNetwork *network = nullptr;

    bool start(const QList<quint8> &ids)
    {
        if (!nodes.create({ ids, {}, {} }).ok() || !nodes.startSlcan().ok())
            return false;
        auto made =
            app::protocolRegistry().create(QStringLiteral("canopen+slcan://127.0.0.1:%1?node=%2")
                                               .arg(nodes.slcanPort())
                                               .arg(ids.first()));
        if (!made)
            return false;
        connection = made.value();
        network = canopen::networkNodeOf(connection.get()).network;
        connection->open();
        return network != nullptr;
    }
    ~Bus()
    {
        if (connection)
            connection->close();
    }
};

QString cell(const NodeListModel *model, canopen::NodeId node, int column,
             int role = Qt::DisplayRole)
{
    return model->index(model->rowOf(node), column).data(role).toString();
}

int rowOf(const QTableWidget *table, const QString &pdo)
{
    for (int row = 0; row < table->rowCount(); ++row) {
        if (table->item(row, PdoPanel::Pdo)->text() == pdo)
            return row;
    }
    return -1;
}

} // namespace

class TestNetworkView : public QObject
{
    Q_OBJECT
private:
    QTemporaryDir m_library; // an empty description folder: no user files take part

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_library.isValid());
        qputenv("DRIVEBENCH_DESCRIPTIONS", m_library.path().toLocal8Bit());
    }

    void scanListsTheNodesWithNamesAndConsumerTimes()
    {
        Bus bus;
        NetworkView view;
        QVERIFY(bus.start({ 1, 2, 5 }));
        view.setConnection(bus.connection.get()); // before the bus is open: Scan waits for it
        auto *scan = view.nodeList()->findChild<QToolButton *>(QStringLiteral("scan"));
        QVERIFY(!bus.network->isOpen() && !scan->isEnabled());
        QTRY_VERIFY_WITH_TIMEOUT(bus.connection->isConnected(), kTimeoutMs);
        QVERIFY(scan->isEnabled());
        view.resize(1200, 600);
        view.show();
        const NodeListModel *model = view.nodeList()->model();
        QSignalSpy finished(view.nodeList(), &widgets::NodeList::scanFinished);
        QTest::mouseClick(view.nodeList()->findChild<QToolButton *>(QStringLiteral("scan")),
                          Qt::LeftButton);
        QVERIFY(view.nodeList()->isScanning());
        QVERIFY(finished.wait(kTimeoutMs));
        QCOMPARE(finished.first().first().toInt(), 3);
        for (const canopen::NodeId node : { 1, 2, 5 }) {
            QVERIFY2(model->rowOf(node) >= 0, qPrintable(QString::number(node)));
            QCOMPARE(cell(model, node, NodeListModel::Name),
                     QStringLiteral("drivebench test node"));
            QVERIFY2(cell(model, node, NodeListModel::Name, Qt::ToolTipRole)
                         .contains(QStringLiteral("serial %1h").arg(node, 8, 16, QLatin1Char('0'))),
                     qPrintable(cell(model, node, NodeListModel::Name, Qt::ToolTipRole)));
        }
        QCOMPARE(model->rowCount(), 3);

        // The heartbeat consumer time of one node, edited in the list.
        canopen::NodeMonitor *monitor = bus.network->monitor();
        const QModelIndex consumer = model->index(model->rowOf(2), NodeListModel::Consumer);
        QVERIFY(consumer.flags() & Qt::ItemIsEditable);
        QVERIFY(view.nodeList()->model()->setData(consumer, 1200));
        QCOMPARE(monitor->consumerTime(2), 1200);
        QCOMPARE(cell(model, 2, NodeListModel::Consumer), QStringLiteral("1200 ms"));
        QVERIFY(!view.nodeList()->model()->setData(consumer, -5));
        QVERIFY(view.nodeList()->model()->setData(consumer, 0));
        QCOMPARE(cell(model, 2, NodeListModel::Consumer), QStringLiteral("off"));
        // Names from 1008h and heartbeat states (the test node beats every 500 ms).
        QTRY_COMPARE_WITH_TIMEOUT(cell(model, 5, NodeListModel::State),
                                  QStringLiteral("pre-operational"), kTimeoutMs);
    }

    void syncSwitchStartsAndStopsTheProducer()
    {
        Bus bus;
        QVERIFY(bus.start({ 3 }));
        QTRY_VERIFY_WITH_TIMEOUT(bus.connection->isConnected(), kTimeoutMs);
        NetworkView view;
        view.setConnection(bus.connection.get());
        view.show();
        int syncs = 0;
        connect(bus.network->bus(), &CanBus::frameSent, &view, [&syncs](const QCanBusFrame &f) {
            if (f.frameId() == canopen::cob::Sync)
                ++syncs;
        });
        auto *on = view.findChild<QCheckBox *>(QStringLiteral("syncOn"));
        QVERIFY(on && !on->isChecked());
        view.setSyncPeriodMs(20);
        on->click();
        QVERIFY(bus.network->sync()->isRunning());
        QCOMPARE(bus.network->sync()->periodMs(), 20);
        QTRY_VERIFY_WITH_TIMEOUT(syncs >= 5, kTimeoutMs);
        view.setSyncPeriodMs(50); // a new period restarts it
        QCOMPARE(bus.network->sync()->periodMs(), 50);
        on->click();
        QVERIFY(!bus.network->sync()->isRunning());
        QVERIFY(!view.isSyncOn());
    }

    void pdoTableIsReadEditedAndWrittenInTheSafeOrder()
    {
        Bus bus;
        QVERIFY(bus.start({ 1, 2 }));
        QTRY_VERIFY_WITH_TIMEOUT(bus.connection->isConnected(), kTimeoutMs);
        NetworkView view;
        view.setConnection(bus.connection.get());
        view.resize(1200, 600);
        view.show();
        // Node 2 is not the connection's node: it is listed by a scan, then selected.
        QSignalSpy scanned(view.nodeList(), &widgets::NodeList::scanFinished);
        QVERIFY(view.nodeList()->scan());
        QVERIFY(scanned.wait(kTimeoutMs));
        view.nodeList()->selectNode(2);
        PdoPanel *panel = view.pdoPanel();
        QCOMPARE(panel->node(), canopen::NodeId(2));

        QSignalSpy read(panel, &PdoPanel::readFinished);
        QTest::mouseClick(panel->findChild<QPushButton *>(QStringLiteral("pdoRead")),
                          Qt::LeftButton);
        QVERIFY(read.wait(kTimeoutMs));
        QVERIFY2(read.first().first().toBool(), qPrintable(panel->status()));
        QTableWidget *table = panel->table();
        QCOMPARE(table->rowCount(), 4); // RPDO1, RPDO2, TPDO1, TPDO2
        const int tpdo1 = rowOf(table, QStringLiteral("TPDO1"));
        QVERIFY(tpdo1 >= 0);
        QCOMPARE(table->item(tpdo1, PdoPanel::CobId)->text(), QStringLiteral("0x182"));
        QCOMPARE(table->item(tpdo1, PdoPanel::Mapping)->text(),
                 QStringLiteral("6041:0/16 6064:0/32"));

        // A cell that does not parse is named and nothing is written.
        table->item(tpdo1, PdoPanel::Mapping)->setText(QStringLiteral("6064:0/32 60zz"));
        QVERIFY(!panel->write());
        QVERIFY2(panel->status().contains(QStringLiteral("TPDO1, Mapping")),
                 qPrintable(panel->status()));

        // Swap the mapping, event timer 250 ms, event driven.
        table->item(tpdo1, PdoPanel::Mapping)->setText(QStringLiteral("6064:0/32 6041:0/16"));
        table->item(tpdo1, PdoPanel::Event)->setText(QStringLiteral("250"));
        table->item(tpdo1, PdoPanel::Type)->setText(QStringLiteral("0xFE"));
        QVERIFY(table->item(tpdo1, PdoPanel::Event)->font().bold()); // changed, not written

        QList<QPair<quint32, quint32>> downloads; // (index << 8 | sub, value) to node 2
        connect(bus.network->bus(), &CanBus::frameSent, panel, [&downloads](const QCanBusFrame &f) {
            const QByteArray d = f.payload();
            if (f.frameId() == 0x602 && d.size() == 8 && (quint8(d[0]) & 0xE0) == 0x20)
                downloads.append(
                    { quint32(qFromLittleEndian<quint16>(d.constData() + 1)) << 8 | quint8(d[3]),
                      qFromLittleEndian<quint32>(d.constData() + 4) });
        });
        QSignalSpy written(panel, &PdoPanel::writeFinished);
        read.clear();
        QTest::mouseClick(panel->findChild<QPushButton *>(QStringLiteral("pdoWrite")),
                          Qt::LeftButton);
        QVERIFY(written.wait(kTimeoutMs));
        QVERIFY2(written.first().first().toBool(), qPrintable(panel->status()));
        // Disabled first, mapping cleared before its entries, count and enable last.
        QVERIFY(downloads.size() >= 6);
        QCOMPARE(downloads.first().first, 0x180001u);
        QVERIFY(downloads.first().second & canopen::PdoConfig::kInvalidBit);
        int clear = -1;
        int firstEntry = -1;
        for (int i = 0; i < downloads.size(); ++i) {
            if (downloads.at(i) == QPair<quint32, quint32>(0x1A0000u, 0u) && clear < 0)
                clear = i;
            if (downloads.at(i).first == 0x1A0001u && firstEntry < 0)
                firstEntry = i;
        }
        QVERIFY(clear > 0 && firstEntry > clear);
        QCOMPARE(downloads.at(firstEntry).second, 0x60640020u);
        QCOMPARE(downloads.last().first, 0x180001u);
        QVERIFY(!(downloads.last().second & canopen::PdoConfig::kInvalidBit));

        // The panel reads back what the node took; an independent read agrees.
        QVERIFY(read.wait(kTimeoutMs));
        QCOMPARE(table->item(tpdo1, PdoPanel::Event)->text(), QStringLiteral("250"));
        QVERIFY(!table->item(tpdo1, PdoPanel::Event)->font().bold());
        canopen::PdoClient client(bus.network->sdo());
        const auto check =
            Reply::wait(client.read(2, canopen::PdoDirection::Transmit, 0), kTimeoutMs);
        QVERIFY2(check, qPrintable(check.error().toString()));
        const auto config = check->value<canopen::PdoConfig>();
        QCOMPARE(config.eventTimer, std::optional<quint16>(250));
        QCOMPARE(config.transmissionType, quint8(0xFE));
        QVERIFY(config.isEnabled());
        QCOMPARE(PdoPanel::mappingText(config.entries), QStringLiteral("6064:0/32 6041:0/16"));
    }

    void lssInquiresAndAssignsANodeId()
    {
        Bus bus;
        QVERIFY(bus.start({ 7 }));
        QTRY_VERIFY_WITH_TIMEOUT(bus.connection->isConnected(), kTimeoutMs);
        NetworkView view;
        view.setConnection(bus.connection.get());
        view.show();
        widgets::LssPanel *lss = view.lssPanel();
        QSignalSpy done(lss, &widgets::LssPanel::done);

        // No slave without a node id: fastscan ends with the cause, it does not hang.
        QVERIFY(lss->fastscan());
        QVERIFY(done.wait(kTimeoutMs));
        QCOMPARE(done.takeFirst().first().toBool(), false);

        QVERIFY(lss->switchAll(true));
        QVERIFY(lss->inquire());
        QVERIFY(done.wait(kTimeoutMs));
        QVERIFY2(done.takeFirst().first().toBool(), qPrintable(lss->logText()));
        QVERIFY2(lss->logText().contains(QStringLiteral("node id 7")), qPrintable(lss->logText()));
        QVERIFY2(lss->logText().contains(QStringLiteral("serial 00000007h")),
                 qPrintable(lss->logText()));

        QVERIFY(lss->assignNodeId(9));
        QVERIFY(done.wait(kTimeoutMs));
        QVERIFY2(done.takeFirst().first().toBool(), qPrintable(lss->logText()));
        QVERIFY(lss->store());
        QVERIFY(done.wait(kTimeoutMs));
        QVERIFY2(done.takeFirst().first().toBool(), qPrintable(lss->logText()));
        QVERIFY(lss->switchAll(false));
        // The new id takes effect at reset communication: node 9 boots.
        QSignalSpy booted(bus.network->monitor(), &canopen::NodeMonitor::bootUp);
        QVERIFY(bus.network->nmt()->send(canopen::NmtCommand::ResetCommunication, 7));
        QTRY_VERIFY_WITH_TIMEOUT(
            !booted.isEmpty() && booted.last().first().value<canopen::NodeId>() == 9, kTimeoutMs);
    }

    void lssFastscanFindsAnUnconfiguredSlave()
    {
        auto *bus = new test::ScriptedCanBus; // the network owns it
        canopen::CanNetwork network(bus);
        bus->open();
        const canopen::LssAddress identity { 0xEC, 0x71, 0x00010001, 0x4D52F567 };
        canopen::LssSlave unconfigured;
        unconfigured.setIdentity(identity);
        canopen::LssSlave configured; // has a node id: stays out of fastscan (CiA 305)
        configured.setIdentity({ 0xEC, 0x71, 0x00010001, 0x11111111 });
        configured.setActiveNodeId(3);
        for (canopen::LssSlave *s : { &unconfigured, &configured }) {
            connect(bus, &test::ScriptedCanBus::frameWritten, s, &canopen::LssSlave::receive);
            connect(s, &canopen::LssSlave::transmit, bus,
                    [bus](const QCanBusFrame &f) { bus->feedLater(f); });
        }
        network.lss()->setFastscanStepMs(5);
        widgets::LssPanel panel;
        panel.setNetwork(&network);
        QSignalSpy done(&panel, &widgets::LssPanel::done);
        QTest::mouseClick(panel.findChild<QPushButton *>(QStringLiteral("lssFastscan")),
                          Qt::LeftButton);
        QVERIFY(panel.isBusy());
        QVERIFY(done.wait(kTimeoutMs));
        QVERIFY2(done.takeFirst().first().toBool(), qPrintable(panel.logText()));
        QVERIFY2(panel.logText().contains(identity.toString()), qPrintable(panel.logText()));
        QCOMPARE(unconfigured.mode(), canopen::LssMode::Configuration);
        QVERIFY(panel.assignNodeId(12));
        QVERIFY(done.wait(kTimeoutMs));
        QVERIFY2(done.takeFirst().first().toBool(), qPrintable(panel.logText()));
        QVERIFY(panel.switchAll(false));
        QCOMPARE(unconfigured.activeNodeId(), quint8(12));
        QCOMPARE(configured.activeNodeId(), quint8(3));
    }

    void frameSenderStartsANode()
    {
        Bus bus;
        QVERIFY(bus.start({ 4, 6 }));
        QTRY_VERIFY_WITH_TIMEOUT(bus.connection->isConnected(), kTimeoutMs);
        widgets::CanMonitor monitor;
        monitor.setConnection(bus.connection.get());
        monitor.show();
        canopen::NodeMonitor *nodes = bus.network->monitor();
        QTRY_COMPARE_WITH_TIMEOUT(nodes->state(6), canopen::NmtState::PreOperational, kTimeoutMs);
        widgets::FrameSender *sender = monitor.frameSender();
        sender->setFrameText(QStringLiteral("000"), QStringLiteral("01 06")); // NMT start node 6
        QVERIFY2(sender->sendOnce(), qPrintable(sender->status()));
        QTRY_COMPARE_WITH_TIMEOUT(nodes->state(6), canopen::NmtState::Operational, kTimeoutMs);
        QCOMPARE(nodes->state(4), canopen::NmtState::PreOperational);
        // A macro: stop node 6, wait, stop node 4.
        sender->setMacroText(QStringLiteral("send 000 02 06\nwait 20\nsend 000 02 04"));
        QSignalSpy macro(sender, &widgets::FrameSender::macroFinished);
        QVERIFY(sender->runMacro());
        QVERIFY(macro.wait(kTimeoutMs));
        QTRY_COMPARE_WITH_TIMEOUT(nodes->state(6), canopen::NmtState::Stopped, kTimeoutMs);
        QTRY_COMPARE_WITH_TIMEOUT(nodes->state(4), canopen::NmtState::Stopped, kTimeoutMs);
    }
};

QTEST_MAIN(TestNetworkView)
#include "tst_networkview.moc"
