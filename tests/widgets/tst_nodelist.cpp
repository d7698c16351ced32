#include "canopen/cannetwork.h"
#include "canopen/nmtmaster.h"
#include "canopen/nodemonitor.h"
#include "scriptedcanbus.h"
#include "widgets/canopen/nodelist.h"
#include "widgets/canopen/nodelistmodel.h"

#include <QCheckBox>
#include <QSignalSpy>
#include <QTableView>
#include <QTest>
#include <QToolButton>

using namespace db;
using namespace db::canopen;
using db::test::ScriptedCanBus;
using db::widgets::NodeList;
using db::widgets::NodeListModel;

// Level 4: the node list offscreen against a ScriptedCanBus with the real NodeMonitor and
// NmtMaster.
class TestNodeList : public QObject
{
    Q_OBJECT

private:
    struct Fixture
    {
        CanNetwork network { new ScriptedCanBus };
        ScriptedCanBus &bus = *static_cast<ScriptedCanBus *>(network.bus());
        NodeMonitor &monitor = *network.monitor();
        NodeList list;
        Fixture()
        {
            bus.open();
            list.setNetwork(&network, 50, QStringLiteral("MovingCap ETH"));
        }
        QString cell(NodeId node, int column) const
        {
            const NodeListModel *m = list.model();
            return m->index(m->rowOf(node), column).data().toString();
        }
        void click(const char *button)
        {
            QTest::mouseClick(list.findChild<QToolButton *>(QString::fromLatin1(button)),
                              Qt::LeftButton);
        }
    };

private Q_SLOTS:
    void listsTheOwnNodeBeforeItIsHeard()
    {
        Fixture f;
        QCOMPARE(f.list.model()->rowCount(), 1);
        QCOMPARE(f.cell(50, NodeListModel::Node), QStringLiteral("50 (0x32)"));
        QCOMPARE(f.cell(50, NodeListModel::State), QStringLiteral("unknown"));
        QCOMPARE(f.cell(50, NodeListModel::Heartbeat), QStringLiteral("never"));
        QCOMPARE(f.cell(50, NodeListModel::Name), QStringLiteral("MovingCap ETH"));
        QCOMPARE(f.list.targetNode(), 50);
    }

    void onlyHeardNodesAgeOnScreen()
    {
        // The age column of a node never heard says "never" and is not refreshed: nothing is
        // repainted while nothing changes. A window of three refresh periods (fixed on purpose:
        // what is checked is that nothing happens in it).
        Fixture f;
        QSignalSpy changed(f.list.model(), &QAbstractItemModel::dataChanged);
        QTest::qWait(3 * NodeListModel::kAgeRefreshMs);
        QCOMPARE(changed.count(), 0);
        f.bus.feed(0x732, "05"); // heard now: its age moves on
        changed.clear();
        QTRY_VERIFY(!changed.isEmpty());
        QCOMPARE(changed.last().at(0).toModelIndex().column(), int(NodeListModel::Heartbeat));
    }

    void showsBootUpAndHeartbeatNodes()
    {
        Fixture f;
        f.bus.feed(0x705, "00");
        QCOMPARE(f.list.model()->rowCount(), 2);
        QCOMPARE(f.list.model()->nodeAt(0), NodeId(5)); // ascending ids
        QCOMPARE(f.cell(5, NodeListModel::State), QStringLiteral("boot-up"));
        f.bus.feed(0x705, "7F");
        QCOMPARE(f.cell(5, NodeListModel::State), QStringLiteral("pre-operational"));
        f.bus.feed(0x732, "05");
        QCOMPARE(f.list.model()->state(50), NmtState::Operational);
        QCOMPARE(f.cell(50, NodeListModel::State), QStringLiteral("operational"));
        QVERIFY(f.list.model()->heartbeatAgeMs(50) >= 0);
        QVERIFY(f.cell(50, NodeListModel::Heartbeat).endsWith(QStringLiteral(" s ago")));
    }

    void reportsALostHeartbeat()
    {
        Fixture f;
        f.monitor.setConsumerTime(7, 50);
        f.bus.feed(0x707, "05");
        QTRY_VERIFY(f.list.model()->isLost(7));
        QCOMPARE(f.cell(7, NodeListModel::State), QStringLiteral("lost (was operational)"));
        f.bus.feed(0x707, "05");
        QVERIFY(!f.list.model()->isLost(7));
    }

    void sendsNmtToTheSelectedNodeAndBroadcast()
    {
        Fixture f;
        f.bus.feed(0x705, "7F");
        f.list.selectNode(5);
        f.click("stop");
        f.click("preop");
        f.click("start");
        f.click("reset");
        f.click("resetComm");
        const QList<QCanBusFrame> sent = f.bus.takeSent();
        QCOMPARE(sent.size(), 5);
        for (const QCanBusFrame &frame : sent)
            QCOMPARE(frame.frameId(), 0u);
        QCOMPARE(sent.at(0).payload(), QByteArray::fromHex("0205"));
        QCOMPARE(sent.at(1).payload(), QByteArray::fromHex("8005"));
        QCOMPARE(sent.at(2).payload(), QByteArray::fromHex("0105"));
        QCOMPARE(sent.at(3).payload(), QByteArray::fromHex("8105"));
        QCOMPARE(sent.at(4).payload(), QByteArray::fromHex("8205"));

        QTest::mouseClick(f.list.findChild<QCheckBox *>(QStringLiteral("broadcast")),
                          Qt::LeftButton);
        QCOMPARE(f.list.targetNode(), 0);
        f.click("start");
        QCOMPARE(f.bus.takeSent().value(0).payload(), QByteArray::fromHex("0100"));
        // Without heartbeat the own node shows what was last asked of it.
        QCOMPARE(f.cell(50, NodeListModel::State), QStringLiteral("unknown (sent start)"));
    }

    void commandsNeedAnOpenBusAndServices()
    {
        Fixture f;
        f.bus.close();
        QVERIFY(!f.list.sendCommand(NmtCommand::Start));
        f.list.setNetwork(nullptr);
        QCOMPARE(f.list.model()->rowCount(), 0);
        QVERIFY(!f.list.findChild<QToolButton *>(QStringLiteral("start"))->isEnabled());
    }
};

QTEST_MAIN(TestNodeList)
#include "tst_nodelist.moc"
