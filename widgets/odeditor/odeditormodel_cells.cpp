// OdEditorModel, part 2: the cells of sub-index rows (definitions and live values).

#include "odeditormodel.h"

#include "widgets/common/widgetstyle.h"

namespace db::widgets {

void OdEditorModel::setValue(ObjectAddress address, const QVariant &raw)
{
    Cell &cell = m_cells[address];
    // A read that crosses a write must not hide the write's outcome.
    if (cell.state == CellState::Writing)
        return;
    const bool keepMessage =
        cell.state == CellState::WriteFailed || cell.state == CellState::Refused;
    if (cell.raw == raw && (cell.state == CellState::Fresh || keepMessage))
        return; // nothing new: no repaint, no re-filtering
    cell.raw = raw;
    if (!keepMessage) {
        cell.state = CellState::Fresh;
        cell.message.clear();
    }
    cellChanged(address);
}

void OdEditorModel::setReadFailed(ObjectAddress address, const QString &message)
{
    Cell &cell = m_cells[address];
    if (cell.state == CellState::Writing || cell.state == CellState::WriteFailed)
        return;
    if (cell.state == CellState::ReadFailed && cell.message == message)
        return;
    cell.state = CellState::ReadFailed;
    cell.message = message;
    cellChanged(address);
}

void OdEditorModel::setWriting(ObjectAddress address, const QVariant &raw)
{
    Cell &cell = m_cells[address];
    cell.state = CellState::Writing;
    cell.message = tr("writing %1…")
                       .arg(definition(address) ? odtext::display(*definition(address), raw, m_hex)
                                                : raw.toString());
    cellChanged(address);
}

void OdEditorModel::setWriteFinished(ObjectAddress address, bool ok, const QString &message)
{
    Cell &cell = m_cells[address];
    cell.state = ok ? CellState::Written : CellState::WriteFailed;
    cell.message = ok ? tr("written") : message;
    cellChanged(address);
}

void OdEditorModel::clearValues()
{
    const QList<ObjectAddress> changed = m_cells.keys();
    m_cells.clear();
    for (ObjectAddress a : changed)
        cellChanged(a);
}

OdEditorModel::CellState OdEditorModel::state(ObjectAddress address) const
{
    return m_cells.value(address).state;
}

QVariant OdEditorModel::value(ObjectAddress address) const
{
    return m_cells.value(address).raw;
}

QString OdEditorModel::statusText(ObjectAddress address) const
{
    return m_cells.value(address).message;
}

void OdEditorModel::setHex(bool hex)
{
    if (m_hex == hex)
        return;
    m_hex = hex;
    const auto each = [this](auto &&self, int node) -> void {
        for (int child : std::as_const(m_nodes[node].children)) {
            if (m_nodes[child].address) {
                Q_EMIT dataChanged(indexOfNode(child, Value),
                                   indexOfNode(child, columnCount() - 1));
            }
            self(self, child);
        }
    };
    each(each, 0);
}

void OdEditorModel::setEditable(bool editable)
{
    if (m_editable == editable)
        return;
    m_editable = editable;
    for (ObjectAddress a : addresses())
        Q_EMIT dataChanged(indexOf(a, Value), indexOf(a, Value));
}

void OdEditorModel::cellChanged(ObjectAddress address)
{
    const QModelIndex index = indexOf(address, Value);
    if (index.isValid())
        Q_EMIT dataChanged(index, index);
}

namespace {
// A value read from the device that is not the description's default (both known).
bool differsFromDefault(const ObjectDef &def, const QVariant &raw)
{
    if (!raw.isValid() || !def.defaultValue.isValid())
        return false;
    return odtext::edit(def, raw, false) != odtext::edit(def, def.defaultValue, false);
}
} // namespace

QVariant OdEditorModel::leafData(const ObjectDef &def, int column, int role) const
{
    const Cell cell = m_cells.value(def.address);
    switch (role) {
    case AddressRole:
        return QVariant::fromValue(def.address);
    case RawValueRole:
        return cell.raw;
    case StatusKindRole:
        return int(cell.state);
    case StatusTextRole:
        return column == Value ? cell.message : QVariant();
    case FilterTextRole:
        // Every language's name: a name from any of the device's manuals finds the object.
        return QStringList({ addressFormat().format(def.address), def.name, def.objectName,
                             QStringList(def.localNames.values()).join(QLatin1Char(' ')),
                             QStringList(def.localObjectNames.values()).join(QLatin1Char(' ')),
                             odtext::display(def, cell.raw, m_hex) })
            .join(QLatin1Char(' '))
            .toLower();
    case Qt::FontRole:
        if (column == Value && differsFromDefault(def, cell.raw)) {
            QFont bold = style::monospaceFont();
            bold.setBold(true);
            return bold;
        }
        if (column == Address || column == Value || column == Default || column == Limits)
            return style::monospaceFont();
        return {};
    case Qt::BackgroundRole:
        if (column == Value && differsFromDefault(def, cell.raw))
            return style::changedBackground();
        return {};
    case Qt::TextAlignmentRole:
        if (column == Pdo || column == AccessColumn)
            return int(Qt::AlignCenter);
        return {};
    case Qt::ForegroundRole:
        if (column == Value && !def.readable())
            return style::inactiveColor();
        if (column == Value && cell.state == CellState::ReadFailed)
            return style::inactiveColor();
        // Values of a connection that is gone are greyed out: they may be out of date.
        if (isValueColumn(column) && !m_editable && cell.raw.isValid())
            return style::inactiveColor();
        if (column == Default || column == Limits || column == Type)
            return style::inactiveColor();
        return {};
    case Qt::EditRole:
        if (column == Value)
            return odtext::edit(def, cell.raw, m_hex);
        return {};
    case Qt::ToolTipRole:
        if (column == Value) {
            QString tip = cell.message;
            if (!def.writable())
                tip = tip.isEmpty() ? tr("read-only") : tip;
            if (!m_editable && cell.raw.isValid())
                tip = tr("Read before the connection ended; may be out of date");
            if (tip.isEmpty() && differsFromDefault(def, cell.raw))
                tip = tr("Differs from the default %1")
                          .arg(odtext::display(def, def.defaultValue, m_hex));
            return tip.isEmpty() ? QVariant() : QVariant(style::toolTip(tip));
        }
        if (column == Name) {
            // A name shown in another language than English also shows the English one: the
            // name files and scripts use. Rich text, so that a long description wraps.
            QString tip;
            if (def.displayName() != def.name)
                tip += style::toolTip(tr("English: %1").arg(def.name));
            tip += style::toolTip(def.description);
            return tip.isEmpty() ? QVariant() : QVariant(tip);
        }
        return {};
    case Qt::DisplayRole:
        break;
    default:
        return {};
    }
    switch (column) {
    case Address:
        return addressFormat().format(def.address);
    case Name:
        return def.displayName();
    case Type:
        return datatype::name(def.type);
    case AccessColumn:
        return access::name(def.access);
    case Value:
        if (!def.readable())
            return tr("(write-only)");
        return odtext::display(def, cell.raw, m_hex, false);
    case Unit:
        return datatype::isNumeric(def.type) ? def.displayUnit() : QString();
    case Default:
        return odtext::display(def, def.defaultValue, m_hex, false);
    case Limits:
        return odtext::limits(def, m_hex);
    case Pdo:
        return def.pdoMappable ? tr("yes") : QString();
    }
    return {};
}

} // namespace db::widgets
