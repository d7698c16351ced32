#include "commands.h"
#include "commands_canopen.h"
#include "commands_description.h"
#include "commands_morse.h"
#include "commands_motion.h"
#include "commands_nm17x.h"
#include "commands_params.h"
#include "commands_record.h"

#include "canopen/canopenconnection.h"
#include "canopen/descriptionnote.h"
#include "core/printable.h"
#include "core/valuecodec.h"
#include <QCoreApplication>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(cli)
};
} // namespace

namespace db::cli {

int fail(Context &context, const Error &error)
{
    context.err << "drivebench-cli: " << error.toString() << Qt::endl;
    return exitCodeFor(error);
}

namespace {

int listProtocols(Context &c)
{
    // scheme, URI form and title, in aligned columns
    qsizetype schemeWidth = 0;
    qsizetype patternWidth = 0;
    for (const ProtocolInfo &p : c.registry.protocols()) {
        schemeWidth = qMax(schemeWidth, p.scheme.size());
        patternWidth = qMax(patternWidth, p.uriPattern.size());
    }
    for (const ProtocolInfo &p : c.registry.protocols()) {
        c.out << p.scheme.leftJustified(schemeWidth + 2)
              << p.uriPattern.leftJustified(patternWidth + 2) << p.title;
        if (p.defaultPort >= 0)
            c.out << Tr::tr(" (default port %1)").arg(p.defaultPort);
        const AddressFormat &format = p.addressFormat ? *p.addressFormat : AddressFormat::canopen();
        c.out << Tr::tr(", addresses like %1").arg(format.example());
        c.out << Qt::endl;
    }
    return ExitOk;
}

// The type for text conversion: the description's, else --type, else a 64-bit integer.
Result<DataType> typeFor(Context &c, const ObjectDef *def)
{
    if (def)
        return def->type;
    if (c.type.isEmpty())
        return DataType::Integer64;
    const auto t = datatype::fromName(c.type);
    if (!t)
        return Error(Error::Kind::InvalidArgument,
                     Tr::tr("unknown type '%1' (e.g. u16, i32, UNSIGNED8, REAL32)").arg(c.type));
    return *t;
}

// The object named by args[1] on the device of args[0], with what the description says of it.
struct ObjectTarget
{
    ObjectAddress address;
    const ObjectDef *def = nullptr; // null for objects the description does not know
    DataType type = DataType::Integer64;
};

Result<ObjectTarget> openObject(Context &c, Session &session)
{
    const auto address = parseAddressFor(c.registry, c.args.value(0), c.args.value(1));
    if (!address)
        return address.error();
    if (auto opened = session.open(c.args.at(0)); !opened)
        return opened.error();
    ObjectTarget target;
    target.address = *address;
    DeviceConnection *connection = session.connection();
    target.def = connection->dictionary().find(*address);
    const auto type = typeFor(c, target.def);
    if (!type)
        return type.error();
    target.type = *type;
    if (!target.def && !c.type.isEmpty()) {
        // --type describes the object for this run, so the connection reads and writes it with
        // that size (a CANopen SDO of 2 bytes for u16, not a guess from the value).
        ObjectDictionary dictionary = connection->dictionary();
        ObjectDef def;
        def.address = *address;
        def.name = Tr::tr("(not in the description)");
        def.type = *type;
        dictionary.insert(def);
        connection->setDictionary(dictionary);
        target.def = connection->dictionary().find(*address);
    }
    return target;
}

// A CANopen node without a description: after a read or write by index that worked, one line on
// stderr says why the object was not described (errors stay one line of their own). With --type
// the object was described for the run: nothing to say.
void noteMissingDescription(Context &c, const Session &session, const ObjectTarget &target)
{
    const DeviceConnection *connection = session.connection();
    const QString note = canopen::descriptionNoteOf(connection);
    if (c.type.isEmpty() && !target.def && !note.isEmpty() && connection->dictionary().isEmpty())
        c.err << "drivebench-cli: " << printable(note) << Qt::endl;
}

int read(Context &c)
{
    Session session(c.registry, c.options);
    const auto target = openObject(c, session);
    if (!target)
        return fail(c, target.error());
    const auto value = session.read(target->address);
    if (!value)
        return fail(c,
                    value.error().prefixed(
                        Tr::tr("reading %1").arg(session.addressFormat().format(target->address))));
    if (!c.file.isEmpty())
        return saveValueToFile(c, target->type, value.value());
    const auto format = c.options.hex ? codec::TextFormat::Hex : codec::TextFormat::Decimal;
    QVariant raw = value.value();
    if (!target->def && !c.type.isEmpty()) {
        auto converted = codec::normalize(target->type, raw);
        if (converted)
            raw = converted.value();
    }
    // Bytes of an object nobody described (e.g. a CANopen string without ?eds=): as text.
    QByteArray bytes = raw.toByteArray();
    while (bytes.endsWith('\0'))
        bytes.chop(1);
    // Fixed-point parameters (inverters) print their physical value with its unit: "10.00 Hz".
    const bool physical = target->def && target->def->decimals >= 0
        && datatype::isInteger(target->type) && format == codec::TextFormat::Decimal;
    const QString text = physical ? target->def->displayText(raw, format)
        : !target->def && c.type.isEmpty() && raw.typeId() == QMetaType::QByteArray
        ? QString::fromUtf8(bytes)
        : datatype::isNumeric(target->type) || target->def
        ? codec::toText(target->type, raw, format)
        : raw.toString();
    // Strings come from the device (e.g. 1008h): escaped, so that one value stays one line.
    if (c.options.verbose) {
        c.out << session.addressFormat().format(target->address) << ' '
              << printable(target->def ? target->def->name : Tr::tr("(unknown object)")) << " = "
              << printable(target->def ? target->def->displayText(raw, format) : text) << Qt::endl;
    } else {
        c.out << printable(text) << Qt::endl;
    }
    noteMissingDescription(c, session, target.value());
    return ExitOk;
}

int write(Context &c)
{
    if (c.file.isEmpty() != (c.args.size() == 3))
        return fail(
            c,
            Error(Error::Kind::InvalidArgument, Tr::tr("write takes either VALUE or --file FILE")));
    Session session(c.registry, c.options);
    const auto target = openObject(c, session);
    if (!target)
        return fail(c, target.error());
    const QString valueText = c.args.value(2);
    const auto raw = !c.file.isEmpty() ? loadValueFromFile(c, target->def, target->type)
        : target->def                  ? target->def->parseText(valueText, session.addressFormat())
                                       : codec::fromText(target->type, valueText);
    if (!raw)
        return fail(c, raw.error());
    if (auto written = session.write(target->address, raw.value()); !written)
        return fail(c,
                    written.error().prefixed(
                        Tr::tr("writing %1").arg(session.addressFormat().format(target->address))));
    if (c.options.verbose)
        c.out << session.addressFormat().format(target->address) << " <- "
              << codec::toText(target->type, raw.value()) << " ok" << Qt::endl;
    noteMissingDescription(c, session, target.value());
    return ExitOk;
}

int refgo(Context &c)
{
    Session session(c.registry, c.options);
    if (auto opened = session.open(c.args.at(0)); !opened)
        return fail(c, opened.error());
    DeviceConnection *conn = session.connection();
    if (!conn->capabilities().testFlag(DeviceConnection::Capability::RawCommands))
        return fail(
            c,
            Error(Error::Kind::InvalidArgument,
                  Tr::tr("'refgo' needs a refgo:// URI, not %1").arg(conn->uri().scheme())));
    const auto result = Reply::wait(conn->rawCommand(c.args.at(1)));
    if (!result)
        return fail(c, result.error());
    for (const QString &line : result.value().toStringList())
        c.out << printable(line) << Qt::endl;
    return ExitOk;
}

} // namespace

const QList<Command> &commands()
{
    static const QList<Command> list = {
        { "list-protocols", "", QT_TRANSLATE_NOOP("cli", "list the protocols and their URI forms"),
          0, 0, listProtocols },
        { "read", "URI ADDRESS",
          QT_TRANSLATE_NOOP(
              "cli",
              "read one object, e.g. read refgo://192.168.2.150 6041:0 (ADDRESS as the protocol "
              "writes it: list-protocols shows an example)"),
          2, 2, read },
        { "write", "URI ADDRESS VALUE|--file FILE",
          QT_TRANSLATE_NOOP("cli", "write one object, e.g. write refgo://HOST 6083:0 2000"), 2, 3,
          write },
        { "refgo", "URI COMMAND",
          QT_TRANSLATE_NOOP("cli", "send one RefGo command and print its result lines, e.g. TP"), 2,
          2, refgo },
        { "scan", "URI",
          QT_TRANSLATE_NOOP("cli", "list the CANopen nodes on the bus of URI (no ?node= needed)"),
          1, 1, scan },
        { "nmt", "URI start|stop|preop|reset|reset-comm [--all]",
          QT_TRANSLATE_NOOP("cli", "NMT command to the URI's node, or to every node with --all"), 2,
          2, nmt },
        { "lss",
          "URI inquire|switch-global|switch-selective V,P,R,S|set-node N|set-bitrate B|"
          "store|fastscan",
          QT_TRANSLATE_NOOP("cli", "CiA 305 layer setting services"), 2, 3, lss },
        { "pdo", "URI", QT_TRANSLATE_NOOP("cli", "print the node's PDO configuration"), 1, 1, pdo },
        { "nm17x",
          "URI list | scan [--bitrates B,B] | setpoint NODE MM [--release] [--direct] "
          "[--plunge S] [--correction MM] | "
          "jog NODE left|right --speed S | stop NODE|all | broadcast unit mm|inch|show-id|"
          "preset MM|start GROUP|stop | address --broadcast FIRST [--count N] | control NODE "
          "WORD | watch [--seconds S] | oscillate NODE start|stop",
          QT_TRANSLATE_NOOP(
              "cli", "Baumer NM170/NM172/NM174 displays on the bus of URI (S: slow, medium, fast)"),
          2, 4, nm17x, nm17xOptions },
        { "dcf", "URI -o FILE",
          QT_TRANSLATE_NOOP("cli", "write a DCF of the device's current values (?eds= needed)"), 1,
          1, dcf },
        { "eds-check", "FILE",
          QT_TRANSLATE_NOOP("cli", "check an EDS/DCF/XDD/XDC file: summary and warnings"), 1, 1,
          edsCheck },
        { "backup", "URI -o FILE",
          QT_TRANSLATE_NOOP("cli", "save every storable object of the device to a parameter set"),
          1, 1, backup, paramsOptions },
        { "restore", "URI FILE [--only ADDRESS,...] [--store] [--no-verify]",
          QT_TRANSLATE_NOOP(
              "cli",
              "write a parameter set (or its selected rows) safely, verify, optionally store"),
          2, 2, restore, paramsOptions },
        { "diff", "A B",
          QT_TRANSLATE_NOOP(
              "cli", "compare two parameter sets, each a URI or a file; exit 1 if they differ"),
          2, 2, diff, paramsOptions },
        { "dump", "URI", QT_TRANSLATE_NOOP("cli", "print every readable object with its value"), 1,
          1, dump, paramsOptions },
        { "morse", "FILE [X,Y,W,H]",
          QT_TRANSLATE_NOOP("cli", "decode the LED Morse IP from a video or a CSV of samples"), 1,
          2, morse },
        { "enable", "URI",
          QT_TRANSLATE_NOOP("cli", "enable the drive (MC_Power on); prints the axis state"), 1, 1,
          enable, motionOptions },
        { "disable", "URI", QT_TRANSLATE_NOOP("cli", "disable the drive (MC_Power off)"), 1, 1,
          disable, motionOptions },
        { "reset", "URI", QT_TRANSLATE_NOOP("cli", "fault reset (MC_Reset)"), 1, 1, reset,
          motionOptions },
        { "home", "URI METHOD [--vel V --acc A]",
          QT_TRANSLATE_NOOP("cli",
                            "home with the drive's homing method number, e.g. 35; prints "
                            "the position"),
          2, 2, home, motionOptions },
        { "move", "URI --abs|--rel|--add VALUE [--vel V --acc A --dec D]",
          QT_TRANSLATE_NOOP("cli", "move and wait for Done; prints the final actual position"), 1,
          1, move, motionOptions },
        { "jog", "URI --vel V --time MS",
          QT_TRANSLATE_NOOP("cli", "jog at V for MS ms, then halt; prints the position"), 1, 1, jog,
          motionOptions },
        { "velocity", "URI --vel V --time MS [--acc A --dec D]",
          QT_TRANSLATE_NOOP("cli",
                            "run the drive's velocity mode at V for MS ms, then halt; prints the "
                            "position"),
          1, 1, velocity, motionOptions },
        { "halt", "URI [--dec D]",
          QT_TRANSLATE_NOOP("cli", "brake to standstill (MC_Halt); prints the position"), 1, 1,
          halt, motionOptions },
        { "stop", "URI [--dec D]",
          QT_TRANSLATE_NOOP("cli",
                            "stop (MC_Stop: nothing else starts until standstill); prints the "
                            "position"),
          1, 1, stop, motionOptions },
        { "travel", "URI BLOCK [--sequence] [--resume]",
          QT_TRANSLATE_NOOP("cli",
                            "run a motion block of the drive's table (or the sequence it "
                            "starts) to its end; prints the position"),
          2, 2, travel, motionOptions },
        { "gear", "URI --ratio N:D --time MS [--acc A --dec D] | URI --out [--dec D]",
          QT_TRANSLATE_NOOP("cli",
                            "couple the axis to its master at N:D (electronic gear) for MS ms, "
                            "then uncouple; --out uncouples a running gear"),
          1, 1, gear, gearOptions },
        { "record",
          "URI --obj INDEX:SUB [--obj ...] --duration S [--rate-ms R] [--trigger SPEC] "
          "[--pdo | --configure-tpdo N [--event-ms MS]] -o FILE",
          QT_TRANSLATE_NOOP(
              "cli", "record objects (host polling or CANopen PDOs) to CSV, optionally triggered"),
          1, 1, record, recordOptions },
    };
    return list;
}

} // namespace db::cli
