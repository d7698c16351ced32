#pragma once

#include <QStyledItemDelegate>

namespace db::widgets {

class OdEditorModel;

// Value cells of the object-dictionary editor: draws the value with its request state next to it
// ("writing…" in grey, the device's error in red), and edits with a line edit that checks the
// input while typing (red frame and the reason as tooltip) or, for enumerations, an editable
// combo box. Refused input is never committed (OdEditorModel::setData refuses it again).
//
// Live refreshes do not disturb an open editor: setEditorData() fills an editor only once.
class OdEditorDelegate : public QStyledItemDelegate
{
    Q_OBJECT
public:
    explicit OdEditorDelegate(OdEditorModel *model, QObject *parent = nullptr);

    void paint(QPainter *painter, const QStyleOptionViewItem &option,
               const QModelIndex &index) const override;
    QSize sizeHint(const QStyleOptionViewItem &option, const QModelIndex &index) const override;
    QWidget *createEditor(QWidget *parent, const QStyleOptionViewItem &option,
                          const QModelIndex &index) const override;
    void setEditorData(QWidget *editor, const QModelIndex &index) const override;
    void setModelData(QWidget *editor, QAbstractItemModel *model,
                      const QModelIndex &index) const override;

Q_SIGNALS:
    // While typing: empty when the text is acceptable, else why not.
    void inputProblem(const QString &reason) const;

private:
    OdEditorModel *m_model;
};

} // namespace db::widgets
