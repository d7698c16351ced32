// Comparing parameter sets (device <-> file <-> defaults).

#include "parameterset.h"

#include <QCoreApplication>
#include <QSet>

#include <algorithm>

namespace db {

QString compareStatusName(CompareStatus status)
{
    switch (status) {
    case CompareStatus::Unchanged:
        return QStringLiteral("unchanged");
    case CompareStatus::Changed:
        return QStringLiteral("changed");
    case CompareStatus::Missing:
        return QStringLiteral("missing");
    case CompareStatus::Unknown:
        return QStringLiteral("unknown");
    }
    return {};
}

QString CompareRow::valueText(int side, codec::TextFormat format) const
{
    const QVariant v = values.value(side);
    if (!v.isValid())
        return QStringLiteral("-");
    return codec::toText(type, v, format);
}

int ParameterComparison::count(CompareStatus status) const
{
    return int(std::count_if(rows.cbegin(), rows.cend(),
                             [status](const CompareRow &r) { return r.status == status; }));
}

int ParameterComparison::differingCount() const
{
    return int(
        std::count_if(rows.cbegin(), rows.cend(), [](const CompareRow &r) { return r.differs; }));
}

QString ParameterComparison::countsText() const
{
    return QStringLiteral("%1 unchanged, %2 changed, %3 missing, %4 unknown")
        .arg(count(CompareStatus::Unchanged))
        .arg(count(CompareStatus::Changed))
        .arg(count(CompareStatus::Missing))
        .arg(count(CompareStatus::Unknown));
}

Result<void> checkSameAddressFormat(const QList<ParameterSet> &sides, const QStringList &sideNames)
{
    for (qsizetype i = 1; i < sides.size(); ++i) {
        const AddressFormat &a = *sides.first().addressFormat;
        const AddressFormat &b = *sides.at(i).addressFormat;
        if (a.key() != b.key())
            return Error(Error::Kind::InvalidArgument,
                         QCoreApplication::translate(
                             "db::ParameterSet",
                             "%1 has %2 addresses (like %3) but %4 has %5 addresses (like %6): "
                             "the same address names different objects, so they cannot be "
                             "compared")
                             .arg(sideNames.value(0), a.key(), a.example(), sideNames.value(i),
                                  b.key(), b.example()));
    }
    return {};
}

ParameterComparison compareParameterSets(const QList<ParameterSet> &sides,
                                         const QStringList &sideNames,
                                         const ObjectDictionary *dictionary)
{
    ParameterComparison out;
    out.sideNames = sideNames;
    if (!sides.isEmpty())
        out.addressFormat = sides.first().addressFormat;
    QList<ObjectAddress> all;
    for (const ParameterSet &set : sides)
        all += set.addresses();
    std::sort(all.begin(), all.end());
    all.erase(std::unique(all.begin(), all.end()), all.end());

    for (const ObjectAddress address : all) {
        CompareRow row;
        row.address = address;
        const ObjectDef *def = dictionary ? dictionary->find(address) : nullptr;
        const ParameterEntry *first = nullptr;
        for (const ParameterSet &set : sides) {
            if ((first = set.find(address)))
                break;
        }
        row.type = def ? def->type : first->type;
        row.name = def ? def->name : first->name;
        row.unit = def ? def->unit : first->unit;
        bool absent = false;
        for (const ParameterSet &set : sides) {
            const ParameterEntry *e = set.find(address);
            if (!e) {
                absent = true;
                row.values.append(QVariant());
                continue;
            }
            // Normalise with the common type so "0x10" from a file equals 16 from a device; a
            // value the type refuses is kept as it is and so compares unequal.
            const auto norm = codec::normalize(row.type, e->raw);
            row.values.append(norm ? norm.value() : e->raw);
        }
        bool equal = !absent;
        for (qsizetype i = 1; equal && i < row.values.size(); ++i)
            equal = row.values.at(i) == row.values.at(0);
        row.differs = !equal;
        if (dictionary && !def)
            row.status = CompareStatus::Unknown;
        else if (absent)
            row.status = CompareStatus::Missing;
        else
            row.status = equal ? CompareStatus::Unchanged : CompareStatus::Changed;
        out.rows.append(row);
    }
    return out;
}

} // namespace db
