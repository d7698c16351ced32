#include "datatype.h"

#include <QHash>

namespace db::datatype {

const QList<DataType> &all()
{
    static const QList<DataType> types = {
        DataType::Boolean,     DataType::Integer8,      DataType::Integer16,
        DataType::Integer32,   DataType::Unsigned8,     DataType::Unsigned16,
        DataType::Unsigned32,  DataType::Real32,        DataType::VisibleString,
        DataType::OctetString, DataType::UnicodeString, DataType::Domain,
        DataType::Integer24,   DataType::Real64,        DataType::Integer40,
        DataType::Integer48,   DataType::Integer56,     DataType::Integer64,
        DataType::Unsigned24,  DataType::Unsigned40,    DataType::Unsigned48,
        DataType::Unsigned56,  DataType::Unsigned64,
    };
    return types;
}

int byteSize(DataType type)
{
    switch (type) {
    case DataType::Boolean:
    case DataType::Integer8:
    case DataType::Unsigned8:
        return 1;
    case DataType::Integer16:
    case DataType::Unsigned16:
        return 2;
    case DataType::Integer24:
    case DataType::Unsigned24:
        return 3;
    case DataType::Integer32:
    case DataType::Unsigned32:
    case DataType::Real32:
        return 4;
    case DataType::Integer40:
    case DataType::Unsigned40:
        return 5;
    case DataType::Integer48:
    case DataType::Unsigned48:
        return 6;
    case DataType::Integer56:
    case DataType::Unsigned56:
        return 7;
    case DataType::Integer64:
    case DataType::Unsigned64:
    case DataType::Real64:
        return 8;
    case DataType::VisibleString:
    case DataType::OctetString:
    case DataType::UnicodeString:
    case DataType::Domain:
        return 0;
    }
    return 0;
}

bool isSignedInteger(DataType type)
{
    switch (type) {
    case DataType::Integer8:
    case DataType::Integer16:
    case DataType::Integer24:
    case DataType::Integer32:
    case DataType::Integer40:
    case DataType::Integer48:
    case DataType::Integer56:
    case DataType::Integer64:
        return true;
    default:
        return false;
    }
}

bool isUnsignedInteger(DataType type)
{
    switch (type) {
    case DataType::Unsigned8:
    case DataType::Unsigned16:
    case DataType::Unsigned24:
    case DataType::Unsigned32:
    case DataType::Unsigned40:
    case DataType::Unsigned48:
    case DataType::Unsigned56:
    case DataType::Unsigned64:
        return true;
    default:
        return false;
    }
}

bool isReal(DataType type)
{
    return type == DataType::Real32 || type == DataType::Real64;
}

bool isNumeric(DataType type)
{
    return isInteger(type) || isReal(type) || type == DataType::Boolean;
}

bool isVariableLength(DataType type)
{
    return byteSize(type) == 0;
}

QString name(DataType type)
{
    switch (type) {
    case DataType::Boolean:
        return QStringLiteral("BOOLEAN");
    case DataType::Integer8:
        return QStringLiteral("INTEGER8");
    case DataType::Integer16:
        return QStringLiteral("INTEGER16");
    case DataType::Integer24:
        return QStringLiteral("INTEGER24");
    case DataType::Integer32:
        return QStringLiteral("INTEGER32");
    case DataType::Integer40:
        return QStringLiteral("INTEGER40");
    case DataType::Integer48:
        return QStringLiteral("INTEGER48");
    case DataType::Integer56:
        return QStringLiteral("INTEGER56");
    case DataType::Integer64:
        return QStringLiteral("INTEGER64");
    case DataType::Unsigned8:
        return QStringLiteral("UNSIGNED8");
    case DataType::Unsigned16:
        return QStringLiteral("UNSIGNED16");
    case DataType::Unsigned24:
        return QStringLiteral("UNSIGNED24");
    case DataType::Unsigned32:
        return QStringLiteral("UNSIGNED32");
    case DataType::Unsigned40:
        return QStringLiteral("UNSIGNED40");
    case DataType::Unsigned48:
        return QStringLiteral("UNSIGNED48");
    case DataType::Unsigned56:
        return QStringLiteral("UNSIGNED56");
    case DataType::Unsigned64:
        return QStringLiteral("UNSIGNED64");
    case DataType::Real32:
        return QStringLiteral("REAL32");
    case DataType::Real64:
        return QStringLiteral("REAL64");
    case DataType::VisibleString:
        return QStringLiteral("VISIBLE_STRING");
    case DataType::OctetString:
        return QStringLiteral("OCTET_STRING");
    case DataType::UnicodeString:
        return QStringLiteral("UNICODE_STRING");
    case DataType::Domain:
        return QStringLiteral("DOMAIN");
    }
    return QStringLiteral("UNKNOWN");
}

std::optional<DataType> fromCode(quint32 code)
{
    for (DataType t : all()) {
        if (static_cast<quint32>(t) == code)
            return t;
    }
    return std::nullopt;
}

std::optional<DataType> fromName(const QString &text)
{
    static const QHash<QString, DataType> aliases = [] {
        QHash<QString, DataType> map;
        for (DataType t : all()) {
            map.insert(name(t), t);
            map.insert(name(t).remove(QLatin1Char('_')), t);
        }
        const struct
        {
            const char *alias;
            DataType type;
        } extra[] = {
            { "BOOL", DataType::Boolean },          { "INT8", DataType::Integer8 },
            { "INT16", DataType::Integer16 },       { "INT24", DataType::Integer24 },
            { "INT32", DataType::Integer32 },       { "INT40", DataType::Integer40 },
            { "INT48", DataType::Integer48 },       { "INT56", DataType::Integer56 },
            { "INT64", DataType::Integer64 },       { "UINT8", DataType::Unsigned8 },
            { "UINT16", DataType::Unsigned16 },     { "UINT24", DataType::Unsigned24 },
            { "UINT32", DataType::Unsigned32 },     { "UINT40", DataType::Unsigned40 },
            { "UINT48", DataType::Unsigned48 },     { "UINT56", DataType::Unsigned56 },
            { "UINT64", DataType::Unsigned64 },     { "S8", DataType::Integer8 },
            { "S16", DataType::Integer16 },         { "S32", DataType::Integer32 },
            { "S64", DataType::Integer64 },         { "U8", DataType::Unsigned8 },
            { "U16", DataType::Unsigned16 },        { "U32", DataType::Unsigned32 },
            { "U64", DataType::Unsigned64 },        { "FLOAT", DataType::Real32 },
            { "FLOAT32", DataType::Real32 },        { "DOUBLE", DataType::Real64 },
            { "FLOAT64", DataType::Real64 },        { "STRING", DataType::VisibleString },
            { "VSTRING", DataType::VisibleString }, { "OSTRING", DataType::OctetString },
            { "USTRING", DataType::UnicodeString },
        };
        for (const auto &e : extra)
            map.insert(QString::fromLatin1(e.alias), e.type);
        return map;
    }();
    const QString key = text.trimmed().toUpper();
    const auto it = aliases.constFind(key);
    if (it != aliases.cend())
        return *it;
    bool ok = false;
    const quint32 code =
        key.startsWith(QLatin1String("0X")) ? key.mid(2).toUInt(&ok, 16) : key.toUInt(&ok, 10);
    if (ok)
        return fromCode(code);
    return std::nullopt;
}

} // namespace db::datatype
