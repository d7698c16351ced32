// The main window tells the truth about a connection: refused, a peer that accepts and never
// answers, a lost link, the user's own disconnect and a reconnect, each as the status bar, the
// Drive Status page and the Motion dock show it. Also: a URI already listed is refused, failed
// and demo URIs are not remembered, and closing a connection with an enabled drive asks first.
#include "common/demodrive.h"
#include "common/protocols.h"
#include "core/connectionhealth.h"
#include "devices/movingcap/movingcapdrive.h"
#include "mainwindow.h"
#include "motion/motionaxis.h"
#include "widgets/common/logconsole.h"
#include "widgets/connection/devicelist.h"
#include "widgets/connection/drivestatuspanel.h"
#include "widgets/motion/jogpanel.h"

#include <QLabel>
#include <QPushButton>
#include <QSettings>
#include <QStatusBar>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTemporaryDir>
#include <QTest>

using namespace db;
using db::gui::MainWindow;

namespace {
constexpr int kWaitMs = 15000;

QString statusBarText(const MainWindow &window)
{
    auto *label = window.findChild<QLabel *>(QStringLiteral("connectionState"));
    return label ? label->text() : QString();
}

QLabel *banner(const MainWindow &window)
{
    return window.findChild<QLabel *>(QStringLiteral("healthBanner"));
}

QPushButton *motionButton(const MainWindow &window, const QString &name)
{
    return window.jogPanel()->findChild<QPushButton *>(name);
}

// Accepts every connection and never sends a byte.
class SilentPeer : public QTcpServer
{
public:
    SilentPeer()
    {
        listen(QHostAddress::LocalHost, 0);
        connect(this, &QTcpServer::newConnection, this, [this] {
            while (QTcpSocket *s = nextPendingConnection())
                s->setParent(this);
        });
    }
    QString uri() const { return QStringLiteral("refgo://127.0.0.1:%1").arg(serverPort()); }
};
} // namespace

class TestMainWindowHealth : public QObject
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

    void refusedConnectionSaysSo()
    {
        quint16 port = 0;
        {
            QTcpServer probe;
            QVERIFY(probe.listen(QHostAddress::LocalHost, 0));
            port = probe.serverPort(); // closed again: nobody listens there
        }
        const QString uri = QStringLiteral("refgo://127.0.0.1:%1").arg(port);
        MainWindow window(app::protocolRegistry());
        window.show();
        auto opened = window.openConnection(uri);
        QVERIFY(opened.ok());
        ConnectionHealth *health = ConnectionHealth::of(*opened);
        QVERIFY(health);
        QTRY_COMPARE_WITH_TIMEOUT(health->status(), ConnectionHealth::Status::Failed, kWaitMs);
        QCOMPARE(health->cause().kind(), Error::Kind::ConnectionRefused);
        QVERIFY2(statusBarText(window).contains(QStringLiteral("connection failed")),
                 qPrintable(statusBarText(window)));
        QVERIFY(banner(window)->isVisible());
        QVERIFY2(banner(window)->text().contains(health->cause().message()),
                 qPrintable(banner(window)->text()));
        QVERIFY(!motionButton(window, QStringLiteral("enable"))->isEnabled());
        QVERIFY(!window.recentConnections().contains(uri));
    }

    void silentPeerIsNeverConnected()
    {
        SilentPeer peer;
        QVERIFY(peer.isListening());
        MainWindow window(app::protocolRegistry());
        window.logConsole()->installMessageHandler();
        window.show();
        auto opened = window.openConnection(peer.uri());
        QVERIFY(opened.ok());
        ConnectionHealth *health = ConnectionHealth::of(*opened);
        QTRY_VERIFY((*opened)->isConnected()); // the link is up ...
        QCOMPARE(health->status(), ConnectionHealth::Status::WaitingForAnswer); // ... no answer
        QVERIFY2(!statusBarText(window).endsWith(QStringLiteral("— connected")),
                 qPrintable(statusBarText(window)));
        QVERIFY(banner(window)->isVisible());
        QVERIFY(!motionButton(window, QStringLiteral("enable"))->isEnabled());
        QVERIFY(!motionButton(window, QStringLiteral("jogPlus"))->isEnabled());

        QTRY_COMPARE_WITH_TIMEOUT(health->status(), ConnectionHealth::Status::NotResponding,
                                  kWaitMs);
        QVERIFY2(statusBarText(window).contains(QStringLiteral("not responding")),
                 qPrintable(statusBarText(window)));
        QVERIFY(banner(window)->text().contains(QStringLiteral("not responding")));
        QVERIFY(!motionButton(window, QStringLiteral("enable"))->isEnabled());
        QVERIFY(!motionButton(window, QStringLiteral("jogMinus"))->isEnabled());
        // No limits from a drive that never answered.
        QVERIFY(!window.jogPanel()->limitsKnown());
        // One log line for the silence, not one per timeout (three timeouts by now).
        QCoreApplication::processEvents();
        const QString log = window.logConsole()->toPlainText();
        QVERIFY2(log.count(QStringLiteral("] timeout: no answer to")) == 1, qPrintable(log));
        QVERIFY2(log.count(QStringLiteral("not responding")) == 1, qPrintable(log));
        QVERIFY(!window.recentConnections().contains(peer.uri()));
    }

    void lostThenReconnected()
    {
        app::DemoDrive demo;
        QVERIFY(demo.startRefgo(0).ok());
        MainWindow window(app::protocolRegistry());
        window.show();
        auto opened = window.openConnection(demo.refgoUri());
        QVERIFY(opened.ok());
        DeviceConnection *c = *opened;
        ConnectionHealth *health = ConnectionHealth::of(c);
        QTRY_COMPARE_WITH_TIMEOUT(health->status(), ConnectionHealth::Status::Responding, kWaitMs);
        QVERIFY2(statusBarText(window).endsWith(QStringLiteral("— connected")),
                 qPrintable(statusBarText(window)));
        QVERIFY(!banner(window)->isVisible());
        QTRY_VERIFY_WITH_TIMEOUT(motionButton(window, QStringLiteral("enable"))->isEnabled(),
                                 kWaitMs);
        QTRY_VERIFY_WITH_TIMEOUT(!window.statusPanel()->isStale(ObjectAddress(0x6041, 0)), kWaitMs);
        QVERIFY(window.recentConnections().contains(demo.refgoUri()));

        QVERIFY(demo.dropClients() > 0); // the cable is cut
        QTRY_COMPARE_WITH_TIMEOUT(health->status(), ConnectionHealth::Status::Lost, kWaitMs);
        QVERIFY2(statusBarText(window).contains(QStringLiteral("connection lost")),
                 qPrintable(statusBarText(window)));
        QVERIFY(banner(window)->isVisible());
        QVERIFY(banner(window)->text().contains(QStringLiteral("connection lost")));
        QVERIFY(banner(window)->text().contains(QStringLiteral("out of date")));
        QVERIFY(window.statusPanel()->isStale(ObjectAddress(0x6041, 0)));
        QVERIFY(!motionButton(window, QStringLiteral("enable"))->isEnabled());
        window.statusBar()->showMessage(QStringLiteral("an old message"));

        c->open(); // reconnect: the old messages go
        QTRY_COMPARE_WITH_TIMEOUT(health->status(), ConnectionHealth::Status::Responding, kWaitMs);
        QVERIFY(!health->cause().isError());
        QVERIFY(window.statusBar()->currentMessage().isEmpty());
        QVERIFY(!banner(window)->isVisible());
        QVERIFY2(statusBarText(window).endsWith(QStringLiteral("— connected")),
                 qPrintable(statusBarText(window)));
        QTRY_VERIFY_WITH_TIMEOUT(!window.statusPanel()->isStale(ObjectAddress(0x6041, 0)), kWaitMs);
        QTRY_VERIFY_WITH_TIMEOUT(motionButton(window, QStringLiteral("enable"))->isEnabled(),
                                 kWaitMs);
    }

    // With the setting on, a lost link is opened again, each attempt in the log and banner.
    void lostLinkIsReconnectedWhenSet()
    {
        app::DemoDrive demo;
        QVERIFY(demo.startRefgo(0).ok());
        MainWindow window(app::protocolRegistry());
        auto values = window.settingsValues();
        QVERIFY(!values.autoReconnect); // off by default
        values.autoReconnect = true;
        values.reconnectWindowS = 30;
        window.applySettings(values);
        window.show();
        auto opened = window.openConnection(demo.refgoUri());
        QVERIFY(opened.ok());
        ConnectionHealth *health = ConnectionHealth::of(*opened);
        QTRY_COMPARE_WITH_TIMEOUT(health->status(), ConnectionHealth::Status::Responding, kWaitMs);
        QVERIFY(demo.dropClients() > 0);
        QTRY_COMPARE_WITH_TIMEOUT(health->status(), ConnectionHealth::Status::Lost, kWaitMs);
        QVERIFY2(banner(window)->text().contains(QStringLiteral("Reconnecting automatically")),
                 qPrintable(banner(window)->text()));
        QTRY_COMPARE_WITH_TIMEOUT(health->status(), ConnectionHealth::Status::Responding, kWaitMs);
        const QString log = window.logConsole()->toPlainText();
        QVERIFY2(log.contains(QStringLiteral("reconnecting automatically, attempt 1")),
                 qPrintable(log));
        QVERIFY2(log.contains(QStringLiteral("up again after 1 attempt")), qPrintable(log));
        QVERIFY(!banner(window)->isVisible());
        QTRY_VERIFY_WITH_TIMEOUT(!window.statusPanel()->isStale(ObjectAddress(0x6041, 0)), kWaitMs);
    }

    void ownDisconnectIsNotAnError()
    {
        app::DemoDrive demo;
        QVERIFY(demo.startRefgo(0).ok());
        MainWindow window(app::protocolRegistry());
        window.show();
        auto opened = window.openConnection(demo.refgoUri());
        QVERIFY(opened.ok());
        ConnectionHealth *health = ConnectionHealth::of(*opened);
        QTRY_COMPARE_WITH_TIMEOUT(health->status(), ConnectionHealth::Status::Responding, kWaitMs);
        window.disconnectCurrent();
        QTRY_COMPARE_WITH_TIMEOUT(health->status(), ConnectionHealth::Status::ClosedByUser,
                                  kWaitMs);
        QVERIFY(!health->cause().isError());
        QVERIFY2(statusBarText(window).contains(QStringLiteral("disconnected by you")),
                 qPrintable(statusBarText(window)));
        QVERIFY(banner(window)->text().contains(QStringLiteral("disconnected by you")));
        QVERIFY(!banner(window)->text().contains(QStringLiteral("lost")));
        QVERIFY(!motionButton(window, QStringLiteral("enable"))->isEnabled());
    }

    void duplicateAndDemoConnections()
    {
        app::DemoDrive demo;
        QVERIFY(demo.startRefgo(0).ok());
        MainWindow window(app::protocolRegistry());
        window.show();
        auto first = window.openConnection(demo.refgoUri(), MainWindow::Remember::No);
        QVERIFY(first.ok());
        auto second = window.openConnection(demo.refgoUri());
        QVERIFY(!second.ok());
        QVERIFY(second.error().message().contains(QStringLiteral("already")));
        QCOMPARE(window.deviceList()->count(), 1);
        QCOMPARE(window.currentConnection(), *first);
        QTRY_COMPARE_WITH_TIMEOUT(ConnectionHealth::of(*first)->status(),
                                  ConnectionHealth::Status::Responding, kWaitMs);
        QVERIFY(!window.recentConnections().contains(demo.refgoUri())); // the demo's
    }

    // Esc quick-stops a move; the Motion dock says the axis is in ErrorStop and offers the reset.
    void errorStopAfterEscIsExplained()
    {
        app::DemoDrive demo;
        QVERIFY(demo.startRefgo(0).ok());
        MainWindow window(app::protocolRegistry());
        window.setConfirmation([](const QString &) { return true; });
        window.show();
        QVERIFY(window.openConnection(demo.refgoUri()).ok());
        widgets::JogPanel *panel = window.jogPanel();
        QTRY_VERIFY_WITH_TIMEOUT(panel->limitsKnown(), kWaitMs);
        auto *reset = motionButton(window, QStringLiteral("stopReset"));
        QVERIFY(reset);
        QVERIFY(!reset->isVisible());
        panel->enableDrive();
        QTRY_COMPARE_WITH_TIMEOUT(panel->motionAxis()->state(), motion::AxisState::Standstill,
                                  kWaitMs);
        panel->startJog(+1);
        QTRY_VERIFY_WITH_TIMEOUT(demo.drive().axis().isMoving(), kWaitMs);
        QTest::keyClick(window.logConsole(), Qt::Key_Escape);
        QCOMPARE(panel->motionAxis()->state(), motion::AxisState::ErrorStop);
        auto *message = panel->findChild<QLabel *>(QStringLiteral("message"));
        QVERIFY2(message->text().contains(QStringLiteral("ErrorStop"))
                     && message->text().contains(QStringLiteral("Reset")),
                 qPrintable(message->text()));
        QVERIFY(reset->isVisible());
        // The Drive Status page says the same, with the reason.
        QVERIFY2(window.statusPanel()->motionNote().contains(QStringLiteral("ErrorStop"))
                     && window.statusPanel()->motionNote().contains(panel->lastStopReason()),
                 qPrintable(window.statusPanel()->motionNote()));
        QTRY_VERIFY_WITH_TIMEOUT(!demo.drive().axis().isMoving(), kWaitMs);
        QTest::mouseClick(reset, Qt::LeftButton); // one click out of ErrorStop
        QTRY_VERIFY_WITH_TIMEOUT(panel->motionAxis()->state() != motion::AxisState::ErrorStop,
                                 kWaitMs);
        QVERIFY(!reset->isVisible());
        QVERIFY(window.statusPanel()->motionNote().isEmpty());
    }

    void closingWithAnEnabledDriveAsks()
    {
        app::DemoDrive demo;
        QVERIFY(demo.startRefgo(0).ok());
        MainWindow window(app::protocolRegistry());
        window.show();
        auto opened = window.openConnection(demo.refgoUri());
        QVERIFY(opened.ok());
        QTRY_VERIFY_WITH_TIMEOUT(motionButton(window, QStringLiteral("enable"))->isEnabled(),
                                 kWaitMs);
        QStringList questions;
        bool answer = false;
        window.setConfirmation([&](const QString &q) {
            questions << q;
            return answer;
        });
        window.disconnectCurrent(); // not enabled: no question
        QTRY_COMPARE((*opened)->state(), DeviceConnection::State::Disconnected);
        QVERIFY(questions.isEmpty());

        (*opened)->open();
        QTRY_VERIFY_WITH_TIMEOUT(motionButton(window, QStringLiteral("enable"))->isEnabled(),
                                 kWaitMs);
        window.jogPanel()->enableDrive();
        QTRY_COMPARE_WITH_TIMEOUT(demo.drive().state(), cia402::State::OperationEnabled, kWaitMs);
        QTRY_VERIFY_WITH_TIMEOUT(window.jogPanel()->axis()->status().powered, kWaitMs);
        window.disconnectCurrent();
        QCOMPARE(questions.size(), 1);
        QVERIFY(questions.first().contains(QStringLiteral("enabled")));
        QVERIFY((*opened)->isConnected()); // "No" keeps it
        QVERIFY(!window.close()); // Quit asks too
        QCOMPARE(questions.size(), 2);
        answer = true;
        window.disconnectCurrent();
        QTRY_COMPARE((*opened)->state(), DeviceConnection::State::Disconnected);
    }
};

QTEST_MAIN(TestMainWindowHealth)
#include "tst_mainwindow_health.moc"
