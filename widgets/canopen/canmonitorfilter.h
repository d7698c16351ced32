#pragma once

// What the CAN monitor shows (Kickdrive-style filters): COB-ID ranges, direction, object index,
// data pattern and text. The parsers are pure and report bad input instead of guessing.

#include "core/result.h"

#include <QSortFilterProxyModel>

#include <optional>

namespace db::widgets {

class CanMonitorModel;

struct CanFrameFilter
{
    enum class Direction { Both, Rx, Tx };

    struct IdRange
    {
        quint32 first = 0;
        quint32 last = 0x1FFFFFFF;
    };
    QList<IdRange> ids; // empty: every id
    Direction direction = Direction::Both;
    std::optional<quint16> index; // SDO frames of this object
    std::optional<quint8> subIndex; // with index
    QByteArray pattern; // data bytes from byte 0 ...
    QByteArray mask; // ... compared where mask bits are set (wildcards clear them)
    QString text; // in the service or the decoded text, case-insensitive

    bool isEmpty() const;

    // Hex ids and ranges, comma separated: "580-5FF", "81-ff, 700-77F", "0x632".
    static Result<QList<IdRange>> parseIds(const QString &text);
    // Hex bytes with wildcards: "4B 41 60 ?? 27", "40??60", "4?" (nibble). Spaces optional.
    // Sets pattern and mask.
    Result<void> setDataPattern(const QString &text);
    // "6041" or "6041:0" (hex; as ObjectAddress::parse); empty = any.
    Result<void> setObject(const QString &text);
};

// Filters a CanMonitorModel; rows keep their order. Criteria are applied to new rows as they
// arrive and to all rows when they change.
class CanMonitorFilter : public QSortFilterProxyModel
{
    Q_OBJECT
public:
    explicit CanMonitorFilter(CanMonitorModel *source, QObject *parent = nullptr);

    const CanFrameFilter &criteria() const { return m_filter; }
    void setCriteria(const CanFrameFilter &filter);

protected:
    bool filterAcceptsRow(int sourceRow, const QModelIndex &sourceParent) const override;

private:
    CanMonitorModel *m_model;
    CanFrameFilter m_filter;
};

} // namespace db::widgets
