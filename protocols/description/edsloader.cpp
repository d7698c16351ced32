// CiA 306 EDS/DCF loader. Section and key names are case-insensitive (CiA 306 4.1); numbers
// are decimal, 0x-hex or octal with a leading 0 (4.6.2).
#include "edsloader.h"
#include "core/filereader.h"

#include "edsinifile.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QHash>
#include <QRegularExpression>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::core)
};
} // namespace

namespace db {

namespace {

using eds::Section;

class EdsReader
{
public:
    EdsReader(const QString &origin, const DescriptionOptions &options)
        : m_origin(origin)
        , m_options(options)
    { }
    Result<DescriptionLoad> read(const QByteArray &data);

private:
    const Section *section(const QString &name) const { return m_ini.section(name); }
    void warn(const QString &where, const QString &what)
    {
        m_load.warnings << where + QLatin1String(": ") + what;
    }
    void readHeader();
    void readObject(quint16 index, const Section &s);
    void readCompact(quint16 index, const Section &s, int count);
    ObjectDef makeDef(ObjectAddress address, const Section &s, const QString &where);
    void applyValue(ObjectDef &def, const Section &s, const char *key, const QString &where);

    QString m_origin;
    DescriptionOptions m_options;
    std::optional<quint8> m_nodeId;
    eds::IniFile m_ini;
    QMap<quint16, QMap<quint8, const Section *>> m_subs;
    DescriptionLoad m_load;
};

Result<DescriptionLoad> EdsReader::read(const QByteArray &data)
{
    m_ini = eds::IniFile::parse(description::decodeText(data), &m_load.warnings);
    if (m_ini.sections.isEmpty())
        return Error(Error::Kind::Malformed,
                     Tr::tr("%1 is not an EDS/DCF: no [sections] found").arg(m_origin));

    static const QRegularExpression objectRe(QStringLiteral("^[0-9A-F]{4}$"));
    static const QRegularExpression subRe(QStringLiteral("^([0-9A-F]{4})SUB([0-9A-F]{1,2})$"));
    static const QRegularExpression auxRe(QStringLiteral("^[0-9A-F]{4}(NAME|VALUE|DENOTATION)$"));
    static const QRegularExpression lookalikeRe(QStringLiteral("^[0-9A-F]{3,}(SUB.*)?$"));
    QMap<quint16, const Section *> objects;
    for (auto it = m_ini.sections.cbegin(); it != m_ini.sections.cend(); ++it) {
        const QString &key = it.key();
        if (objectRe.match(key).hasMatch()) {
            objects.insert(quint16(key.toUInt(nullptr, 16)), &it.value());
        } else if (const auto m = subRe.match(key); m.hasMatch()) {
            m_subs[quint16(m.captured(1).toUInt(nullptr, 16))].insert(
                quint8(m.captured(2).toUInt(nullptr, 16)), &it.value());
        } else if (!auxRe.match(key).hasMatch() && lookalikeRe.match(key).hasMatch()) {
            warn(QStringLiteral("[%1]").arg(it->name),
                 QStringLiteral("looks like an object but is not a valid object section name; "
                                "ignored"));
        }
    }
    if (objects.isEmpty())
        return Error(Error::Kind::Malformed,
                     Tr::tr("%1 is not an EDS/DCF: it has no object sections ([1000], "
                            "[1018], ...)")
                         .arg(m_origin));

    const QString suffix = QFileInfo(m_origin).suffix().toLower();
    m_load.format = suffix == QLatin1String("dcf")      ? DescriptionLoad::Format::Dcf
        : suffix == QLatin1String("eds")                ? DescriptionLoad::Format::Eds
        : section(QStringLiteral("DeviceComissioning")) ? DescriptionLoad::Format::Dcf
                                                        : DescriptionLoad::Format::Eds;
    readHeader();
    m_nodeId = m_options.nodeId ? m_options.nodeId : m_load.nodeId;
    eds::checkObjectLists(m_ini, objects, &m_load.warnings);
    for (auto it = objects.cbegin(); it != objects.cend(); ++it)
        readObject(it.key(), *it.value());
    for (auto it = m_subs.cbegin(); it != m_subs.cend(); ++it) {
        if (!objects.contains(it.key()))
            warn(QStringLiteral("[%1sub%2]")
                     .arg(it.key(), 4, 16, QLatin1Char('0'))
                     .arg(it->firstKey(), 0, 16),
                 QStringLiteral("sub-index without its object section; ignored"));
    }
    if (m_load.dictionary.isEmpty())
        return Error(
            Error::Kind::Malformed,
            Tr::tr("%1: none of its object sections describes a usable object").arg(m_origin));
    return m_load;
}

void EdsReader::readHeader()
{
    DeviceIdentity &id = m_load.dictionary.identity;
    id.descriptionFile = m_origin;
    if (const Section *info = section(QStringLiteral("FileInfo"))) {
        id.descriptionVersion = info->value("fileversion");
        if (info->has("filerevision"))
            id.descriptionVersion += QLatin1Char('.') + info->value("filerevision");
    } else {
        warn(QStringLiteral("[FileInfo]"), QStringLiteral("missing"));
    }
    const Section *dev = section(QStringLiteral("DeviceInfo"));
    if (!dev) {
        warn(QStringLiteral("[DeviceInfo]"), QStringLiteral("missing; vendor and product unknown"));
    } else {
        id.vendorName = dev->value("vendorname");
        id.productName = dev->value("productname");
        id.revision = dev->value("revisionnumber");
        const struct
        {
            const char *key;
            quint32 *target;
        } numbers[] = { { "vendornumber", &id.vendorId }, { "productnumber", &id.productCode } };
        for (const auto &n : numbers) {
            if (!dev->has(n.key) || dev->value(n.key).isEmpty())
                continue;
            const auto v = description::parseInteger(dev->value(n.key), true);
            if (v && *v >= 0 && *v <= 0xFFFFFFFFLL)
                *n.target = quint32(*v);
            else
                warn(QStringLiteral("[DeviceInfo]"),
                     QStringLiteral("%1 '%2' is not a number")
                         .arg(QLatin1String(n.key), dev->value(n.key)));
        }
    }
    const Section *com = section(QStringLiteral("DeviceComissioning"));
    if (!com)
        com = section(QStringLiteral("DeviceCommissioning"));
    if (com) {
        const auto node = description::parseInteger(com->value("nodeid"), true);
        if (node && *node >= 1 && *node <= 127)
            m_load.nodeId = quint8(*node);
        else if (com->has("nodeid"))
            warn(QStringLiteral("[DeviceComissioning]"),
                 QStringLiteral("NodeID '%1' is not 1..127").arg(com->value("nodeid")));
        const auto rate = description::parseInteger(com->value("baudrate"), true);
        if (rate && *rate > 0)
            m_load.bitrateKbit = quint32(*rate);
    }
}

void EdsReader::readObject(quint16 index, const Section &s)
{
    const QString where = QStringLiteral("[%1]").arg(s.name);
    // CiA 306 4.6.3: ObjectType defaults to VAR (7) when absent.
    const auto objectType =
        s.has("objecttype") ? description::parseInteger(s.value("objecttype"), true) : 7;
    if (!objectType) {
        warn(where,
             Tr::tr("ObjectType '%1' is not a number; object skipped").arg(s.value("objecttype")));
        return;
    }
    if (index < 0x1000 || *objectType == 5 || *objectType == 6) {
        ++m_load.typeDefinitions; // DEFTYPE/DEFSTRUCT: data type area, not device objects
        return;
    }
    const auto subs = m_subs.value(index);
    switch (*objectType) {
    case 0: // NULL
        warn(where, Tr::tr("NULL object skipped"));
        return;
    case 2: // DOMAIN
    case 7: // VAR
        if (!subs.isEmpty())
            warn(where, Tr::tr("a VAR/DOMAIN with sub-index sections; those are ignored"));
        m_load.dictionary.insert(makeDef(ObjectAddress(index, 0), s, where));
        return;
    case 8: // ARRAY
    case 9: // RECORD
        break;
    default:
        warn(where,
             Tr::tr("unknown ObjectType %1; read as %2")
                 .arg(s.value("objecttype"),
                      subs.isEmpty() ? QStringLiteral("VAR") : QStringLiteral("RECORD")));
        if (subs.isEmpty()) {
            m_load.dictionary.insert(makeDef(ObjectAddress(index, 0), s, where));
            return;
        }
    }
    const int compact = int(description::parseInteger(s.value("compactsubobj"), true).value_or(0));
    if (compact > 0 && compact <= 254)
        return readCompact(index, s, compact);
    if (subs.isEmpty()) {
        warn(where, Tr::tr("ARRAY/RECORD without sub-index sections; skipped"));
        return;
    }
    const QString name = s.value("parametername");
    const int stated = int(description::parseInteger(s.value("subnumber"), true).value_or(-1));
    if (stated != subs.size())
        warn(where,
             Tr::tr("SubNumber=%1 but %2 sub-index sections are present")
                 .arg(s.has("subnumber") ? s.value("subnumber") : QStringLiteral("(none)"))
                 .arg(subs.size()));
    const quint8 highest = subs.lastKey();
    if (!subs.contains(0)) {
        warn(where, Tr::tr("no sub-index 0; made one (UNSIGNED8, ro, %1)").arg(highest));
        ObjectDef def;
        def.address = ObjectAddress(index, 0);
        def.name = QStringLiteral("Highest sub-index supported");
        def.objectName = name;
        def.type = DataType::Unsigned8;
        def.access = Access::ReadOnly;
        def.defaultValue = QVariant::fromValue<qulonglong>(highest);
        m_load.dictionary.insert(def);
    }
    for (auto it = subs.cbegin(); it != subs.cend(); ++it) {
        const QString subWhere = QStringLiteral("[%1]").arg(it.value()->name);
        ObjectDef def = makeDef(ObjectAddress(index, it.key()), *it.value(), subWhere);
        def.objectName = name;
        if (it.key() == 0 && def.type != DataType::Unsigned8)
            warn(subWhere,
                 Tr::tr("sub-index 0 should be UNSIGNED8 (number of entries), "
                        "is %1")
                     .arg(datatype::name(def.type)));
        // In 1003h and the PDO mappings sub-index 0 counts entries in use, not the highest one.
        const bool countsInUse = index == 0x1003 || (index >= 0x1600 && index < 0x1800)
            || (index >= 0x1A00 && index < 0x1C00);
        if (it.key() == 0 && !countsInUse && datatype::isUnsignedInteger(def.type)
            && def.defaultValue.isValid() && def.defaultValue.toULongLong() < highest)
            warn(subWhere,
                 Tr::tr("default %1 is below the highest sub-index present (%2)")
                     .arg(def.defaultValue.toULongLong())
                     .arg(highest));
        m_load.dictionary.insert(def);
    }
}

// CiA 306 4.5.2.3: CompactSubObj=N describes sub-indices 1..N alike; sub-index 0 is UNSIGNED8 ro
// with value N. Names come from [xxxxName], values (DCF) from [xxxxValue].
void EdsReader::readCompact(quint16 index, const Section &s, int count)
{
    const QString where = QStringLiteral("[%1]").arg(s.name);
    const QString hex = QStringLiteral("%1").arg(index, 4, 16, QLatin1Char('0'));
    const Section *names = section(hex + QLatin1String("Name"));
    const Section *values = section(hex + QLatin1String("Value"));
    const QString name = s.value("parametername");
    ObjectDef sub0;
    sub0.address = ObjectAddress(index, 0);
    sub0.name = QStringLiteral("Number of entries");
    sub0.objectName = name;
    sub0.type = DataType::Unsigned8;
    sub0.access = Access::ReadOnly;
    sub0.defaultValue = QVariant::fromValue<qulonglong>(quint64(count));
    m_load.dictionary.insert(sub0);
    const ObjectDef base = makeDef(ObjectAddress(index, 1), s, where);
    for (int i = 1; i <= count; ++i) {
        ObjectDef def = base;
        def.address = ObjectAddress(index, quint8(i));
        def.objectName = name;
        def.name = name + QString::number(i);
        const QString key = QString::number(i);
        if (names && names->values.contains(key))
            def.name = names->values.value(key);
        m_load.dictionary.insert(def);
        if (m_load.nodeIdDefaults.contains(base.address))
            m_load.nodeIdDefaults.insert(def.address, m_load.nodeIdDefaults.value(base.address));
        if (values && values->values.contains(key)) {
            const auto v =
                description::parseValue(def.type, values->values.value(key), m_nodeId, true);
            if (v.raw.isValid())
                m_load.values.insert(def.address, v.raw);
            else if (!v.error.isEmpty())
                warn(QStringLiteral("[%1Value]").arg(hex), v.error);
        }
    }
    m_load.values.remove(base.address); // ParameterValue of the compact section itself is moot
}

ObjectDef EdsReader::makeDef(ObjectAddress address, const Section &s, const QString &where)
{
    ObjectDef def;
    def.address = address;
    def.name = s.value("parametername");
    if (def.name.isEmpty()) {
        def.name = QStringLiteral("Object %1").arg(address.toString());
        warn(where, Tr::tr("no ParameterName; called '%1'").arg(def.name));
    }
    const bool isDomain = description::parseInteger(s.value("objecttype"), true) == 2;
    if (!s.has("datatype")) {
        def.type = DataType::Domain;
        if (!isDomain)
            warn(where, Tr::tr("no DataType; read as DOMAIN"));
    } else {
        const auto code = description::parseInteger(s.value("datatype"), true);
        const auto type = code ? datatype::fromCode(quint32(*code)) : std::nullopt;
        def.type = type.value_or(DataType::Domain);
        if (!type)
            warn(
                where,
                Tr::tr("DataType %1 is not a basic type; read as DOMAIN").arg(s.value("datatype")));
    }
    const QString acc = s.value("accesstype").toLower();
    if (acc == QLatin1String("ro"))
        def.access = Access::ReadOnly;
    else if (acc == QLatin1String("wo"))
        def.access = Access::WriteOnly;
    else if (acc == QLatin1String("const"))
        def.access = Access::Const;
    else if (acc == QLatin1String("rw") || acc == QLatin1String("rwr")
             || acc == QLatin1String("rww"))
        def.access = Access::ReadWrite; // rwr/rww only hint the PDO direction
    else
        warn(where,
             acc.isEmpty() ? QStringLiteral("no AccessType; read as rw")
                           : QStringLiteral("AccessType '%1' unknown; read as rw").arg(acc));
    if (s.has("pdomapping")) {
        const auto pdo = description::parseInteger(s.value("pdomapping"), true);
        if (!pdo)
            warn(where, Tr::tr("PDOMapping '%1' is not 0/1").arg(s.value("pdomapping")));
        def.pdoMappable = pdo.value_or(0) != 0;
    }
    if (s.has("objflags") && !description::parseInteger(s.value("objflags"), true))
        warn(where, Tr::tr("ObjFlags '%1' is not a number").arg(s.value("objflags")));
    def.traceable = def.pdoMappable && datatype::isNumeric(def.type);
    def.unit = s.value("unit");
    def.description = s.value("description");
    if (s.has("factor") && !s.value("factor").isEmpty()) {
        bool ok = false;
        const double factor = s.value("factor").toDouble(&ok);
        if (ok && factor != 0.0)
            def.factor = factor;
        else
            warn(where, Tr::tr("Factor '%1' is not a number").arg(s.value("factor")));
    }
    for (const char *key : { "defaultvalue", "lowlimit", "highlimit", "parametervalue" })
        applyValue(def, s, key, where);
    if (datatype::isNumeric(def.type) && def.minimum.isValid() && def.maximum.isValid()
        && !codec::checkLimits(def.type, def.minimum, QVariant(), def.maximum))
        warn(where,
             Tr::tr("LowLimit %1 is above HighLimit %2")
                 .arg(s.value("lowlimit"), s.value("highlimit")));
    return def;
}

void EdsReader::applyValue(ObjectDef &def, const Section &s, const char *key, const QString &where)
{
    if (!s.has(key))
        return;
    const auto v = description::parseValue(def.type, s.value(key), m_nodeId, true);
    const QString keyName = QString::fromLatin1(key);
    if (!v.error.isEmpty()) {
        warn(where, Tr::tr("%1 ignored: %2").arg(keyName, v.error));
        return;
    }
    if (v.nodeIdRelative) {
        if (key[0] == 'd')
            m_load.nodeIdDefaults.insert(def.address, v.offset);
        else
            warn(where, Tr::tr("%1 '%2' needs a node id; ignored").arg(keyName, s.value(key)));
        return;
    }
    if (key[0] == 'd') {
        def.defaultValue = v.raw;
        if (s.value(key).contains(QLatin1String("$NODEID"), Qt::CaseInsensitive))
            m_load.nodeIdDefaults.insert(def.address, v.raw.toLongLong() - *m_nodeId);
    } else if (key[0] == 'l') {
        def.minimum = v.raw;
    } else if (key[0] == 'h') {
        def.maximum = v.raw;
    } else if (v.raw.isValid()) {
        m_load.values.insert(def.address, v.raw);
    }
}

} // namespace

Result<DescriptionLoad> loadEds(const QString &path, const DescriptionOptions &options)
{
    const Result<QByteArray> bytes =
        files::readAll(path, files::kDescriptionLimit, Tr::tr("a device description"));
    if (!bytes)
        return bytes.error();
    return parseEds(*bytes, path, options);
}

Result<DescriptionLoad> parseEds(const QByteArray &data, const QString &origin,
                                 const DescriptionOptions &options)
{
    if (description::looksBinary(data))
        return Error(Error::Kind::Malformed,
                     Tr::tr("%1 holds binary data, not an EDS/DCF").arg(origin));
    return EdsReader(origin, options).read(data);
}

} // namespace db
