#pragma once

// An item delegate for views whose rows are painted far more often than they change (logs that
// scroll as lines arrive): each cell's text is laid out once and then drawn from a cache
// (QStaticText), instead of being shaped again on every paint. Single-line plain text with the
// model's font, colour and alignment; a text wider than its cell is elided at the right, as
// QStyledItemDelegate does. Icons and check boxes are not drawn.

#include <QCache>
#include <QFont>
#include <QStaticText>
#include <QStyledItemDelegate>

namespace db::widgets {

class StaticTextDelegate : public QStyledItemDelegate
{
    Q_OBJECT
public:
    explicit StaticTextDelegate(QObject *parent = nullptr);

    void paint(QPainter *painter, const QStyleOptionViewItem &option,
               const QModelIndex &index) const override;

    // The text as painted in a cell `width` pixels wide (elided when it does not fit).
    QString shownText(const QString &text, const QFont &font, int width) const;
    int cachedTexts() const { return int(m_cache.size()); }

private:
    struct Key
    {
        QString text;
        QString font;
        int width = 0;
        bool operator==(const Key &o) const
        {
            return width == o.width && text == o.text && font == o.font;
        }
    };
    friend size_t qHash(const Key &key, size_t seed = 0)
    {
        return qHashMulti(seed, key.text, key.font, key.width);
    }
    const QStaticText &laidOut(const QString &text, const QFont &font, int width) const;

    mutable QCache<Key, QStaticText> m_cache;
};

} // namespace db::widgets
