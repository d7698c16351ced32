#pragma once

// Rows of a parameter-set comparison (device <-> file <-> defaults) for the compare page, with a
// check box per row that selects it for restore. No I/O; ParamCompareView fills it.

#include "parameters/parameterset.h"

#include <QAbstractTableModel>
#include <QSet>
#include <QSortFilterProxyModel>

namespace db::widgets {

class ParamCompareModel : public QAbstractTableModel
{
    Q_OBJECT
public:
    enum Column {
        Select,
        Address,
        Name,
        DeviceValue,
        FileValue,
        DefaultValue,
        Status,
        ColumnCount
    };
    enum Role { DiffersRole = Qt::UserRole + 1, AddressRole, StatusRole };

    explicit ParamCompareModel(QObject *parent = nullptr);

    // comparison.rows give the address set, status and the device (side 0) and file (side 1)
    // values; defaults fills the defaults column (it may or may not be a side of the comparison).
    // `dictionary` decides which rows can be restored (known and writable). The selection is
    // reset to selectDifferences().
    void setComparison(const ParameterComparison &comparison, const ParameterSet &defaults,
                       const ObjectDictionary &dictionary);
    const ParameterComparison &comparison() const { return m_comparison; }

    // Restorable: the file has a value and the object is known and writable.
    bool isRestorable(int row) const;
    QList<ObjectAddress> selection() const; // in address order
    void setSelected(ObjectAddress address, bool selected);
    void selectDifferences(); // every restorable row that differs
    void selectNone();

    bool isHex() const { return m_hex; }
    void setHex(bool hex);

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    bool setData(const QModelIndex &index, const QVariant &value, int role) override;
    Qt::ItemFlags flags(const QModelIndex &index) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

Q_SIGNALS:
    void selectionChanged();

private:
    QString valueText(const CompareRow &row, int side) const;

    ParameterComparison m_comparison;
    ParameterSet m_defaults;
    ObjectDictionary m_dictionary;
    QSet<ObjectAddress> m_selected;
    bool m_hex = false;
};

// "Only differences" for the compare table.
class ParamCompareFilter : public QSortFilterProxyModel
{
    Q_OBJECT
public:
    using QSortFilterProxyModel::QSortFilterProxyModel;
    bool onlyDifferences() const { return m_onlyDifferences; }
    void setOnlyDifferences(bool only);

protected:
    bool filterAcceptsRow(int sourceRow, const QModelIndex &sourceParent) const override;

private:
    bool m_onlyDifferences = false;
};

QColor compareStatusColor(CompareStatus status);

} // namespace db::widgets
