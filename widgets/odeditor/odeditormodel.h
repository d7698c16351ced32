#pragma once

// The object dictionary as a tree for the editor: groups (communication,
// manufacturer, profile) -> objects -> sub-indices, with the device's last known value of each
// sub-index and the state of the last request for it. Definitions come from the dictionary
// (ARCHITECTURE.md habit 4); values only from setValue(). No I/O and no widgets here: an edit
// only emits writeRequested(), the owner of the connection sends it.

#include "core/objectdictionary.h"

#include <QAbstractItemModel>
#include <QHash>

namespace db::widgets {

// Value <-> text for the editor: physical value for scaled numeric objects, enumeration names,
// hex on request. Pure.
namespace odtext {
// The text shown in a cell: "1200 mm", "1 (Profile position)", "0x0427". Words with named bits
// and identifiers (device type, identity, COB-IDs, PDO mapping entries) are always shown in hex.
// withUnit false: without the unit (the editor shows it in a column of its own). Enumeration
// names in the language the program speaks; English with `english` (for what is written to files).
QString display(const ObjectDef &def, const QVariant &raw, bool hex, bool withUnit = true,
                bool english = false);
// True for objects always shown in hex (see display()).
bool isShownInHex(const ObjectDef &def);
// The text an editor starts with: like display() but without unit and enumeration name.
QString edit(const ObjectDef &def, const QVariant &raw, bool hex);
// User text -> raw, checked against type, the object's limits and its access. Scaled objects take
// the physical value; enumeration names are accepted.
// Errors name the object as `format` writes addresses.
Result<QVariant> parse(const ObjectDef &def, const QString &text,
                       const AddressFormat &format = AddressFormat::canopen());
// "0 … 65535" (scaled and hex like display()); empty when the object states no limit.
QString limits(const ObjectDef &def, bool hex);
} // namespace odtext

class OdEditorModel : public QAbstractItemModel
{
    Q_OBJECT
public:
    enum Column {
        Address,
        Name,
        Type,
        AccessColumn,
        Value,
        Unit,
        Default,
        Limits,
        Pdo,
        ColumnCount,
        // Parameter lists with data sets (hasDataSetColumns()): one value column per data set
        // after the others; Value is then data set 0 (single parameters).
        DataSet1 = ColumnCount,
        DataSetColumnCount = DataSet1 + 4,
    };
    enum Role {
        AddressRole = Qt::UserRole + 1, // ObjectAddress of a sub-index row (invalid otherwise)
        StatusTextRole, // "writing…", the device's error; shown next to the value
        StatusKindRole, // int(CellState)
        RawValueRole, // the last raw value read or written
        FilterTextRole, // address, names and value text, lower case, for the filter
    };
    enum class CellState { Unknown, Fresh, Writing, Written, ReadFailed, WriteFailed, Refused };
    Q_ENUM(CellState)
    // The CANopen ranges for hex dictionaries; one Parameters group for parameter lists.
    enum class Group { Communication, Manufacturer, Profile, Other, Extra, Parameters };

    static constexpr const char *kMimeType = "application/x-drivebench-objects";

    explicit OdEditorModel(QObject *parent = nullptr);

    // Replaces every object (values and states are forgotten).
    void setDictionary(const ObjectDictionary &dictionary);
    const ObjectDictionary &dictionary() const { return m_dictionary; }
    // How addresses are shown, dragged and searched: the connection's. Without one set, the
    // dictionary's. Call before setDictionary() (it does not rebuild).
    void setAddressFormat(const AddressFormat *format) { m_addressFormat = format; }
    const AddressFormat &addressFormat() const
    {
        return m_addressFormat ? *m_addressFormat : m_dictionary.addressFormat();
    }
    // Adds an object the description does not know (read/write by index), in group "Not in
    // description". Known addresses are left as they are.
    void addExtraObject(const ObjectDef &def);
    // True for parameter lists whose parameters have data sets (NUMBER:1 .. NUMBER:4): a
    // parameter is one row, its data sets 1-4 are columns DataSet1.., and Value holds single
    // parameters (data set 0).
    bool hasDataSetColumns() const { return m_dataSetColumns; }
    // Value and, with data-set columns, DataSet1..4.
    bool isValueColumn(int column) const
    {
        return column == Value
            || (m_dataSetColumns && column >= DataSet1 && column < DataSetColumnCount);
    }
    // Null for addresses not in the tree.
    const ObjectDef *definition(ObjectAddress address) const;
    QList<ObjectAddress> addresses() const; // every sub-index, in tree order

    // Values from the device; these never trigger a write.
    void setValue(ObjectAddress address, const QVariant &raw);
    void setReadFailed(ObjectAddress address, const QString &message);
    // Write lifecycle, driven by the owner of the connection.
    void setWriting(ObjectAddress address, const QVariant &raw);
    void setWriteFinished(ObjectAddress address, bool ok, const QString &message = {});
    // Forgets every value and state (e.g. another device).
    void clearValues();

    CellState state(ObjectAddress address) const;
    QVariant value(ObjectAddress address) const;
    QString statusText(ObjectAddress address) const;

    bool isHex() const { return m_hex; }
    void setHex(bool hex);
    // Whether value cells may be edited at all (connected device).
    bool isEditable() const { return m_editable; }
    void setEditable(bool editable);

    QModelIndex indexOf(ObjectAddress address, int column = Address) const;
    // The sub-index of a row, or nothing for group rows and objects with several sub-indices.
    // With data-set columns: the data set of a DataSet column's cell, else the parameter's
    // first value (data set 0 of a single parameter, data set 1 otherwise).
    std::optional<ObjectAddress> addressAt(const QModelIndex &index) const;
    // Every value address of a row: its data sets 1-4 with data-set columns, else addressAt().
    QList<ObjectAddress> valueAddressesAt(const QModelIndex &index) const;
    // Every sub-index under the rows of `indexes` (objects give all their sub-indices).
    QList<ObjectAddress> addressesUnder(const QModelIndexList &indexes) const;

    QModelIndex index(int row, int column, const QModelIndex &parent = {}) const override;
    QModelIndex parent(const QModelIndex &child) const override;
    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;
    Qt::ItemFlags flags(const QModelIndex &index) const override;
    // Value column, EditRole: text parsed by odtext::parse(); refused input (editRefused) is
    // never sent; accepted input emits writeRequested(). Returns whether it was accepted.
    bool setData(const QModelIndex &index, const QVariant &value, int role = Qt::EditRole) override;
    QStringList mimeTypes() const override;
    // kMimeType and text/plain: one ObjectAddress::toString() per line, UTF-8.
    QMimeData *mimeData(const QModelIndexList &indexes) const override;

Q_SIGNALS:
    void writeRequested(db::ObjectAddress address, const QVariant &raw);
    void editRefused(db::ObjectAddress address, const QString &reason);

private:
    struct Node
    {
        int parent = -1;
        QList<int> children;
        Group group = Group::Other;
        quint16 index = 0; // object rows
        std::optional<ObjectAddress> address; // leaf rows (sub-index or single sub 0 object)
        QString title; // group and object rows
        bool dataSets = false; // a parameter row with data-set columns (address is data set 1)
    };
    struct Cell
    {
        QVariant raw;
        CellState state = CellState::Unknown;
        QString message;
    };

    void rebuild();
    int addNode(Node node);
    int groupNode(Group group);
    void insertObject(int group, const QList<ObjectDef> &subs);
    int nodeOf(const QModelIndex &index) const;
    QModelIndex indexOfNode(int node, int column) const;
    void cellChanged(ObjectAddress address);
    QVariant leafData(const ObjectDef &def, int column, int role) const;
    QVariant objectData(const Node &node, int column, int role) const;
    // The address of a value cell (Value or a DataSet column), nothing for other cells.
    std::optional<ObjectAddress> cellAddress(const Node &node, int column) const;

    ObjectDictionary m_dictionary;
    const AddressFormat *m_addressFormat = nullptr; // null: the dictionary's
    QMap<ObjectAddress, ObjectDef> m_extra;
    QList<Node> m_nodes; // m_nodes[0] is the invisible root
    QHash<ObjectAddress, int> m_leafNode;
    QHash<ObjectAddress, Cell> m_cells;
    bool m_hex = false;
    bool m_editable = false;
    bool m_dataSetColumns = false;
};

QString groupName(OdEditorModel::Group group);

} // namespace db::widgets
