#include "odeditorfilter.h"

#include "odeditormodel.h"

#include <QRegularExpression>

namespace db::widgets {

namespace {
// "0x6041" -> "6041", "6041h" -> "6041", "6041h.00h" -> "6041:0", "6041:00" -> "6041:0"
QString normaliseWord(const QString &word)
{
    static const QRegularExpression address(
        QStringLiteral("^(?:0x)?([0-9a-f]{4})h?(?:[:.](?:0x)?([0-9a-f]{1,2})h?)?$"));
    const auto m = address.match(word);
    if (!m.hasMatch())
        return word;
    QString text = m.captured(1);
    if (m.hasCaptured(2))
        text += QLatin1Char(':') + QString::number(m.captured(2).toUInt(nullptr, 16), 16);
    return text;
}
} // namespace

OdEditorFilter::OdEditorFilter(QObject *parent)
    : QSortFilterProxyModel(parent)
{
    setRecursiveFilteringEnabled(true);
    setAutoAcceptChildRows(true);
    setFilterRole(OdEditorModel::FilterTextRole);
}

void OdEditorFilter::setText(const QString &text)
{
    if (text == m_text)
        return;
    m_text = text;
    m_words.clear();
    for (const QString &word : text.toLower().split(QLatin1Char(' '), Qt::SkipEmptyParts))
        m_words.append(normaliseWord(word));
    invalidateFilter();
}

bool OdEditorFilter::filterAcceptsRow(int sourceRow, const QModelIndex &sourceParent) const
{
    if (m_words.isEmpty())
        return true;
    const QModelIndex index = sourceModel()->index(sourceRow, 0, sourceParent);
    if (!sourceParent.isValid())
        return false; // group rows are shown through their objects
    const QString text = index.data(OdEditorModel::FilterTextRole).toString();
    return std::all_of(m_words.cbegin(), m_words.cend(),
                       [&text](const QString &word) { return text.contains(word); });
}

} // namespace db::widgets
