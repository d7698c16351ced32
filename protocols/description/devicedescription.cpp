#include "devicedescription.h"
#include "core/filereader.h"

#include "descriptionfile.h"
#include "edsloader.h"
#include "xddloader.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>
#include <QStringDecoder>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::core)
};
} // namespace

namespace db {

QString formatName(DescriptionLoad::Format format)
{
    switch (format) {
    case DescriptionLoad::Format::Eds:
        return QStringLiteral("EDS");
    case DescriptionLoad::Format::Dcf:
        return QStringLiteral("DCF");
    case DescriptionLoad::Format::Xdd:
        return QStringLiteral("XDD");
    case DescriptionLoad::Format::Xdc:
        return QStringLiteral("XDC");
    case DescriptionLoad::Format::Json:
        return QStringLiteral("JSON");
    }
    return QString();
}

bool DescriptionLoad::resolveNodeId(quint8 id)
{
    bool allFit = true;
    for (auto it = nodeIdDefaults.cbegin(); it != nodeIdDefaults.cend(); ++it) {
        const ObjectDef *found = dictionary.find(it.key());
        if (!found)
            continue;
        ObjectDef def = *found;
        const qlonglong sum = it.value() + id;
        auto raw = codec::normalize(def.type, QVariant::fromValue(sum));
        if (!raw) {
            warnings << QStringLiteral("%1: $NODEID default %2+%3 does not fit: %4")
                            .arg(it.key().toString())
                            .arg(it.value())
                            .arg(id)
                            .arg(raw.error().message());
            allFit = false;
            continue;
        }
        def.defaultValue = raw.value();
        dictionary.insert(def);
    }
    return allFit;
}

Result<DescriptionLoad> loadDeviceDescription(const QString &path,
                                              const DescriptionOptions &options)
{
    const Result<QByteArray> bytes =
        files::readAll(path, files::kDescriptionLimit, Tr::tr("a device description"));
    if (!bytes)
        return bytes.error();
    return parseDeviceDescription(*bytes, path, options);
}

Result<DescriptionLoad> parseDeviceDescription(const QByteArray &data, const QString &origin,
                                               const DescriptionOptions &options)
{
    if (data.trimmed().isEmpty())
        return Error(Error::Kind::Malformed, Tr::tr("%1 is empty").arg(origin));
    if (description::looksBinary(data))
        return Error(Error::Kind::Malformed,
                     Tr::tr("%1 holds binary data, not a device description").arg(origin));
    QByteArray head = data.left(256);
    if (head.startsWith("\xEF\xBB\xBF"))
        head = head.mid(3);
    head = head.trimmed();
    if (head.startsWith('<'))
        return parseXdd(data, origin, options);
    if (head.startsWith('{')) {
        auto dict = parseJsonDescription(data, origin);
        if (!dict)
            return dict.error();
        DescriptionLoad load;
        load.dictionary = dict.value();
        load.format = DescriptionLoad::Format::Json;
        return load;
    }
    return parseEds(data, origin, options);
}

namespace description {

std::optional<qlonglong> parseInteger(const QString &input, bool allowOctal)
{
    QString text = input.trimmed();
    bool negative = false;
    if (text.startsWith(QLatin1Char('-')) || text.startsWith(QLatin1Char('+'))) {
        negative = text.startsWith(QLatin1Char('-'));
        text = text.mid(1).trimmed();
    }
    int base = 10;
    if (text.startsWith(QLatin1String("0x"), Qt::CaseInsensitive)) {
        base = 16;
        text = text.mid(2);
    } else if (allowOctal && text.size() > 1 && text.startsWith(QLatin1Char('0'))) {
        base = 8; // CiA 306 4.6.2: a leading 0 means octal
    }
    bool ok = false;
    const quint64 magnitude = text.toULongLong(&ok, base);
    if (!ok || text.isEmpty())
        return std::nullopt;
    return negative ? -qlonglong(magnitude) : qlonglong(magnitude);
}

namespace {

// "$NODEID+0x180", "0x180 + $NODEID", "$NODEID": the constant part, or nullopt.
std::optional<qlonglong> nodeIdOffset(const QString &text, bool allowOctal)
{
    QString t = text;
    static const QRegularExpression space(QStringLiteral("\\s"));
    t.remove(space);
    const QStringList terms = t.split(QLatin1Char('+'));
    qlonglong sum = 0;
    int nodeIds = 0;
    for (const QString &term : terms) {
        if (term.compare(QLatin1String("$NODEID"), Qt::CaseInsensitive) == 0) {
            ++nodeIds;
            continue;
        }
        const auto v = parseInteger(term, allowOctal);
        if (!v)
            return std::nullopt;
        sum += *v;
    }
    if (nodeIds != 1)
        return std::nullopt;
    return sum;
}

} // namespace

ParsedValue parseValue(DataType type, const QString &input, std::optional<quint8> nodeId,
                       bool allowOctal)
{
    ParsedValue out;
    const QString text = (type == DataType::VisibleString || type == DataType::UnicodeString)
        ? input
        : input.trimmed();
    if (text.isEmpty())
        return out;
    if (text.contains(QLatin1String("$NODEID"), Qt::CaseInsensitive)) {
        const auto offset = nodeIdOffset(text, allowOctal);
        if (!offset || !datatype::isInteger(type)) {
            out.error = Tr::tr("cannot evaluate '%1'").arg(text);
            return out;
        }
        if (!nodeId) {
            out.nodeIdRelative = true;
            out.offset = *offset;
            return out;
        }
        auto raw = codec::normalize(type, QVariant::fromValue(*offset + *nodeId));
        if (!raw)
            out.error = Tr::tr("'%1' with node id %2: %3")
                            .arg(text)
                            .arg(*nodeId)
                            .arg(raw.error().message());
        else
            out.raw = raw.value();
        return out;
    }
    QString literal = text;
    if (datatype::isInteger(type) && allowOctal) {
        static const QRegularExpression octal(QStringLiteral("^([+-]?)0([0-7]+)$"));
        const auto m = octal.match(text);
        if (m.hasMatch())
            literal = m.captured(1) + QString::number(m.captured(2).toULongLong(nullptr, 8));
    }
    auto raw = codec::fromText(type, literal);
    if (!raw && type == DataType::Domain) {
        out.raw = text.toUtf8(); // free-form domain contents are taken as they are
        return out;
    }
    if (!raw && datatype::isInteger(type)) {
        // 0/1 style reals ("1.0") or floats in integer objects are a common slip
        bool ok = false;
        const double d = text.toDouble(&ok);
        if (ok)
            raw = codec::normalize(type, d);
    }
    if (!raw)
        out.error = raw.error().message();
    else
        out.raw = raw.value();
    return out;
}

QString valueText(DataType type, const QVariant &raw)
{
    if (!raw.isValid())
        return QString();
    if (datatype::isUnsignedInteger(type))
        return codec::toText(type, raw, codec::TextFormat::Hex);
    if (type == DataType::OctetString || type == DataType::Domain)
        return QString::fromLatin1(raw.toByteArray().toHex().toUpper());
    return codec::toText(type, raw);
}

QString decodeText(const QByteArray &bytes)
{
    QByteArray data = bytes;
    if (data.startsWith("\xEF\xBB\xBF"))
        data = data.mid(3);
    QStringDecoder utf8(QStringDecoder::Utf8, QStringDecoder::Flag::Stateless);
    QString text = utf8.decode(data);
    if (!utf8.hasError())
        return text;
    return QString::fromLatin1(data);
}

bool looksBinary(const QByteArray &bytes)
{
    const QByteArray head = bytes.left(4096);
    int control = 0;
    for (char c : head) {
        if (c == '\0')
            return true;
        const auto u = uchar(c);
        if (u < 0x20 && c != '\t' && c != '\n' && c != '\r' && c != '\f')
            ++control;
    }
    return control * 10 > head.size();
}

} // namespace description
} // namespace db
