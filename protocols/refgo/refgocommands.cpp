// The typed calls of RefgoClient (one per command of movingcap.md 3.3) and the decoders that
// turn result lines into values. The engine lives in refgoclient.cpp.

#include "refgoclient.h"
#include <QCoreApplication>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::refgo)
};
} // namespace

namespace db::refgo {

namespace {

Error malformed(const QString &command, const QString &what)
{
    return Error(Error::Kind::Malformed, Tr::tr("answer to '%1' %2").arg(command, what));
}

// Integer, Hex32 and ObjectRead answers have exactly one result line (spec 3.3).
Result<QString> singleLine(const QString &command, const QStringList &lines)
{
    if (lines.size() != 1)
        return malformed(command,
                         Tr::tr("has %1 result lines, expected one: %2")
                             .arg(lines.size())
                             .arg(lines.join(QLatin1String(" / "))));
    return lines.first();
}

// The value field of an OR result line looks like a number but is not one: a control character
// inside it, or digits beyond 64 bits. That is a broken answer; a missing field or a word
// ("none") is the drive's way to give no value (spec 3.7 [R]).
bool isBrokenNumber(const QString &line)
{
    const QString field = line.section(QLatin1Char(','), 2).trimmed();
    if (field.isEmpty())
        return false;
    bool numeric = true;
    for (const QChar c : field) {
        if (c.unicode() < 0x20 || c.unicode() == 0x7F)
            return true;
        numeric = numeric && QStringLiteral("0123456789abcdefABCDEF+-xXhH").contains(c);
    }
    return numeric;
}

Result<QVariant> decodeNone(const QString &, const QStringList &)
{
    return QVariant();
}

Result<QVariant> decodeInteger(const QString &command, const QStringList &lines, bool asBool)
{
    const auto line = singleLine(command, lines);
    if (!line)
        return line.error();
    const auto n = parseNumber(line.value());
    if (!n)
        return malformed(command, Tr::tr("is not a number: %1").arg(n.error().message()));
    if (asBool) // TI: 0 or 1 (spec 3.3)
        return QVariant(n.value() != 0);
    return QVariant::fromValue<qlonglong>(n.value());
}

} // namespace

Reply *RefgoClient::send(Command command, std::optional<qint64> argument)
{
    const CommandInfo &ci = info(command);
    const QString name = QLatin1String(ci.mnemonic);
    QString problem;
    if (ci.parameter == Parameter::Object)
        problem = Tr::tr("use objectRead()/objectWrite() for %1").arg(name);
    else if (ci.parameter == Parameter::None && argument)
        problem = Tr::tr("%1 takes no parameter").arg(name);
    else if (ci.parameter == Parameter::Required && !argument)
        problem = Tr::tr("%1 needs a parameter").arg(name);
    if (!problem.isEmpty())
        return Reply::failed({}, Error(Error::Kind::InvalidArgument, problem));

    const QString text = format(command, argument);
    switch (command) {
    case Command::TPSR:
        return enqueue(text, [](const QString &sent, const QStringList &lines) -> Result<QVariant> {
            const auto line = singleLine(sent, lines);
            if (!line)
                return line.error();
            const auto status = parseTpsr(line.value());
            if (!status)
                return malformed(sent, status.error().message());
            return QVariant::fromValue<quint32>(status->raw);
        });
    case Command::TS:
        return enqueue(text, [](const QString &sent, const QStringList &lines) -> Result<QVariant> {
            const auto v = decodeInteger(sent, lines, false);
            if (!v)
                return v;
            return QVariant(int(v.value().toLongLong()));
        });
    case Command::TP:
        return enqueue(text, [](const QString &sent, const QStringList &lines) {
            return decodeInteger(sent, lines, false);
        });
    case Command::TI:
        return enqueue(text, [](const QString &sent, const QStringList &lines) {
            return decodeInteger(sent, lines, true);
        });
    default:
        return enqueue(text, decodeNone);
    }
}

Reply *RefgoClient::go(std::optional<qint64> position)
{
    return send(Command::G, position);
}
Reply *RefgoClient::goWay(std::optional<qint64> distance)
{
    return send(Command::GW, distance);
}
Reply *RefgoClient::setTargetPosition(qint64 position)
{
    return send(Command::PO, position);
}
Reply *RefgoClient::setWay(qint64 distance)
{
    return send(Command::WA, distance);
}
Reply *RefgoClient::stopMotion()
{
    return send(Command::SM);
}
Reply *RefgoClient::powerContinue()
{
    return send(Command::PWC);
}
Reply *RefgoClient::continueMotion()
{
    return send(Command::CM);
}
Reply *RefgoClient::reference(int method)
{
    return send(Command::REF, method);
}
Reply *RefgoClient::powerQuit()
{
    return send(Command::PQ);
}
Reply *RefgoClient::speed(qint64 velocity)
{
    return send(Command::SP, velocity);
}
Reply *RefgoClient::acceleration(qint64 value)
{
    return send(Command::AC, value);
}
Reply *RefgoClient::deceleration(qint64 value)
{
    return send(Command::DE, value);
}
Reply *RefgoClient::jerk(qint64 value)
{
    return send(Command::ACV, value);
}
Reply *RefgoClient::jogPositive(std::optional<qint64> ms)
{
    return send(Command::JP, ms);
}
Reply *RefgoClient::jogNegative(std::optional<qint64> ms)
{
    return send(Command::JN, ms);
}
Reply *RefgoClient::repeatReverse(std::optional<qint64> d)
{
    return send(Command::RR, d);
}
Reply *RefgoClient::repeatWay(qint64 distance)
{
    return send(Command::RW, distance);
}
Reply *RefgoClient::waitRepeat(qint64 ms)
{
    return send(Command::WT, ms);
}
Reply *RefgoClient::setOutput(int output)
{
    return send(Command::SO, output);
}
Reply *RefgoClient::clearOutput(int output)
{
    return send(Command::CO, output);
}
Reply *RefgoClient::tellProcessStatus()
{
    return send(Command::TPSR);
}
Reply *RefgoClient::tellStatus()
{
    return send(Command::TS);
}
Reply *RefgoClient::tellPosition()
{
    return send(Command::TP);
}
Reply *RefgoClient::tellInput(int input)
{
    return send(Command::TI, input);
}

Reply *RefgoClient::objectRead(ObjectAddress address, bool hexOutput)
{
    return enqueue(formatRead(address, hexOutput), objectReadDecoder(address), address);
}

void RefgoClient::objectRead(ObjectAddress address, Completion done, bool hexOutput)
{
    enqueue(formatRead(address, hexOutput), objectReadDecoder(address), std::move(done));
}

RefgoClient::Decoder RefgoClient::objectReadDecoder(ObjectAddress address)
{
    return [address](const QString &sent, const QStringList &lines) -> Result<QVariant> {
        // Spec 3.7 [R]: an OR answer without a numeric value field is a failure.
        if (lines.isEmpty())
            return Error(Error::Kind::DeviceError,
                         Tr::tr("drive gave no value for '%1'").arg(sent));
        const auto line = singleLine(sent, lines);
        if (!line)
            return line.error();
        const auto value = parseObjectRead(line.value());
        if (!value && isBrokenNumber(line.value()))
            return malformed(sent, value.error().message());
        if (!value)
            return Error(
                Error::Kind::DeviceError,
                Tr::tr("drive gave no value for '%1': %2").arg(sent, value.error().message()));
        if (value->address != address)
            return malformed(
                sent, Tr::tr("names object %1: '%2'").arg(value->address.toString(), line.value()));
        return QVariant::fromValue<qlonglong>(value->value);
    };
}

Reply *RefgoClient::objectWrite(ObjectAddress address, const QVariant &value)
{
    switch (value.typeId()) {
    case QMetaType::Bool:
    case QMetaType::LongLong:
    case QMetaType::ULongLong:
    case QMetaType::Long:
    case QMetaType::ULong:
    case QMetaType::Int:
    case QMetaType::UInt:
    case QMetaType::Short:
    case QMetaType::UShort:
    case QMetaType::Char:
    case QMetaType::SChar:
    case QMetaType::UChar:
        break;
    default:
        return Reply::failed(address,
                             Error(Error::Kind::InvalidArgument,
                                   Tr::tr("OW writes integers only, not %1 '%2'")
                                       .arg(QLatin1String(value.typeName()), value.toString())));
    }
    const QString text = formatWrite(address, value);
    return enqueue(
        text,
        [](const QString &sent, const QStringList &lines) -> Result<QVariant> {
            // Spec 3.7 [R]: every OW result line must end in ",OK" (and there must be one).
            const bool acknowledged = !lines.isEmpty()
                && std::all_of(lines.begin(), lines.end(), [](const QString &line) {
                       return line.trimmed().endsWith(QLatin1String(",OK"), Qt::CaseInsensitive);
                   });
            if (!acknowledged)
                return Error(Error::Kind::DeviceError,
                             Tr::tr("drive did not acknowledge '%1' with ',OK': %2")
                                 .arg(sent,
                                      lines.isEmpty() ? QStringLiteral("(no result)")
                                                      : lines.join(QLatin1String(" / "))));
            return QVariant();
        },
        address);
}

} // namespace db::refgo
