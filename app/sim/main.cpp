// drivebench-sim: simulated devices on loopback for demos, tests and scripts (README "Simulator").
//   drivebench-sim movingcap [--refgo-port PORT] [--slcan-port PORT] [--set INDEX:SUB=VALUE ...]
//                            [--reject-write INDEX:SUB ...] [--fault CODE] [--control]
//   drivebench-sim canopen [--slcan-port PORT] [--virtualcan IFACE] --nodes 1,2,5 [--eds FILE]
//   drivebench-sim nm17x [--slcan-port PORT] [--virtualcan IFACE] [--control-port PORT]
//                        --devices nm172@127,nm172@127,nm174@5
//   drivebench-sim acu --vabus-port PORT [--watchdog-ms MS] [--fail MODE] [--slave ID ...]
//                      [--control]
#include "../common/demodrive.h"
#include "../common/simconsole.h"
#include "../common/simnodes.h"
#include "acuconsole.h"
#include "core/objectaddress.h"
#include "devices/movingcap/movingcapdrive.h"
#include "resources/builtindescriptions.h"
#include "sim_nm17x.h"
#include "simacu.h"
#include "translations/language.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QSet>
#include <QSocketNotifier>
#include <QTextStream>

#include <csignal>
#include <optional>
#include <sys/socket.h>
#include <unistd.h>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::sim)
};
} // namespace

using namespace db;

namespace {

int signalPipe[2] = { -1, -1 };
QCoreApplication *theApp = nullptr;

void onSignal(int)
{
    const char byte = 1;
    [[maybe_unused]] const auto n = ::write(signalPipe[1], &byte, 1);
}

// SIGINT/SIGTERM end the event loop cleanly (self-pipe: nothing unsafe in the handler).
void quitOnSignals(QCoreApplication &app)
{
    if (::socketpair(AF_UNIX, SOCK_STREAM, 0, signalPipe) != 0)
        return;
    auto *notifier = new QSocketNotifier(signalPipe[0], QSocketNotifier::Read, &app);
    QObject::connect(notifier, &QSocketNotifier::activated, &app, &QCoreApplication::quit);
    std::signal(SIGINT, onSignal);
    std::signal(SIGTERM, onSignal);
}

// --control: one console command per line on standard input, answers on standard output.
template<typename Console>
void readControlLines(QCoreApplication &app, Console *console, QTextStream &out)
{
    auto *notifier = new QSocketNotifier(STDIN_FILENO, QSocketNotifier::Read, &app);
    QObject::connect(console, &Console::answered, &app,
                     [&out](const QString &line) { out << line << Qt::endl; });
    QObject::connect(notifier, &QSocketNotifier::activated, console,
                     [notifier, console, pending = QByteArray()]() mutable {
                         char buffer[512];
                         const auto n = ::read(STDIN_FILENO, buffer, sizeof buffer);
                         if (n <= 0) {
                             notifier->setEnabled(
                                 false); // end of input: the simulator keeps serving
                             return;
                         }
                         pending.append(buffer, n);
                         qsizetype nl;
                         while ((nl = pending.indexOf('\n')) >= 0) {
                             const QString line = QString::fromUtf8(pending.left(nl));
                             pending.remove(0, nl + 1);
                             console->execute(line);
                         }
                     });
}

void quitOnSignalsOfApp()
{
    quitOnSignals(*theApp);
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    theApp = &app;
    QCoreApplication::setApplicationName(QStringLiteral("drivebench-sim"));
    QCoreApplication::setApplicationVersion(QStringLiteral(DRIVEBENCH_VERSION));
    i18n::installTranslations(app, i18n::chooseLanguage()); // DRIVEBENCH_LANG, LC_*, LANG
    QTextStream out(stdout);
    QTextStream err(stderr);

    QCommandLineParser parser;
    parser.setApplicationDescription(QCoreApplication::translate(
        "sim",
        "Simulated drives on 127.0.0.1.\n\nDevices:\n  movingcap   a MovingCap ETH drive "
        "(RefGo and SLCAN doors)\n  canopen     CANopen nodes driven by a device description "
        "(SLCAN "
        "and/or virtualcan doors)\n  nm17x       a line of Baumer NM170/NM172/NM174 displays "
        "(SLCAN and/or virtualcan doors, control socket)\n  acu         a Bonfiglioli ACTIVE Cube "
        "with CM-VABus/TCP (PLC "
        "port)"));
    parser.addHelpOption();
    parser.addVersionOption();
    const QCommandLineOption refgoPort(
        QStringLiteral("refgo-port"),
        QCoreApplication::translate("sim", "Serve RefGo on this TCP port (0 = chosen by the OS)."),
        QStringLiteral("port"));
    const QCommandLineOption set(
        QStringLiteral("set"),
        QCoreApplication::translate("sim",
                                    "Preset an object before serving, e.g. 3511:8=110 "
                                    "(repeatable)."),
        QStringLiteral("INDEX:SUB=VALUE"));
    const QCommandLineOption slcanPort(
        QStringLiteral("slcan-port"),
        QCoreApplication::translate("sim",
                                    "Serve CANopen (movingcap: node 50) as SLCAN over TCP on "
                                    "this port (0 = chosen by the OS)."),
        QStringLiteral("port"));
    const QCommandLineOption virtualCan(
        QStringLiteral("virtualcan"),
        QCoreApplication::translate("sim", "canopen: also serve on this Qt virtualcan interface."),
        QStringLiteral("iface"));
    const QCommandLineOption nodes(
        QStringLiteral("nodes"),
        QCoreApplication::translate("sim", "canopen: node ids, e.g. 1,2,5 (default 1)."),
        QStringLiteral("ids"), QStringLiteral("1"));
    const QCommandLineOption eds(
        QStringLiteral("eds"),
        QCoreApplication::translate("sim",
                                    "canopen: device description of the nodes (EDS, DCF, XDD, "
                                    "XDC, JSON; default: the built-in test node)."),
        QStringLiteral("file"));
    const QCommandLineOption noReply(
        QStringLiteral("no-reply-node"),
        QCoreApplication::translate("sim",
                                    "canopen: this node's SDO server stays silent (repeatable)."),
        QStringLiteral("id"));
    const QCommandLineOption rejectWrite(
        QStringLiteral("reject-write"),
        QCoreApplication::translate("sim",
                                    "movingcap: writes to this object fail with a device error "
                                    "(failure mode for tests; repeatable)."),
        QStringLiteral("INDEX:SUB"));
    const QCommandLineOption fault(
        QStringLiteral("fault"),
        QCoreApplication::translate("sim",
                                    "movingcap: the drive starts in fault with this EMCY code "
                                    "(hexadecimal, e.g. 7121)."),
        QStringLiteral("CODE"));
    const QCommandLineOption control(
        QStringLiteral("control"),
        QCoreApplication::translate(
            "sim",
            "movingcap, acu: read commands from standard input while serving, one a line: state, "
            "standstill, drop (abort every client: a cut cable), fault CODE; movingcap: "
            "heartbeat off|on; acu: mains on|off, sto on|off, master SPEED (the electronic "
            "gear's master, u/s), watchdog MS."));
    const QCommandLineOption devices(
        QStringLiteral("devices"),
        QCoreApplication::translate("sim",
                                    "nm17x: the displays on the bus, VARIANT@NODE, e.g. "
                                    "nm172@127,nm172@127,nm174@5 (each its own serial number)."),
        QStringLiteral("list"), QStringLiteral("nm172@127"));
    const QCommandLineOption controlPort(
        QStringLiteral("control-port"),
        QCoreApplication::translate("sim",
                                    "nm17x: line-based control socket on this TCP port (turn a "
                                    "shaft, press a key; 0 = chosen by the OS)."),
        QStringLiteral("port"));
    const QCommandLineOption bitrate(
        QStringLiteral("bitrate"),
        QCoreApplication::translate("sim",
                                    "nm17x: the bus's bit rate in bit/s (default 125000); SLCAN "
                                    "clients set to another one hear nothing."),
        QStringLiteral("bit/s"));
    parser.addOptions({ refgoPort, slcanPort, set, virtualCan, nodes, eds, noReply, rejectWrite,
                        devices, controlPort, fault, control, bitrate });
    app::addAcuOptions(parser);
    parser.addPositionalArgument(
        QStringLiteral("device"),
        QCoreApplication::translate("sim", "Which device: movingcap, canopen, nm17x or acu."));
    parser.process(app);

    const QStringList args = parser.positionalArguments();
    if (args.size() == 1 && args.first() == QLatin1String("acu")) {
        const auto console = [&app, &out](app::AcuConsole *c) {
            readControlLines(app, c, out);
        };
        if (const int code = app::runAcu(
                parser, out, err,
                parser.isSet(control) ? console : std::function<void(app::AcuConsole *)>());
            code >= 0)
            return code;
        quitOnSignals(app);
        return app.exec();
    }
    if (args.size() == 1 && args.first() == QLatin1String("nm17x")) {
        const auto valueOf = [&parser](const QCommandLineOption &o) {
            return parser.isSet(o) ? std::optional<QString>(parser.value(o)) : std::nullopt;
        };
        return sim::runNm17x({ parser.value(devices), valueOf(slcanPort), valueOf(virtualCan),
                               valueOf(controlPort), valueOf(bitrate) },
                             quitOnSignalsOfApp);
    }
    if (args.size() == 1 && args.first() == QLatin1String("canopen")) {
        app::SimNodesOptions options;
        const auto ids = app::SimNodes::parseNodeList(parser.value(nodes));
        const auto silent = app::SimNodes::parseNodeList(parser.values(noReply).join(u','));
        bool port = false;
        const uint slcan = parser.value(slcanPort).toUInt(&port);
        if (!ids || (parser.isSet(noReply) && !silent)
            || (parser.isSet(slcanPort) && (!port || slcan > 65535))
            || (!parser.isSet(slcanPort) && !parser.isSet(virtualCan))) {
            err << "drivebench-sim: "
                << (!ids ? ids.error().message()
                        : parser.isSet(noReply) && !silent
                        ? silent.error().message()
                        : QCoreApplication::translate("sim",
                                                      "give --slcan-port PORT (0..65535) and/or "
                                                      "--virtualcan IFACE"))
                << Qt::endl;
            return 2;
        }
        options.nodes = ids.value();
        options.noReply = silent.valueOr({});
        options.descriptionFile = parser.value(eds);
        app::SimNodes sim;
        if (auto created = sim.create(options); !created) {
            err << "drivebench-sim: " << created.error().toString() << Qt::endl;
            return 2;
        }
        if (parser.isSet(slcanPort)) {
            if (auto listening = sim.startSlcan(quint16(slcan)); !listening) {
                err << "drivebench-sim: " << listening.error().toString() << Qt::endl;
                return 3;
            }
            out << "canopen: SLCAN listening on 127.0.0.1:" << sim.slcanPort() << " ("
                << sim.describe() << ", canopen+slcan://127.0.0.1:" << sim.slcanPort() << ")"
                << Qt::endl;
        }
        if (parser.isSet(virtualCan)) {
            if (auto joined = sim.startVirtualCan(parser.value(virtualCan)); !joined) {
                err << "drivebench-sim: " << joined.error().toString() << Qt::endl;
                return 3;
            }
            out << "canopen: virtualcan listening on " << parser.value(virtualCan) << " ("
                << sim.describe() << ", canopen+virtualcan://" << parser.value(virtualCan) << ")"
                << Qt::endl;
        }
        quitOnSignals(app);
        return app.exec();
    }
    if (args.size() != 1 || args.first() != QLatin1String("movingcap")) {
        err << "drivebench-sim: "
            << QCoreApplication::translate(
                   "sim",
                   "give the device to simulate (movingcap, canopen, nm17x or acu), "
                   "e.g. drivebench-sim movingcap --refgo-port PORT "
                   "[--slcan-port PORT]")
            << Qt::endl;
        return 2;
    }
    if (!parser.isSet(refgoPort) && !parser.isSet(slcanPort)) {
        err << "drivebench-sim: "
            << QCoreApplication::translate("sim",
                                           "no door to serve; give --refgo-port PORT and/or "
                                           "--slcan-port PORT (0 = any free port)")
            << Qt::endl;
        return 2;
    }
    // Port of a door flag, -1 when absent, -2 when not a port number.
    const auto portOf = [&](const QCommandLineOption &option) {
        if (!parser.isSet(option))
            return -1;
        bool ok = false;
        const uint port = parser.value(option).toUInt(&ok);
        return ok && port <= 65535 ? int(port) : -2;
    };
    const int refgo = portOf(refgoPort);
    const int slcan = portOf(slcanPort);
    if (refgo == -2 || slcan == -2) {
        err << "drivebench-sim: "
            << QCoreApplication::translate("sim", "%1 takes a port number 0..65535")
                   .arg(refgo == -2 ? QStringLiteral("--refgo-port")
                                    : QStringLiteral("--slcan-port"))
            << Qt::endl;
        return 2;
    }

    QHash<ObjectAddress, QVariant> presets;
    for (const QString &assignment : parser.values(set)) {
        const qsizetype eq = assignment.indexOf(QLatin1Char('='));
        const auto address = ObjectAddress::parse(assignment.left(eq));
        if (eq < 0 || !address) {
            err << "drivebench-sim: "
                << QCoreApplication::translate("sim", "--set takes INDEX:SUB=VALUE, not '%1'")
                       .arg(assignment)
                << Qt::endl;
            return 2;
        }
        const ObjectDef *def = resources::movingCapDictionary().find(*address);
        const auto raw = def
            ? def->parseText(assignment.mid(eq + 1))
            : Result<QVariant>(
                Error(Error::Kind::InvalidArgument,
                      Tr::tr("the MovingCap has no object %1").arg(address->toString())));
        if (!raw) {
            err << "drivebench-sim: --set " << assignment << ": " << raw.error().toString()
                << Qt::endl;
            return 2;
        }
        presets.insert(*address, raw.value());
    }
    QSet<ObjectAddress> rejected;
    for (const QString &text : parser.values(rejectWrite)) {
        const auto address = ObjectAddress::parse(text);
        if (!address) {
            err << "drivebench-sim: "
                << QCoreApplication::translate("sim", "--reject-write takes INDEX:SUB, not '%1'")
                       .arg(text)
                << Qt::endl;
            return 2;
        }
        rejected.insert(*address);
    }
    std::optional<quint16> startFault;
    if (parser.isSet(fault)) {
        const auto code = app::SimConsole::parseFaultCode(parser.value(fault));
        if (!code) {
            err << "drivebench-sim: --fault: " << code.error().message() << Qt::endl;
            return 2;
        }
        startFault = *code;
    }
    app::DemoDrive demo(presets);
    demo.drive().setRejectedWrites(rejected);
    if (startFault)
        demo.drive().injectFault(*startFault);
    if (refgo >= 0) {
        if (auto listening = demo.startRefgo(quint16(refgo)); !listening) {
            err << "drivebench-sim: " << listening.error().toString() << Qt::endl;
            return 3;
        }
        out << "movingcap: RefGo listening on 127.0.0.1:" << demo.refgoPort() << " ("
            << demo.refgoUri() << ")" << Qt::endl;
    }
    if (slcan >= 0) {
        if (auto listening = demo.startSlcan(quint16(slcan)); !listening) {
            err << "drivebench-sim: " << listening.error().toString() << Qt::endl;
            return 3;
        }
        out << "movingcap: SLCAN listening on 127.0.0.1:" << demo.slcanPort() << " ("
            << demo.slcanUri() << ")" << Qt::endl;
    }
    app::SimConsole console(&demo);
    if (parser.isSet(control))
        readControlLines(app, &console, out);
    quitOnSignals(app);
    return app.exec();
}
