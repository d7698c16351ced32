#pragma once

// The descriptions drivebench can give a device it finds without being told which one: our own
// (compiled in, registered by the application) and the EDS/DCF/XDD/XDC/JSON files of a folder
// the user keeps. A device is matched by its identity (CiA 301 1018h: vendor id, product code,
// revision number).

#include "core/objectdictionary.h"
#include "core/result.h"

#include <QStringList>

#include <functional>
#include <optional>

namespace db {

// 1018h sub 1..3 as a device reports them. The revision is optional: not every device has 1018h:03.
struct IdentityNumbers
{
    quint32 vendorId = 0;
    quint32 productCode = 0;
    std::optional<quint32> revision;

    // "vendor 000000ECh, product 00000071h, revision 00010001h"
    QString toString() const;
};

// One description the library can give.
struct LibraryEntry
{
    QString name; // "NM172", "MovingCap ETH"
    QString origin; // the file's path, or "built-in"
    quint32 vendorId = 0;
    std::optional<quint32> productCode; // nullopt: every product of the vendor (a family)
    std::optional<quint32> revision; // nullopt: every revision
    // The dictionary for a node id ($NODEID defaults resolved). Called once per match.
    std::function<Result<ObjectDictionary>(quint8 nodeId)> load;
};

class DescriptionLibrary
{
public:
    // File name patterns the folder is searched for (case-insensitive).
    static QStringList filePatterns();

    // Our own descriptions. Entries added later do not replace earlier ones.
    void addBuiltin(LibraryEntry entry);

    // The user's folder; read by rescan(). An empty path means none.
    void setFolder(const QString &path);
    QString folder() const { return m_folder; }
    // Reads every description file in the folder (not its subfolders). Files that cannot be
    // used (unreadable, no vendor id) are skipped with one warning line each.
    void rescan();
    const QStringList &warnings() const { return m_warnings; }
    // Built-ins first, then the folder's files (as of the last rescan()).
    QList<LibraryEntry> entries() const;

    // The best entry for a device: same vendor and product (an entry for the vendor's whole
    // family if no entry names the product), the same revision preferred over another one. Among
    // equally good entries the user's files win over ours, since the user put them there.
    // nullopt when nothing has the vendor and product.
    std::optional<LibraryEntry> match(const IdentityNumbers &identity) const;

    // Copies a description file into the folder (atomically; an existing file of that name is
    // replaced) after checking that it loads, then rescans. Returns the new path. Fails with a
    // message naming the cause when no folder is set, the file does not load or the copy fails.
    Result<QString> addFile(const QString &path);

private:
    QList<LibraryEntry> m_builtin;
    QList<LibraryEntry> m_files;
    QString m_folder;
    QStringList m_warnings;
};

// Revision text of a description ("0x00010001", "65537") as a number; nullopt for free text
// ("1.0", "manual rev. 0").
std::optional<quint32> parseRevision(const QString &text);

} // namespace db
