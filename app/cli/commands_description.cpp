#include "commands_description.h"

#include "core/printable.h"
#include "description/devicedescription.h"

#include <QCoreApplication>
#include <QSet>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(cli)
};
} // namespace

namespace db::cli {

namespace {

QString hex32(quint32 v)
{
    return QStringLiteral("0x%1").arg(v, 8, 16, QLatin1Char('0'));
}

// "UNSIGNED16 226, UNSIGNED8 97, ..." most frequent first.
QString countsText(const QMap<QString, int> &counts)
{
    QList<std::pair<QString, int>> sorted;
    for (auto it = counts.cbegin(); it != counts.cend(); ++it)
        sorted.append({ it.key(), it.value() });
    std::stable_sort(sorted.begin(), sorted.end(),
                     [](const auto &a, const auto &b) { return a.second > b.second; });
    QStringList parts;
    for (const auto &[name, count] : sorted)
        parts << QStringLiteral("%1 %2").arg(name).arg(count);
    return parts.join(QLatin1String(", "));
}

} // namespace

int edsCheck(Context &c)
{
    const QString path = c.args.at(0);
    const auto loaded = loadDeviceDescription(path);
    if (!loaded) {
        // The message names the file and the cause; Error::toString() would call a broken file
        // a "malformed answer", which fits devices, not files.
        c.err << "drivebench-cli: " << loaded.error().message() << Qt::endl;
        return ExitFailure;
    }
    const DescriptionLoad &load = loaded.value();
    const ObjectDictionary &dict = load.dictionary;
    const DeviceIdentity &id = dict.identity;

    QSet<quint16> indices;
    QMap<QString, int> byType;
    QMap<QString, int> byAccess;
    int pdo = 0;
    for (const ObjectDef &def : dict.objects()) {
        indices.insert(def.address.index);
        byType[datatype::name(def.type)] += 1;
        byAccess[access::name(def.access)] += 1;
        pdo += def.pdoMappable ? 1 : 0;
    }
    QTextStream &o = c.out;
    // Everything but the counts is quoted from the file (or is its name): one line each.
    o << "file:         " << printable(path) << Qt::endl;
    o << "format:       " << formatName(load.format) << Qt::endl;
    o << "vendor:       " << printable(id.vendorName) << " (" << hex32(id.vendorId) << ')'
      << Qt::endl;
    o << "product:      " << printable(id.productName) << " (" << hex32(id.productCode) << ')'
      << Qt::endl;
    o << "revision:     " << printable(id.revision) << Qt::endl;
    o << "file version: " << printable(id.descriptionVersion) << Qt::endl;
    o << "objects:      " << indices.size() << " (" << dict.size() << " sub-objects)" << Qt::endl;
    o << "by type:      " << countsText(byType) << Qt::endl;
    o << "by access:    " << countsText(byAccess) << Qt::endl;
    o << "PDO-mappable: " << pdo << Qt::endl;
    if (!load.nodeIdDefaults.isEmpty())
        o << "$NODEID defaults: " << load.nodeIdDefaults.size()
          << (load.nodeId ? Tr::tr(" (resolved for node %1)").arg(*load.nodeId)
                          : Tr::tr(" (symbolic, no node id)"))
          << Qt::endl;
    if (load.nodeId || load.bitrateKbit)
        o << "commissioning: node id " << (load.nodeId ? QString::number(*load.nodeId) : u"-"_qs)
          << ", bitrate "
          << (load.bitrateKbit ? QStringLiteral("%1 kbit/s").arg(*load.bitrateKbit) : u"-"_qs)
          << Qt::endl;
    if (!load.values.isEmpty())
        o << "configured values: " << load.values.size() << Qt::endl;
    if (load.typeDefinitions > 0)
        o << "type definitions: " << load.typeDefinitions << " (not loaded as objects)" << Qt::endl;
    o << "warnings:     " << load.warnings.size() << Qt::endl;
    for (const QString &w : load.warnings)
        o << "warning: " << printable(w) << Qt::endl;
    return ExitOk;
}

} // namespace db::cli
