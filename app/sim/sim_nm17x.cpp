#include "sim_nm17x.h"

#include "devices/nm17x/device/nm17xsim.h"

#include <QCoreApplication>
#include <QTextStream>

namespace db::sim {

namespace {
std::optional<quint16> portOf(const QString &text)
{
    bool ok = false;
    const uint port = text.toUInt(&ok);
    return ok && port <= 65535 ? std::optional<quint16>(quint16(port)) : std::nullopt;
}
} // namespace

int runNm17x(const Nm17xOptions &options, void (*quitOnSignals)())
{
    QTextStream out(stdout);
    QTextStream err(stderr);
    const auto specs = nm17x::Nm17xSim::parseDevices(options.devices);
    if (!specs) {
        err << "drivebench-sim: --devices: " << specs.error().message() << Qt::endl;
        return 2;
    }
    const auto slcan = options.slcanPort ? portOf(*options.slcanPort) : std::nullopt;
    const auto control = options.controlPort ? portOf(*options.controlPort) : std::nullopt;
    if ((options.slcanPort && !slcan) || (options.controlPort && !control)
        || (!options.slcanPort && !options.virtualCan)) {
        err << "drivebench-sim: "
            << QCoreApplication::translate("sim",
                                           "nm17x needs --slcan-port PORT (0..65535) and/or "
                                           "--virtualcan IFACE; --control-port takes a port "
                                           "0..65535")
            << Qt::endl;
        return 2;
    }
    bool bitrateOk = true;
    const int bitrate =
        options.bitrate ? options.bitrate->toInt(&bitrateOk) : nm17x::kDeliveryBitrate;
    if (!bitrateOk || bitrate <= 0) {
        err << "drivebench-sim: "
            << QCoreApplication::translate("sim", "--bitrate takes bit/s, e.g. 125000 or 250000")
            << Qt::endl;
        return 2;
    }
    nm17x::Nm17xSim sim;
    sim.create(specs.value());
    sim.setBitrate(bitrate);
    if (slcan) {
        if (auto listening = sim.startSlcan(*slcan); !listening) {
            err << "drivebench-sim: " << listening.error().toString() << Qt::endl;
            return 3;
        }
        out << "nm17x: SLCAN listening on 127.0.0.1:" << sim.slcanPort() << " (" << sim.describe()
            << ", canopen+slcan://127.0.0.1:" << sim.slcanPort() << "?bitrate=" << bitrate << ")"
            << Qt::endl;
    }
    if (options.virtualCan) {
        if (auto joined = sim.startVirtualCan(*options.virtualCan); !joined) {
            err << "drivebench-sim: " << joined.error().toString() << Qt::endl;
            return 3;
        }
        out << "nm17x: virtualcan listening on " << *options.virtualCan << " (" << sim.describe()
            << ", canopen+virtualcan://" << *options.virtualCan << ")" << Qt::endl;
    }
    if (control) {
        if (auto listening = sim.startControl(*control); !listening) {
            err << "drivebench-sim: " << listening.error().toString() << Qt::endl;
            return 3;
        }
        out << "nm17x: control listening on 127.0.0.1:" << sim.controlPort()
            << " (list | turn INDEX DELTA | key INDEX left|right [MS] | fault INDEX "
               "motor|sensor|none)"
            << Qt::endl;
    }
    quitOnSignals();
    return QCoreApplication::exec();
}

} // namespace db::sim
