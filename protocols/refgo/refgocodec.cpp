#include "refgocodec.h"

#include <QCoreApplication>
#include <limits>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::refgo)
};
} // namespace

namespace db::refgo {

namespace {

Error invalid(const QString &message)
{
    return Error(Error::Kind::InvalidArgument, message);
}

// The command table of movingcap.md 3.3, in the order of enum Command (info() indexes it).
const QList<CommandInfo> kCommands = {
    { Command::G, "G", Parameter::Optional, ResultKind::None, "Go Direct Position" },
    { Command::GW, "GW", Parameter::Optional, ResultKind::None, "Go Way" },
    { Command::PO, "PO", Parameter::Required, ResultKind::None, "Set Target Position" },
    { Command::WA, "WA", Parameter::Required, ResultKind::None, "Set Way" },
    { Command::SM, "SM", Parameter::None, ResultKind::None, "Stop Motion" },
    { Command::PWC, "PWC", Parameter::None, ResultKind::None, "Power Continue" },
    { Command::CM, "CM", Parameter::None, ResultKind::None, "Continue Motion" },
    { Command::REF, "REF", Parameter::Optional, ResultKind::None, "Referencing" },
    { Command::PQ, "PQ", Parameter::None, ResultKind::None, "Power Quit" },
    { Command::OW, "OW", Parameter::Object, ResultKind::ObjectWrite, "CANopen Object Write" },
    { Command::OR, "OR", Parameter::Object, ResultKind::ObjectRead, "CANopen Object Read" },
    { Command::TPSR, "TPSR", Parameter::None, ResultKind::Hex32, "Tell Process Status Register" },
    { Command::TS, "TS", Parameter::None, ResultKind::Integer, "Tell Status" },
    { Command::TP, "TP", Parameter::None, ResultKind::Integer, "Tell Actual Position" },
    { Command::SP, "SP", Parameter::Required, ResultKind::None, "Speed" },
    { Command::AC, "AC", Parameter::Required, ResultKind::None, "Acceleration" },
    { Command::DE, "DE", Parameter::Required, ResultKind::None, "Deceleration" },
    { Command::ACV, "ACV", Parameter::Required, ResultKind::None, "Acceleration Variation (Jerk)" },
    { Command::JP, "JP", Parameter::Optional, ResultKind::None, "Jog Positive" },
    { Command::JN, "JN", Parameter::Optional, ResultKind::None, "Jog Negative" },
    { Command::RR, "RR", Parameter::Optional, ResultKind::None, "Repeat Reverse" },
    { Command::RW, "RW", Parameter::Required, ResultKind::None, "Repeat Way" },
    { Command::WT, "WT", Parameter::Required, ResultKind::None, "Wait Repeat" },
    { Command::SO, "SO", Parameter::Required, ResultKind::None, "Set Output" },
    { Command::CO, "CO", Parameter::Required, ResultKind::None, "Clear Output" },
    { Command::TI, "TI", Parameter::Required, ResultKind::Integer, "Tell Input" },
};

const CommandInfo *findMnemonic(const QString &mnemonic)
{
    for (const CommandInfo &c : kCommands) {
        if (mnemonic == QLatin1String(c.mnemonic))
            return &c;
    }
    return nullptr;
}

bool isLetter(QChar c)
{
    return (c >= QLatin1Char('A') && c <= QLatin1Char('Z'))
        || (c >= QLatin1Char('a') && c <= QLatin1Char('z'));
}

bool endsWithH(QStringView text)
{
    return text.endsWith(QLatin1Char('h'), Qt::CaseInsensitive);
}

// A number as written in RefGo text (spec 3.2): signed decimal, "0x" hex, or hex with an "h"
// suffix (the drive's hex output, errata 13/14).
struct ScannedNumber
{
    qulonglong magnitude = 0;
    bool negative = false;
    bool hex = false;
};

Result<ScannedNumber> scanNumber(QStringView original)
{
    QStringView t = original.trimmed();
    ScannedNumber n;
    if (t.startsWith(QLatin1Char('-')) || t.startsWith(QLatin1Char('+'))) {
        n.negative = t.front() == QLatin1Char('-');
        t = t.mid(1);
    }
    if (t.startsWith(QLatin1String("0x"), Qt::CaseInsensitive)) {
        n.hex = true;
        t = t.mid(2);
    } else if (endsWithH(t)) {
        n.hex = true;
        t.chop(1);
    }
    if (t.isEmpty())
        return invalid(Tr::tr("'%1' is not a number").arg(original.toString()));
    for (QChar c : t) {
        const bool digit = c >= QLatin1Char('0') && c <= QLatin1Char('9');
        const bool hexLetter = (c >= QLatin1Char('a') && c <= QLatin1Char('f'))
            || (c >= QLatin1Char('A') && c <= QLatin1Char('F'));
        if (!digit && !(n.hex && hexLetter))
            return invalid(Tr::tr("'%1' is not a number").arg(original.toString()));
    }
    bool ok = false;
    n.magnitude = t.toULongLong(&ok, n.hex ? 16 : 10);
    if (!ok)
        return invalid(Tr::tr("'%1' is too large").arg(original.toString()));
    return n;
}

// Index or sub-index field: hexadecimal, with or without "h" suffix or "0x" prefix (spec 3.2).
Result<quint32> parseHexField(QStringView field, quint32 max, const QString &what)
{
    QStringView t = field.trimmed();
    if (t.startsWith(QLatin1String("0x"), Qt::CaseInsensitive))
        t = t.mid(2);
    else if (endsWithH(t))
        t.chop(1);
    if (t.isEmpty())
        return invalid(Tr::tr("missing %1").arg(what));
    bool ok = false;
    const qulonglong v = t.toULongLong(&ok, 16);
    if (!ok || t.startsWith(QLatin1Char('+')) || t.startsWith(QLatin1Char('-')))
        return invalid(Tr::tr("%1 '%2' is not hexadecimal").arg(what, field.trimmed().toString()));
    if (v > max)
        return invalid(Tr::tr("%1 '%2' is too large").arg(what, field.trimmed().toString()));
    return quint32(v);
}

Result<ObjectAddress> parseAddress(QStringView indexField, QStringView subField)
{
    const auto index = parseHexField(indexField, 0xFFFF, QStringLiteral("index"));
    if (!index)
        return index.error();
    const auto sub = parseHexField(subField, 0xFF, QStringLiteral("sub-index"));
    if (!sub)
        return sub.error();
    return ObjectAddress(quint16(index.value()), quint8(sub.value()));
}

// OR/OW parameters "index,sub[,h]" and "index,sub,value" (spec 3.2, errata 15/16).
Result<void> parseObjectParameters(Request &r, const QString &rest)
{
    const bool write = r.command == Command::OW;
    const QStringList fields = rest.split(QLatin1Char(','));
    if (write ? fields.size() != 3 : (fields.size() < 2 || fields.size() > 3)) {
        return invalid(write ? QStringLiteral("OW needs index,sub-index,value")
                             : QStringLiteral("OR needs index,sub-index[,h]"));
    }
    const auto address = parseAddress(fields.at(0), fields.at(1));
    if (!address)
        return address.error();
    r.address = address.value();
    if (write) {
        const auto n = scanNumber(fields.at(2));
        if (!n)
            return n.error();
        const ScannedNumber v = n.value();
        const auto signedMax = qulonglong(std::numeric_limits<qint64>::max());
        if (v.negative) {
            if (v.magnitude > signedMax + 1)
                return invalid(Tr::tr("value '%1' is too small").arg(fields.at(2)));
            r.value = QVariant::fromValue<qlonglong>(qlonglong(0 - v.magnitude));
        } else if (v.hex || v.magnitude > signedMax) {
            r.value = QVariant::fromValue<qulonglong>(v.magnitude);
        } else {
            r.value = QVariant::fromValue<qlonglong>(qlonglong(v.magnitude));
        }
        return {};
    }
    if (fields.size() == 3) {
        if (fields.at(2).trimmed().compare(QLatin1String("h"), Qt::CaseInsensitive) != 0)
            return invalid(Tr::tr("third OR field must be 'h' (hex output), not '%1'")
                               .arg(fields.at(2).trimmed()));
        r.hexOutput = true;
    } else {
        // Erratum 15: "OR6041,0h" asks for hex output. When the index carries an "h" too
        // ("OR3410h,1h", Appendix C), the suffixes only mark the radix: the drive answered
        // that form in decimal.
        r.hexOutput = endsWithH(fields.at(1).trimmed()) && !endsWithH(fields.at(0).trimmed());
    }
    return {};
}

} // namespace

const QList<CommandInfo> &commands()
{
    return kCommands;
}

const CommandInfo &info(Command command)
{
    return kCommands.at(qsizetype(command));
}

QString format(Command command, std::optional<qint64> argument)
{
    QString text = QLatin1String(info(command).mnemonic);
    if (argument)
        text += QString::number(*argument);
    return text;
}

QString formatRead(ObjectAddress address, bool hexOutput)
{
    // Written digit by digit: this runs for every object read, and QString::arg would
    // allocate three strings.
    static constexpr char kDigits[] = "0123456789ABCDEF";
    char text[12] = { 'O', 'R' };
    qsizetype n = 2;
    for (int shift = 12; shift >= 0; shift -= 4)
        text[n++] = kDigits[(address.index >> shift) & 0xF];
    text[n++] = ',';
    if (address.sub > 0xF)
        text[n++] = kDigits[address.sub >> 4];
    text[n++] = kDigits[address.sub & 0xF];
    if (hexOutput) {
        text[n++] = ',';
        text[n++] = 'h';
    }
    return QString::fromLatin1(text, n);
}

QString formatWrite(ObjectAddress address, const QVariant &value)
{
    QString number;
    switch (value.typeId()) {
    case QMetaType::Bool:
        number = value.toBool() ? QStringLiteral("1") : QStringLiteral("0");
        break;
    case QMetaType::ULongLong:
    case QMetaType::ULong:
    case QMetaType::UInt:
    case QMetaType::UShort:
    case QMetaType::UChar:
        number = QString::number(value.toULongLong());
        break;
    case QMetaType::LongLong:
    case QMetaType::Long:
    case QMetaType::Int:
    case QMetaType::Short:
    case QMetaType::Char:
    case QMetaType::SChar:
        number = QString::number(value.toLongLong());
        break;
    default:
        number = value.toString();
        break; // callers check types; keeps text visible
    }
    return QStringLiteral("OW%1,%2,%3")
        .arg(QString::number(address.index, 16).rightJustified(4, QLatin1Char('0')).toUpper(),
             QString::number(address.sub, 16).toUpper(), number);
}

Result<Request> parseRequest(const QString &line)
{
    Request r;
    r.text = line;
    const QString t = line.trimmed();
    if (t.isEmpty())
        return invalid(Tr::tr("empty request"));
    qsizetype n = 0;
    while (n < t.size() && isLetter(t.at(n)))
        ++n;
    if (n == 0)
        return invalid(Tr::tr("'%1' does not start with a command").arg(t));
    const QString letters = t.left(n).toUpper();
    const CommandInfo *ci = findMnemonic(letters);
    if (!ci
        && (letters.startsWith(QLatin1String("OR")) || letters.startsWith(QLatin1String("OW")))) {
        ci = findMnemonic(letters.left(2)); // index starting with a hex letter: "ORA000,0"
        n = 2;
    }
    if (!ci)
        return invalid(Tr::tr("unknown command '%1'").arg(letters));
    r.command = ci->command;
    const QString rest = t.mid(n).trimmed(); // a space after the mnemonic is fine (erratum 16)
    const QString name = QLatin1String(ci->mnemonic);
    switch (ci->parameter) {
    case Parameter::None:
        if (!rest.isEmpty())
            return invalid(Tr::tr("%1 takes no parameter, got '%2'").arg(name, rest));
        break;
    case Parameter::Required:
    case Parameter::Optional: {
        if (rest.isEmpty()) {
            if (ci->parameter == Parameter::Required)
                return invalid(Tr::tr("%1 needs a numeric parameter").arg(name));
            break;
        }
        const auto v = parseNumber(rest);
        if (!v)
            return v.error().prefixed(name);
        r.argument = v.value();
        break;
    }
    case Parameter::Object:
        if (const auto ok = parseObjectParameters(r, rest); !ok)
            return ok.error().prefixed(name);
        break;
    }
    return r;
}

namespace {

Result<qint64> parseNumberView(QStringView text)
{
    const auto n = scanNumber(text);
    if (!n)
        return n.error();
    const ScannedNumber v = n.value();
    const auto signedMax = qulonglong(std::numeric_limits<qint64>::max());
    if (v.negative) {
        if (v.magnitude > signedMax + 1)
            return invalid(Tr::tr("'%1' is too small").arg(text.trimmed().toString()));
        return qint64(0 - v.magnitude);
    }
    if (!v.hex && v.magnitude > signedMax)
        return invalid(Tr::tr("'%1' is too large").arg(text.trimmed().toString()));
    return qint64(v.magnitude); // hex: the unsigned bit pattern
}

} // namespace

Result<qint64> parseNumber(const QString &text)
{
    return parseNumberView(text);
}

namespace {

// Digits of `text` from `pos` up to `stop` (or the end) in base 16 or 10, at most maxDigits of
// them; the position after them, or -1 when there are none, too many, or another character.
qsizetype scanDigits(QStringView text, qsizetype pos, char16_t stop, int base, int maxDigits,
                     quint64 &value)
{
    value = 0;
    const qsizetype start = pos;
    for (; pos < text.size() && text[pos].unicode() != stop; ++pos) {
        const char16_t c = text[pos].unicode();
        unsigned digit;
        if (c >= u'0' && c <= u'9')
            digit = c - u'0';
        else if (base == 16 && c >= u'A' && c <= u'F')
            digit = c - u'A' + 10;
        else if (base == 16 && c >= u'a' && c <= u'f')
            digit = c - u'a' + 10;
        else
            return -1;
        value = value * unsigned(base) + digit;
    }
    const qsizetype digits = pos - start;
    return digits == 0 || digits > maxDigits ? -1 : pos;
}

// The drive's own form of an OR result line, "OR6041,0,1591" or "OR6041,0,427h", read without
// the general parser's string work: it comes once for every object read. False for anything
// else (spaces, prefixes, signs on hex, more digits), which the general parser then reads.
bool parseCanonicalObjectRead(QStringView t, ObjectValue &out)
{
    if (t.size() < 7 || t[0] != u'O' || t[1] != u'R')
        return false;
    quint64 index = 0;
    quint64 sub = 0;
    quint64 magnitude = 0;
    qsizetype pos = scanDigits(t, 2, u',', 16, 4, index);
    if (pos < 0 || pos == t.size())
        return false;
    pos = scanDigits(t, pos + 1, u',', 16, 2, sub);
    if (pos < 0 || ++pos >= t.size())
        return false;
    const bool hex = t.back() == u'h' || t.back() == u'H';
    if (hex) {
        if (scanDigits(t.first(t.size() - 1), pos, u',', 16, 16, magnitude) != t.size() - 1)
            return false;
        out = { ObjectAddress(quint16(index), quint8(sub)), qint64(magnitude), true };
        return true;
    }
    const bool negative = t[pos] == u'-';
    if (scanDigits(t, negative ? pos + 1 : pos, u',', 10, 18, magnitude) != t.size())
        return false;
    const qint64 value = qint64(magnitude); // 18 digits always fit
    out = { ObjectAddress(quint16(index), quint8(sub)), negative ? -value : value, false };
    return true;
}

} // namespace

// Fields are views into the line, not copies: this runs once for every object read.
Result<ObjectValue> parseObjectRead(const QString &line)
{
    if (ObjectValue canonical; parseCanonicalObjectRead(line, canonical))
        return canonical;
    const QStringView t = QStringView(line).trimmed();
    if (!t.startsWith(QLatin1String("OR"), Qt::CaseInsensitive))
        return invalid(Tr::tr("'%1' is not an OR result line").arg(t.toString()));
    const QStringView fields = t.sliced(2);
    const qsizetype first = fields.indexOf(QLatin1Char(','));
    const qsizetype second = first < 0 ? -1 : fields.indexOf(QLatin1Char(','), first + 1);
    const qsizetype third = second < 0 ? -1 : fields.indexOf(QLatin1Char(','), second + 1);
    const QStringView valueField = second < 0
        ? QStringView()
        : fields.sliced(second + 1, (third < 0 ? fields.size() : third) - second - 1);
    const QStringView v = valueField.trimmed();
    if (v.isEmpty())
        return invalid(Tr::tr("'%1' has no value field").arg(t.toString()));
    if (third >= 0)
        return invalid(Tr::tr("'%1' has more than three fields").arg(t.toString()));
    const auto address =
        parseAddress(fields.first(first), fields.sliced(first + 1, second - first - 1));
    if (!address)
        return address.error().prefixed(t.toString());
    const auto value = parseNumberView(valueField);
    if (!value)
        return value.error().prefixed(t.toString());
    return ObjectValue { address.value(), value.value(),
                         endsWithH(v) || v.contains(QLatin1String("0x"), Qt::CaseInsensitive) };
}

Result<ProcessStatus> parseTpsr(const QString &line)
{
    const QString t = line.trimmed();
    bool ok = t.size() == 8;
    const quint32 bits = ok ? t.toUInt(&ok, 16) : 0;
    if (!ok || t.startsWith(QLatin1Char('+')) || t.startsWith(QLatin1Char('-')))
        return invalid(Tr::tr("TPSR answer '%1' is not 8 hex digits").arg(t));
    return ProcessStatus { bits };
}

QString formatTpsr(quint32 bits)
{
    return QStringLiteral("%1").arg(bits, 8, 16, QLatin1Char('0'));
}

Result<SimpleStatus> parseTs(const QString &line)
{
    const QString t = line.trimmed();
    bool ok = false;
    const int v = t.toInt(&ok, 10);
    if (ok && (v == 0 || v == 1 || v == 2 || v == 9))
        return SimpleStatus(v);
    return invalid(Tr::tr("TS answer '%1' is not 0, 1, 2 or 9").arg(t));
}

QString simpleStatusName(SimpleStatus status)
{
    switch (status) {
    case SimpleStatus::PowerOff:
        return QStringLiteral("Power Off");
    case SimpleStatus::PowerOn:
        return QStringLiteral("Power On");
    case SimpleStatus::Moving:
        return QStringLiteral("Moving");
    case SimpleStatus::Error:
        return QStringLiteral("Error");
    }
    return QStringLiteral("unknown (%1)").arg(int(status));
}

} // namespace db::refgo
