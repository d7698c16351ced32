#include "commands_nm17x.h"

#include "nm17xargs.h"

#include "networksession.h"

#include "canopen/nmtmaster.h"
#include "canopen/sdoclient.h"
#include "core/printable.h"
#include "devices/nm17x/nm17xaddressing.h"
#include "devices/nm17x/nm17xcodes.h"
#include "devices/nm17x/nm17xline.h"
#include "devices/nm17x/nm17xscan.h"

#include <QElapsedTimer>
#include <QEventLoop>
#include <QTimer>
#include <QtEndian>

namespace db::cli {

namespace {

using namespace db::nm17x;
using canopen::NodeId;
using namespace nm17xargs;

constexpr int kFlushMs = 1000; // time for the last frames to leave before the bus closes
constexpr int kPollMs = 100; // reading the display while waiting for In Position
constexpr int kDefaultWaitS = 30;
constexpr int kDefaultWatchS = 5;
constexpr int kDefaultStepS = 60;

// Runs the event loop for ms (the CLI waits for frames from the bus).
void spin(int ms)
{
    QEventLoop loop;
    QTimer::singleShot(ms, &loop, &QEventLoop::quit);
    loop.exec();
}

// The displays execute PDOs only in Operational: the command starts the node (0 = all) first.
void startNode(NetworkSession &session, NodeId node)
{
    session.network()->nmt()->send(canopen::NmtCommand::Start, node);
}

int list(Context &c, NetworkSession &session, Nm17xLine &line)
{
    QList<DisplayState> displays;
    if (const auto found = Reply::wait(line.findDisplays()); found)
        displays = found->value<QList<DisplayState>>();
    for (const QString &problem : line.problems())
        c.err << "drivebench-cli: " << printable(problem) << Qt::endl;
    for (const DisplayState &display : displays)
        c.out << printable(display.toString()) << Qt::endl;
    if (displays.isEmpty())
        return fail(
            c,
            Error(
                Error::Kind::Timeout,
                Tr::tr("no NM170/NM172/NM174 display answered on %1").arg(session.bus()->name())));
    return ExitOk;
}

// The displays may answer at 125 or 250 kbit/s (nm17xscan.h): look at each bit rate asked for
// (default both), each on a bus of its own, and tell at which the displays answer.
int scan(Context &c)
{
    auto bitrates = BitrateScan::defaultBitrates();
    if (c.parser && c.parser->isSet(QStringLiteral("bitrates"))) {
        const auto parsed = BitrateScan::parseBitrates(c.parser->value(QStringLiteral("bitrates")));
        if (!parsed)
            return fail(c, parsed.error());
        bitrates = parsed.value();
    }
    const auto uri = ConnectionUri::parse(c.args.at(0));
    if (!uri)
        return fail(c, uri.error());
    BitrateScan scan(*uri, bitrates);
    scan.setTimeouts(c.options.connectTimeoutMs, c.options.requestTimeoutMs);
    QEventLoop loop;
    QObject::connect(&scan, &BitrateScan::finished, &loop, &QEventLoop::quit);
    scan.start();
    if (scan.isRunning())
        loop.exec();
    int found = 0;
    for (const BitrateResult &r : scan.results()) {
        c.out << Tr::tr("%1 kbit/s: %n display(s)", nullptr, int(r.displays.size()))
                     .arg(r.bitrate / 1000.0)
              << Qt::endl;
        if (r.displays.isEmpty() && !r.problem.isEmpty())
            c.err << "drivebench-cli: " << printable(r.problem) << Qt::endl;
        for (const DisplayState &display : r.displays)
            c.out << "  " << printable(display.toString()) << Qt::endl;
        found += int(r.displays.size());
    }
    if (found == 0) {
        QStringList rates;
        for (const int b : std::as_const(bitrates))
            rates.append(QString::number(b));
        return fail(
            c,
            Error(
                Error::Kind::Timeout,
                Tr::tr("no NM170/NM172/NM174 display answered at %1 bit/s").arg(rates.join(u','))));
    }
    return ExitOk;
}

// Reads the display until the motor is off; In Position is success, an error bit a failure.
int waitInPosition(Context &c, Nm17xLine &line, NodeId node, int seconds)
{
    QElapsedTimer clock;
    clock.start();
    while (clock.elapsed() < seconds * 1000) {
        spin(kPollMs);
        const auto read = Reply::wait(line.readState(node));
        if (!read)
            return fail(c, read.error());
        const DisplayState s = read->value<DisplayState>();
        if (s.status & status::Moving)
            continue;
        if (s.errors)
            return fail(c,
                        Error(Error::Kind::DeviceError,
                              Tr::tr("node %1: %2").arg(node).arg(errorText(s.errors))));
        if (s.status & status::InPosition) {
            c.out << printable(s.toString()) << Qt::endl;
            return ExitOk;
        }
    }
    return fail(
        c,
        Error(Error::Kind::Timeout,
              Tr::tr("node %1 did not report In Position within %2 s").arg(node).arg(seconds)));
}

int setpoint(Context &c, NetworkSession &session, Nm17xLine &line)
{
    if (c.args.size() != 4)
        return fail(c,
                    usage(Tr::tr("usage: nm17x URI setpoint NODE MM [--release] [--direct] "
                                 "[--plunge SPEED] [--correction MM]")));
    const auto node = nodeArg(c.args.at(2));
    const auto value = parseMillimetres(c.args.at(3));
    if (!node || !value)
        return fail(c, !node ? node.error() : value.error());
    const bool release = c.parser->isSet(QStringLiteral("release"));
    const bool direct = c.parser->isSet(QStringLiteral("direct"));
    std::optional<Speed> speed;
    if (c.parser->isSet(QStringLiteral("plunge"))) {
        speed = parseSpeed(c.parser->value(QStringLiteral("plunge")));
        if (!speed || direct)
            return fail(
                c, usage(Tr::tr("--plunge takes slow, medium or fast, and not with --direct")));
    }
    // A correction beyond the 16 bits of the PDO goes to 2010h by SDO first; the PDO then
    // carries -32768, "keep 2010h".
    std::optional<qint16> correction;
    std::optional<qint32> wideCorrection;
    if (c.parser->isSet(QStringLiteral("correction"))) {
        const auto mm = parseMillimetres(c.parser->value(QStringLiteral("correction")));
        if (!mm)
            return fail(c, mm.error());
        if (*mm >= -32767 && *mm <= 32767)
            correction = qint16(*mm);
        else
            wideCorrection = *mm;
    }
    const SetpointKind kind = direct ? SetpointKind::Direct
        : speed   ? (release ? SetpointKind::PlungeRelease : SetpointKind::Plunge)
        : release ? SetpointKind::Release
                  : SetpointKind::Standard;
    const auto waitS = intOption(c, QStringLiteral("position-timeout"), kDefaultWaitS, 1, 3600);
    if (!waitS)
        return fail(c, waitS.error());
    if (wideCorrection) {
        QByteArray data(4, '\0');
        qToLittleEndian(*wideCorrection, data.data());
        const auto written =
            Reply::wait(session.network()->sdo()->download(*node, { 0x2010, 0 }, data));
        if (!written)
            return fail(c, written.error().prefixed(Tr::tr("node %1, 2010:0").arg(*node)));
    }
    startNode(session, *node);
    if (auto sent = line.setpoint(*node, *value, kind, correction, speed); !sent)
        return fail(c, sent.error());
    if (kind == SetpointKind::Standard || kind == SetpointKind::Plunge) {
        session.flush(wideCorrection ? 3 : 2, kFlushMs);
        c.out << Tr::tr("node %1: setpoint %2 set (no release)")
                     .arg(*node)
                     .arg(formatPosition(*value, false))
              << Qt::endl;
        return ExitOk;
    }
    return waitInPosition(c, line, *node, *waitS);
}

int jog(Context &c, NetworkSession &session, Nm17xLine &line)
{
    if (c.args.size() != 4 || (c.args.at(3) != u"left" && c.args.at(3) != u"right"))
        return fail(c,
                    usage(Tr::tr("usage: nm17x URI jog NODE left|right --speed slow|medium|fast")));
    const auto node = nodeArg(c.args.at(2));
    if (!node)
        return fail(c, node.error());
    const auto speed = parseSpeed(c.parser->value(QStringLiteral("speed")));
    if (!speed)
        return fail(c, usage(Tr::tr("jog needs --speed slow, medium or fast")));
    startNode(session, *node);
    const int direction = c.args.at(3) == u"right" ? 1 : -1;
    if (auto sent = line.jog(*node, direction, *speed); !sent)
        return fail(c, sent.error());
    session.flush(2, kFlushMs);
    c.out << Tr::tr("node %1: jogging %2 at %3 speed until stop or limit")
                 .arg(*node)
                 .arg(c.args.at(3), speedName(*speed))
          << Qt::endl;
    return ExitOk;
}

int stop(Context &c, NetworkSession &session, Nm17xLine &line)
{
    if (c.args.size() != 3)
        return fail(c, usage(Tr::tr("usage: nm17x URI stop NODE|all")));
    if (c.args.at(2) == u"all") {
        startNode(session, 0);
        if (auto sent = line.stopAll(); !sent)
            return fail(c, sent.error());
    } else {
        const auto node = nodeArg(c.args.at(2));
        if (!node)
            return fail(c, node.error());
        startNode(session, *node);
        if (auto sent = line.stop(*node); !sent)
            return fail(c, sent.error());
    }
    session.flush(2, kFlushMs);
    c.out << Tr::tr("stop sent to %1").arg(c.args.at(2)) << Qt::endl;
    return ExitOk;
}

// 204Dh:02 by SDO: oscillation between D1 and D2 (2045h:01/02, set them first with write).
int oscillate(Context &c, NetworkSession &session)
{
    const QString what = c.args.value(3);
    if (c.args.size() != 4 || (what != u"start" && what != u"stop"))
        return fail(c, usage(Tr::tr("usage: nm17x URI oscillate NODE start|stop")));
    const auto node = nodeArg(c.args.at(2));
    if (!node)
        return fail(c, node.error());
    const QByteArray data(1, what == u"start" ? '\x01' : '\x00');
    if (auto written = Reply::wait(session.network()->sdo()->download(*node, { 0x204D, 2 }, data));
        !written)
        return fail(c, written.error().prefixed(Tr::tr("node %1: 204Dh:02").arg(*node)));
    c.out << Tr::tr("node %1: oscillation %2").arg(*node).arg(what) << Qt::endl;
    return ExitOk;
}

int broadcast(Context &c, NetworkSession &session, Nm17xLine &line)
{
    const QString what = c.args.value(2);
    const QString arg = c.args.value(3);
    Result<void> sent = usage(Tr::tr("usage: nm17x URI broadcast unit mm|inch | show-id [off] | "
                                     "preset MM | start GROUP | stop"));
    startNode(session, 0);
    if (what == u"unit" && (arg == u"mm" || arg == u"inch")) {
        sent = line.setUnit(arg == u"inch");
    } else if (what == u"show-id" && (arg.isEmpty() || arg == u"off")) {
        sent = line.showNodeIds(arg.isEmpty());
    } else if (what == u"preset" && !arg.isEmpty()) {
        const auto value = parseMillimetres(arg);
        sent = value ? line.presetAll(*value) : Result<void>(value.error());
    } else if (what == u"start" && !arg.isEmpty()) {
        bool ok = false;
        const int group = arg.toInt(&ok);
        sent =
            ok ? line.startGroup(group) : Result<void>(usage(Tr::tr("start takes a group 1..8")));
    } else if (what == u"stop" && arg.isEmpty()) {
        sent = line.stopAll();
    }
    if (!sent)
        return fail(c, sent.error());
    session.flush(2, kFlushMs);
    c.out << Tr::tr("broadcast %1 %2 sent on 201h").arg(what, arg).trimmed() << Qt::endl;
    return ExitOk;
}

int control(Context &c, NetworkSession &session, Nm17xLine &line)
{
    if (c.args.size() != 4)
        return fail(c,
                    usage(Tr::tr("usage: nm17x URI control NODE WORD [--setpoint MM] "
                                 "[--correction MM]")));
    const auto node = nodeArg(c.args.at(2));
    bool ok = false;
    const QString w = c.args.at(3);
    const uint word =
        w.startsWith(u"0x", Qt::CaseInsensitive) ? w.mid(2).toUInt(&ok, 16) : w.toUInt(&ok);
    if (!node || !ok || word > 0xFFFF)
        return fail(
            c, !node ? node.error() : usage(Tr::tr("'%1' is not a 16-bit control word").arg(w)));
    PositionCommand command { 0, kKeepCorrection, quint16(word) };
    if (c.parser->isSet(QStringLiteral("setpoint"))) {
        const auto v = parseMillimetres(c.parser->value(QStringLiteral("setpoint")));
        if (!v)
            return fail(c, v.error());
        command.setpoint = *v;
    }
    if (c.parser->isSet(QStringLiteral("correction"))) {
        const auto v = parseMillimetres(c.parser->value(QStringLiteral("correction")));
        if (!v || *v < -32767 || *v > 32767)
            return fail(c, usage(Tr::tr("--correction takes -327.67..327.67 mm")));
        command.correction = qint16(*v);
    }
    if (const auto allowed = classify(command.control); !allowed)
        return fail(c, allowed.error()); // nothing has been sent
    startNode(session, *node);
    if (auto sent = line.send(*node, command); !sent)
        return fail(c, sent.error());
    session.flush(2, kFlushMs);
    c.out << Tr::tr("node %1: %2 sent")
                 .arg(*node)
                 .arg(commandName(classify(command.control)->command))
          << Qt::endl;
    return ExitOk;
}

int watch(Context &c, NetworkSession &session, Nm17xLine &line)
{
    const auto seconds = intOption(c, QStringLiteral("seconds"), kDefaultWatchS, 1, 86400);
    if (!seconds)
        return fail(c, seconds.error());
    QObject::connect(&line, &Nm17xLine::tpdo1, &line, [&c](NodeId node, const Tpdo1 &p) {
        c.out << Tr::tr("node %1 TxPDO1 position %2 status %3 errors %4")
                     .arg(node)
                     .arg(formatPosition(p.position, false), statusText(p.status),
                          p.errors ? errorText(p.errors) : QStringLiteral("-"))
              << Qt::endl;
    });
    QObject::connect(&line, &Nm17xLine::tpdo2, &line, [&c](NodeId node, const Tpdo2 &p) {
        c.out << Tr::tr("node %1 TxPDO2 position %2 correction %3 status %4")
                     .arg(node)
                     .arg(formatPosition(p.position, false), formatPosition(p.correction, false),
                          statusText(p.status))
              << Qt::endl;
    });
    QObject::connect(&line, &Nm17xLine::emergency, &line,
                     [&c](NodeId node, quint16 code, quint8 sub, const QString &text) {
                         c.out << Tr::tr("node %1 EMCY %2h sub %3: %4")
                                      .arg(node)
                                      .arg(QString::number(code, 16).toUpper())
                                      .arg(sub, 2, 16, QLatin1Char('0'))
                                      .arg(printable(text))
                               << Qt::endl;
                     });
    c.out << Tr::tr("watching %1 for %2 s").arg(session.bus()->name()).arg(*seconds) << Qt::endl;
    spin(*seconds * 1000);
    return ExitOk;
}

int address(Context &c, NetworkSession &session)
{
    const auto first = intOption(c, QStringLiteral("broadcast"), -1, 1, 127);
    const auto count = intOption(c, QStringLiteral("count"), 0, 1, 127);
    const auto step = intOption(c, QStringLiteral("step-timeout"), kDefaultStepS, 1, 3600);
    if (!first || !count || !step)
        return fail(c, !first ? first.error() : !count ? count.error() : step.error());
    if (*first < 0)
        return fail(c, usage(Tr::tr("address needs --broadcast FIRST (the first node id)")));
    BroadcastAddressing addressing(session.network());
    addressing.setStepTimeoutMs(*step * 1000);
    QObject::connect(&addressing, &BroadcastAddressing::offering, &addressing, [&c](NodeId node) {
        c.out << Tr::tr("offering node %1: turn the shaft (or press a key) of the display that "
                        "should become node %1")
                     .arg(node)
              << Qt::endl;
    });
    QObject::connect(&addressing, &BroadcastAddressing::assigned, &addressing, [&c](NodeId node) {
        c.out << Tr::tr("node %1 assigned").arg(node) << Qt::endl;
    });
    QEventLoop loop;
    QObject::connect(&addressing, &BroadcastAddressing::finished, &loop, &QEventLoop::quit);
    if (auto started = addressing.start(NodeId(*first), *count); !started)
        return fail(c, started.error());
    loop.exec();
    QStringList ids;
    for (const NodeId id : addressing.assignedIds())
        ids.append(QString::number(id));
    c.out << Tr::tr("assigned node ids: %1; every node reset")
                 .arg(ids.isEmpty() ? QStringLiteral("none") : ids.join(QLatin1String(", ")))
          << Qt::endl;
    session.flush(0, kFlushMs);
    if (addressing.state() == BroadcastAddressing::State::Failed)
        return fail(c, addressing.error());
    return ExitOk;
}

} // namespace

QList<QCommandLineOption> nm17xOptions()
{
    return {
        { QStringLiteral("release"), Tr::tr("nm17x setpoint: start the motor at once.") },
        { QStringLiteral("direct"), Tr::tr("nm17x setpoint: with release, without loop.") },
        { QStringLiteral("plunge"), Tr::tr("nm17x setpoint: plunge cut at this speed."),
          QStringLiteral("speed") },
        { QStringLiteral("correction"), Tr::tr("nm17x: actual value correction in mm."),
          QStringLiteral("mm") },
        { QStringLiteral("setpoint"), Tr::tr("nm17x control: the setpoint in mm."),
          QStringLiteral("mm") },
        { QStringLiteral("speed"), Tr::tr("nm17x jog: slow, medium or fast."),
          QStringLiteral("speed") },
        { QStringLiteral("broadcast"), Tr::tr("nm17x address: first node id of the line."),
          QStringLiteral("id") },
        { QStringLiteral("count"),
          Tr::tr("nm17x address: number of displays (default: until a step "
                 "times out)."),
          QStringLiteral("n") },
        { QStringLiteral("step-timeout"),
          Tr::tr("nm17x address: seconds the operator has per display (default 60)."),
          QStringLiteral("s") },
        { QStringLiteral("position-timeout"),
          Tr::tr("nm17x setpoint: seconds to wait for In Position (default 30)."),
          QStringLiteral("s") },
        { QStringLiteral("seconds"), Tr::tr("nm17x watch: how long to watch (default 5)."),
          QStringLiteral("s") },
        { QStringLiteral("input-mode"),
          Tr::tr("nm17x settings: inputs F/G: standard, takten, externposi or off."),
          QStringLiteral("mode") },
        { QStringLiteral("key-mode"),
          Tr::tr("nm17x settings: keys: standard, slow, middle or fast."), QStringLiteral("mode") },
        { QStringLiteral("pitch"),
          Tr::tr("nm17x settings: spindle pitch in mm per revolution (sets the scaling)."),
          QStringLiteral("mm") },
        { QStringLiteral("steps"),
          Tr::tr("nm17x settings: sensor steps per revolution (default 2304; NM174 4096)."),
          QStringLiteral("n") },
        { QStringLiteral("filter-width"),
          Tr::tr("nm17x settings: jump filter width in sensor steps."), QStringLiteral("steps") },
        { QStringLiteral("filter-count"),
          Tr::tr("nm17x settings: jumps filtered before one is taken as real."),
          QStringLiteral("n") },
        { QStringLiteral("pre-shutdown"), Tr::tr("nm17x settings: dynamic pre-shutdown on or off."),
          QStringLiteral("on|off") },
        { QStringLiteral("bitrates"),
          Tr::tr("nm17x scan: the bit rates to look at (default 125000,250000)."),
          QStringLiteral("list") },
    };
}

int nm17x(Context &c)
{
    const QString sub = c.args.value(1);
    static const QStringList kSubs = { QStringLiteral("list"),      QStringLiteral("setpoint"),
                                       QStringLiteral("jog"),       QStringLiteral("stop"),
                                       QStringLiteral("broadcast"), QStringLiteral("address"),
                                       QStringLiteral("control"),   QStringLiteral("watch"),
                                       QStringLiteral("scan"),      QStringLiteral("oscillate"),
                                       QStringLiteral("settings") };
    if (!kSubs.contains(sub))
        return fail(c, usage(Tr::tr("unknown nm17x command '%1' (%2)").arg(sub, kSubs.join(u'|'))));
    if (sub == u"scan")
        return scan(c);
    NetworkSession session;
    if (auto opened = session.open(c.args.at(0), c.options.connectTimeoutMs); !opened)
        return fail(c, opened.error());
    session.network()->sdo()->setTimeoutMs(c.options.requestTimeoutMs);
    Nm17xLine line(session.network());
    if (sub == u"list")
        return list(c, session, line);
    if (sub == u"setpoint")
        return setpoint(c, session, line);
    if (sub == u"jog")
        return jog(c, session, line);
    if (sub == u"stop")
        return stop(c, session, line);
    if (sub == u"broadcast")
        return broadcast(c, session, line);
    if (sub == u"control")
        return control(c, session, line);
    if (sub == u"watch")
        return watch(c, session, line);
    if (sub == u"oscillate")
        return oscillate(c, session);
    if (sub == u"settings")
        return nm17xSettings(c, line);
    return address(c, session);
}

} // namespace db::cli
