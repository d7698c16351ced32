// The main window on a 1366x768 laptop screen, in English and German, with the demo drive
// connected over RefGo and CANopen: its minimum size fits, and the controls that stop or move the
// drive are inside the window, not cut off at its right edge. Also the toolbar, View → Reset
// Layout and the welcome page shown while no device is listed.
#include "common/demodrive.h"
#include "common/protocols.h"
#include "devices/movingcap/movingcapdrive.h"
#include "devices/nm17x/device/nm17xsim.h"
#include "mainwindow.h"
#include "settingsdialog.h"
#include "translations/language.h"
#include "widgets/common/plot.h"
#include "widgets/connection/devicelist.h"
#include "widgets/connection/drivestatuspanel.h"
#include "widgets/motion/jogpanel.h"
#include "widgets/nm17x/nm17xlinemodel.h"
#include "widgets/nm17x/nm17xlinepanel.h"
#include "widgets/scope/scopecursors.h"
#include "widgets/scope/scopemeasurements.h"
#include "widgets/scope/scopepage.h"
#include "widgets/scope/scopeplot.h"

#include <QAbstractScrollArea>
#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QPushButton>
#include <QRegularExpression>
#include <QScrollArea>
#include <QSettings>
#include <QStackedWidget>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QToolBar>

using namespace db;
using db::gui::MainWindow;

namespace {
constexpr int kLaptopWidth = 1366;
constexpr int kLaptopHeight = 768;
// A desktop's title bar and panel take some of the 768 rows.
constexpr int kUsableHeight = 740;

QString layoutReport(const MainWindow &window)
{
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
    return parts;
}
} // namespace

class TestMainWindowLaptop : public QObject
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

    void cleanup() { i18n::installTranslations(*qApp, QStringLiteral("en")); }

    void fitsWithTheDemoConnected_data()
    {
        QTest::addColumn<QString>("language");
        QTest::newRow("en") << QStringLiteral("en");
        QTest::newRow("de") << QStringLiteral("de");
    }

    void fitsWithTheDemoConnected()
    {
        QFETCH(QString, language);
        QVERIFY(i18n::installTranslations(*qApp, language));
        app::DemoDrive demo;
        QVERIFY(demo.startRefgo(0).ok());
        QVERIFY(demo.startSlcan(0).ok());

        MainWindow window(app::protocolRegistry());
        window.resize(kLaptopWidth, kUsableHeight);
        window.show();
        QVERIFY(window.openConnection(demo.refgoUri()).ok());
        auto canopen = window.openConnection(demo.slcanUri());
        QVERIFY(canopen.ok());
        // The values and limits of the drive are shown (they change the widths of labels).
        QTRY_VERIFY_WITH_TIMEOUT(!window.statusPanel()->isStale(ObjectAddress(0x6041, 0)), 10000);
        QTRY_VERIFY_WITH_TIMEOUT(window.jogPanel()->limitsKnown(), 10000);

        const QSize min = window.minimumSizeHint().expandedTo(window.minimumSize());
        QVERIFY2(min.width() <= kLaptopWidth && min.height() <= kUsableHeight,
                 qPrintable(QStringLiteral("%1: window needs %2x%3:%4")
                                .arg(language)
                                .arg(min.width())
                                .arg(min.height())
                                .arg(layoutReport(window))));
        QVERIFY(window.width() <= kLaptopWidth && window.height() <= kLaptopHeight);

        // Every button of the Motion dock lies inside the window and inside the viewport of its
        // scroll area horizontally (vertical scrolling is fine, cut-off columns are not).
        auto *dock = window.findChild<QDockWidget *>(QStringLiteral("motionDock"));
        QVERIFY(dock && dock->isVisible());
        auto *scroll = qobject_cast<QAbstractScrollArea *>(dock->widget());
        QVERIFY(scroll);
        const QStringList required = { QStringLiteral("enable"),    QStringLiteral("disable"),
                                       QStringLiteral("reset"),     QStringLiteral("jogPlus"),
                                       QStringLiteral("jogMinus"),  QStringLiteral("stepPlus"),
                                       QStringLiteral("stepMinus"), QStringLiteral("halt"),
                                       QStringLiteral("stop"),      QStringLiteral("execute") };
        for (const QString &name : required) {
            auto *button = window.jogPanel()->findChild<QPushButton *>(name);
            QVERIFY2(button, qPrintable(name));
            QVERIFY2(button->isVisible(), qPrintable(name));
            const QRect inViewport(button->mapTo(scroll->viewport(), QPoint(0, 0)), button->size());
            const QRect inWindow(button->mapTo(&window, QPoint(0, 0)), button->size());
            QVERIFY2(inViewport.left() >= 0 && inViewport.right() < scroll->viewport()->width()
                         && inWindow.right() < window.width(),
                     qPrintable(QStringLiteral("%1: '%2' at x %3..%4, viewport %5 wide")
                                    .arg(language, button->text())
                                    .arg(inViewport.left())
                                    .arg(inViewport.right())
                                    .arg(scroll->viewport()->width())));
        }

        // The Drive Status page needs no sideways scrolling: every lamp (I/O included) lies
        // inside its viewport. With DRIVEBENCH_SCREENSHOT_DIR=DIR the window is saved as
        // DIR/screenshot-status-LANGUAGE.png.
        window.pages()->setCurrentIndex(0);
        auto *statusScroll = qobject_cast<QScrollArea *>(window.pages()->widget(0));
        QVERIFY(statusScroll);
        QTRY_VERIFY(window.statusPanel()->findChild<QWidget *>(QStringLiteral("IN10")));
        QTRY_VERIFY(
            window.statusPanel()->findChild<QWidget *>(QStringLiteral("IN10"))->isVisible());
        const int viewportWidth = statusScroll->viewport()->width();
        QVERIFY2(statusScroll->widget()->width() <= viewportWidth,
                 qPrintable(QStringLiteral("%1: the Drive Status page is %2 wide in %3")
                                .arg(language)
                                .arg(statusScroll->widget()->width())
                                .arg(viewportWidth)));
        int lamps = 0;
        for (QWidget *lamp : window.statusPanel()->findChildren<QWidget *>()) {
            const QString name = lamp->objectName();
            if (!lamp->isVisible()
                || !(name.startsWith(QLatin1String("IN")) || name.startsWith(QLatin1String("OUT"))
                     || name.startsWith(QLatin1String("bit_"))))
                continue;
            ++lamps;
            const QRect inViewport(lamp->mapTo(statusScroll->viewport(), QPoint(0, 0)),
                                   lamp->size());
            QVERIFY2(inViewport.left() >= 0 && inViewport.right() < viewportWidth,
                     qPrintable(QStringLiteral("%1: '%2' at x %3..%4, viewport %5 wide")
                                    .arg(language, name)
                                    .arg(inViewport.left())
                                    .arg(inViewport.right())
                                    .arg(viewportWidth)));
        }
        QVERIFY(lamps >= 10);
        const QString dir = qEnvironmentVariable("DRIVEBENCH_SCREENSHOT_DIR");
        if (!dir.isEmpty())
            QVERIFY(window.grab().save(
                QStringLiteral("%1/screenshot-status-%2.png").arg(dir, language)));
    }

    void nm17xDockFitsWithALine_data() { fitsWithTheDemoConnected_data(); }

    // The NM17x Line dock with three displays found: every control of the panel lies inside
    // the dock's viewport horizontally. With DRIVEBENCH_SCREENSHOT_DIR=DIR (under xvfb-run) it
    // saves the window as DIR/screenshot-nm17x-dock-LANGUAGE.png.
    void nm17xDockFitsWithALine()
    {
        QFETCH(QString, language);
        QVERIFY(i18n::installTranslations(*qApp, language));
        nm17x::Nm17xSim displays;
        displays.create(
            nm17x::Nm17xSim::parseDevices(QStringLiteral("nm172@2,nm172@3,nm174@4")).value());
        QVERIFY(displays.startSlcan(0).ok());
        MainWindow window(app::protocolRegistry());
        window.resize(kLaptopWidth, kUsableHeight);
        window.show();
        const auto opened = window.openConnection(
            QStringLiteral("canopen+slcan://127.0.0.1:%1?node=2").arg(displays.slcanPort()));
        QVERIFY(opened.ok());
        QTRY_VERIFY(opened.value()->isConnected());
        auto *dock = window.findChild<QDockWidget *>(QStringLiteral("nm17xDock"));
        QVERIFY(dock);
        dock->show();
        dock->raise();
        auto *panel = dock->findChild<widgets::Nm17xLinePanel *>();
        QVERIFY(panel);
        auto *find = panel->findChild<QPushButton *>(QStringLiteral("find"));
        QVERIFY(find->isEnabled()); // the line's network is attached
        QTest::mouseClick(find, Qt::LeftButton);
        QTRY_VERIFY2_WITH_TIMEOUT(panel->model()->rowCount() == 3, qPrintable(panel->message()),
                                  10000);
        panel->selectNode(3);
        QTest::qWait(300); // the settings of node 3 arrive
        const QString dir = qEnvironmentVariable("DRIVEBENCH_SCREENSHOT_DIR");
        if (!dir.isEmpty())
            QVERIFY(window.grab().save(
                QStringLiteral("%1/screenshot-nm17x-dock-%2.png").arg(dir, language)));

        const QSize min = window.minimumSizeHint().expandedTo(window.minimumSize());
        QVERIFY2(min.width() <= kLaptopWidth && min.height() <= kUsableHeight,
                 qPrintable(QStringLiteral("%1: window needs %2x%3:%4")
                                .arg(language)
                                .arg(min.width())
                                .arg(min.height())
                                .arg(layoutReport(window))));
        auto *scroll = qobject_cast<QAbstractScrollArea *>(dock->widget());
        QVERIFY(scroll);
        QList<QWidget *> controls;
        for (QPushButton *b : panel->findChildren<QPushButton *>())
            controls.append(b);
        for (QComboBox *b : panel->findChildren<QComboBox *>())
            controls.append(b);
        for (QWidget *w : std::as_const(controls)) {
            if (!w->isVisibleTo(panel))
                continue;
            const QRect inViewport(w->mapTo(scroll->viewport(), QPoint(0, 0)), w->size());
            QVERIFY2(inViewport.left() >= 0 && inViewport.right() < scroll->viewport()->width(),
                     qPrintable(QStringLiteral("%1: '%2' at x %3..%4, viewport %5 wide")
                                    .arg(language, w->objectName())
                                    .arg(inViewport.left())
                                    .arg(inViewport.right())
                                    .arg(scroll->viewport()->width())));
        }
        window.close();
    }

    void welcomePageUntilADeviceIsListed()
    {
        app::DemoDrive demo;
        QVERIFY(demo.startRefgo(0).ok());
        MainWindow window(app::protocolRegistry());
        window.show();
        auto *central = qobject_cast<QStackedWidget *>(window.centralWidget());
        QVERIFY(central);
        QCOMPARE(central->currentWidget(), window.welcomePage());
        auto *demoButton =
            window.welcomePage()->findChild<QPushButton *>(QStringLiteral("welcomeDemo"));
        QVERIFY(demoButton);
        QVERIFY(!demoButton->isVisible()); // no demo without a starter
        int started = 0;
        window.setDemoStarter([&] {
            ++started;
            window.openConnection(demo.refgoUri());
        });
        QVERIFY(demoButton->isVisible());
        QTest::mouseClick(demoButton, Qt::LeftButton);
        QCOMPARE(started, 1);
        QCOMPARE(central->currentWidget(), window.pages());
        QTRY_VERIFY(window.currentConnection()->isConnected());

        // Removing the last device brings the welcome page back.
        QMetaObject::invokeMethod(window.deviceList(), "removeRequested",
                                  Q_ARG(db::DeviceConnection *, window.currentConnection()));
        QCOMPARE(central->currentWidget(), window.welcomePage());
    }

    void toolbarCommands()
    {
        app::DemoDrive demo;
        QVERIFY(demo.startRefgo(0).ok());
        MainWindow window(app::protocolRegistry());
        window.show();
        QToolBar *bar = window.mainToolBar();
        QVERIFY(bar && bar->isVisible());
        QStringList names;
        for (QAction *a : bar->actions())
            names << a->objectName();
        for (const char *name : { "connectAction", "enableAction", "stopAction", "scopeAction" })
            QVERIFY2(names.contains(QLatin1String(name)), name);
        auto *enable = bar->findChild<QAction *>(QStringLiteral("enableAction"));
        if (!enable)
            enable = window.findChild<QAction *>(QStringLiteral("enableAction"));
        QVERIFY(enable);
        QVERIFY(!enable->isEnabled()); // no drive

        QVERIFY(window.openConnection(demo.refgoUri()).ok());
        QTRY_VERIFY_WITH_TIMEOUT(enable->isEnabled(), 10000);
        enable->trigger();
        QTRY_COMPARE_WITH_TIMEOUT(demo.drive().state(), cia402::State::OperationEnabled, 10000);

        // The scope's Start/Stop shows the Scope page; without channels it says what is missing.
        auto *scope = window.findChild<QAction *>(QStringLiteral("scopeAction"));
        QVERIFY(scope);
        scope->trigger();
        QCOMPARE(window.pages()->currentWidget(), static_cast<QWidget *>(window.scopePage()));
    }

    void aboutNamesVersionCommitAndLicence()
    {
        MainWindow window(app::protocolRegistry());
        const QString text = window.aboutText();
        QVERIFY(text.contains(QStringLiteral(DRIVEBENCH_VERSION)));
        QVERIFY(text.contains(QStringLiteral("all rights are reserved")));
        // A commit hash (or "unknown" outside a git checkout), never an empty one.
        static const QRegularExpression commit(QStringLiteral("commit ([0-9a-f]{7,}|unknown) "));
        QVERIFY2(commit.match(text).hasMatch(), qPrintable(text));
    }

    void settingsAreAppliedAndKept()
    {
        app::DemoDrive demo;
        QVERIFY(demo.startRefgo(0).ok());
        {
            gui::SettingsDialog dialog(
                { QStringLiteral("de"),
                  1500,
                  700,
                  { QStringLiteral("refgo://10.0.0.1"), QStringLiteral("refgo://10.0.0.2") } });
            const auto shown = dialog.values();
            QCOMPARE(shown.language, QStringLiteral("de"));
            QCOMPARE(shown.requestTimeoutMs, 700);
            auto *clear = dialog.findChild<QPushButton *>(QStringLiteral("clearRecent"));
            QVERIFY(clear);
            clear->click();
            QVERIFY(dialog.values().recent.isEmpty());
        }
        {
            MainWindow window(app::protocolRegistry());
            window.applySettings(
                { QStringLiteral("de"), 1500, 700, { QStringLiteral("refgo://10.0.0.1") } });
            QCOMPARE(window.recentConnections(),
                     QStringList { QStringLiteral("refgo://10.0.0.1") });
            auto opened = window.openConnection(demo.refgoUri(), MainWindow::Remember::No);
            QVERIFY(opened.ok());
            QCOMPARE((*opened)->requestTimeoutMs(), 700); // new connections get the limits
            QCOMPARE((*opened)->connectTimeoutMs(), 1500);
        }
        MainWindow again(app::protocolRegistry()); // kept in the settings file
        const auto kept = again.settingsValues();
        QCOMPARE(kept.language, QStringLiteral("de"));
        QCOMPARE(kept.connectTimeoutMs, 1500);
        QCOMPARE(kept.requestTimeoutMs, 700);
        again.applySettings({ QString(), 3000, 1000, {} }); // as before, for the other tests
    }

    // For the README: DRIVEBENCH_SCREENSHOT_DIR=docs writes screenshot-scope.png, the Scope page
    // at 1366x740 with a move of the demo drive recorded by a trigger on its velocity.
    void scopeScreenshot()
    {
        const QString dir = qEnvironmentVariable("DRIVEBENCH_SCREENSHOT_DIR");
        if (dir.isEmpty())
            QSKIP("DRIVEBENCH_SCREENSHOT_DIR not set");
        app::DemoDrive demo;
        QVERIFY(demo.startRefgo(0).ok());
        MainWindow window(app::protocolRegistry());
        window.resize(kLaptopWidth, kUsableHeight);
        window.show();
        const Result<DeviceConnection *> connection = window.openConnection(demo.refgoUri());
        QVERIFY(connection.ok());
        // As an engineer would lay it out for the scope on a laptop: the other docks closed.
        for (QDockWidget *dock : window.findChildren<QDockWidget *>()) {
            if (dock->objectName() != QLatin1String("devicesDock"))
                dock->close();
        }
        window.pages()->setCurrentWidget(window.scopePage());
        widgets::ScopePage *page = window.scopePage();
        QVERIFY(page->addChannels(
            { ObjectAddress(0x606C, 0), ObjectAddress(0x6064, 0), ObjectAddress(0x6078, 0) }, 0));
        page->setMode(int(scope::Recorder::Mode::Single));
        scope::Trigger trigger = page->triggerSettings();
        QCOMPARE(trigger.channel, 0); // preselected
        trigger.kind = scope::Trigger::Kind::RisingEdge;
        trigger.level = 50;
        trigger.preTriggerS = 0.25;
        trigger.postTriggerS = 2.0;
        page->setTriggerSettings(trigger);
        QTRY_VERIFY((*connection)->isConnected());
        page->start();
        QVERIFY2(page->recorder()->state() == scope::Recorder::State::Armed,
                 qPrintable(page->statusText()));
        QTRY_VERIFY(page->recorder()->now() > 0.4); // some pre-trigger at standstill
        std::unique_ptr<Reply> go((*connection)->rawCommand(QStringLiteral("G1000")));
        QTRY_COMPARE_WITH_TIMEOUT(page->recorder()->state(), scope::Recorder::State::Stopped,
                                  10000);
        page->plot()->autoscale();
        page->setCursorsEnabled(true);
        const double t0 = page->recorder()->triggerTime();
        page->plot()->cursors()->setPositions(t0, t0 + 1.5);
        QTRY_COMPARE(page->measurements()->table()->rowCount(), 3);
        page->plot()->refreshNow();
        page->plot()->customPlot()->replot();
        QVERIFY(window.grab().save(QDir(dir).filePath(QStringLiteral("screenshot-scope.png"))));
    }

    void resetLayoutBringsEveryDockBack()
    {
        MainWindow window(app::protocolRegistry());
        window.show();
        auto *motion = window.findChild<QDockWidget *>(QStringLiteral("motionDock"));
        auto *log = window.findChild<QDockWidget *>(QStringLiteral("logDock"));
        QVERIFY(motion && log);
        motion->close();
        log->setFloating(true);
        window.mainToolBar()->hide();
        QVERIFY(!motion->isVisible());
        window.resetLayout();
        QVERIFY(motion->isVisible());
        QVERIFY(!log->isFloating());
        QVERIFY(window.mainToolBar()->isVisible());
        QCOMPARE(window.dockWidgetArea(motion), Qt::RightDockWidgetArea);
    }
};

QTEST_MAIN(TestMainWindowLaptop)
#include "tst_mainwindow_laptop.moc"
