#include "core/connectionhealth.h"
#include "fakeconnection.h"
#include "mainwindow.h"
#include "resources/builtindescriptions.h"
#include "widgets/common/logconsole.h"
#include "widgets/connection/devicelist.h"
#include "widgets/connection/drivestatuspanel.h"
#include "widgets/morse/morsepanel.h"
#include "widgets/odeditor/objectaccessbox.h"

#include <QDockWidget>
#include <QLabel>
#include <QSettings>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>

using namespace db;
using db::gui::MainWindow;
using db::test::FakeConnection;

namespace {
// "fake://NAME" connections that answer a healthy drive's status objects.
ProtocolRegistry fakeRegistry()
{
    ProtocolRegistry registry;
    registry.add({ QStringLiteral("fake"),
                   QStringLiteral("fake"),
                   QStringLiteral("Test double"),
                   QStringLiteral("fake://NAME"),
                   -1,
                   [](const ConnectionPlan &plan) -> Result<std::unique_ptr<DeviceConnection>> {
                       auto fake = std::make_unique<FakeConnection>(plan.uri.toString());
                       fake->setDictionary(resources::movingCapDictionary());
                       fake->setValue({ 0x6041, 0 }, QVariant::fromValue<qulonglong>(0x0427));
                       return std::unique_ptr<DeviceConnection>(std::move(fake));
                   },
                   {},
                   {} });
    return registry;
}
} // namespace

class TestMainWindow : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_settingsDir;
    const ProtocolRegistry m_registry = fakeRegistry();

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_settingsDir.isValid());
        QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_settingsDir.path());
    }

    void connectionBecomesCurrentEverywhere()
    {
        MainWindow window(m_registry);
        window.show();
        auto opened = window.openConnection(QStringLiteral("fake://drive1"));
        QVERIFY(opened.ok());
        QCOMPARE(window.currentConnection(), opened.value());
        QCOMPARE(window.statusPanel()->connection(), opened.value());
        QCOMPARE(window.objectAccessBox()->connection(), opened.value());
        QCOMPARE(window.deviceList()->count(), 1);
        QTRY_COMPARE(window.statusPanel()->findChild<QLabel *>(QStringLiteral("stateName"))->text(),
                     QStringLiteral("Operation enabled"));
        QVERIFY(window.logConsole()->toPlainText().contains(
            QStringLiteral("fake://drive1 is connected")));
    }

    void badUriIsRefusedAndLogged()
    {
        MainWindow window(m_registry);
        auto opened = window.openConnection(QStringLiteral("nope://x"));
        QVERIFY(!opened.ok());
        QCOMPARE(window.deviceList()->count(), 0);
        QVERIFY(window.logConsole()->toPlainText().contains(QStringLiteral("unknown protocol")));
    }

    void closingDisconnectsAndPersistsRecent()
    {
        QList<QPointer<DeviceConnection>> connections;
        {
            MainWindow window(m_registry);
            window.show();
            connections.append(window.openConnection(QStringLiteral("fake://a")).value());
            connections.append(window.openConnection(QStringLiteral("fake://b")).value());
            QTRY_VERIFY(connections[0]->isConnected() && connections[1]->isConnected());
            // Remembered once the device answered (a connection nobody polls is probed).
            QTRY_VERIFY_WITH_TIMEOUT(ConnectionHealth::of(connections[0])->isResponding()
                                         && ConnectionHealth::of(connections[1])->isResponding(),
                                     2 * ConnectionHealth::kProbeIntervalMs + 1000);
            QVERIFY(window.close());
            QCOMPARE(connections[0]->state(), DeviceConnection::State::Disconnected);
            QCOMPARE(connections[1]->state(), DeviceConnection::State::Disconnected);
        }
        QVERIFY(!connections[0]); // owned by the window
        MainWindow again(m_registry);
        // Most recently answered first; which of the two answered first is up to the event loop.
        QStringList recent = again.recentConnections();
        recent.sort();
        QCOMPARE(recent, (QStringList { QStringLiteral("fake://a"), QStringLiteral("fake://b") }));
    }

    // The camera (Qt Multimedia) is attached when the Morse tab is first shown, not at start-up.
    void cameraIsAttachedWhenTheMorseTabIsShown()
    {
        MainWindow window(m_registry);
        window.show();
        auto *panel = window.findChild<widgets::MorsePanel *>();
        auto *dock = window.findChild<QDockWidget *>(QStringLiteral("morseDock"));
        QVERIFY(panel && dock);
        QVERIFY(!panel->liveSource());
        dock->raise();
        QTRY_VERIFY(panel->liveSource());
    }

    void fitsALaptopScreen()
    {
        // 1366x768 is still a common commissioning laptop: every dock and page together must
        // fit (the docks can be closed, but the default arrangement must not overflow).
        MainWindow window(m_registry);
        window.show();
        QVERIFY(window.openConnection(QStringLiteral("fake://drive1")).ok());
        QString parts;
        for (const QDockWidget *dock : window.findChildren<QDockWidget *>()) {
            if (dock->isVisible())
                parts += QStringLiteral(" %1=%2x%3")
                             .arg(dock->objectName())
                             .arg(dock->minimumSizeHint().width())
                             .arg(dock->minimumSizeHint().height());
        }
        for (int i = 0; i < window.pages()->count(); ++i)
            parts += QStringLiteral(" '%1'=%2x%3")
                         .arg(window.pages()->tabText(i))
                         .arg(window.pages()->widget(i)->minimumSizeHint().width())
                         .arg(window.pages()->widget(i)->minimumSizeHint().height());
        const QSize min = window.minimumSizeHint().expandedTo(window.minimumSize());
        QVERIFY2(min.width() <= 1366 && min.height() <= 740,
                 qPrintable(QStringLiteral("window needs %1x%2:%3")
                                .arg(min.width())
                                .arg(min.height())
                                .arg(parts)));
    }
};

QTEST_MAIN(TestMainWindow)
#include "tst_mainwindow.moc"
