#include "odeditordelegate.h"

#include "odeditormodel.h"
#include "widgets/common/widgetstyle.h"

#include <QComboBox>
#include <QLineEdit>
#include <QPainter>

namespace db::widgets {

namespace {
constexpr int kStatusGap = 12; // px between a value and its request state
constexpr const char *kFilledProperty = "odFilled";

const ObjectDef *definitionAt(const OdEditorModel *model, const QModelIndex &index)
{
    const QVariant a = index.data(OdEditorModel::AddressRole);
    return a.isValid() ? model->definition(a.value<ObjectAddress>()) : nullptr;
}
} // namespace

OdEditorDelegate::OdEditorDelegate(OdEditorModel *model, QObject *parent)
    : QStyledItemDelegate(parent)
    , m_model(model)
{ }

void OdEditorDelegate::paint(QPainter *painter, const QStyleOptionViewItem &option,
                             const QModelIndex &index) const
{
    const QString status = index.data(OdEditorModel::StatusTextRole).toString();
    if (status.isEmpty()) {
        QStyledItemDelegate::paint(painter, option, index);
        return;
    }
    // Value on the left, state on the right of the same cell, elided first.
    QStyleOptionViewItem opt = option;
    initStyleOption(&opt, index);
    const QFontMetrics valueMetrics(opt.font);
    const int valueWidth = valueMetrics.horizontalAdvance(opt.text) + 2 * kStatusGap;
    QStyledItemDelegate::paint(painter, option, index);

    const auto state = OdEditorModel::CellState(index.data(OdEditorModel::StatusKindRole).toInt());
    QColor color = style::inactiveColor();
    if (state == OdEditorModel::CellState::WriteFailed
        || state == OdEditorModel::CellState::ReadFailed
        || state == OdEditorModel::CellState::Refused)
        color = style::errorColor();
    else if (state == OdEditorModel::CellState::Written)
        color = style::okColor();
    if (opt.state & QStyle::State_Selected)
        color = opt.palette.color(QPalette::HighlightedText);
    QRect r = opt.rect.adjusted(valueWidth, 0, -4, 0);
    if (r.width() < 20)
        return;
    painter->save();
    QFont font = option.font;
    font.setItalic(true);
    painter->setFont(font);
    painter->setPen(color);
    const QString text = QFontMetrics(font).elidedText(status, Qt::ElideRight, r.width());
    painter->drawText(r, Qt::AlignVCenter | Qt::AlignLeft, text);
    painter->restore();
}

QSize OdEditorDelegate::sizeHint(const QStyleOptionViewItem &option, const QModelIndex &index) const
{
    QSize size = QStyledItemDelegate::sizeHint(option, index);
    size.setHeight(qMax(size.height(), option.fontMetrics.height() + 8));
    return size;
}

QWidget *OdEditorDelegate::createEditor(QWidget *parent, const QStyleOptionViewItem &option,
                                        const QModelIndex &index) const
{
    const ObjectDef *def = definitionAt(m_model, index);
    if (!def || !m_model->isValueColumn(index.column()))
        return QStyledItemDelegate::createEditor(parent, option, index);
    if (!def->enumeration.isEmpty() || def->type == DataType::Boolean) {
        auto *combo = new QComboBox(parent);
        combo->setEditable(true);
        if (def->type == DataType::Boolean) {
            combo->addItem(tr("0 (false)"), QStringLiteral("0"));
            combo->addItem(tr("1 (true)"), QStringLiteral("1"));
        }
        const auto names = def->displayEnumeration();
        for (auto it = names.cbegin(); it != names.cend(); ++it)
            combo->addItem(QStringLiteral("%1 (%2)").arg(it.key()).arg(*it),
                           QString::number(it.key()));
        return combo;
    }
    auto *edit = new QLineEdit(parent);
    edit->setFont(style::monospaceFont());
    const QString limits = odtext::limits(*def, false);
    edit->setPlaceholderText(limits.isEmpty() ? datatype::name(def->type) : limits);
    const ObjectDef copy = *def;
    const AddressFormat *format = &m_model->addressFormat();
    connect(edit, &QLineEdit::textEdited, edit, [this, edit, copy, format](const QString &text) {
        const auto parsed = odtext::parse(copy, text, *format);
        const QString problem = parsed ? QString() : parsed.error().message();
        edit->setToolTip(problem);
        style::setTextColor(edit, problem.isEmpty() ? QColor() : style::errorColor());
        Q_EMIT inputProblem(problem);
    });
    return edit;
}

void OdEditorDelegate::setEditorData(QWidget *editor, const QModelIndex &index) const
{
    // Called again on every dataChanged of the cell (live refresh): keep what the user typed.
    if (editor->property(kFilledProperty).toBool())
        return;
    editor->setProperty(kFilledProperty, true);
    const QString text = index.data(Qt::EditRole).toString();
    if (auto *combo = qobject_cast<QComboBox *>(editor)) {
        const int i = combo->findData(text);
        if (i >= 0)
            combo->setCurrentIndex(i);
        else
            combo->setEditText(text);
        return;
    }
    if (auto *edit = qobject_cast<QLineEdit *>(editor)) {
        edit->setText(text);
        edit->selectAll();
        return;
    }
    QStyledItemDelegate::setEditorData(editor, index);
}

void OdEditorDelegate::setModelData(QWidget *editor, QAbstractItemModel *model,
                                    const QModelIndex &index) const
{
    QString text;
    if (auto *combo = qobject_cast<QComboBox *>(editor)) {
        const int i = combo->findText(combo->currentText());
        text = i >= 0 ? combo->itemData(i).toString() : combo->currentText();
    } else if (auto *edit = qobject_cast<QLineEdit *>(editor)) {
        text = edit->text();
    } else {
        QStyledItemDelegate::setModelData(editor, model, index);
        return;
    }
    Q_EMIT inputProblem(QString());
    model->setData(index, text, Qt::EditRole);
}

} // namespace db::widgets
