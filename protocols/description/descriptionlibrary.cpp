#include "descriptionlibrary.h"
#include "core/filewriter.h"

#include "devicedescription.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSaveFile>

namespace db {

namespace {
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::description)
};

QString hex32(quint32 v)
{
    return QString::number(v, 16).rightJustified(8, QLatin1Char('0')).toUpper() + QLatin1Char('h');
}

// How well an entry fits: 0 = not at all. Product named > whole family; revision equal > any
// revision > another revision.
int score(const LibraryEntry &e, const IdentityNumbers &id)
{
    if (e.vendorId != id.vendorId)
        return 0;
    int s = 0;
    if (e.productCode) {
        if (*e.productCode != id.productCode)
            return 0;
        s += 10;
    } else {
        s += 5;
    }
    if (e.revision && id.revision && *e.revision == *id.revision)
        s += 3;
    else if (!e.revision)
        s += 2;
    else
        s += 1;
    return s;
}

} // namespace

QString IdentityNumbers::toString() const
{
    QString text = Tr::tr("vendor %1, product %2").arg(hex32(vendorId), hex32(productCode));
    if (revision)
        text += Tr::tr(", revision %1").arg(hex32(*revision));
    return text;
}

std::optional<quint32> parseRevision(const QString &text)
{
    const auto n = description::parseInteger(text.trimmed(), false);
    if (!n || *n < 0 || *n > 0xFFFFFFFFLL)
        return std::nullopt;
    return quint32(*n);
}

QStringList DescriptionLibrary::filePatterns()
{
    return { QStringLiteral("*.eds"), QStringLiteral("*.dcf"), QStringLiteral("*.xdd"),
             QStringLiteral("*.xdc"), QStringLiteral("*.json") };
}

void DescriptionLibrary::addBuiltin(LibraryEntry entry)
{
    m_builtin.append(std::move(entry));
}

void DescriptionLibrary::setFolder(const QString &path)
{
    m_folder = path;
}

void DescriptionLibrary::rescan()
{
    m_files.clear();
    m_warnings.clear();
    if (m_folder.isEmpty())
        return;
    const QDir dir(m_folder);
    if (!dir.exists())
        return; // no folder yet: nothing added so far
    const QFileInfoList files = dir.entryInfoList(filePatterns(), QDir::Files | QDir::Readable,
                                                  QDir::Name | QDir::IgnoreCase);
    for (const QFileInfo &file : files) {
        const QString path = file.absoluteFilePath();
        auto loaded = loadDeviceDescription(path);
        if (!loaded) {
            m_warnings.append(loaded.error().message());
            continue;
        }
        const DeviceIdentity &id = loaded->dictionary.identity;
        if (id.vendorId == 0) {
            m_warnings.append(
                Tr::tr("%1 states no vendor id: it cannot be matched to a device").arg(path));
            continue;
        }
        LibraryEntry entry;
        entry.name = id.productName.isEmpty() ? file.fileName() : id.productName;
        entry.origin = path;
        entry.vendorId = id.vendorId;
        entry.productCode = id.productCode;
        entry.revision = parseRevision(id.revision);
        entry.load = [path](quint8 node) -> Result<ObjectDictionary> {
            DescriptionOptions options;
            options.nodeId = node;
            auto again = loadDeviceDescription(path, options);
            if (!again)
                return again.error();
            return again->dictionary;
        };
        m_files.append(entry);
    }
}

QList<LibraryEntry> DescriptionLibrary::entries() const
{
    return m_builtin + m_files;
}

std::optional<LibraryEntry> DescriptionLibrary::match(const IdentityNumbers &identity) const
{
    std::optional<LibraryEntry> best;
    int bestScore = 0;
    // Files first: on equal scores the first one found stays.
    for (const QList<LibraryEntry> *list : { &m_files, &m_builtin }) {
        for (const LibraryEntry &e : *list) {
            const int s = score(e, identity);
            if (s > bestScore) {
                best = e;
                bestScore = s;
            }
        }
    }
    return best;
}

Result<QString> DescriptionLibrary::addFile(const QString &path)
{
    if (m_folder.isEmpty())
        return Error(Error::Kind::InvalidArgument,
                     Tr::tr("no description folder is set to add %1 to").arg(path));
    auto loaded = loadDeviceDescription(path);
    if (!loaded)
        return loaded.error();
    const QFileInfo source(path);
    if (!QDir().mkpath(m_folder))
        return Error(Error::Kind::Io, Tr::tr("cannot create the folder %1").arg(m_folder));
    const QString target = QDir(m_folder).absoluteFilePath(source.fileName());
    if (QFileInfo(target) == source) {
        rescan();
        return target;
    }
    QFile in(path);
    if (!in.open(QIODevice::ReadOnly))
        return Error(Error::Kind::Io, Tr::tr("cannot read %1: %2").arg(path, in.errorString()));
    db::files::removeStaleTemporaries(target); // what a killed writer left
    QSaveFile out(target);
    if (!out.open(QIODevice::WriteOnly) || out.write(in.readAll()) < 0 || !out.commit())
        return Error(Error::Kind::Io, Tr::tr("cannot write %1: %2").arg(target, out.errorString()));
    rescan();
    return target;
}

} // namespace db
