#include "simacu.h"

#include "acuconsole.h"

#include "devices/bonfiglioli/simulatedacu.h"

#include <QCoreApplication>

namespace db::app {

namespace {

struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(sim)
};

const QCommandLineOption &vabusPort()
{
    static const QCommandLineOption o(
        QStringLiteral("vabus-port"),
        Tr::tr("acu: serve VABus/TCP (the PLC port) on this TCP port (0 = chosen by the OS)."),
        QStringLiteral("port"));
    return o;
}
const QCommandLineOption &watchdogMs()
{
    static const QCommandLineOption o(
        QStringLiteral("watchdog-ms"),
        Tr::tr("acu: time without exchange before the reaction of parameter 388 (default 10000)."),
        QStringLiteral("ms"));
    return o;
}
const QCommandLineOption &fail()
{
    static const QCommandLineOption o(
        QStringLiteral("fail"),
        Tr::tr("acu: failure mode for tests: silent, garbage, slow, drop-after or split (every "
               "answer in 1-byte TCP segments)."),
        QStringLiteral("mode"));
    return o;
}
const QCommandLineOption &slowMs()
{
    static const QCommandLineOption o(QStringLiteral("slow-ms"),
                                      Tr::tr("acu: --fail slow delays every answer this long "
                                             "(default 2000)."),
                                      QStringLiteral("ms"), QStringLiteral("2000"));
    return o;
}
const QCommandLineOption &dropAfter()
{
    static const QCommandLineOption o(QStringLiteral("drop-after"),
                                      Tr::tr("acu: --fail drop-after closes the connection after "
                                             "this many answers (default 1)."),
                                      QStringLiteral("n"), QStringLiteral("1"));
    return o;
}
const QCommandLineOption &startupDelay()
{
    static const QCommandLineOption o(
        QStringLiteral("startup-delay-ms"),
        Tr::tr("acu: answer nothing for this long after start, as the module initialising after "
               "power-on (up to 20000)."),
        QStringLiteral("ms"), QStringLiteral("0"));
    return o;
}
const QCommandLineOption &slave()
{
    static const QCommandLineOption o(
        QStringLiteral("slave"),
        Tr::tr("acu: a system bus slave with this node id (1-63) behind the "
               "module (repeatable)."),
        QStringLiteral("id"));
    return o;
}

const QCommandLineOption &acuFault()
{
    static const QCommandLineOption o(
        QStringLiteral("acu-fault"),
        Tr::tr("acu: start in fault with this code (hex as parameter 260 shows it, e.g. 2714 "
               "for F2714)."),
        QStringLiteral("code"));
    return o;
}
const QCommandLineOption &inputs()
{
    static const QCommandLineOption o(
        QStringLiteral("acu-inputs"),
        Tr::tr("acu: simulated inputs off at start, comma-separated: mains, sto, or the limit "
               "switches on: limit-pos, limit-neg."),
        QStringLiteral("list"));
    return o;
}

// A non-negative integer option, or -1 when it is not one.
int number(const QCommandLineParser &parser, const QCommandLineOption &option, int max)
{
    bool ok = false;
    const int v = parser.value(option).toInt(&ok);
    return ok && v >= 0 && v <= max ? v : -1;
}

} // namespace

void addAcuOptions(QCommandLineParser &parser)
{
    parser.addOptions({ vabusPort(), watchdogMs(), fail(), slowMs(), dropAfter(), startupDelay(),
                        slave(), acuFault(), inputs() });
}

int runAcu(const QCommandLineParser &parser, QTextStream &out, QTextStream &err,
           const std::function<void(AcuConsole *)> &readLines)
{
    if (!parser.isSet(vabusPort())) {
        err << "drivebench-sim: " << Tr::tr("acu needs --vabus-port PORT (0 = any free port)")
            << Qt::endl;
        return 2;
    }
    const int port = number(parser, vabusPort(), 65535);
    const int watchdog = parser.isSet(watchdogMs()) ? number(parser, watchdogMs(), 3600000)
                                                    : bonfiglioli::SimulatedAcu::kWatchdogMs;
    const int slow = number(parser, slowMs(), 600000);
    const int drop = number(parser, dropAfter(), 1000000);
    const int startup = number(parser, startupDelay(), 600000);
    if (port < 0 || watchdog < 1 || slow < 0 || drop < 0 || startup < 0) {
        err << "drivebench-sim: "
            << (port < 0           ? Tr::tr("--vabus-port takes a port number 0..65535")
                    : watchdog < 1 ? Tr::tr("--watchdog-ms takes a time in ms (1 or more)")
                                   : Tr::tr("--slow-ms, --drop-after and --startup-delay-ms take "
                                            "a number"))
            << Qt::endl;
        return 2;
    }
    vabus::Server::FailureMode mode;
    if (parser.isSet(fail())) {
        const auto failure = vabus::Server::failureFromName(parser.value(fail()));
        if (!failure) {
            err << "drivebench-sim: "
                << Tr::tr("--fail takes silent, garbage, slow, drop-after or split, not '%1'")
                       .arg(parser.value(fail()))
                << Qt::endl;
            return 2;
        }
        mode.failure = *failure;
    }
    mode.slowMs = slow;
    mode.dropAfter = drop;

    auto *acu = new bonfiglioli::SimulatedAcu(QCoreApplication::instance());
    for (const QString &id : parser.values(slave())) {
        bool ok = false;
        const int node = id.toInt(&ok);
        if (!ok || node < 1 || node > 63) {
            err << "drivebench-sim: " << Tr::tr("--slave takes a node id 1..63, not '%1'").arg(id)
                << Qt::endl;
            return 2;
        }
        acu->addSystemBusSlave(quint8(node));
    }
    if (parser.isSet(acuFault())) {
        bool ok = false;
        const uint code = parser.value(acuFault()).toUInt(&ok, 16);
        if (!ok || code == 0 || code > 0xFFFF) {
            err << "drivebench-sim: "
                << Tr::tr("--acu-fault takes a fault code in hex, e.g. 2714, not '%1'")
                       .arg(parser.value(acuFault()))
                << Qt::endl;
            return 2;
        }
        acu->raiseFault(quint16(code));
    }
    const QStringList in = parser.value(inputs()).split(QLatin1Char(','), Qt::SkipEmptyParts);
    for (const QString &name : in) {
        if (name == QLatin1String("mains"))
            acu->motion().setMains(false);
        else if (name == QLatin1String("sto"))
            acu->motion().setSto(false);
        else if (name != QLatin1String("limit-pos") && name != QLatin1String("limit-neg")) {
            err << "drivebench-sim: "
                << Tr::tr("--acu-inputs takes mains, sto, limit-pos, limit-neg, not '%1'").arg(name)
                << Qt::endl;
            return 2;
        }
    }
    acu->motion().setLimitSwitches(in.contains(QLatin1String("limit-pos")),
                                   in.contains(QLatin1String("limit-neg")));
    acu->setWatchdogMs(watchdog);
    acu->setStartupDelayMs(startup);
    acu->server().setFailure(mode);
    QObject::connect(acu, &bonfiglioli::SimulatedAcu::logLine, acu,
                     [&err](const QString &line) { err << "acu: " << line << Qt::endl; });
    if (auto listening = acu->listen(quint16(port)); !listening) {
        err << "drivebench-sim: " << listening.error().toString() << Qt::endl;
        return 3;
    }
    out << "acu: VABus/TCP listening on 127.0.0.1:" << acu->port()
        << " (vabus://127.0.0.1:" << acu->port() << ")" << Qt::endl;
    QObject::connect(
        QCoreApplication::instance(), &QCoreApplication::aboutToQuit, acu,
        [acu, &out] { out << "acu: " << acu->eepromWrites() << " EEPROM writes" << Qt::endl; });
    if (readLines)
        readLines(new AcuConsole(acu, acu));
    return -1; // serve: the caller runs the event loop
}

} // namespace db::app
