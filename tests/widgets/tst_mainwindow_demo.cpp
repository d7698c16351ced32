#include "common/demodrive.h"
#include "common/protocols.h"
#include "mainwindow.h"
#include "widgets/connection/drivestatuspanel.h"

#include <QLabel>
#include <QSettings>
#include <QTemporaryDir>
#include <QTest>

using namespace db;
using db::gui::MainWindow;

// End to end: the main window against the in-process simulated MovingCap over loopback RefGo.
class TestMainWindowDemo : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_settingsDir;

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_settingsDir.isValid());
        QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_settingsDir.path());
    }

    void statusPanelShowsTheDemoDrive()
    {
        app::DemoDrive demo;
        const auto started = demo.startRefgo(0);
        QVERIFY2(started.ok(), qPrintable(started.error().toString()));

        MainWindow window(app::protocolRegistry());
        window.show();
        auto opened = window.openConnection(demo.refgoUri());
        QVERIFY2(opened.ok(), qPrintable(opened.error().toString()));

        widgets::DriveStatusPanel *panel = window.statusPanel();
        auto *state = panel->findChild<QLabel *>(QStringLiteral("stateName"));
        auto *statusword = panel->findChild<QLabel *>(QStringLiteral("statusword"));
        QTRY_VERIFY_WITH_TIMEOUT(!panel->isStale(ObjectAddress(0x6041, 0)), 10000);
        QVERIFY(statusword->text().startsWith(QStringLiteral("0x")));
        QVERIFY(state->text() != QStringLiteral("No status"));
        QVERIFY(state->text() != QStringLiteral("Unknown state"));

        window.close();
        QCOMPARE(opened.value()->state(), DeviceConnection::State::Disconnected);
    }
};

QTEST_MAIN(TestMainWindowDemo)
#include "tst_mainwindow_demo.moc"
