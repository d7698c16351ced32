#include "odeditormodel.h"

#include "widgets/common/widgetstyle.h"

#include <QMimeData>

namespace db::widgets {

namespace {
// A parameter described at data sets 1-4 (inverter parameter lists: four data sets).
bool hasAllDataSets(const ObjectDictionary &dictionary, quint16 parameter)
{
    for (quint8 ds = 1; ds <= 4; ++ds) {
        if (!dictionary.find(ObjectAddress(parameter, ds)))
            return false;
    }
    return true;
}

OdEditorModel::Group groupOf(quint16 index, const AddressFormat &format)
{
    if (format.key() != AddressFormat::canopen().key())
        return OdEditorModel::Group::Parameters;
    if (index >= 0x1000 && index <= 0x1FFF)
        return OdEditorModel::Group::Communication;
    if (index >= 0x2000 && index <= 0x5FFF)
        return OdEditorModel::Group::Manufacturer;
    if (index >= 0x6000 && index <= 0x9FFF)
        return OdEditorModel::Group::Profile;
    return OdEditorModel::Group::Other;
}

} // namespace

QString groupName(OdEditorModel::Group group)
{
    switch (group) {
    case OdEditorModel::Group::Communication:
        return OdEditorModel::tr("Communication (1000h–1FFFh)");
    case OdEditorModel::Group::Manufacturer:
        return OdEditorModel::tr("Manufacturer (2000h–5FFFh)");
    case OdEditorModel::Group::Profile:
        return OdEditorModel::tr("Device profile (6000h–9FFFh)");
    case OdEditorModel::Group::Other:
        return OdEditorModel::tr("Other");
    case OdEditorModel::Group::Extra:
        return OdEditorModel::tr("Not in the description");
    case OdEditorModel::Group::Parameters:
        return OdEditorModel::tr("Parameters");
    }
    return {};
}

OdEditorModel::OdEditorModel(QObject *parent)
    : QAbstractItemModel(parent)
{
    rebuild();
}

void OdEditorModel::setDictionary(const ObjectDictionary &dictionary)
{
    m_dictionary = dictionary;
    m_extra.clear();
    m_cells.clear();
    rebuild();
}

void OdEditorModel::addExtraObject(const ObjectDef &def)
{
    if (definition(def.address))
        return;
    m_extra.insert(def.address, def);
    rebuild();
}

const ObjectDef *OdEditorModel::definition(ObjectAddress address) const
{
    if (const ObjectDef *def = m_dictionary.find(address))
        return def;
    const auto it = m_extra.constFind(address);
    return it == m_extra.cend() ? nullptr : &*it;
}

namespace {
// A data-set row's data sets 1-4, or the row's one address.
QList<ObjectAddress> rowAddresses(ObjectAddress address, bool dataSets)
{
    if (!dataSets)
        return { address };
    QList<ObjectAddress> result;
    for (quint8 ds = 1; ds <= 4; ++ds)
        result.append(ObjectAddress(address.index, ds));
    return result;
}
} // namespace

QList<ObjectAddress> OdEditorModel::addresses() const
{
    QList<ObjectAddress> result;
    for (const Node &node : m_nodes) {
        if (node.address)
            result.append(rowAddresses(*node.address, node.dataSets));
    }
    return result;
}

void OdEditorModel::rebuild()
{
    beginResetModel();
    m_nodes.clear();
    m_leafNode.clear();
    m_nodes.append(Node {});
    m_dataSetColumns = false;
    if (addressFormat().key() == AddressFormat::parameter().key()) {
        for (const ObjectDef &def : m_dictionary.objects()) {
            if (def.address.sub == 4 && hasAllDataSets(m_dictionary, def.address.index)) {
                m_dataSetColumns = true;
                break;
            }
        }
    }
    // Objects in address order, each object's sub-indices together.
    const auto addAll = [this](const QList<ObjectDef> &defs, bool extra) {
        QList<ObjectDef> subs;
        const auto flush = [&] {
            if (subs.isEmpty())
                return;
            const Group group =
                extra ? Group::Extra : groupOf(subs.first().address.index, addressFormat());
            insertObject(groupNode(group), subs);
            subs.clear();
        };
        for (const ObjectDef &def : defs) {
            if (!subs.isEmpty() && subs.first().address.index != def.address.index)
                flush();
            subs.append(def);
        }
        flush();
    };
    addAll(m_dictionary.objects(), false);
    addAll(m_extra.values(), true);
    endResetModel();
}

int OdEditorModel::addNode(Node node)
{
    const int id = int(m_nodes.size());
    m_nodes[node.parent].children.append(id);
    if (node.address && node.dataSets) {
        for (quint8 ds = 0; ds <= 4; ++ds)
            m_leafNode.insert(ObjectAddress(node.address->index, ds), id);
    } else if (node.address) {
        m_leafNode.insert(*node.address, id);
    }
    m_nodes.append(std::move(node));
    return id;
}

int OdEditorModel::groupNode(Group group)
{
    for (int child : std::as_const(m_nodes[0].children)) {
        if (m_nodes[child].group == group)
            return child;
    }
    Node node;
    node.parent = 0;
    node.group = group;
    node.title = groupName(group);
    return addNode(node);
}

void OdEditorModel::insertObject(int group, const QList<ObjectDef> &subs)
{
    Node object;
    object.parent = group;
    object.group = m_nodes[group].group;
    object.index = subs.first().address.index;
    const ObjectDef &first = subs.first();
    const bool dataSets = m_dataSetColumns && hasAllDataSets(m_dictionary, object.index);
    if (dataSets) {
        // One row; its data sets are columns (data set 0, "all four", is not shown).
        object.address = ObjectAddress(object.index, 1);
        object.dataSets = true;
        object.title = first.objectName.isEmpty() ? first.displayName() : first.displayObjectName();
        addNode(object);
        return;
    }
    if (subs.size() == 1 && first.address.sub == 0) {
        object.address = first.address; // a plain variable: the object row is the value row
        addNode(object);
        return;
    }
    object.title = first.displayObjectName();
    if (object.title.isEmpty() || object.title.startsWith(QLatin1Char('\''))) {
        // No object name (or only its signature): the name of the first real sub-index.
        const auto named = std::find_if(subs.begin(), subs.end(),
                                        [](const ObjectDef &d) { return d.address.sub != 0; });
        object.title = named != subs.end() ? named->displayName() : first.displayName();
        if (!first.objectName.isEmpty())
            object.title += QLatin1Char(' ') + first.objectName;
    }
    const int id = addNode(object);
    for (const ObjectDef &def : subs) {
        Node leaf;
        leaf.parent = id;
        leaf.group = object.group;
        leaf.index = def.address.index;
        leaf.address = def.address;
        addNode(leaf);
    }
}

int OdEditorModel::nodeOf(const QModelIndex &index) const
{
    return index.isValid() ? int(index.internalId()) : 0;
}

QModelIndex OdEditorModel::indexOfNode(int node, int column) const
{
    if (node <= 0)
        return {};
    const int row = int(m_nodes[m_nodes[node].parent].children.indexOf(node));
    return createIndex(row, column, quintptr(node));
}

QModelIndex OdEditorModel::index(int row, int column, const QModelIndex &parent) const
{
    const int p = nodeOf(parent);
    if (row < 0 || column < 0 || column >= columnCount() || row >= m_nodes[p].children.size())
        return {};
    return createIndex(row, column, quintptr(m_nodes[p].children[row]));
}

QModelIndex OdEditorModel::parent(const QModelIndex &child) const
{
    return child.isValid() ? indexOfNode(m_nodes[nodeOf(child)].parent, 0) : QModelIndex();
}

int OdEditorModel::rowCount(const QModelIndex &parent) const
{
    if (parent.isValid() && parent.column() != 0)
        return 0;
    return int(m_nodes[nodeOf(parent)].children.size());
}

int OdEditorModel::columnCount(const QModelIndex &) const
{
    return m_dataSetColumns ? DataSetColumnCount : ColumnCount;
}

QModelIndex OdEditorModel::indexOf(ObjectAddress address, int column) const
{
    const int node = m_leafNode.value(address, -1);
    if (node > 0 && column == Value && m_nodes[node].dataSets && address.sub >= 1
        && address.sub <= 4)
        column = DataSet1 + address.sub - 1;
    return indexOfNode(node, column);
}

std::optional<ObjectAddress> OdEditorModel::cellAddress(const Node &node, int column) const
{
    if (!node.address)
        return std::nullopt;
    if (!node.dataSets)
        return column == Value ? node.address : std::nullopt;
    if (column >= DataSet1 && column < DataSetColumnCount)
        return ObjectAddress(node.address->index, quint8(column - DataSet1 + 1));
    return std::nullopt;
}

std::optional<ObjectAddress> OdEditorModel::addressAt(const QModelIndex &index) const
{
    if (!index.isValid())
        return std::nullopt;
    const Node &node = m_nodes[nodeOf(index)];
    if (const auto cell = cellAddress(node, index.column()))
        return cell;
    return node.address;
}

QList<ObjectAddress> OdEditorModel::valueAddressesAt(const QModelIndex &index) const
{
    if (!index.isValid())
        return {};
    const Node &node = m_nodes[nodeOf(index)];
    return node.address ? rowAddresses(*node.address, node.dataSets) : QList<ObjectAddress>();
}

QList<ObjectAddress> OdEditorModel::addressesUnder(const QModelIndexList &indexes) const
{
    QList<ObjectAddress> result;
    for (const QModelIndex &index : indexes) {
        const Node &node = m_nodes[nodeOf(index)];
        if (node.address) {
            for (ObjectAddress a : rowAddresses(*node.address, node.dataSets)) {
                if (!result.contains(a))
                    result.append(a);
            }
        }
        if (node.parent == 0)
            continue; // a whole group is too much to drag
        for (int child : node.children) {
            const auto a = m_nodes[child].address;
            if (a && !result.contains(*a))
                result.append(*a);
        }
    }
    return result;
}

QVariant OdEditorModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid())
        return {};
    const Node &node = m_nodes[nodeOf(index)];
    const int column = index.column();
    if (node.address && m_dataSetColumns && isValueColumn(column)) {
        // A value cell: data set 0 of a single parameter, or one data set of a data-set row.
        const auto address = cellAddress(node, column);
        const ObjectDef *def = address ? definition(*address) : nullptr;
        return def ? leafData(*def, Value, role) : QVariant();
    }
    if (node.address && node.dataSets) {
        // The parameter as a whole: its number and name; type, limits from data set 1.
        if ((column == Address || column == Name) && role != FilterTextRole)
            return objectData(node, column, role);
        if (const ObjectDef *def = definition(*node.address))
            return leafData(*def, column, role);
        return {};
    }
    if (node.address) {
        if (const ObjectDef *def = definition(*node.address))
            return leafData(*def, column, role);
        return {};
    }
    return objectData(node, column, role);
}

QVariant OdEditorModel::objectData(const Node &node, int column, int role) const
{
    if (role == Qt::FontRole && node.parent == 0) {
        QFont font;
        font.setBold(true);
        return font;
    }
    if (role == Qt::FontRole && column == Address)
        return style::monospaceFont();
    if (role == FilterTextRole)
        return QString(addressFormat().formatIndex(node.index) + QLatin1Char(' ') + node.title)
            .toLower();
    if (role != Qt::DisplayRole && role != Qt::ToolTipRole)
        return {};
    if (node.parent == 0)
        return column == Address ? node.title : QVariant();
    if (column == Address)
        return addressFormat().formatIndex(node.index);
    if (column == Name)
        return node.title;
    return {};
}

QVariant OdEditorModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case Address:
        return m_dataSetColumns ? tr("Parameter") : tr("Index:Sub");
    case Name:
        return tr("Name");
    case Type:
        return tr("Type");
    case AccessColumn:
        return tr("Access");
    case Value:
        return m_dataSetColumns ? tr("DS %1").arg(0) : tr("Value");
    case Unit:
        return tr("Unit");
    case Default:
        return tr("Default");
    case Limits:
        return tr("Min … Max");
    case Pdo:
        return tr("PDO");
    }
    if (m_dataSetColumns && section >= DataSet1 && section < DataSetColumnCount)
        return tr("DS %1").arg(section - DataSet1 + 1);
    return {};
}

Qt::ItemFlags OdEditorModel::flags(const QModelIndex &index) const
{
    if (!index.isValid())
        return Qt::NoItemFlags;
    Qt::ItemFlags f = Qt::ItemIsEnabled | Qt::ItemIsSelectable;
    const Node &node = m_nodes[nodeOf(index)];
    if (node.parent != 0)
        f |= Qt::ItemIsDragEnabled;
    const auto address = cellAddress(node, index.column());
    if (address && m_editable && state(*address) != CellState::Writing) {
        const ObjectDef *def = definition(*address);
        if (def && def->writable())
            f |= Qt::ItemIsEditable;
    }
    return f;
}

bool OdEditorModel::setData(const QModelIndex &index, const QVariant &value, int role)
{
    const auto address =
        index.isValid() ? cellAddress(m_nodes[nodeOf(index)], index.column()) : std::nullopt;
    const ObjectDef *def = address ? definition(*address) : nullptr;
    if (role != Qt::EditRole || !def)
        return false;
    if (!m_editable) {
        Q_EMIT editRefused(*address, tr("not connected"));
        return false;
    }
    auto raw = odtext::parse(*def, value.toString(), addressFormat());
    if (!raw) {
        Cell &cell = m_cells[*address];
        if (cell.state != CellState::Writing) {
            cell.state = CellState::Refused;
            cell.message = raw.error().message();
            cellChanged(*address);
        }
        Q_EMIT editRefused(*address, raw.error().message());
        return false;
    }
    Q_EMIT writeRequested(*address, raw.value());
    return true;
}

QStringList OdEditorModel::mimeTypes() const
{
    return { QString::fromLatin1(kMimeType), QStringLiteral("text/plain") };
}

QMimeData *OdEditorModel::mimeData(const QModelIndexList &indexes) const
{
    const QList<ObjectAddress> list = addressesUnder(indexes);
    if (list.isEmpty())
        return nullptr;
    QStringList lines;
    // CANopen lists are plain lines as they always were; other formats say which they are.
    if (addressFormat().key() != AddressFormat::canopen().key())
        lines.append(QStringLiteral("addresses ") + addressFormat().key());
    for (ObjectAddress a : list)
        lines.append(addressFormat().format(a));
    const QByteArray text = lines.join(QLatin1Char('\n')).toUtf8();
    auto *mime = new QMimeData;
    mime->setData(QString::fromLatin1(kMimeType), text);
    mime->setText(QString::fromUtf8(text));
    return mime;
}

} // namespace db::widgets
