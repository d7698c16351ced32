// Loader for drivebench's own JSON device descriptions (resources/devices/*.json).
// Format (version 1):
//   { "format": "drivebench-device-description", "version": 1,
//     "device": { "vendor", "vendorId", "product", "productCode", "revision", "version" },
//     "objects": [ { "index": "0x6041", "sub": 0, "name", "object", "type": "UNSIGNED16",
//                    "access": "ro|wo|rw|const", "unit", "unit_de", "factor", "offset", "decimals",
//                    "default", "min", "max", "enum": { "1": "Profile Position" },
//                    "enum_de": { "1": "Profilpositionierung" },
//                    "bits": [ { "bit": 0, "width": 1, "name": "ready to switch on",
//                                "name_de": "Einschaltbereit" } ],
//                    "storable", "pdo", "trace", "description",
//                    "name_de": "Statuswort", "object_de": ... } ],
//     "errors": [ { "code": "0x2220", "name": "ERROR_OVER_CURRENT", "text": "Over-current",
//                   "text_de": "Überstrom" } ],
//     "addresses": "canopen" }
// "addresses" says how people write the objects' addresses: "canopen" (hex INDEX:SUB, the
// default) or "parameter" (decimal NUMBER:DATASET, index = parameter number, sub = data set).
// Numbers may be JSON numbers or strings ("0x..", decimal); values are given in raw units.
// "name", "object", "enum", a bit's "name", "unit" and an error's "text" are English; "name_LANG",
// "object_LANG", "enum_LANG" (value -> text, for values of "enum"), a bit's "name_LANG",
// "unit_LANG" (for units that are words) and "text_LANG" give them in further languages (LANG: a
// language code such as "de").
#include "descriptionfile.h"
#include "core/filereader.h"

#include "core/objectdictionary.h"

#include <QCoreApplication>
#include <QFile>

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <algorithm>
#include <cmath>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::core)
};
} // namespace

namespace db {

namespace {

bool toUInt(const QJsonValue &v, quint32 *out)
{
    if (v.isDouble()) {
        const double d = v.toDouble();
        if (d < 0 || d > 4294967295.0)
            return false;
        *out = quint32(d);
        return true;
    }
    bool ok = false;
    const QString s = v.toString().trimmed();
    *out = s.startsWith(QLatin1String("0x"), Qt::CaseInsensitive) ? s.mid(2).toUInt(&ok, 16)
                                                                  : s.toUInt(&ok, 10);
    return ok;
}

bool isLanguageCode(const QString &language)
{
    return language.size() >= 2 && language.size() <= 3
        && std::all_of(language.begin(), language.end(),
                       [](QChar c) { return c >= u'a' && c <= u'z'; });
}

// The "KEY_LANG" members of o: LANG -> text. Errors name the member when its value is not a
// non-empty string or LANG is not a language code.
Result<LocalTexts> localTexts(const QJsonObject &o, QLatin1String key)
{
    LocalTexts texts;
    const QString prefix = key + QLatin1Char('_');
    for (auto it = o.begin(); it != o.end(); ++it) {
        if (!it.key().startsWith(prefix))
            continue;
        const QString language = it.key().mid(prefix.size());
        if (!isLanguageCode(language))
            return Error(Error::Kind::Malformed,
                         Tr::tr("\"%1\": \"%2\" is not a language code such as \"de\"")
                             .arg(it.key(), language));
        if (!it.value().isString() || it.value().toString().trimmed().isEmpty())
            return Error(Error::Kind::Malformed,
                         Tr::tr("\"%1\" must be a non-empty text").arg(it.key()));
        texts.insert(language, it.value().toString());
    }
    return texts;
}

// The "enum_LANG" members of o: value -> (LANG -> text). Each names values of `english`.
Result<QMap<qlonglong, LocalTexts>> localEnumeration(const QJsonObject &o,
                                                     const QMap<qlonglong, QString> &english)
{
    QMap<qlonglong, LocalTexts> local;
    for (auto it = o.begin(); it != o.end(); ++it) {
        if (!it.key().startsWith(QLatin1String("enum_")))
            continue;
        const QString language = it.key().mid(5);
        if (!isLanguageCode(language))
            return Error(Error::Kind::Malformed,
                         Tr::tr("\"%1\": \"%2\" is not a language code such as \"de\"")
                             .arg(it.key(), language));
        if (!it.value().isObject())
            return Error(Error::Kind::Malformed,
                         Tr::tr("\"%1\" must map values to texts").arg(it.key()));
        const QJsonObject texts = it.value().toObject();
        for (auto t = texts.begin(); t != texts.end(); ++t) {
            bool ok = false;
            const qlonglong value = t.key().toLongLong(&ok);
            if (!ok || !english.contains(value))
                return Error(
                    Error::Kind::Malformed,
                    Tr::tr("\"%1\": %2 is not a value of \"enum\"").arg(it.key(), t.key()));
            if (!t.value().isString() || t.value().toString().trimmed().isEmpty())
                return Error(Error::Kind::Malformed,
                             Tr::tr("\"%1\": the text of %2 must be a non-empty text")
                                 .arg(it.key(), t.key()));
            local[value].insert(language, t.value().toString());
        }
    }
    return local;
}

Result<QVariant> rawValue(DataType type, const QJsonValue &v)
{
    if (v.isUndefined() || v.isNull())
        return QVariant();
    if (v.isDouble())
        return codec::normalize(type, v.toDouble());
    if (v.isBool())
        return codec::normalize(type, v.toBool());
    return codec::fromText(type, v.toString());
}

} // namespace

Result<ObjectDictionary> loadJsonDescription(const QString &path)
{
    const Result<QByteArray> bytes =
        files::readAll(path, files::kDescriptionLimit, Tr::tr("a device description"));
    if (!bytes)
        return bytes.error();
    return parseJsonDescription(*bytes, path);
}

Result<ObjectDictionary> parseJsonDescription(const QByteArray &json, const QString &origin)
{
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(json, &parseError);
    if (doc.isNull())
        return Error(Error::Kind::Malformed,
                     Tr::tr("%1: JSON error at %2: %3")
                         .arg(origin, files::textPosition(json, parseError.offset),
                              parseError.errorString()));
    const QJsonObject root = doc.object();
    if (root.value(QLatin1String("format")).toString()
        != QLatin1String("drivebench-device-description"))
        return Error(Error::Kind::Malformed,
                     Tr::tr("%1 is not a drivebench device description").arg(origin));
    if (root.value(QLatin1String("version")).toInt() != 1)
        return Error(Error::Kind::NotSupported,
                     Tr::tr("%1: description version %2 is not supported (1 is)")
                         .arg(origin)
                         .arg(root.value(QLatin1String("version")).toInt()));

    ObjectDictionary dict;
    const QJsonObject device = root.value(QLatin1String("device")).toObject();
    dict.identity.vendorName = device.value(QLatin1String("vendor")).toString();
    toUInt(device.value(QLatin1String("vendorId")), &dict.identity.vendorId);
    dict.identity.productName = device.value(QLatin1String("product")).toString();
    toUInt(device.value(QLatin1String("productCode")), &dict.identity.productCode);
    dict.identity.revision = device.value(QLatin1String("revision")).toString();
    dict.identity.descriptionVersion = device.value(QLatin1String("version")).toString();
    dict.identity.descriptionFile = origin;
    if (const QJsonValue addresses = root.value(QLatin1String("addresses"));
        !addresses.isUndefined()) {
        const AddressFormat *format = AddressFormat::byKey(addresses.toString());
        if (!format)
            return Error(Error::Kind::Malformed,
                         Tr::tr("%1: unknown \"addresses\" '%2' (canopen or parameter)")
                             .arg(origin, addresses.toVariant().toString()));
        dict.setAddressFormat(*format);
    }

    const QJsonArray objects = root.value(QLatin1String("objects")).toArray();
    for (qsizetype i = 0; i < objects.size(); ++i) {
        const QJsonObject o = objects.at(i).toObject();
        auto fail = [&](const QString &what) {
            return Error(Error::Kind::Malformed,
                         Tr::tr("%1: object #%2: %3").arg(origin).arg(i + 1).arg(what));
        };
        quint32 index = 0;
        quint32 sub = 0;
        if (!toUInt(o.value(QLatin1String("index")), &index) || index > 0xFFFF)
            return fail(Tr::tr("bad index"));
        if (!toUInt(o.value(QLatin1String("sub")), &sub) || sub > 0xFF)
            return fail(Tr::tr("bad sub-index"));
        ObjectDef def;
        def.address = ObjectAddress(quint16(index), quint8(sub));
        def.name = o.value(QLatin1String("name")).toString();
        def.objectName = o.value(QLatin1String("object")).toString();
        const auto names = localTexts(o, QLatin1String("name"));
        if (!names)
            return fail(names.error().message());
        def.localNames = *names;
        const auto objectNames = localTexts(o, QLatin1String("object"));
        if (!objectNames)
            return fail(objectNames.error().message());
        def.localObjectNames = *objectNames;
        const auto type = datatype::fromName(o.value(QLatin1String("type")).toString());
        if (!type)
            return fail(Tr::tr("unknown type '%1'").arg(o.value(QLatin1String("type")).toString()));
        def.type = *type;
        const auto acc =
            access::fromName(o.value(QLatin1String("access")).toString(QStringLiteral("rw")));
        if (!acc)
            return fail(
                Tr::tr("unknown access '%1'").arg(o.value(QLatin1String("access")).toString()));
        def.access = *acc;
        def.unit = o.value(QLatin1String("unit")).toString();
        const auto units = localTexts(o, QLatin1String("unit"));
        if (!units)
            return fail(units.error().message());
        def.localUnits = *units;
        def.factor = o.value(QLatin1String("factor")).toDouble(1.0);
        def.offset = o.value(QLatin1String("offset")).toDouble(0.0);
        // Fixed-point parameters give their decimals; the factor follows from them.
        def.decimals = o.value(QLatin1String("decimals")).toInt(-1);
        if (def.decimals > 9)
            return fail(Tr::tr("decimals %1 (0-9 allowed)").arg(def.decimals));
        if (def.decimals >= 0)
            def.factor = std::pow(10.0, -def.decimals);
        for (const char *key : { "default", "min", "max" }) {
            auto v = rawValue(def.type, o.value(QLatin1String(key)));
            if (!v)
                return fail(QStringLiteral("%1: %2").arg(QLatin1String(key), v.error().message()));
            QVariant &target = key[0] == 'd' ? def.defaultValue
                : key[1] == 'i'              ? def.minimum
                                             : def.maximum;
            target = v.value();
        }
        const QJsonObject enums = o.value(QLatin1String("enum")).toObject();
        for (auto it = enums.begin(); it != enums.end(); ++it)
            def.enumeration.insert(it.key().toLongLong(), it.value().toString());
        if (auto local = localEnumeration(o, def.enumeration); !local)
            return fail(local.error().message());
        else
            def.localEnumeration = *local;
        const QJsonArray bits = o.value(QLatin1String("bits")).toArray();
        for (qsizetype b = 0; b < bits.size(); ++b) {
            const QJsonObject bo = bits.at(b).toObject();
            const auto bitNames = localTexts(bo, QLatin1String("name"));
            if (!bitNames)
                return fail(Tr::tr("bit #%1: %2").arg(b + 1).arg(bitNames.error().message()));
            def.bitFields.append({ bo.value(QLatin1String("bit")).toInt(),
                                   bo.value(QLatin1String("width")).toInt(1),
                                   bo.value(QLatin1String("name")).toString(), *bitNames });
        }
        def.storable = o.value(QLatin1String("storable")).toBool(false);
        def.pdoMappable = o.value(QLatin1String("pdo")).toBool(false);
        def.traceable = o.value(QLatin1String("trace")).toBool(false);
        def.description = o.value(QLatin1String("description")).toString();
        dict.insert(def);
    }
    const QJsonArray errors = root.value(QLatin1String("errors")).toArray();
    for (qsizetype i = 0; i < errors.size(); ++i) {
        const QJsonObject eo = errors.at(i).toObject();
        ErrorCodeDef def;
        toUInt(eo.value(QLatin1String("code")), &def.code);
        def.name = eo.value(QLatin1String("name")).toString();
        def.text = eo.value(QLatin1String("text")).toString();
        const auto texts = localTexts(eo, QLatin1String("text"));
        if (!texts)
            return Error(
                Error::Kind::Malformed,
                Tr::tr("%1: error #%2: %3").arg(origin).arg(i + 1).arg(texts.error().message()));
        def.localTexts = *texts;
        dict.insertErrorCode(def);
    }
    return dict;
}

} // namespace db
