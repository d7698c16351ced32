// drivebench: the GUI's composition root. It picks the real protocols (app/common) and, with
// --demo, runs the simulated MovingCap, an ACTIVE Cube and a line of NM17x displays in-process.
#include "common/descriptions.h"
#include "common/protocols.h"
#include "demosimulators.h"
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
    db::gui::DemoSimulators demo; // outlives the window and its connections
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
        const bool first = !demo.isRunning();
        const auto started = demo.start();
        if (!started) {
            const QString text = QApplication::translate("main", "Cannot start the demo drive: %1")
                                     .arg(started.error().toString());
            std::fprintf(stderr, "drivebench: %s\n", qPrintable(text));
            window.logConsole()->error(text);
            return false;
        }
        const db::gui::DemoSimulators::Started &uris = started.value();
        // The ACTIVE Cube inverter is opened first so that the MovingCap stays the device shown
        // at start. A second start reconnects to the devices that already run.
        if (!uris.acuUri.isEmpty()) {
            if (first)
                window.logConsole()->info(
                    QApplication::translate("main", "Demo ACTIVE Cube at %1").arg(uris.acuUri));
            window.openConnection(uris.acuUri, Remember::No);
        }
        if (first)
            window.logConsole()->info(
                QApplication::translate("main", "Demo drive listening at %1").arg(uris.refgoUri));
        window.openConnection(uris.refgoUri, Remember::No);
        // The same drive as CANopen node 50 on its SLCAN door: the CAN monitor shows its traffic.
        if (!uris.slcanUri.isEmpty()) {
            if (first)
                window.logConsole()->info(
                    QApplication::translate("main", "Demo drive CANopen at %1").arg(uris.slcanUri));
            window.openConnection(uris.slcanUri, Remember::No);
            if (first)
                window.showCanMonitor();
        }
        // A line of three NM17x displays on a bus of their own, for the NM17x Line dock.
        if (first && uris.nm17xPort != 0)
            window.logConsole()->info(
                QApplication::translate("main",
                                        "Demo NM17x displays (nodes 2, 3, 4) at "
                                        "canopen+slcan://127.0.0.1:%1?node=2")
                    .arg(uris.nm17xPort));
        if (first)
            for (const QString &warning : uris.warnings)
                window.logConsole()->warning(warning);
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
