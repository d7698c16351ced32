// Level 4: the node list offscreen on the network of a real CANopen connection to the simulated
// MovingCap (SLCAN on loopback). The drive beats every 50 ms (1017h); the connection makes the
// node monitor watch it with twice that as consumer time, so when the simulator stops the
// heartbeat the list shows the node as lost within the consumer time, and back when it beats.
#include "canopen/canopenconnection.h"
#include "canopen/nodemonitor.h"
#include "common/demodrive.h"
#include "common/protocols.h"
#include "resources/builtindescriptions.h"
#include "widgets/canopen/nodelist.h"
#include "widgets/canopen/nodelistmodel.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QTest>

using namespace db;
using db::widgets::NodeList;
using db::widgets::NodeListModel;

namespace {
constexpr int kMarginMs = 150; // event loop and SLCAN latency on a busy machine
}

class TestNodeListSim : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void silentDriveShowsAsLostWithinItsConsumerTime()
    {
        app::DemoDrive demo({ { ObjectAddress(0x1017, 0), 50 } });
        QVERIFY(demo.startSlcan().ok());
        auto made = app::protocolRegistry().create(demo.slcanUri());
        QVERIFY(made);
        const std::shared_ptr<DeviceConnection> connection = made.value();
        connection->setDictionary(resources::movingCapDictionary());
        connection->open();
        QTRY_VERIFY(connection->isConnected());
        auto *canopen = qobject_cast<canopen::CanopenConnection *>(connection.get());
        QVERIFY(canopen);
        canopen::NodeMonitor *monitor = canopen->network()->monitor();

        NodeList list;
        list.setNetwork(canopen->network(), 50, QStringLiteral("MovingCap ETH"));
        list.resize(640, 200);
        list.show();
        const NodeListModel *model = list.model();
        QTRY_COMPARE(monitor->consumerTime(50), 100); // on by default: 1017h x 2
        QTRY_VERIFY(model->heartbeatAgeMs(50) >= 0);
        QVERIFY(!model->isLost(50));

        QElapsedTimer since;
        since.start();
        demo.setHeartbeatSilenced(true);
        QTRY_VERIFY_WITH_TIMEOUT(model->isLost(50), monitor->consumerTime(50) + kMarginMs);
        qInfo("node 50 shown as lost %lld ms after its heartbeat stopped (consumer time %d ms)",
              since.elapsed(), monitor->consumerTime(50));
        const QString state =
            model->index(model->rowOf(50), NodeListModel::State).data().toString();
        QVERIFY2(state.startsWith(QLatin1String("lost")), qPrintable(state));
        const QString shot =
            QCoreApplication::applicationDirPath() + QStringLiteral("/nodelist-heartbeat-lost.png");
        if (list.grab().save(shot))
            qInfo("screenshot: %s", qPrintable(shot));

        demo.setHeartbeatSilenced(false);
        QTRY_VERIFY(!model->isLost(50));
        connection->close();
    }
};

QTEST_MAIN(TestNodeListSim)
#include "tst_nodelist_sim.moc"
