#include "dcfwriter.h"
#include "core/filewriter.h"

#include "descriptionlibrary.h"
#include "devicedescription.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QSaveFile>
#include <QTextStream>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::core)
};
} // namespace

namespace db {

namespace {

QString oneLine(QString text)
{
    text.replace(QLatin1String("\r\n"), QLatin1String(" "));
    text.replace(QLatin1Char('\n'), QLatin1Char(' '));
    text.replace(QLatin1Char('\r'), QLatin1Char(' '));
    return text;
}

QString hex32(quint32 v)
{
    return QStringLiteral("0x%1")
        .arg(v, 8, 16, QLatin1Char('0'))
        .toUpper()
        .replace(QLatin1String("0X"), QLatin1String("0x"));
}

QString accessText(Access access)
{
    return access::name(access);
}

// A number of the identity object (1018h) as the device reported it in `values`, else the
// description's when it states one; nothing when neither knows it (never a made-up 0).
std::optional<quint32> identityNumber(const QMap<ObjectAddress, QVariant> &values, quint8 sub,
                                      std::optional<quint32> fromDescription)
{
    bool ok = false;
    const qulonglong v = values.value(ObjectAddress(0x1018, sub)).toULongLong(&ok);
    if (ok && v <= 0xFFFFFFFFULL)
        return quint32(v);
    return fromDescription;
}

std::optional<quint32> nonZero(quint32 v)
{
    return v != 0 ? std::optional<quint32>(v) : std::nullopt;
}

void writeEntry(QTextStream &out, const ObjectDef &def, const QMap<ObjectAddress, QVariant> &values)
{
    out << "ParameterName=" << oneLine(def.name) << '\n'
        << "ObjectType=0x7\n"
        << "DataType=0x" << QStringLiteral("%1").arg(quint16(def.type), 4, 16, QLatin1Char('0'))
        << '\n'
        << "AccessType=" << accessText(def.access) << '\n'
        << "PDOMapping=" << (def.pdoMappable ? 1 : 0) << '\n';
    if (def.defaultValue.isValid())
        out << "DefaultValue=" << oneLine(description::valueText(def.type, def.defaultValue))
            << '\n';
    if (def.minimum.isValid())
        out << "LowLimit=" << description::valueText(def.type, def.minimum) << '\n';
    if (def.maximum.isValid())
        out << "HighLimit=" << description::valueText(def.type, def.maximum) << '\n';
    if (!def.unit.isEmpty())
        out << "Unit=" << oneLine(def.unit) << '\n';
    if (def.factor != 1.0)
        out << "Factor=" << QString::number(def.factor, 'g', 17) << '\n';
    if (!def.description.isEmpty())
        out << "Description=" << oneLine(def.description) << '\n';
    const auto value = values.constFind(def.address);
    if (value != values.cend()) {
        const auto raw = codec::normalize(def.type, value.value());
        if (raw)
            out << "ParameterValue=" << oneLine(description::valueText(def.type, raw.value()))
                << '\n';
    }
    out << '\n';
}

// CiA 306 4.5.2: the three object lists, by index range.
void writeObjectLists(QTextStream &out, const QList<quint16> &indices)
{
    QList<quint16> mandatory, optional, manufacturer;
    for (quint16 index : indices) {
        if (index == 0x1000 || index == 0x1001 || index == 0x1018)
            mandatory << index;
        else if (index >= 0x2000 && index < 0x6000)
            manufacturer << index;
        else
            optional << index;
    }
    const struct
    {
        const char *name;
        const QList<quint16> &list;
    } lists[] = { { "MandatoryObjects", mandatory },
                  { "OptionalObjects", optional },
                  { "ManufacturerObjects", manufacturer } };
    for (const auto &l : lists) {
        out << '[' << l.name << "]\nSupportedObjects=" << l.list.size() << '\n';
        for (qsizetype i = 0; i < l.list.size(); ++i)
            out << i + 1 << "=0x"
                << QStringLiteral("%1").arg(l.list.at(i), 4, 16, QLatin1Char('0')).toUpper()
                << '\n';
        out << '\n';
    }
}

} // namespace

QByteArray dcfText(const ObjectDictionary &dictionary, const QMap<ObjectAddress, QVariant> &values,
                   const DcfCommissioning &commissioning, const QDateTime &now)
{
    QByteArray bytes;
    QTextStream out(&bytes);
    out.setEncoding(QStringConverter::Utf8);
    const DeviceIdentity &id = dictionary.identity;
    const QString time = now.toString(QStringLiteral("hh:mmAP"));
    const QString date = now.toString(QStringLiteral("MM-dd-yyyy"));
    out << "[FileInfo]\nFileVersion=1\nFileRevision=0\nEDSVersion=4.0\n"
        << "Description=configuration of " << oneLine(id.productName) << '\n'
        << "CreationTime=" << time << "\nCreationDate=" << date << '\n'
        << "CreatedBy=drivebench\n"
        << "ModificationTime=" << time << "\nModificationDate=" << date << '\n'
        << "ModifiedBy=drivebench\n";
    if (!id.descriptionFile.isEmpty())
        out << "LastEDS=" << QFileInfo(id.descriptionFile).fileName() << '\n';
    // CiA 306 4.6: the numbers are Unsigned32; the device's own 1018h wins over the description.
    const auto vendor = identityNumber(values, 1, nonZero(id.vendorId));
    const auto product = identityNumber(values, 2, nonZero(id.productCode));
    const auto revision = identityNumber(values, 3, parseRevision(id.revision));
    out << "\n[DeviceInfo]\nVendorName=" << oneLine(id.vendorName) << '\n';
    if (vendor)
        out << "VendorNumber=" << hex32(*vendor) << '\n';
    out << "ProductName=" << oneLine(id.productName) << '\n';
    if (product)
        out << "ProductNumber=" << hex32(*product) << '\n';
    if (revision)
        out << "RevisionNumber=" << hex32(*revision) << '\n';
    out << '\n';
    out << "[DeviceComissioning]\n";
    if (commissioning.nodeId > 0)
        out << "NodeID=" << commissioning.nodeId << '\n';
    out << "NodeName=" << oneLine(commissioning.nodeName) << '\n';
    if (commissioning.bitrateKbit > 0)
        out << "Baudrate=" << commissioning.bitrateKbit << '\n';
    out << "NetNumber=0\n\n";

    QMap<quint16, QList<ObjectDef>> byIndex;
    for (const ObjectDef &def : dictionary.objects())
        byIndex[def.address.index].append(def);
    writeObjectLists(out, byIndex.keys());

    for (auto it = byIndex.cbegin(); it != byIndex.cend(); ++it) {
        const QList<ObjectDef> &subs = it.value();
        const QString hex = QStringLiteral("%1").arg(it.key(), 4, 16, QLatin1Char('0')).toUpper();
        if (subs.size() == 1 && subs.first().address.sub == 0
            && subs.first().objectName.isEmpty()) {
            out << '[' << hex << "]\n";
            writeEntry(out, subs.first(), values);
            continue;
        }
        bool sameType = subs.size() > 1;
        for (const ObjectDef &def : subs)
            sameType &= def.address.sub == 0 || def.type == subs.last().type;
        const QString name =
            subs.first().objectName.isEmpty() ? subs.first().name : subs.first().objectName;
        out << '[' << hex << "]\nParameterName=" << oneLine(name) << '\n'
            << "ObjectType=" << (sameType ? "0x8" : "0x9") << '\n'
            << "SubNumber=" << subs.size() << "\n\n";
        for (const ObjectDef &def : subs) {
            out << '[' << hex << "sub" << QString::number(def.address.sub, 16).toUpper() << "]\n";
            writeEntry(out, def, values);
        }
    }
    out.flush();
    return bytes;
}

Result<void> writeDcf(const QString &path, const ObjectDictionary &dictionary,
                      const QMap<ObjectAddress, QVariant> &values,
                      const DcfCommissioning &commissioning)
{
    db::files::removeStaleTemporaries(path); // what a killed writer left
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return Error(Error::Kind::Io, Tr::tr("cannot write %1: %2").arg(path, file.errorString()));
    const QByteArray text = dcfText(dictionary, values, commissioning);
    if (file.write(text) != text.size() || !file.commit())
        return Error(Error::Kind::Io, Tr::tr("cannot write %1: %2").arg(path, file.errorString()));
    return {};
}

} // namespace db
