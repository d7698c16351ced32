#include "xddparameter.h"

#include <QHash>

namespace db::xdd {

std::optional<DataType> typeFromIecName(const QString &name)
{
    static const QHash<QString, DataType> types = {
        { QStringLiteral("BOOL"), DataType::Boolean },
        { QStringLiteral("SINT"), DataType::Integer8 },
        { QStringLiteral("INT"), DataType::Integer16 },
        { QStringLiteral("DINT"), DataType::Integer32 },
        { QStringLiteral("LINT"), DataType::Integer64 },
        { QStringLiteral("USINT"), DataType::Unsigned8 },
        { QStringLiteral("BYTE"), DataType::Unsigned8 },
        { QStringLiteral("UINT"), DataType::Unsigned16 },
        { QStringLiteral("WORD"), DataType::Unsigned16 },
        { QStringLiteral("UDINT"), DataType::Unsigned32 },
        { QStringLiteral("DWORD"), DataType::Unsigned32 },
        { QStringLiteral("ULINT"), DataType::Unsigned64 },
        { QStringLiteral("LWORD"), DataType::Unsigned64 },
        { QStringLiteral("REAL"), DataType::Real32 },
        { QStringLiteral("LREAL"), DataType::Real64 },
        { QStringLiteral("STRING"), DataType::VisibleString },
        { QStringLiteral("WSTRING"), DataType::UnicodeString },
        { QStringLiteral("BITSTRING"), DataType::OctetString },
    };
    const auto it = types.constFind(name);
    return it == types.cend() ? std::nullopt : std::optional<DataType>(*it);
}

Parameter readParameter(QXmlStreamReader &xml)
{
    auto text = [](const QXmlStreamAttributes &a, const char *name) {
        return a.value(QLatin1String(name)).toString().trimmed();
    };
    Parameter p;
    p.uniqueId = text(xml.attributes(), "uniqueID");
    p.access = text(xml.attributes(), "access");
    int depth = 0;
    QString parent;
    while (!xml.atEnd()) {
        const auto token = xml.readNext();
        if (token == QXmlStreamReader::EndElement) {
            if (depth-- == 0)
                break;
            continue;
        }
        if (token != QXmlStreamReader::StartElement)
            continue;
        ++depth;
        const QString name = xml.name().toString();
        const QXmlStreamAttributes a = xml.attributes();
        if (depth == 1 && typeFromIecName(name))
            p.typeName = name;
        if (name == QLatin1String("label") && depth == 1) {
            const QString lang = text(a, "lang");
            const QString label = xml.readElementText().trimmed();
            --depth;
            if (p.label.isEmpty() || lang == QLatin1String("en"))
                p.label = label.isEmpty() ? p.label : label;
        } else if (name == QLatin1String("description") && depth == 1) {
            p.description = xml.readElementText().trimmed();
            --depth;
        } else if (name == QLatin1String("defaultValue")) {
            p.defaultValue = text(a, "value");
        } else if (name == QLatin1String("actualValue")) {
            p.actualValue = text(a, "value");
        } else if (name == QLatin1String("minValue")) {
            p.minValue = text(a, "value");
        } else if (name == QLatin1String("maxValue")) {
            p.maxValue = text(a, "value");
        } else if (name == QLatin1String("value") && depth == 2) {
            parent = text(a, "value");
            p.allowed.insert(parent, QString());
        } else if (name == QLatin1String("label") && depth == 3 && !parent.isEmpty()) {
            const QString lang = text(a, "lang").toLower();
            const QString label = xml.readElementText().trimmed();
            --depth;
            if (label.isEmpty())
                continue;
            if (p.allowed.value(parent).isEmpty() || lang == QLatin1String("en"))
                p.allowed.insert(parent, label);
            if (!lang.isEmpty())
                p.allowedLocal[parent].insert(lang, label);
        }
    }
    return p;
}

} // namespace db::xdd
