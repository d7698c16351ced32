// The reading half of csv.h (fromCsv); the format is described there.
#include "csv.h"

#include <QCoreApplication>
#include <QHash>
#include <QPair>
#include <QSet>
#include <algorithm>
#include <cmath>

namespace db::scope::csv {

namespace {

struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::scope::csv)
};

Error malformed(int line, const QString &why)
{
    return Error(Error::Kind::Malformed, Tr::tr("line %1: %2").arg(QString::number(line), why));
}

// Splits at ';' not escaped by a backslash and removes the escapes (see escape() in csv.cpp).
QStringList splitUnescaped(const QString &text)
{
    QStringList parts(1);
    for (qsizetype i = 0; i < text.size(); ++i) {
        const QChar ch = text[i];
        if (ch == QLatin1Char('\\') && i + 5 < text.size() && text[i + 1] == QLatin1Char('u')) {
            bool ok = false;
            const uint code = text.mid(i + 2, 4).toUInt(&ok, 16);
            if (ok) { // "\uNNNN": a control character the writer escaped
                parts.last() += QChar(char16_t(code));
                i += 5;
                continue;
            }
        }
        if (ch == QLatin1Char('\\') && i + 1 < text.size()) {
            const QChar next = text[++i];
            parts.last() += next == QLatin1Char('n') ? QChar(QLatin1Char('\n'))
                : next == QLatin1Char('r')           ? QChar(QLatin1Char('\r'))
                                                     : next;
        } else if (ch == QLatin1Char(';')) {
            parts.append(QString());
        } else {
            parts.last() += ch;
        }
    }
    return parts;
}

QString unescape(const QString &s)
{
    return splitUnescaped(s).join(QLatin1Char(';'));
}

// "9.000000001" -> nanoseconds, exactly (no floating-point detour for the row time).
std::optional<qint64> parseNanos(QByteArrayView text)
{
    bool negative = false;
    if (text.startsWith('-')) {
        negative = true;
        text = text.sliced(1);
    }
    const qsizetype dot = text.indexOf('.');
    const QByteArrayView whole = dot < 0 ? text : text.first(dot);
    QByteArray frac = dot < 0 ? QByteArray() : text.sliced(dot + 1).toByteArray();
    if (whole.isEmpty() || frac.size() > 9)
        return std::nullopt;
    bool ok = false;
    const qint64 seconds = whole.toLongLong(&ok);
    if (!ok || seconds < 0 || seconds > 9'000'000'000LL)
        return std::nullopt;
    frac = frac.leftJustified(9, '0');
    qint64 ns = 0;
    for (char ch : frac) {
        if (ch < '0' || ch > '9')
            return std::nullopt;
        ns = ns * 10 + (ch - '0');
    }
    const qint64 total = seconds * 1000000000LL + ns;
    return negative ? -total : total;
}

// "key: value; key: value" -> map (the first pair's key is the line's kind).
QHash<QString, QString> pairs(const QString &text)
{
    QHash<QString, QString> map;
    for (const QString &part : splitUnescaped(text)) {
        const qsizetype colon = part.indexOf(QLatin1Char(':'));
        if (colon > 0)
            map.insert(part.left(colon).trimmed(), part.mid(colon + 1).trimmed());
    }
    return map;
}

std::optional<double> number(const QString &text)
{
    bool ok = false;
    const double v = text.toDouble(&ok);
    return ok && std::isfinite(v) ? std::optional<double>(v) : std::nullopt;
}

struct Pending
{
    QString triggerSpec;
    int triggerLine = 0;
    QHash<QString, QSet<qint64>> gaps; // channel id -> times (ns) that start a gap
    // (channel id, device) -> the same, for channels of another device than the file's
    QHash<QPair<QString, QString>, QSet<qint64>> deviceGaps;
    QList<QPair<qint64, qint64>> counters; // per channel line: (dropped, lost)
};

Result<void> parseTrigger(Recording &rec, const Pending &p)
{
    if (p.triggerSpec.isEmpty() || p.triggerSpec == QLatin1String("none"))
        return {};
    const QStringList parts = p.triggerSpec.split(QLatin1Char(';'));
    QStringList ids;
    for (const RecordedChannel &c : rec.channels)
        ids.append(c.info.id);
    auto trigger = Trigger::parse(parts[0], ids);
    if (!trigger)
        return malformed(p.triggerLine, trigger.error().message());
    Trigger t = *trigger;
    for (int i = 1; i < parts.size(); ++i) {
        const QStringList words = parts[i].trimmed().split(QLatin1Char(' '), Qt::SkipEmptyParts);
        const auto value = words.size() >= 2 ? number(words[1]) : std::nullopt;
        if (!value)
            return malformed(p.triggerLine,
                             Tr::tr("bad trigger detail '%1'").arg(parts[i].trimmed()));
        if (words[0] == QLatin1String("pre"))
            t.preTriggerS = *value;
        else if (words[0] == QLatin1String("post"))
            t.postTriggerS = *value;
        else if (words[0] == QLatin1String("at"))
            rec.triggerTime = *value;
    }
    rec.trigger = t;
    return {};
}

} // namespace

Result<Recording> fromCsv(const QByteArray &text)
{
    const QList<QByteArray> lines = text.split('\n');
    if (lines.isEmpty() || !lines[0].trimmed().startsWith("# drivebench recording"))
        return malformed(1,
                         Tr::tr("not a drivebench recording (the first line must be '# "
                                "drivebench recording v1')"));
    Recording rec;
    Pending pending;
    QHash<QString, QString> channelDevice;
    int lineNo = 1;
    // Comment header.
    for (; lineNo < lines.size(); ++lineNo) {
        const QString line = QString::fromUtf8(lines[lineNo]).trimmed();
        if (!line.startsWith(QLatin1Char('#')))
            break;
        const QString body = line.mid(1).trimmed();
        const qsizetype colon = body.indexOf(QLatin1Char(':'));
        const QString key = body.left(colon).trimmed();
        const QString value = body.mid(colon + 1).trimmed();
        const int n = lineNo + 1;
        if (key == QLatin1String("device")) {
            rec.device = unescape(value);
        } else if (key == QLatin1String("started")) {
            rec.startedAt = QDateTime::fromString(value, Qt::ISODateWithMs);
            if (!rec.startedAt.isValid())
                return malformed(n, Tr::tr("bad start time '%1'").arg(value));
        } else if (key == QLatin1String("mode")) {
            rec.mode = unescape(value);
        } else if (key == QLatin1String("trigger")) {
            pending.triggerSpec = value;
            pending.triggerLine = n;
        } else if (key == QLatin1String("channel")) {
            const QHash<QString, QString> map = pairs(body);
            RecordedChannel c;
            c.info.id = map.value(QStringLiteral("channel"));
            const QString formatKey =
                map.value(QStringLiteral("addresses"), AddressFormat::canopen().key());
            c.info.addressFormat = AddressFormat::byKey(formatKey);
            if (!c.info.addressFormat)
                return malformed(n,
                                 Tr::tr("channel %1: unknown address format '%2' (canopen or "
                                        "parameter)")
                                     .arg(c.info.id, formatKey));
            const auto address = c.info.addressFormat->parse(c.info.id);
            if (c.info.id.isEmpty() || !address)
                return malformed(n,
                                 Tr::tr("channel line without a valid id (%1 addresses are "
                                        "written like %2)")
                                     .arg(formatKey, c.info.addressFormat->example()));
            c.info.address = *address;
            c.info.name = map.value(QStringLiteral("name"));
            c.info.unit = map.value(QStringLiteral("unit"));
            const auto scale = number(map.value(QStringLiteral("scale"), QStringLiteral("1")));
            const auto offset = number(map.value(QStringLiteral("offset"), QStringLiteral("0")));
            if (!scale || *scale == 0 || !offset)
                return malformed(n, Tr::tr("channel %1: bad scale or offset").arg(c.info.id));
            c.info.scale = *scale;
            c.info.offset = *offset;
            c.info.sourceRateMs = map.value(QStringLiteral("rate-ms")).toInt();
            c.info.decimals = std::clamp(
                map.value(QStringLiteral("decimals"), QStringLiteral("-1")).toInt(), -1, 9);
            c.info.deviceName = map.value(QStringLiteral("device-name"));
            pending.counters.append({ map.value(QStringLiteral("dropped")).toLongLong(),
                                      map.value(QStringLiteral("lost")).toLongLong() });
            rec.channels.append(c);
        } else if (key == QLatin1String("channel-device")) {
            const QStringList parts = splitUnescaped(value);
            // It follows its channel's line: the same object of two devices has the same id.
            if (parts.size() == 2 && !rec.channels.isEmpty()
                && rec.channels.constLast().info.id == parts[0].trimmed())
                rec.channels.last().info.device = parts[1].trimmed();
            else if (parts.size() == 2)
                channelDevice.insert(parts[0].trimmed(), parts[1].trimmed());
        } else if (key == QLatin1String("gaps") || key == QLatin1String("device-gaps")) {
            // "ID; T1 T2 ..." or, for a channel of another device, "ID; DEVICE; T1 T2 ...".
            const QStringList parts = splitUnescaped(value);
            const bool ofDevice = key == QLatin1String("device-gaps");
            if (parts.size() != (ofDevice ? 3 : 2))
                return malformed(n, Tr::tr("bad gap line '%1'").arg(value));
            const QString id = parts[0].trimmed();
            QSet<qint64> &times =
                ofDevice ? pending.deviceGaps[{ id, parts[1].trimmed() }] : pending.gaps[id];
            for (const QString &word : parts.last().split(QLatin1Char(' '), Qt::SkipEmptyParts)) {
                const auto ns = parseNanos(word.toLatin1());
                if (!ns)
                    return malformed(n, Tr::tr("bad gap time '%1'").arg(word));
                times.insert(*ns);
            }
        }
    }
    if (rec.channels.isEmpty())
        return malformed(lineNo + 1, Tr::tr("no '# channel:' lines before the data"));
    for (RecordedChannel &c : rec.channels)
        if (c.info.device.isEmpty())
            c.info.device = channelDevice.value(c.info.id, rec.device);
    if (auto ok = parseTrigger(rec, pending); !ok)
        return ok.error();
    // Each channel's gap times. A "gaps" line names an object of the file's device; files
    // written before "device-gaps" existed also used it for other devices' channels, so it
    // applies to those when the file's device has no channel of that id.
    QList<QSet<qint64>> channelGaps;
    for (const RecordedChannel &c : rec.channels) {
        QSet<qint64> times = pending.deviceGaps.value({ c.info.id, c.info.device });
        const bool own = c.info.device == rec.device
            || std::none_of(rec.channels.cbegin(), rec.channels.cend(),
                            [&](const RecordedChannel &o) {
                                return o.info.id == c.info.id && o.info.device == rec.device;
                            });
        if (own)
            times.unite(pending.gaps.value(c.info.id));
        channelGaps.append(times);
    }

    // Column header.
    if (lineNo >= lines.size() || !lines[lineNo].startsWith("time_s"))
        return malformed(lineNo + 1, Tr::tr("missing the column header 'time_s,...'"));
    ++lineNo;

    const int columns = int(rec.channels.size()) + 1;
    for (RecordedChannel &c : rec.channels)
        c.buffer = TraceBuffer(std::max<qint64>(1, lines.size() - lineNo));
    qint64 previous = std::numeric_limits<qint64>::min();
    for (; lineNo < lines.size(); ++lineNo) {
        const QByteArray line = lines[lineNo].trimmed();
        const int n = lineNo + 1;
        if (line.isEmpty())
            continue;
        const QList<QByteArray> cells = line.split(',');
        if (cells.size() != columns)
            return malformed(n,
                             Tr::tr("%1 cells, expected %2 (time and one per channel)")
                                 .arg(cells.size())
                                 .arg(columns));
        const auto ns = parseNanos(cells[0]);
        if (!ns)
            return malformed(
                n, Tr::tr("'%1' is not a time in seconds").arg(QString::fromUtf8(cells[0])));
        if (*ns < previous)
            return malformed(
                n,
                Tr::tr("time goes back (%1 s after a later row)").arg(QString::fromUtf8(cells[0])));
        previous = *ns;
        for (int c = 1; c < columns; ++c) {
            if (cells[c].isEmpty())
                continue;
            bool ok = false;
            const double v = cells[c].toDouble(&ok);
            RecordedChannel &ch = rec.channels[c - 1];
            if (!ok)
                return malformed(n,
                                 Tr::tr("column %1 (%2): '%3' is not a number")
                                     .arg(c + 1)
                                     .arg(ch.info.id, QString::fromUtf8(cells[c])));
            if (channelGaps[c - 1].contains(*ns))
                ch.buffer.markGap();
            ch.buffer.append(double(*ns) * 1e-9, v);
        }
    }
    for (qsizetype i = 0; i < rec.channels.size(); ++i) {
        const auto counters = pending.counters.value(i);
        rec.channels[i].buffer.setCounters(counters.first, counters.second);
    }
    return rec;
}

} // namespace db::scope::csv
