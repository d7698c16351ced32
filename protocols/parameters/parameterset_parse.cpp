// Reading the parameter-set text format (format described in parameterset.h). Every error names
// the origin and the line, so a user can open the file and see what is wrong.

#include "parameterset.h"

#include <QSet>

#include <QCoreApplication>
#include <algorithm>
#include <cctype>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::core)
};
} // namespace

namespace db {

namespace {

constexpr auto kMagic = "# drivebench parameter set";

struct Token
{
    QString text;
    bool quoted = false;
};

// Splits a line into bare words and "quoted strings" (with \" \\ \n \r \t \xNN \uNNNN
// escapes).
Result<QList<Token>> tokenize(const QString &line)
{
    QList<Token> tokens;
    qsizetype i = 0;
    const qsizetype n = line.size();
    while (i < n) {
        if (line.at(i).isSpace()) {
            ++i;
            continue;
        }
        Token token;
        if (line.at(i) == QLatin1Char('"')) {
            token.quoted = true;
            ++i;
            bool closed = false;
            while (i < n) {
                const QChar c = line.at(i++);
                if (c == QLatin1Char('"')) {
                    closed = true;
                    break;
                }
                if (c != QLatin1Char('\\')) {
                    token.text += c;
                    continue;
                }
                if (i >= n)
                    break;
                const QChar e = line.at(i++);
                switch (e.unicode()) {
                case 'n':
                    token.text += QLatin1Char('\n');
                    break;
                case 'r':
                    token.text += QLatin1Char('\r');
                    break;
                case 't':
                    token.text += QLatin1Char('\t');
                    break;
                case '"':
                case '\\':
                    token.text += e;
                    break;
                case 'x':
                case 'u': {
                    const qsizetype digits = e == QLatin1Char('x') ? 2 : 4;
                    const QString hex = line.mid(i, digits);
                    bool ok =
                        hex.size() == digits && std::all_of(hex.begin(), hex.end(), [](QChar h) {
                            return h.unicode() < 0x80 && std::isxdigit(h.unicode());
                        });
                    const uint code = ok ? hex.toUInt(&ok, 16) : 0;
                    if (!ok)
                        return Error(Error::Kind::Malformed,
                                     Tr::tr("'\\%1' needs %2 hex digits").arg(e).arg(digits));
                    token.text += QChar(char16_t(code));
                    i += digits;
                    break;
                }
                default:
                    return Error(Error::Kind::Malformed,
                                 Tr::tr("unknown escape '\\%1' in a quoted string").arg(e));
                }
            }
            if (!closed)
                return Error(Error::Kind::Malformed, Tr::tr("unterminated quoted string"));
            if (i < n && !line.at(i).isSpace())
                return Error(Error::Kind::Malformed, Tr::tr("text right after a closing quote"));
        } else {
            while (i < n && !line.at(i).isSpace())
                token.text += line.at(i++);
        }
        tokens.append(token);
    }
    return tokens;
}

Result<quint32> parseU32(const QString &text)
{
    bool ok = false;
    const quint32 v = text.startsWith(QLatin1String("0x"), Qt::CaseInsensitive)
        ? text.mid(2).toUInt(&ok, 16)
        : text.toUInt(&ok, 10);
    if (!ok)
        return Error(Error::Kind::Malformed, Tr::tr("'%1' is not a number").arg(text));
    return v;
}

// The parser's state: which part of the file comes next.
class Parser
{
public:
    explicit Parser(QString origin)
        : m_origin(std::move(origin))
    { }

    Result<ParameterSet> run(const QByteArray &bytes);

private:
    enum class Part { Magic, Format, Header, Entries, End, Done };

    Error error(const QString &message) const
    {
        return Error(Error::Kind::Malformed,
                     Tr::tr("%1:%2: %3").arg(m_origin).arg(m_line).arg(message));
    }
    Result<void> header(const QList<Token> &t);
    Result<void> entry(const QList<Token> &t);

    QString m_origin;
    int m_line = 0;
    Part m_part = Part::Magic;
    qsizetype m_expected = 0;
    QSet<ObjectAddress> m_seen;
    ParameterSet m_set;
};

Result<ParameterSet> Parser::run(const QByteArray &bytes)
{
    if (bytes.isEmpty())
        return Error(Error::Kind::Malformed,
                     Tr::tr("%1: empty file, not a drivebench parameter set").arg(m_origin));
    QString text = QString::fromUtf8(bytes);
    if (text.startsWith(QChar(0xFEFF)))
        text.remove(0, 1);
    const QStringList lines = text.split(QLatin1Char('\n'));
    for (const QString &raw : lines) {
        ++m_line;
        QString line = raw;
        if (line.endsWith(QLatin1Char('\r')))
            line.chop(1);
        if (m_part == Part::Magic) {
            if (line.trimmed() != QLatin1String(kMagic))
                return error(Tr::tr("not a drivebench parameter set (expected '%1' as the "
                                    "first line)")
                                 .arg(QLatin1String(kMagic)));
            m_part = Part::Format;
            continue;
        }
        const QString trimmed = line.trimmed();
        if (trimmed.isEmpty() || trimmed.startsWith(QLatin1Char('#')))
            continue;
        if (line.contains(QChar::ReplacementCharacter))
            return error(Tr::tr("the line is not valid UTF-8"));
        const auto tokens = tokenize(trimmed);
        if (!tokens)
            return error(tokens.error().message());
        const QList<Token> &t = tokens.value();
        const QString key = t.first().text;
        switch (m_part) {
        case Part::Magic:
            break;
        case Part::Format: {
            if (key != QLatin1String("format") || t.size() != 2)
                return error(Tr::tr("expected 'format %1'").arg(ParameterSet::kFormatVersion));
            bool ok = false;
            const int version = t.at(1).text.toInt(&ok);
            if (!ok || version < 1)
                return error(Tr::tr("bad format version '%1'").arg(t.at(1).text));
            if (version > ParameterSet::kFormatVersion)
                return error(Tr::tr("format %1 is newer than this drivebench reads (%2)")
                                 .arg(version)
                                 .arg(ParameterSet::kFormatVersion));
            m_part = Part::Header;
            break;
        }
        case Part::Header:
            if (auto r = header(t); !r)
                return r.error();
            break;
        case Part::Entries:
            if (auto r = entry(t); !r)
                return r.error();
            if (m_set.size() == m_expected)
                m_part = Part::End;
            break;
        case Part::End:
            if (key != QLatin1String("end") || t.size() != 1)
                return error(Tr::tr("expected 'end' after %1 objects").arg(m_expected));
            m_part = Part::Done;
            break;
        case Part::Done:
            return error(Tr::tr("text after 'end'"));
        }
    }
    switch (m_part) {
    case Part::Done:
        return m_set;
    case Part::Magic:
    case Part::Format:
        return error(Tr::tr("truncated: no 'format' line"));
    case Part::Header:
        return error(Tr::tr("truncated: no 'entries' line"));
    case Part::Entries:
        return error(Tr::tr("truncated: 'entries %1' but only %2 object lines")
                         .arg(m_expected)
                         .arg(m_set.size()));
    case Part::End:
        return error(Tr::tr("truncated: no 'end' line"));
    }
    return m_set;
}

Result<void> Parser::header(const QList<Token> &t)
{
    const QString key = t.first().text;
    auto want = [&](qsizetype n) -> Result<void> {
        if (t.size() != n)
            return error(Tr::tr("'%1' takes %2 values").arg(key).arg(n - 1));
        return {};
    };
    DeviceIdentity &id = m_set.identity;
    if (key == QLatin1String("vendor") || key == QLatin1String("product")) {
        if (auto r = want(3); !r)
            return r;
        const bool vendor = key == QLatin1String("vendor");
        if (!t.at(1).quoted && t.at(1).text == QLatin1String("unknown")) {
            (vendor ? m_set.vendorIdKnown : m_set.productCodeKnown) = false;
            (vendor ? id.vendorId : id.productCode) = 0;
        } else {
            const auto number = parseU32(t.at(1).text);
            if (!number)
                return error(number.error().message());
            (vendor ? id.vendorId : id.productCode) = number.value();
        }
        (key == QLatin1String("vendor") ? id.vendorName : id.productName) = t.at(2).text;
    } else if (key == QLatin1String("addresses")) {
        if (auto r = want(2); !r)
            return r;
        const AddressFormat *format = AddressFormat::byKey(t.at(1).text);
        if (!format)
            return error(
                Tr::tr("unknown address format '%1' (canopen or parameter)").arg(t.at(1).text));
        m_set.addressFormat = format;
    } else if (key == QLatin1String("revision")) {
        if (auto r = want(2); !r)
            return r;
        id.revision = t.at(1).text;
    } else if (key == QLatin1String("serial")) {
        if (auto r = want(2); !r)
            return r;
        m_set.serialNumber = t.at(1).text;
    } else if (key == QLatin1String("description")) {
        if (auto r = want(3); !r)
            return r;
        id.descriptionFile = t.at(1).text;
        id.descriptionVersion = t.at(2).text;
    } else if (key == QLatin1String("source")) {
        if (auto r = want(2); !r)
            return r;
        m_set.source = t.at(1).text;
    } else if (key == QLatin1String("created")) {
        if (auto r = want(2); !r)
            return r;
        m_set.created = QDateTime::fromString(t.at(1).text, Qt::ISODateWithMs);
        if (!m_set.created.isValid())
            return error(Tr::tr("bad time '%1'").arg(t.at(1).text));
    } else if (key == QLatin1String("entries")) {
        if (auto r = want(2); !r)
            return r;
        bool ok = false;
        m_expected = t.at(1).text.toInt(&ok);
        if (!ok || m_expected < 0)
            return error(Tr::tr("bad object count '%1'").arg(t.at(1).text));
        m_part = m_expected == 0 ? Part::End : Part::Entries;
    } else {
        return error(Tr::tr("unknown header line '%1'").arg(key));
    }
    return {};
}

Result<void> Parser::entry(const QList<Token> &t)
{
    if (t.size() != 5 || t.at(0).quoted || !t.at(1).quoted || t.at(2).quoted || !t.at(4).quoted)
        return error(Tr::tr("expected an object line: ADDRESS \"NAME\" TYPE VALUE "
                            "\"UNIT\" (%1 of %2 objects read)")
                         .arg(m_set.size())
                         .arg(m_expected));
    const AddressFormat &format = *m_set.addressFormat;
    const auto address = format.parse(t.at(0).text);
    if (!address)
        return error(Tr::tr("bad address '%1' (%2 addresses are written like %3)")
                         .arg(t.at(0).text, format.key(), format.example()));
    if (m_seen.contains(address.value()))
        return error(Tr::tr("%1 appears twice").arg(format.format(*address)));
    const auto type = datatype::fromName(t.at(2).text);
    if (!type)
        return error(Tr::tr("unknown type '%1'").arg(t.at(2).text));
    const bool wantQuoted = datatype::isVariableLength(*type);
    if (t.at(3).quoted != wantQuoted)
        return error(
            wantQuoted
                ? QStringLiteral("a %1 value must be quoted").arg(datatype::name(*type))
                : QStringLiteral("a %1 value must not be quoted").arg(datatype::name(*type)));
    const auto raw = codec::fromText(*type, t.at(3).text);
    if (!raw)
        return error(QStringLiteral("%1: %2").arg(format.format(*address), raw.error().message()));
    m_seen.insert(address.value());
    m_set.insert({ address.value(), t.at(1).text, *type, raw.value(), t.at(4).text });
    return {};
}

} // namespace

Result<ParameterSet> ParameterSet::parse(const QByteArray &bytes, const QString &origin)
{
    return Parser(origin).run(bytes);
}

} // namespace db
