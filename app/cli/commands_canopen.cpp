#include "commands_canopen.h"
#include "core/filereader.h"
#include "core/filewriter.h"

#include "networksession.h"

#include "canopen/canbusfactory.h"
#include "canopen/cannetworkpool.h"
#include "canopen/canopenconnection.h"
#include "canopen/lssmaster.h"
#include "canopen/nmtmaster.h"
#include "canopen/nodemonitor.h"
#include "canopen/nodescanner.h"
#include "canopen/pdoclient.h"
#include "canopen/sdoclient.h"
#include "core/printable.h"
#include "description/dcfwriter.h"
#include "transport/canbus.h"

#include <QElapsedTimer>
#include <QEventLoop>
#include <QFile>
#include <QSaveFile>
#include <QTimer>

#include <QCoreApplication>
#include <memory>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(cli)
};
} // namespace

namespace db::cli {

namespace {

using namespace db::canopen;

Error usage(const QString &text)
{
    return Error(Error::Kind::InvalidArgument, text);
}

Result<quint32> number(const QString &text)
{
    bool ok = false;
    const quint32 v = text.startsWith(QLatin1String("0x"), Qt::CaseInsensitive)
        ? text.mid(2).toUInt(&ok, 16)
        : text.toUInt(&ok, 10);
    if (!ok)
        return usage(Tr::tr("'%1' is not a number").arg(text));
    return v;
}

} // namespace

int scan(Context &c)
{
    NetworkSession session;
    if (auto opened = session.open(c.args.at(0), c.options.connectTimeoutMs); !opened)
        return fail(c, opened.error());
    SdoClient *sdo = session.network()->sdo();
    sdo->setTimeoutMs(c.options.requestTimeoutMs);
    NodeScanner scanner(sdo, session.network()->monitor());
    QElapsedTimer clock;
    clock.start();
    QEventLoop loop;
    QObject::connect(&scanner, &NodeScanner::finished, &loop, &QEventLoop::quit);
    // Each request has its own timeout; the safety limit only guards against a defect.
    QTimer::singleShot(10 * c.options.requestTimeoutMs + 10000, &loop, &QEventLoop::quit);
    scanner.start();
    if (scanner.isRunning())
        loop.exec();
    const QList<NodeInfo> nodes = scanner.nodes();
    for (const NodeInfo &node : nodes) {
        c.out << printable(node.toString()) << Qt::endl; // holds the device's 1008h/100Ah strings
        if (c.options.verbose) {
            for (const QString &problem : node.problems)
                c.err << Tr::tr("  node %1: %2").arg(int(node.id)).arg(printable(problem))
                      << Qt::endl;
        }
    }
    if (c.options.verbose)
        c.err << Tr::tr("scanned nodes 1..127 on %1 in %2 ms")
                     .arg(session.bus()->name())
                     .arg(clock.elapsed())
              << Qt::endl;
    if (nodes.isEmpty())
        return fail(c,
                    Error(Error::Kind::Timeout,
                          Tr::tr("no CANopen node answered on %1 within %2 ms")
                              .arg(session.bus()->name())
                              .arg(c.options.requestTimeoutMs)));
    return ExitOk;
}

int nmt(Context &c)
{
    static const QMap<QString, NmtCommand> kCommands {
        { QStringLiteral("start"), NmtCommand::Start },
        { QStringLiteral("stop"), NmtCommand::Stop },
        { QStringLiteral("preop"), NmtCommand::EnterPreOperational },
        { QStringLiteral("reset"), NmtCommand::ResetNode },
        { QStringLiteral("reset-comm"), NmtCommand::ResetCommunication },
    };
    if (!kCommands.contains(c.args.at(1)))
        return fail(c,
                    usage(Tr::tr("unknown NMT command '%1' (start, stop, preop, reset, "
                                 "reset-comm)")
                              .arg(c.args.at(1))));
    const NmtCommand command = kCommands.value(c.args.at(1));
    NodeId node = NmtMaster::kAllNodes;
    if (!c.all) {
        const auto uri = ConnectionUri::parse(c.args.at(0));
        const auto id = uri ? CanopenConnection::nodeFromUri(*uri) : Result<NodeId>(uri.error());
        if (!id)
            return fail(c, id.error().prefixed(Tr::tr("nmt (or give --all)")));
        node = *id;
    }
    NetworkSession session;
    if (auto opened = session.open(c.args.at(0), c.options.connectTimeoutMs); !opened)
        return fail(c, opened.error());
    NodeMonitor &monitor = *session.network()->monitor();
    NmtMaster &master = *session.network()->nmt();
    // NMT is unconfirmed: report the state the node's heartbeat or boot-up shows afterwards.
    const bool reset =
        command == NmtCommand::ResetNode || command == NmtCommand::ResetCommunication;
    const NmtState expected = command == NmtCommand::Start ? NmtState::Operational
        : command == NmtCommand::Stop                      ? NmtState::Stopped
                                                           : NmtState::PreOperational;
    bool confirmed = false;
    QEventLoop confirmation;
    QObject::connect(&monitor, &NodeMonitor::bootUp, &confirmation, [&](NodeId id) {
        confirmed = confirmed || (reset && id == node);
        if (confirmed)
            confirmation.quit();
    });
    QObject::connect(&monitor, &NodeMonitor::stateChanged, &confirmation,
                     [&](NodeId id, NmtState s) {
                         confirmed = confirmed || (!reset && id == node && s == expected);
                         if (confirmed)
                             confirmation.quit();
                     });
    if (!master.send(command, node))
        return fail(c, Error(Error::Kind::Disconnected, Tr::tr("cannot send NMT")));
    if (node == NmtMaster::kAllNodes) {
        session.flush(1, c.options.requestTimeoutMs);
        c.out << "sent " << NmtMaster::commandName(command) << " to all nodes" << Qt::endl;
        return ExitOk;
    }
    QTimer::singleShot(c.options.requestTimeoutMs, &confirmation, &QEventLoop::quit);
    if (!confirmed)
        confirmation.exec();
    if (confirmed)
        c.out << "node " << node << ": "
              << (reset ? QStringLiteral("boot-up") : nmtStateName(expected)) << Qt::endl;
    else
        c.out << "node " << node << ": sent " << NmtMaster::commandName(command)
              << " (no heartbeat confirmed it within " << c.options.requestTimeoutMs << " ms)"
              << Qt::endl;
    return ExitOk;
}

int lss(Context &c)
{
    const QString action = c.args.at(1);
    const QString value = c.args.value(2);
    static const QStringList kActions { "inquire",  "switch-global", "switch-selective",
                                        "set-node", "set-bitrate",   "store",
                                        "fastscan" };
    if (!kActions.contains(action))
        return fail(c,
                    usage(Tr::tr("unknown LSS action '%1' (%2)")
                              .arg(action, kActions.join(QLatin1String(", ")))));
    // Arguments first: a usage error needs no bus.
    LssAddress address;
    int nodeId = 0;
    int bitTiming = -1;
    if (action == u"switch-selective") {
        const QStringList parts = value.split(QLatin1Char(','));
        quint32 *fields[] = { &address.vendorId, &address.productCode, &address.revision,
                              &address.serial };
        if (parts.size() != 4)
            return fail(c,
                        usage(Tr::tr("switch-selective takes VENDOR,PRODUCT,REVISION,"
                                     "SERIAL (e.g. 0xEC,0x71,0x10001,0x4D52F567)")));
        for (int i = 0; i < 4; ++i) {
            const auto v = number(parts.at(i).trimmed());
            if (!v)
                return fail(c, v.error());
            *fields[i] = *v;
        }
    } else if (action == u"set-node") {
        const auto v = number(value);
        if (!v || *v < 1 || *v > 127)
            return fail(c, usage(Tr::tr("set-node takes a node id 1..127")));
        nodeId = int(*v);
    } else if (action == u"set-bitrate") {
        const bool kilo = value.endsWith(QLatin1Char('k'));
        const auto v = number(kilo ? value.chopped(1) : value);
        bitTiming = v ? lss::bitTimingIndex(int(*v) * (kilo ? 1000 : 1)) : -1;
        if (bitTiming < 0)
            return fail(c,
                        usage(Tr::tr("set-bitrate takes a CiA bit rate: 1000k, 800k, "
                                     "500k, 250k, 125k, 100k, 50k, 20k or 10k")));
    }
    NetworkSession session;
    if (auto opened = session.open(c.args.at(0), c.options.connectTimeoutMs); !opened)
        return fail(c, opened.error());
    LssMaster &master = *session.network()->lss();
    master.setTimeoutMs(c.options.requestTimeoutMs);
    const auto done = [&](Reply *reply, const QString &what) -> int {
        const auto result = Reply::wait(reply);
        if (!result)
            return fail(c, result.error().prefixed(Tr::tr("LSS %1").arg(what)));
        c.out << what << ": ok" << Qt::endl;
        return ExitOk;
    };
    if (action == u"switch-global") {
        const bool waiting = value == u"waiting" || value == u"operation" || value == u"0";
        master.switchModeGlobal(waiting ? LssMode::Waiting : LssMode::Configuration);
        session.flush(1, c.options.requestTimeoutMs);
        c.out << "switch-global: " << (waiting ? "waiting" : "configuration") << Qt::endl;
        return ExitOk;
    }
    if (action == u"switch-selective")
        return done(master.switchModeSelective(address), QStringLiteral("switch-selective"));
    if (action == u"set-node")
        return done(master.configureNodeId(NodeId(nodeId)), Tr::tr("set-node %1").arg(nodeId));
    if (action == u"set-bitrate")
        return done(master.configureBitTiming(quint8(bitTiming)),
                    Tr::tr("set-bitrate %1").arg(value));
    if (action == u"store")
        return done(master.storeConfiguration(), QStringLiteral("store"));
    if (action == u"fastscan") {
        const auto found = Reply::wait(master.fastscan());
        if (!found)
            return fail(c, found.error().prefixed(Tr::tr("LSS fastscan")));
        c.out << "found " << found->value<LssAddress>().toString() << " (now in configuration mode)"
              << Qt::endl;
        return ExitOk;
    }
    // inquire: the identity and node id of the slave in configuration mode.
    static const char *kNames[] = { "vendor", "product", "revision", "serial", "node-id" };
    for (quint8 cs = lss::InquireVendor; cs <= lss::InquireNodeId; ++cs) {
        const auto v = Reply::wait(master.inquire(cs));
        if (!v)
            return fail(c,
                        v.error().prefixed(Tr::tr("LSS inquire (is a slave in configuration mode? "
                                                  "use switch-selective or switch-global first)")));
        const quint32 n = quint32(v->toULongLong());
        c.out << kNames[cs - lss::InquireVendor] << ' '
              << (cs == lss::InquireNodeId ? QString::number(n)
                                           : QStringLiteral("0x%1").arg(n, 8, 16, QLatin1Char('0')))
              << Qt::endl;
    }
    return ExitOk;
}

int pdo(Context &c)
{
    Session session(c.registry, c.options);
    if (auto opened = session.open(c.args.at(0)); !opened)
        return fail(c, opened.error());
    DeviceConnection *conn = session.connection();
    const NetworkNode at = networkNodeOf(conn);
    if (!at)
        return fail(c, usage(Tr::tr("pdo needs a canopen+... URI")));
    PdoClient client(at.network->sdo());
    const auto read = Reply::wait(client.readAll(at.node, conn->dictionary()));
    if (!read)
        return fail(c, read.error().prefixed(Tr::tr("reading the PDO configuration")));
    const auto configs = read->value<QList<PdoConfig>>();
    for (const PdoConfig &config : configs) {
        c.out << config.toString() << Qt::endl;
        for (const PdoMappingEntry &e : config.entries) {
            const ObjectDef *def = conn->dictionary().find(e.address);
            c.out << "    " << conn->addressFormat().format(e.address) << " " << e.bits << " bits"
                  << (def ? QStringLiteral("  %1").arg(printable(def->name)) : QString())
                  << Qt::endl;
        }
    }
    if (configs.isEmpty())
        c.out << "node " << at.node << " has no PDO communication objects" << Qt::endl;
    return ExitOk;
}

int dcf(Context &c)
{
    if (c.output.isEmpty())
        return fail(c, usage(Tr::tr("dcf needs the output file: -o FILE")));
    Session session(c.registry, c.options);
    if (auto opened = session.open(c.args.at(0)); !opened)
        return fail(c, opened.error());
    const ObjectDictionary &dict = session.connection()->dictionary();
    if (dict.isEmpty())
        return fail(c,
                    usage(Tr::tr("no device description for %1: give ?eds=FILE")
                              .arg(session.connection()->uri().toString())));
    QMap<ObjectAddress, QVariant> values;
    int skipped = 0;
    for (const ObjectDef &def : dict.objects()) {
        if (def.access == Access::WriteOnly)
            continue;
        const auto value = session.read(def.address);
        if (value) {
            values.insert(def.address, value.value());
            continue;
        }
        const auto kind = value.error().kind();
        if (kind == Error::Kind::Timeout || kind == Error::Kind::Disconnected)
            return fail(c,
                        value.error().prefixed(
                            Tr::tr("reading %1").arg(session.addressFormat().format(def.address))));
        ++skipped;
        if (c.options.verbose)
            c.err << Tr::tr("warning: %1: %2")
                         .arg(session.addressFormat().format(def.address), value.error().message())
                  << Qt::endl;
    }
    DcfCommissioning commissioning;
    if (const NetworkNode at = networkNodeOf(session.connection()))
        commissioning.nodeId = at.node;
    if (auto written = writeDcf(c.output, dict, values, commissioning); !written)
        return fail(c, written.error());
    c.out << "wrote " << c.output << ": " << values.size() << " values"
          << (skipped ? Tr::tr(", %1 objects not readable").arg(skipped) : QString()) << Qt::endl;
    return ExitOk;
}

int saveValueToFile(Context &c, DataType type, const QVariant &raw)
{
    QByteArray bytes;
    if (raw.typeId() == QMetaType::QByteArray)
        bytes = raw.toByteArray();
    else if (raw.typeId() == QMetaType::QString)
        bytes = raw.toString().toUtf8();
    else if (auto encoded = codec::encode(type, raw))
        bytes = encoded.value();
    else
        return fail(c, encoded.error());
    db::files::removeStaleTemporaries(c.file); // what a killed writer left
    QSaveFile file(c.file);
    if (!file.open(QIODevice::WriteOnly) || file.write(bytes) != bytes.size() || !file.commit())
        return fail(
            c,
            Error(Error::Kind::Io, Tr::tr("cannot write %1: %2").arg(c.file, file.errorString())));
    if (c.options.verbose)
        c.out << "wrote " << bytes.size() << " bytes to " << c.file << Qt::endl;
    return ExitOk;
}

Result<QVariant> loadValueFromFile(const Context &c, const ObjectDef *def, DataType type)
{
    const Result<QByteArray> read = files::readAll(c.file, files::kValueLimit, Tr::tr("a value"));
    if (!read)
        return read.error();
    const QByteArray &bytes = *read;
    if (!def && c.type.isEmpty())
        return QVariant(bytes); // unknown object: the bytes as they are
    if (type == DataType::VisibleString || type == DataType::UnicodeString)
        return QVariant(QString::fromUtf8(bytes));
    if (datatype::isVariableLength(type))
        return QVariant(bytes);
    return codec::decode(type, bytes);
}

} // namespace db::cli
