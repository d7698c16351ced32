#pragma once

#include "core/objectdictionary.h"

#include <QDateTime>
#include <QList>
#include <QStringList>
#include <QVariant>

namespace db {

// One object of a parameter set.
struct ParameterEntry
{
    ObjectAddress address;
    QString name;
    DataType type = DataType::Unsigned32;
    QVariant raw; // canonical raw value of `type` (codec::normalize)
    QString unit;

    friend bool operator==(const ParameterEntry &, const ParameterEntry &) = default;
};

// The values of a device's parameters at one moment, with who they belong to (ARCHITECTURE.md,
// protocols/core). A value type: cheap to copy, no connection, no I/O except load/save.
//
// File format (text, UTF-8, one record per line, diffs well; see README "Parameter sets"):
//
//   # drivebench parameter set          <- magic, first line
//   format 1                            <- format version; newer versions are refused
//   addresses parameter                 <- how the addresses below are written: "parameter"
//                                          (decimal NUMBER:DATASET) or "canopen" (hex INDEX:SUB);
//                                          written for non-CANopen sets only: files without
//                                          the line are canopen
//   vendor 0x000002D6 "Fullmo"          <- identity: id + quoted name
//   product 0x00000001 "MovingCap"      <- "unknown" instead of the number: not read (below)
//   revision "1.2"
//   serial "0x00012345"                 <- the unit's serial number (CANopen 1018h.4); only
//                                          written when the device reported one
//   description "resources/devices/movingcap_eth.json" "1.0"   <- file + version
//   source "refgo://127.0.0.1:10001"
//   created 2026-11-21T21:00:00Z
//   entries 2                           <- number of object lines that follow
//   6083:0 "Profile acceleration" UNSIGNED32 100000 "mm/s²"
//   1A00:1 "Mapped object 1" UNSIGNED32 0x60410010 ""
//   end                                 <- end marker; a file without it is truncated
//
// Strings are double-quoted with \" \\ \n \t \r escapes, so names with spaces, commas and quotes
// are safe; other control characters (C0, DEL, C1, bidi overrides, U+2028/9: what
// db::printable() escapes) are written as \xNN or \uNNNN, so that the file can be shown on a
// terminal and read back to the same text. Value text is codec::toText (decimal; strings quoted,
// bytes as quoted hex). Lines starting with '#' after the first line and blank lines are ignored.
class ParameterSet
{
public:
    static constexpr int kFormatVersion = 1;

    // identity.descriptionFile / descriptionVersion name the description the set was read with.
    DeviceIdentity identity;
    // False when a backup could not read the device's 1018h.1 / 1018h.2: identity.vendorId /
    // productCode are then 0 and mean nothing, the file says "unknown" instead of a number, and
    // a restore cannot check the product against the set.
    bool vendorIdKnown = true;
    bool productCodeKnown = true;
    // The unit's serial number as the device reported it (CANopen 1018h.4 as "0x0001E240");
    // empty when not read. Two units of one product differ only here.
    QString serialNumber;
    QString source; // URI or file the values came from ("defaults" for defaults())
    // How the addresses are written in the file and in messages: the device's format (an
    // address means a different object in another format, so sets of different formats are
    // never compared or restored across). Never null.
    const AddressFormat *addressFormat = &AddressFormat::canopen();
    QDateTime created; // UTC

    // Sorted by address, one entry per address.
    const QList<ParameterEntry> &entries() const { return m_entries; }
    int size() const { return int(m_entries.size()); }
    bool isEmpty() const { return m_entries.isEmpty(); }
    bool contains(ObjectAddress address) const { return find(address) != nullptr; }
    // Null when absent. The pointer is valid until the set is changed.
    const ParameterEntry *find(ObjectAddress address) const;
    QList<ObjectAddress> addresses() const;
    // Raw values by address (e.g. for writeDcf()).
    QMap<ObjectAddress, QVariant> values() const;

    // Inserts in address order, replacing an entry with the same address.
    void insert(const ParameterEntry &entry);
    bool remove(ObjectAddress address);

    // The text format above. Never fails for a set whose values are canonical raw values.
    // comments go after the header as "# " lines (control characters escaped), which the
    // loader skips: notes for people, e.g. the objects a partial backup could not read.
    QByteArray serialize(const QStringList &comments = {}) const;
    // Atomic (QSaveFile): either the whole new file or the old one stays.
    Result<void> save(const QString &path, const QStringList &comments = {}) const;

    // Errors name the origin and the line: "set.dbp:7: value 'x' is not a UNSIGNED16".
    // Kind Malformed for corrupt/truncated/foreign content, Io when the file cannot be read.
    static Result<ParameterSet> load(const QString &path);
    static Result<ParameterSet> parse(const QByteArray &bytes, const QString &origin);

    // A 32-bit identity number (revision, serial number) as the set writes it: "0x0001E240".
    static QString identityNumber(quint32 value);

    // The description's defaults: every storable object that states a default value.
    static ParameterSet defaults(const ObjectDictionary &dictionary);

private:
    QList<ParameterEntry> m_entries;
};

// ---- Comparison (device <-> file <-> defaults) ----

enum class CompareStatus {
    Unchanged, // present on every side with equal values
    Changed, // present on every side, some value differs
    Missing, // absent on at least one side
    Unknown, // not in the description given to compare() (takes precedence over the others;
             // values are still shown, and `differs` says whether they differ)
};

QString compareStatusName(CompareStatus status); // "unchanged", "changed", ...

struct CompareRow
{
    ObjectAddress address;
    QString name; // from the description, else from the first side that has it
    DataType type = DataType::Unsigned32;
    QString unit;
    // One per side in the order given to compare(); invalid QVariant = absent on that side.
    // Values are normalised raw values (codec::normalize with `type`).
    QList<QVariant> values;
    CompareStatus status = CompareStatus::Unchanged;
    // True when the sides do not all hold the same value (Changed, Missing, or an Unknown row
    // whose values differ or is absent somewhere).
    bool differs = false;

    // codec::toText of side `side`'s value; "-" when absent.
    QString valueText(int side, codec::TextFormat format = codec::TextFormat::Decimal) const;
};

struct ParameterComparison
{
    QStringList sideNames; // as given to compare()
    QList<CompareRow> rows; // sorted by address, the union of all sides' addresses
    // How the rows' addresses are written: the reference side's format. Never null.
    const AddressFormat *addressFormat = &AddressFormat::canopen();

    int count(CompareStatus status) const;
    int differingCount() const; // rows with differs == true
    bool identical() const { return differingCount() == 0; }
    // "12 unchanged, 2 changed, 1 missing, 0 unknown"
    QString countsText() const;
};

// Compares `sides` (2 or 3 sets; sides[0] is the reference, e.g. device, file, defaults).
// Values are compared after codec::normalize with the description's type (else the entry's),
// so "0x10" read from a file and 16 read from a device are equal. `dictionary` may be null:
// then no row is Unknown.
ParameterComparison compareParameterSets(const QList<ParameterSet> &sides,
                                         const QStringList &sideNames,
                                         const ObjectDictionary *dictionary = nullptr);
// Sets whose addresses are written in different formats hold different objects under the same
// address: an InvalidArgument error naming the first side that differs from sides[0].
Result<void> checkSameAddressFormat(const QList<ParameterSet> &sides, const QStringList &sideNames);

} // namespace db
