// drivebench: the GUI's composition root. It picks the real protocols (app/common) and, with
// --demo, runs the simulated MovingCap, an ACTIVE Cube and a line of NM17x displays in-process.
#include "common/demodrive.h"
#include "common/descriptions.h"
#include "common/protocols.h"
#include "devices/bonfiglioli/simulatedacu.h"
#include "devices/nm17x/device/nm17xsim.h"
#include "jogtesthook.h"
#include "mainwindow.h"
#include "translations/language.h"
#include "widgets/common/logconsole.h"
#include "widgets/odeditor/odeditor.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QIcon>
#include <QSettings>

#include <cstdio>
#include <memory>

int main(int argc, char *argv[])
{
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("drivebench"));
    QApplication::setApplicationName(QStringLiteral("drivebench"));
    QApplication::setApplicationDisplayName(QStringLiteral("drivebench"));
    QApplication::setApplicationVersion(QStringLiteral(DRIVEBENCH_VERSION));
    // The installed desktop entry and icon (packaging/) carry this id; in the build tree the
    // icon theme has no such icon and the window keeps the platform's default.
    QGuiApplication::setDesktopFileName(QStringLiteral("org.drivebench.drivebench"));
    QApplication::setWindowIcon(QIcon::fromTheme(QStringLiteral("org.drivebench.drivebench")));
    // The language: --lang, else DRIVEBENCH_LANG, else the setting "language" (empty: follow
    // the system; a Settings dialog writes it), else the locale variables.
    QString language = db::i18n::languageArgument(QApplication::arguments());
    if (language.isEmpty() && qEnvironmentVariableIsEmpty("DRIVEBENCH_LANG"))
        language =
            QSettings(QSettings::IniFormat, QSettings::UserScope, QStringLiteral("drivebench"),
                      QStringLiteral("drivebench"))
                .value(QStringLiteral("language"))
                .toString(); // the file MainWindow writes (File → Settings)
    db::i18n::installTranslations(app, db::i18n::chooseLanguage(language));

    QCommandLineParser parser;
    parser.setApplicationDescription(
        QApplication::translate("main", "Commissioning tool for industrial drives."));
    parser.addHelpOption();
    parser.addVersionOption();
    const QCommandLineOption demoOption(
        QStringLiteral("demo"),
        QApplication::translate("main",
                                "Start a simulated MovingCap in-process and connect "
                                "to it over RefGo and over CANopen (SLCAN, node 50)."));
    const QCommandLineOption connectOption(
        QStringLiteral("connect"),
        QApplication::translate("main", "Connect to <uri> at start, e.g. refgo://192.168.2.150."),
        QStringLiteral("uri"));
    const QCommandLineOption langOption(
        QStringLiteral("lang"),
        QApplication::translate("main",
                                "Language of the window: de or en (default: DRIVEBENCH_LANG, "
                                "the setting, LC_ALL, LC_MESSAGES, LANG)."),
        QStringLiteral("language"));
    parser.addOption(demoOption);
    parser.addOption(connectOption);
    parser.addOption(langOption);
    parser.process(app);

    const db::ProtocolRegistry &registry = db::app::protocolRegistry();
    std::unique_ptr<db::app::DemoDrive> demo; // outlives the window and its connections
    std::unique_ptr<db::nm17x::Nm17xSim> displays; // the demo's line of NM17x displays
    std::unique_ptr<db::bonfiglioli::SimulatedAcu> acu; // the demo's ACTIVE Cube inverter
    db::gui::MainWindow window(registry);
    window.logConsole()->installMessageHandler();
    // A description the user picks for a device goes into the library, so that the next device
    // with that identity gets it without asking.
    QObject::connect(
        window.odEditor(), &db::widgets::OdEditor::descriptionFileUsed, &window,
        [&window](const QString &path) {
            db::DescriptionLibrary &library = db::app::descriptionLibrary();
            library.setFolder(db::app::descriptionFolder());
            if (auto added = library.addFile(path); added)
                window.logConsole()->info(
                    QApplication::translate("main", "%1 added to the description library")
                        .arg(*added));
            else
                window.logConsole()->warning(
                    QApplication::translate("main",
                                            "%1 not added to the description "
                                            "library: %2")
                        .arg(path, added.error().message()));
        });

    window.setDescriptionLibrary(&db::app::descriptionLibrary(), db::app::descriptionFolder);

    using Remember = db::gui::MainWindow::Remember; // the demo is never a recent connection
    // The demo: from --demo or the welcome page's button. A second start reconnects to the
    // drive that already runs.
    const auto startDemo = [&]() -> bool {
        const auto acuUri = [&acu] {
            return QStringLiteral("vabus://127.0.0.1:%1").arg(acu->port());
        };
        if (demo) {
            if (acu)
                window.openConnection(acuUri(), Remember::No);
            window.openConnection(demo->refgoUri(), Remember::No);
            if (demo->slcanPort() != 0)
                window.openConnection(demo->slcanUri(), Remember::No);
            return true;
        }
        // An ACTIVE Cube inverter over VABus/TCP, opened first so that the MovingCap stays the
        // device shown at start.
        acu = std::make_unique<db::bonfiglioli::SimulatedAcu>();
        if (auto started = acu->listen(0); started) {
            window.logConsole()->info(
                QApplication::translate("main", "Demo ACTIVE Cube at %1").arg(acuUri()));
            window.openConnection(acuUri(), Remember::No);
        } else {
            acu.reset();
        }
        demo = std::make_unique<db::app::DemoDrive>();
        if (auto started = demo->startRefgo(0); !started) {
            const QString text = QApplication::translate("main", "Cannot start the demo drive: %1")
                                     .arg(started.error().toString());
            std::fprintf(stderr, "drivebench: %s\n", qPrintable(text));
            window.logConsole()->error(text);
            demo.reset();
            return false;
        }
        window.logConsole()->info(
            QApplication::translate("main", "Demo drive listening at %1").arg(demo->refgoUri()));
        window.openConnection(demo->refgoUri(), Remember::No);
        // The same drive as CANopen node 50 on its SLCAN door: the CAN monitor shows its traffic.
        if (auto slcan = demo->startSlcan(0); !slcan) {
            window.logConsole()->warning(
                QApplication::translate("main", "Demo drive without CANopen: %1")
                    .arg(slcan.error().toString()));
        } else {
            window.logConsole()->info(
                QApplication::translate("main", "Demo drive CANopen at %1").arg(demo->slcanUri()));
            window.openConnection(demo->slcanUri(), Remember::No);
            window.showCanMonitor();
        }
        // A line of three NM17x displays on a bus of their own, for the NM17x Line dock.
        displays = std::make_unique<db::nm17x::Nm17xSim>();
        displays->create(
            db::nm17x::Nm17xSim::parseDevices(QStringLiteral("nm172@2,nm172@3,nm174@4"))
                .valueOr({}));
        if (auto started = displays->startSlcan(0); started)
            window.logConsole()->info(
                QApplication::translate("main",
                                        "Demo NM17x displays (nodes 2, 3, 4) at "
                                        "canopen+slcan://127.0.0.1:%1?node=2")
                    .arg(displays->slcanPort()));
        return true;
    };
    window.setDemoStarter([&startDemo] { startDemo(); });
    if (parser.isSet(demoOption) && !startDemo())
        return 1;
    if (parser.isSet(connectOption)) {
        if (auto opened = window.openConnection(parser.value(connectOption)); !opened) {
            std::fprintf(stderr, "drivebench: %s\n", qPrintable(opened.error().toString()));
            return 2;
        }
    }

    window.show();
    db::gui::holdJogFromEnvironment(window); // only with DRIVEBENCH_TEST_HOLD_JOG set
    return app.exec();
}
