#pragma once

#include <QSortFilterProxyModel>

namespace db::widgets {

// The editor's search: rows whose address, name or value text contains every word of the filter
// (case-insensitive). "6041", "0x6041", "6041h" and "6041:0" all find 6041h sub 0. A matching
// object shows all its sub-indices; a matching sub-index shows its object and group. Values
// change live, so a value search follows the device.
class OdEditorFilter : public QSortFilterProxyModel
{
    Q_OBJECT
public:
    explicit OdEditorFilter(QObject *parent = nullptr);

    QString text() const { return m_text; }
    void setText(const QString &text);

protected:
    bool filterAcceptsRow(int sourceRow, const QModelIndex &sourceParent) const override;

private:
    QString m_text;
    QStringList m_words; // lower case, address spellings normalised
};

} // namespace db::widgets
