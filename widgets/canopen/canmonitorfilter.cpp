#include "canmonitorfilter.h"

#include "canmonitormodel.h"

#include <QRegularExpression>

namespace db::widgets {

namespace {

Error invalid(const QString &message)
{
    return Error(Error::Kind::InvalidArgument, message);
}

std::optional<quint32> hexId(QString text)
{
    text = text.trimmed();
    if (text.startsWith(QLatin1String("0x"), Qt::CaseInsensitive))
        text = text.mid(2);
    else if (text.endsWith(QLatin1Char('h'), Qt::CaseInsensitive))
        text.chop(1);
    bool ok = false;
    const quint32 id = text.toUInt(&ok, 16);
    if (!ok || text.isEmpty() || id > 0x1FFFFFFF)
        return std::nullopt;
    return id;
}

} // namespace

bool CanFrameFilter::isEmpty() const
{
    return ids.isEmpty() && direction == Direction::Both && !index && pattern.isEmpty()
        && text.isEmpty();
}

Result<QList<CanFrameFilter::IdRange>> CanFrameFilter::parseIds(const QString &text)
{
    QList<IdRange> ranges;
    for (const QString &part : text.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        if (part.trimmed().isEmpty())
            continue;
        const QStringList ends = part.split(QLatin1Char('-'));
        const auto first = ends.size() <= 2 ? hexId(ends.first()) : std::nullopt;
        const auto last = ends.size() == 2 ? hexId(ends.last()) : first;
        if (!first || !last || *last < *first)
            return invalid(QStringLiteral("\"%1\" is not a hex id or range such as 580-5FF")
                               .arg(part.trimmed()));
        ranges.append({ *first, *last });
    }
    return ranges;
}

Result<void> CanFrameFilter::setDataPattern(const QString &text)
{
    QString digits = text;
    digits.remove(QRegularExpression(QStringLiteral("\\s")));
    static const QRegularExpression valid(QStringLiteral("^[0-9A-Fa-f?]*$"));
    if (!valid.match(digits).hasMatch() || digits.size() % 2 != 0 || digits.size() > 16)
        return invalid(QStringLiteral("\"%1\" is not a data pattern such as 4B 41 60 ?? 27 (up "
                                      "to 8 bytes, ?? for any byte)")
                           .arg(text));
    QByteArray pattern, mask;
    for (int i = 0; i < digits.size(); i += 2) {
        quint8 value = 0, bits = 0;
        for (int nibble = 0; nibble < 2; ++nibble) {
            const QChar c = digits.at(i + nibble);
            value <<= 4;
            bits <<= 4;
            if (c != QLatin1Char('?')) {
                value |= quint8(QString(c).toUInt(nullptr, 16));
                bits |= 0x0F;
            }
        }
        pattern.append(char(value));
        mask.append(char(bits));
    }
    this->pattern = pattern;
    this->mask = mask;
    return {};
}

Result<void> CanFrameFilter::setObject(const QString &text)
{
    index.reset();
    subIndex.reset();
    if (text.trimmed().isEmpty())
        return {};
    const auto address = ObjectAddress::parse(text.trimmed());
    if (!address)
        return invalid(QStringLiteral("\"%1\" is not an object index such as 6041 or 6041:0")
                           .arg(text.trimmed()));
    index = address.value().index;
    if (text.contains(QLatin1Char(':')) || text.contains(QLatin1Char('.')))
        subIndex = address.value().sub;
    return {};
}

CanMonitorFilter::CanMonitorFilter(CanMonitorModel *source, QObject *parent)
    : QSortFilterProxyModel(parent)
    , m_model(source)
{
    setSourceModel(source);
}

void CanMonitorFilter::setCriteria(const CanFrameFilter &filter)
{
    m_filter = filter;
    invalidateFilter();
}

bool CanMonitorFilter::filterAcceptsRow(int sourceRow, const QModelIndex &) const
{
    if (m_filter.isEmpty())
        return true;
    const CanMonitorModel::Entry &e = m_model->entry(sourceRow);
    using Direction = CanFrameFilter::Direction;
    if ((m_filter.direction == Direction::Rx && e.transmitted)
        || (m_filter.direction == Direction::Tx && !e.transmitted))
        return false;
    if (!m_filter.ids.isEmpty()) {
        const quint32 id = e.frame.frameId();
        const bool inRange =
            std::any_of(m_filter.ids.cbegin(), m_filter.ids.cend(),
                        [id](const auto &r) { return id >= r.first && id <= r.last; });
        if (!inRange)
            return false;
    }
    if (m_filter.index) {
        if (!e.decoded.hasAddress || e.decoded.address.index != *m_filter.index)
            return false;
        if (m_filter.subIndex && e.decoded.address.sub != *m_filter.subIndex)
            return false;
    }
    if (!m_filter.pattern.isEmpty()) {
        const QByteArray payload = e.frame.payload();
        if (payload.size() < m_filter.pattern.size())
            return false;
        for (int i = 0; i < m_filter.pattern.size(); ++i) {
            const quint8 m = quint8(m_filter.mask.at(i));
            if ((quint8(payload.at(i)) & m) != (quint8(m_filter.pattern.at(i)) & m))
                return false;
        }
    }
    if (!m_filter.text.isEmpty()) {
        const QString service =
            canopen::FrameDecoder::serviceName(e.decoded.service, e.decoded.pdoNumber);
        if (!e.decoded.text.contains(m_filter.text, Qt::CaseInsensitive)
            && !service.contains(m_filter.text, Qt::CaseInsensitive))
            return false;
    }
    return true;
}

} // namespace db::widgets
