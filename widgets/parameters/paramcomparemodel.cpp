#include "paramcomparemodel.h"

#include "widgets/common/widgetstyle.h"

#include "core/printable.h"

namespace db::widgets {

QColor compareStatusColor(CompareStatus status)
{
    switch (status) {
    case CompareStatus::Unchanged:
        return style::okColor();
    case CompareStatus::Changed:
        return style::warningColor();
    case CompareStatus::Missing:
        return style::errorColor();
    case CompareStatus::Unknown:
        return style::inactiveColor();
    }
    return {};
}

ParamCompareModel::ParamCompareModel(QObject *parent)
    : QAbstractTableModel(parent)
{ }

void ParamCompareModel::setComparison(const ParameterComparison &comparison,
                                      const ParameterSet &defaults,
                                      const ObjectDictionary &dictionary)
{
    beginResetModel();
    m_comparison = comparison;
    m_defaults = defaults;
    m_dictionary = dictionary;
    m_selected.clear();
    endResetModel();
    selectDifferences();
}

bool ParamCompareModel::isRestorable(int row) const
{
    if (row < 0 || row >= m_comparison.rows.size())
        return false;
    const CompareRow &r = m_comparison.rows[row];
    const ObjectDef *def = m_dictionary.find(r.address);
    return r.values.size() > 1 && r.values[1].isValid() && def && def->writable();
}

QList<ObjectAddress> ParamCompareModel::selection() const
{
    QList<ObjectAddress> result;
    for (const CompareRow &r : m_comparison.rows) {
        if (m_selected.contains(r.address))
            result.append(r.address);
    }
    return result;
}

void ParamCompareModel::setSelected(ObjectAddress address, bool selected)
{
    for (int row = 0; row < m_comparison.rows.size(); ++row) {
        if (m_comparison.rows[row].address != address)
            continue;
        if (selected && !isRestorable(row))
            return;
        if (selected == m_selected.contains(address))
            return;
        if (selected)
            m_selected.insert(address);
        else
            m_selected.remove(address);
        Q_EMIT dataChanged(index(row, Select), index(row, Select), { Qt::CheckStateRole });
        Q_EMIT selectionChanged();
        return;
    }
}

void ParamCompareModel::selectDifferences()
{
    m_selected.clear();
    for (int row = 0; row < m_comparison.rows.size(); ++row) {
        const CompareRow &r = m_comparison.rows[row];
        // Device and file differ (a difference to the defaults alone is no reason to write).
        const bool differs = r.values.size() > 1 && r.values[0] != r.values[1];
        if (differs && isRestorable(row))
            m_selected.insert(r.address);
    }
    if (rowCount() > 0)
        Q_EMIT dataChanged(index(0, Select), index(rowCount() - 1, Select), { Qt::CheckStateRole });
    Q_EMIT selectionChanged();
}

void ParamCompareModel::selectNone()
{
    m_selected.clear();
    if (rowCount() > 0)
        Q_EMIT dataChanged(index(0, Select), index(rowCount() - 1, Select), { Qt::CheckStateRole });
    Q_EMIT selectionChanged();
}

void ParamCompareModel::setHex(bool hex)
{
    m_hex = hex;
    if (rowCount() > 0)
        Q_EMIT dataChanged(index(0, DeviceValue), index(rowCount() - 1, DefaultValue));
}

int ParamCompareModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_comparison.rows.size());
}

int ParamCompareModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QString ParamCompareModel::valueText(const CompareRow &row, int side) const
{
    QVariant raw;
    if (side == 2) {
        const ParameterEntry *e = m_defaults.find(row.address);
        raw = e ? e->raw : QVariant();
    } else if (side < row.values.size()) {
        raw = row.values[side];
    }
    if (!raw.isValid())
        return QStringLiteral("—");
    const auto format = m_hex ? codec::TextFormat::Hex : codec::TextFormat::Decimal;
    if (const ObjectDef *def = m_dictionary.find(row.address))
        return def->localDisplayText(raw, format);
    return codec::toText(row.type, raw, format);
}

QVariant ParamCompareModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() >= m_comparison.rows.size())
        return {};
    const CompareRow &r = m_comparison.rows[index.row()];
    const int column = index.column();
    if (role == DiffersRole)
        return r.values.size() > 1 && r.values[0] != r.values[1];
    if (role == AddressRole)
        return QVariant::fromValue(r.address);
    if (role == StatusRole)
        return int(r.status);
    if (role == Qt::CheckStateRole && column == Select)
        return m_selected.contains(r.address) ? Qt::Checked : Qt::Unchecked;
    if (role == Qt::FontRole && column != Name && column != Status && column != Select)
        return style::monospaceFont();
    if (role == Qt::ForegroundRole && column == Status)
        return compareStatusColor(r.status);
    if (role == Qt::ForegroundRole && column == DefaultValue)
        return style::inactiveColor();
    if (role == Qt::BackgroundRole && (column == DeviceValue || column == FileValue)
        && data(index, DiffersRole).toBool()) {
        QColor c = style::warningColor();
        c.setAlpha(40);
        return c;
    }
    if (role == Qt::ToolTipRole && column == Select && !isRestorable(index.row()))
        return tr("Not restorable: the file has no value, or the object is read-only or unknown");
    if (role != Qt::DisplayRole)
        return {};
    // Names and string values come from the file and the device: shown escaped, one line.
    switch (column) {
    case Address:
        return m_comparison.addressFormat->format(r.address);
    case Name:
        // The description's name in the program's language where it has one, else the file's.
        if (const ObjectDef *def = m_dictionary.find(r.address); def && def->name == r.name)
            return printable(def->displayName());
        return printable(r.name);
    case DeviceValue:
        return printable(valueText(r, 0));
    case FileValue:
        return printable(valueText(r, 1));
    case DefaultValue:
        return printable(valueText(r, 2));
    case Status:
        return compareStatusName(r.status);
    default:
        return {};
    }
}

bool ParamCompareModel::setData(const QModelIndex &index, const QVariant &value, int role)
{
    if (role != Qt::CheckStateRole || index.column() != Select || !index.isValid())
        return false;
    const bool on = value.toInt() == Qt::Checked;
    if (on && !isRestorable(index.row()))
        return false;
    setSelected(m_comparison.rows[index.row()].address, on);
    return true;
}

Qt::ItemFlags ParamCompareModel::flags(const QModelIndex &index) const
{
    Qt::ItemFlags f = QAbstractTableModel::flags(index);
    if (index.column() == Select) {
        if (isRestorable(index.row()))
            f |= Qt::ItemIsUserCheckable;
        else
            f &= ~Qt::ItemIsEnabled;
    }
    return f;
}

QVariant ParamCompareModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    const QStringList sides = m_comparison.sideNames;
    switch (section) {
    case Select:
        return QString();
    case Address:
        return m_comparison.addressFormat->key() == AddressFormat::canopen().key() ? tr("Index:Sub")
                                                                                   : tr("Address");
    case Name:
        return tr("Name");
    case DeviceValue:
        return sides.value(0, tr("Device"));
    case FileValue:
        return sides.value(1, tr("File"));
    case DefaultValue:
        return tr("Defaults");
    case Status:
        return tr("Status");
    }
    return {};
}

void ParamCompareFilter::setOnlyDifferences(bool only)
{
    if (only == m_onlyDifferences)
        return;
    m_onlyDifferences = only;
    invalidateFilter();
}

bool ParamCompareFilter::filterAcceptsRow(int sourceRow, const QModelIndex &sourceParent) const
{
    if (!m_onlyDifferences)
        return true;
    const QModelIndex i = sourceModel()->index(sourceRow, 0, sourceParent);
    const auto status = CompareStatus(i.data(ParamCompareModel::StatusRole).toInt());
    return status != CompareStatus::Unchanged;
}

} // namespace db::widgets
