#include "fakeconnection.h"
#include "widgets/connection/devicelist.h"

#include <QListWidget>
#include <QSignalSpy>
#include <QTest>
#include <QToolButton>

using namespace db;
using db::test::FakeConnection;
using db::widgets::DeviceList;

class TestDeviceList : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void showsConnectionsAndFollowsTheirState()
    {
        FakeConnection a(QStringLiteral("refgo://10.0.0.1:10001"));
        FakeConnection b(QStringLiteral("refgo://10.0.0.2:10001"));
        DeviceList list;
        QSignalSpy current(&list, &DeviceList::currentConnectionChanged);
        list.addConnection(&a);
        list.addConnection(&b);
        list.addConnection(&a); // no duplicates
        QCOMPARE(list.count(), 2);
        QCOMPARE(list.currentConnection(), &a); // the first becomes current
        QCOMPARE(current.count(), 1);

        auto *view = list.findChild<QListWidget *>();
        QCOMPARE(view->item(1)->text(), QStringLiteral("refgo://10.0.0.2:10001"));
        QVERIFY(view->item(0)->toolTip().contains(QStringLiteral("disconnected")));
        a.open();
        QTRY_VERIFY(view->item(0)->toolTip().contains(QStringLiteral("State: connected")));

        list.setCurrentConnection(&b);
        QCOMPARE(current.count(), 2);
        QCOMPARE(current.last().first().value<DeviceConnection *>(), &b);
    }

    void buttonsRequestActionsForTheCurrentConnection()
    {
        FakeConnection a;
        DeviceList list;
        list.addConnection(&a);
        QSignalSpy connectSpy(&list, &DeviceList::connectRequested);
        QSignalSpy disconnectSpy(&list, &DeviceList::disconnectRequested);
        QSignalSpy removeSpy(&list, &DeviceList::removeRequested);
        const auto button = [&](const QString &text) {
            for (auto *b : list.findChildren<QToolButton *>()) {
                if (b->text() == text)
                    return b;
            }
            return static_cast<QToolButton *>(nullptr);
        };
        QVERIFY(button(QStringLiteral("Connect"))->isEnabled());
        QVERIFY(!button(QStringLiteral("Disconnect"))->isEnabled());
        button(QStringLiteral("Connect"))->click();
        QCOMPARE(connectSpy.count(), 1);
        a.open();
        QTRY_VERIFY(button(QStringLiteral("Disconnect"))->isEnabled());
        QVERIFY(!button(QStringLiteral("Connect"))->isEnabled());
        button(QStringLiteral("Disconnect"))->click();
        QCOMPARE(disconnectSpy.count(), 1);
        button(QStringLiteral("Remove"))->click();
        QCOMPARE(removeSpy.count(), 1);
        QCOMPARE(removeSpy.first().first().value<DeviceConnection *>(), &a);
    }

    void destroyedConnectionDisappears()
    {
        DeviceList list;
        QSignalSpy current(&list, &DeviceList::currentConnectionChanged);
        {
            FakeConnection a;
            list.addConnection(&a);
            QCOMPARE(list.count(), 1);
        }
        QCOMPARE(list.count(), 0);
        QCOMPARE(list.currentConnection(), nullptr);
        list.addConnection(nullptr);
        QCOMPARE(list.count(), 0);
    }

    void removeConnection()
    {
        FakeConnection a;
        DeviceList list;
        list.addConnection(&a);
        list.removeConnection(&a);
        QCOMPARE(list.count(), 0);
        QVERIFY(list.connections().isEmpty());
    }
};

QTEST_MAIN(TestDeviceList)
#include "tst_devicelist.moc"
