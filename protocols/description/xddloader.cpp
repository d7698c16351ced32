// CiA 311 XDD/XDC loader. Element and attribute names follow CiA 311 (ISO 15745 profile
// container, ProfileBody_Device_CANopen and ProfileBody_CommunicationNetwork_CANopen).
#include "xddloader.h"
#include "core/filereader.h"

#include "xddparameter.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QHash>
#include <QXmlStreamReader>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::core)
};
} // namespace

namespace db {

namespace {

using xdd::Parameter;
using xdd::typeFromIecName;

struct ObjectRecord
{
    QXmlStreamAttributes attributes;
    QList<QXmlStreamAttributes> subs;
    qint64 line = 0;
};

class XddReader
{
public:
    XddReader(const QString &origin, const DescriptionOptions &options)
        : m_origin(origin)
        , m_options(options)
    { }
    Result<DescriptionLoad> read(const QByteArray &data);

private:
    void warn(const QString &where, const QString &what)
    {
        m_load.warnings << where + QLatin1String(": ") + what;
    }
    void readObject(const ObjectRecord &record);
    ObjectDef makeDef(ObjectAddress address, const QXmlStreamAttributes &a, const QString &where);
    QString text(const QXmlStreamAttributes &a, const char *name) const
    {
        return a.value(QLatin1String(name)).toString().trimmed();
    }

    QString m_origin;
    DescriptionOptions m_options;
    std::optional<quint8> m_nodeId;
    QXmlStreamReader m_xml;
    QHash<QString, Parameter> m_parameters;
    QList<ObjectRecord> m_objects;
    bool m_haveObjectList = false;
    bool m_haveActualValues = false;
    DescriptionLoad m_load;
};

Result<DescriptionLoad> XddReader::read(const QByteArray &data)
{
    m_xml.addData(data);
    DeviceIdentity &id = m_load.dictionary.identity;
    bool vendorSeen = false;
    bool productSeen = false;
    bool rootSeen = false;
    while (!m_xml.atEnd()) {
        if (m_xml.readNext() != QXmlStreamReader::StartElement)
            continue;
        const QString name = m_xml.name().toString();
        const QXmlStreamAttributes a = m_xml.attributes();
        if (!rootSeen) {
            rootSeen = true;
            if (name != QLatin1String("ISO15745ProfileContainer")
                && name != QLatin1String("ISO15745Profile"))
                return Error(Error::Kind::Malformed,
                             Tr::tr("%1 is XML but not an XDD/XDC: the root element is "
                                    "<%2>, not <ISO15745ProfileContainer>")
                                 .arg(m_origin, name));
        }
        if (name == QLatin1String("ProfileBody") && id.descriptionVersion.isEmpty()) {
            id.descriptionVersion = text(a, "fileVersion");
        } else if (name == QLatin1String("parameter")) {
            const Parameter p = xdd::readParameter(m_xml);
            if (!p.uniqueId.isEmpty())
                m_parameters.insert(p.uniqueId, p);
        } else if (name == QLatin1String("vendorName")) {
            id.vendorName = m_xml.readElementText().trimmed();
        } else if (name == QLatin1String("productName")) {
            id.productName = m_xml.readElementText().trimmed();
        } else if (name == QLatin1String("vendorID") || name == QLatin1String("productID")) {
            // DeviceIdentity (device profile) first, then the communication profile's identity
            const bool vendor = name == QLatin1String("vendorID");
            const QString value = m_xml.readElementText().trimmed();
            const auto number = description::parseInteger(value, false);
            quint32 &target = vendor ? id.vendorId : id.productCode;
            bool &seen = vendor ? vendorSeen : productSeen;
            if (!number || *number < 0 || *number > 0xFFFFFFFFLL) {
                if (!value.isEmpty())
                    warn(QStringLiteral("<%1>").arg(name),
                         QStringLiteral("'%1' is not a number").arg(value));
            } else if (!seen) {
                target = quint32(*number);
                seen = true;
            } else if (target != quint32(*number)) {
                warn(QStringLiteral("<%1>").arg(name),
                     QStringLiteral("%1 differs from the DeviceIdentity's 0x%2")
                         .arg(value)
                         .arg(target, 0, 16));
            }
        } else if (name == QLatin1String("version") && id.revision.isEmpty()) {
            id.revision = m_xml.readElementText().trimmed();
        } else if (name == QLatin1String("CANopenObjectList")) {
            m_haveObjectList = true;
        } else if (name == QLatin1String("CANopenObject")) {
            m_objects.append({ a, {}, m_xml.lineNumber() });
            m_haveActualValues |= a.hasAttribute(QLatin1String("actualValue"));
        } else if (name == QLatin1String("CANopenSubObject")) {
            if (m_objects.isEmpty())
                warn(Tr::tr("line %1").arg(m_xml.lineNumber()),
                     QStringLiteral("CANopenSubObject outside a CANopenObject; ignored"));
            else
                m_objects.last().subs.append(a);
            m_haveActualValues |= a.hasAttribute(QLatin1String("actualValue"));
        } else if (name == QLatin1String("deviceCommissioning")) {
            const auto node = description::parseInteger(text(a, "nodeID"), false);
            if (node && *node >= 1 && *node <= 127)
                m_load.nodeId = quint8(*node);
            const auto rate = description::parseInteger(text(a, "actualBaudRate"), false);
            if (rate && *rate > 0)
                m_load.bitrateKbit = quint32(*rate);
        }
    }
    if (m_xml.hasError())
        return Error(Error::Kind::Malformed,
                     Tr::tr("%1: XML error at line %2, column %3: %4")
                         .arg(m_origin)
                         .arg(m_xml.lineNumber())
                         .arg(m_xml.columnNumber())
                         .arg(m_xml.errorString()));
    if (!m_haveObjectList)
        return Error(Error::Kind::Malformed,
                     Tr::tr("%1: no CANopenObjectList; not a CANopen XDD/XDC").arg(m_origin));
    id.descriptionFile = m_origin;
    if (id.vendorName.isEmpty())
        warn(QStringLiteral("DeviceIdentity"), QStringLiteral("no vendorName"));

    const QString suffix = QFileInfo(m_origin).suffix().toLower();
    m_load.format = suffix == QLatin1String("xdc") ? DescriptionLoad::Format::Xdc
        : suffix == QLatin1String("xdd")           ? DescriptionLoad::Format::Xdd
        : m_haveActualValues                       ? DescriptionLoad::Format::Xdc
                                                   : DescriptionLoad::Format::Xdd;
    m_nodeId = m_options.nodeId ? m_options.nodeId : m_load.nodeId;
    for (const ObjectRecord &record : std::as_const(m_objects))
        readObject(record);
    if (m_load.dictionary.isEmpty())
        return Error(Error::Kind::Malformed,
                     Tr::tr("%1: the CANopenObjectList holds no usable object").arg(m_origin));
    return m_load;
}

void XddReader::readObject(const ObjectRecord &record)
{
    const QXmlStreamAttributes &a = record.attributes;
    const QString where =
        QStringLiteral("CANopenObject %1 (line %2)")
            .arg(text(a, "index").isEmpty() ? QStringLiteral("?") : text(a, "index"))
            .arg(record.line);
    bool ok = false;
    const uint index =
        text(a, "index").remove(QLatin1String("0x"), Qt::CaseInsensitive).toUInt(&ok, 16);
    if (!ok || index > 0xFFFF) {
        warn(where, Tr::tr("index '%1' is not a hex index; skipped").arg(text(a, "index")));
        return;
    }
    const QString typeText = text(a, "objectType");
    const int objectType =
        typeText.isEmpty() ? (record.subs.isEmpty() ? 7 : 9) : typeText.toInt(&ok, 16);
    if (typeText.isEmpty())
        warn(where,
             Tr::tr("no objectType; read as %1")
                 .arg(objectType == 7 ? QStringLiteral("VAR") : QStringLiteral("RECORD")));
    if (index < 0x1000 || objectType == 5 || objectType == 6) {
        ++m_load.typeDefinitions;
        return;
    }
    if (objectType == 7 || objectType == 2 || record.subs.isEmpty()) {
        if (objectType == 8 || objectType == 9) {
            warn(where, Tr::tr("ARRAY/RECORD without CANopenSubObjects; skipped"));
            return;
        }
        if (!record.subs.isEmpty())
            warn(where, Tr::tr("VAR with CANopenSubObjects; those are ignored"));
        m_load.dictionary.insert(makeDef(ObjectAddress(quint16(index), 0), a, where));
        return;
    }
    const QString name = text(a, "name");
    const QString subNumber = text(a, "subNumber");
    if (!subNumber.isEmpty() && subNumber.toInt() != record.subs.size())
        warn(where,
             Tr::tr("subNumber=%1 but %2 CANopenSubObjects are present")
                 .arg(subNumber)
                 .arg(record.subs.size()));
    bool haveSub0 = false;
    for (const QXmlStreamAttributes &s : record.subs) {
        const uint sub = text(s, "subIndex").toUInt(&ok, 16);
        if (!ok || sub > 0xFF) {
            warn(where, Tr::tr("subIndex '%1' is not hex; skipped").arg(text(s, "subIndex")));
            continue;
        }
        haveSub0 |= sub == 0;
        const QString subWhere =
            where + QStringLiteral(" sub %1").arg(sub, 2, 16, QLatin1Char('0'));
        ObjectDef def = makeDef(ObjectAddress(quint16(index), quint8(sub)), s, subWhere);
        def.objectName = name;
        m_load.dictionary.insert(def);
    }
    if (!haveSub0)
        warn(where, Tr::tr("no sub-index 0 (number of entries)"));
}

ObjectDef XddReader::makeDef(ObjectAddress address, const QXmlStreamAttributes &a,
                             const QString &where)
{
    ObjectDef def;
    def.address = address;
    const QString ref = text(a, "uniqueIDRef");
    Parameter param;
    if (!ref.isEmpty()) {
        if (m_parameters.contains(ref))
            param = m_parameters.value(ref);
        else
            warn(where, Tr::tr("uniqueIDRef '%1' names no parameter").arg(ref));
    }
    def.name = text(a, "name");
    if (def.name.isEmpty())
        def.name = param.label;
    if (def.name.isEmpty()) {
        def.name = QStringLiteral("Object %1").arg(address.toString());
        warn(where, Tr::tr("no name; called '%1'").arg(def.name));
    }
    bool ok = false;
    const QString typeCode = text(a, "dataType");
    const auto type = typeCode.isEmpty() ? typeFromIecName(param.typeName)
                                         : datatype::fromCode(typeCode.toUInt(&ok, 16));
    def.type = type.value_or(DataType::Domain);
    if (!type)
        warn(where,
             typeCode.isEmpty()
                 ? QStringLiteral("no dataType; read as DOMAIN")
                 : QStringLiteral("dataType %1 is not a basic type; read as DOMAIN").arg(typeCode));
    QString acc = text(a, "accessType");
    if (acc.isEmpty()) {
        static const QHash<QString, QString> fromParameter = {
            { QStringLiteral("read"), QStringLiteral("ro") },
            { QStringLiteral("write"), QStringLiteral("wo") },
            { QStringLiteral("readWrite"), QStringLiteral("rw") },
            { QStringLiteral("readWriteInput"), QStringLiteral("rw") },
            { QStringLiteral("readWriteOutput"), QStringLiteral("rw") },
            { QStringLiteral("const"), QStringLiteral("const") },
        };
        acc = fromParameter.value(param.access);
    }
    acc = acc.toLower();
    if (acc == QLatin1String("rwr") || acc == QLatin1String("rww"))
        acc = QStringLiteral("rw");
    const auto access = access::fromName(acc);
    if (!access)
        warn(where,
             acc.isEmpty() ? QStringLiteral("no accessType; read as rw")
                           : QStringLiteral("accessType '%1' unknown; read as rw").arg(acc));
    def.access = access.value_or(Access::ReadWrite);
    const QString pdo = text(a, "PDOmapping");
    def.pdoMappable = !pdo.isEmpty() && pdo != QLatin1String("no");
    def.traceable = def.pdoMappable && datatype::isNumeric(def.type);
    def.description = param.description;
    const struct
    {
        const char *attribute;
        QString fallback;
        QVariant *target;
    } values[] = { { "defaultValue", param.defaultValue, &def.defaultValue },
                   { "lowLimit", param.minValue, &def.minimum },
                   { "highLimit", param.maxValue, &def.maximum },
                   { "actualValue", param.actualValue, nullptr } };
    for (const auto &v : values) {
        const QString given = text(a, v.attribute);
        const QString valueText = given.isEmpty() ? v.fallback : given;
        const auto parsed = description::parseValue(def.type, valueText, m_nodeId, false);
        if (!parsed.error.isEmpty())
            warn(where, Tr::tr("%1 ignored: %2").arg(QLatin1String(v.attribute), parsed.error));
        else if (parsed.nodeIdRelative && v.target == &def.defaultValue)
            m_load.nodeIdDefaults.insert(address, parsed.offset);
        else if (parsed.nodeIdRelative)
            warn(where,
                 Tr::tr("%1 '%2' needs a node id; ignored")
                     .arg(QLatin1String(v.attribute), valueText));
        else if (v.target)
            *v.target = parsed.raw;
        else if (parsed.raw.isValid())
            m_load.values.insert(address, parsed.raw);
        if (v.target == &def.defaultValue && m_nodeId && parsed.raw.isValid()
            && valueText.contains(QLatin1String("$NODEID"), Qt::CaseInsensitive))
            m_load.nodeIdDefaults.insert(address, parsed.raw.toLongLong() - *m_nodeId);
    }
    if (datatype::isInteger(def.type)) {
        for (auto it = param.allowed.cbegin(); it != param.allowed.cend(); ++it) {
            const auto v = description::parseInteger(it.key(), false);
            if (!v || it.value().isEmpty())
                continue;
            def.enumeration.insert(*v, it.value());
            // Labels in further languages; the English one is the enumeration's own.
            LocalTexts local = param.allowedLocal.value(it.key());
            local.remove(QStringLiteral("en"));
            if (!local.isEmpty())
                def.localEnumeration.insert(*v, local);
        }
    }
    return def;
}

} // namespace

Result<DescriptionLoad> loadXdd(const QString &path, const DescriptionOptions &options)
{
    const Result<QByteArray> bytes =
        files::readAll(path, files::kDescriptionLimit, Tr::tr("a device description"));
    if (!bytes)
        return bytes.error();
    return parseXdd(*bytes, path, options);
}

Result<DescriptionLoad> parseXdd(const QByteArray &data, const QString &origin,
                                 const DescriptionOptions &options)
{
    if (description::looksBinary(data))
        return Error(Error::Kind::Malformed,
                     Tr::tr("%1 holds binary data, not an XDD/XDC").arg(origin));
    return XddReader(origin, options).read(data);
}

} // namespace db
