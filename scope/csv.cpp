#include "csv.h"
#include "core/filereader.h"
#include "core/filewriter.h"

#include "core/printable.h"

#include <QBuffer>
#include <QCoreApplication>
#include <QFile>
#include <QLocale>
#include <QSaveFile>
#include <cmath>

namespace db::scope::csv {

namespace {

constexpr char kMagic[] = "# drivebench recording v1";

struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::scope::csv)
};

// Times are written with 9 decimals (1 ns, the resolution of the time base) and merged into
// rows on that integer, so a round trip gives back exactly the same rows.
qint64 nanos(double t)
{
    return std::llround(t * 1e9);
}

QByteArray timeText(qint64 ns)
{
    const char *sign = ns < 0 ? "-" : "";
    const quint64 a = quint64(ns < 0 ? -ns : ns);
    return QByteArray(sign) + QByteArray::number(a / 1000000000u) + '.'
        + QByteArray::number(a % 1000000000u).rightJustified(9, '0');
}

// Integers as integers; other values in the shortest form that reads back exactly.
QByteArray numberText(double v)
{
    if (std::isfinite(v) && v == std::floor(v) && std::abs(v) < 9.0e15)
        return QByteArray::number(qint64(v));
    return QByteArray::number(v, 'g', QLocale::FloatingPointShortest);
}

// Comment values are "key: value" pairs separated by ';': a backslash escapes what would split
// them ("\\;", "\\n", "\\r", "\\\\") and, as "\\uNNNN", the control characters that would act on
// a terminal showing the file (db::printable()); everything else (units such as "%") stays.
QString escape(const QString &s)
{
    QString out;
    out.reserve(s.size());
    for (QChar ch : s) {
        if (ch == QLatin1Char('\\') || ch == QLatin1Char(';'))
            out += QLatin1Char('\\') + ch;
        else if (ch == QLatin1Char('\n'))
            out += QLatin1String("\\n");
        else if (ch == QLatin1Char('\r'))
            out += QLatin1String("\\r");
        else if (!ch.isSurrogate() && !isPrintable(QStringView(&ch, 1)))
            out += QStringLiteral("\\u%1").arg(ch.unicode(), 4, 16, QLatin1Char('0'));
        else
            out += ch;
    }
    return out;
}

QByteArray quoted(const QString &cell)
{
    QByteArray text = cell.toUtf8();
    if (!text.contains(',') && !text.contains('"') && !text.contains('\n') && !text.contains('\r'))
        return text;
    return '"' + text.replace("\"", "\"\"") + '"';
}

} // namespace

namespace {

constexpr qsizetype kChunkBytes = 1 << 20; // rows are flushed to the device in ~1 MB pieces

// Writes the CSV of the samples with t0 <= t <= t1 to `device`, without copying the samples.
bool writeCsv(QIODevice &device, const Recording &rec, double t0, double t1)
{
    if (t0 > t1)
        std::swap(t0, t1);
    const int n = int(rec.channels.size());
    std::vector<qint64> next(static_cast<size_t>(n), 0);
    std::vector<qint64> end(static_cast<size_t>(n), 0);
    double first = std::numeric_limits<double>::infinity();
    double last = -first;
    for (int c = 0; c < n; ++c) {
        const TraceBuffer &b = rec.channels[c].buffer;
        next[size_t(c)] = b.lowerBound(t0);
        end[size_t(c)] = b.upperBound(t1);
        if (next[size_t(c)] < end[size_t(c)]) {
            first = std::min(first, b.time(next[size_t(c)]));
            last = std::max(last, b.time(end[size_t(c)] - 1));
        }
    }
    if (std::isinf(first))
        first = last = 0;

    QByteArray out;
    out += kMagic;
    out += "\n# device: " + escape(rec.device).toUtf8() + '\n';
    if (rec.startedAt.isValid())
        out += "# started: " + rec.startedAt.toUTC().toString(Qt::ISODateWithMs).toUtf8() + '\n';
    if (!rec.mode.isEmpty())
        out += "# mode: " + escape(rec.mode).toUtf8() + '\n';
    if (rec.trigger.isValid() && rec.trigger.channel < n) {
        out += "# trigger: " + escape(rec.channels[rec.trigger.channel].info.id).toUtf8() + ','
            + rec.trigger.conditionText().toUtf8() + "; pre " + numberText(rec.trigger.preTriggerS)
            + " s; post " + numberText(rec.trigger.postTriggerS) + " s";
        if (rec.hasTriggerTime())
            out += "; at " + timeText(nanos(rec.triggerTime)) + " s";
        out += '\n';
    } else {
        out += "# trigger: none\n";
    }
    for (const RecordedChannel &c : rec.channels) {
        const ChannelInfo &i = c.info;
        out += "# channel: " + escape(i.id).toUtf8() + "; name: " + escape(i.name).toUtf8()
            + "; unit: " + escape(i.unit).toUtf8() + "; scale: " + numberText(i.scale)
            + "; offset: " + numberText(i.offset)
            + "; rate-ms: " + QByteArray::number(i.sourceRateMs)
            + "; dropped: " + QByteArray::number(c.buffer.droppedOverwritten())
            + "; lost: " + QByteArray::number(c.buffer.lostAtSource());
        // CANopen ids are written as before the key existed; other formats say so, because
        // "372:2" means another object in hex.
        if (i.addressFormat->key() != AddressFormat::canopen().key())
            out += "; addresses: " + i.addressFormat->key().toUtf8();
        if (i.decimals >= 0)
            out += "; decimals: " + QByteArray::number(i.decimals);
        if (!i.deviceName.isEmpty())
            out += "; device-name: " + escape(i.deviceName).toUtf8();
        out += '\n';
        if (i.device != rec.device)
            out += "# channel-device: " + escape(i.id).toUtf8() + "; " + escape(i.device).toUtf8()
                + '\n';
    }
    for (int c = 0; c < n; ++c) {
        const TraceBuffer &b = rec.channels[c].buffer;
        QByteArray gaps;
        for (qint64 k = next[size_t(c)]; k < end[size_t(c)]; ++k) {
            if (b.startsGap(k))
                gaps += ' ' + timeText(nanos(b.time(k)));
        }
        if (gaps.isEmpty())
            continue;
        // Keyed by the channel as recorded: the same object of two devices has the same id.
        const ChannelInfo &i = rec.channels[c].info;
        if (i.device != rec.device)
            out += "# device-gaps: " + escape(i.id).toUtf8() + "; " + escape(i.device).toUtf8()
                + ';' + gaps + '\n';
        else
            out += "# gaps: " + escape(i.id).toUtf8() + ';' + gaps + '\n';
    }
    out += "# range: " + timeText(nanos(first)) + " .. " + timeText(nanos(last)) + " s\n";
    out += "time_s";
    for (const RecordedChannel &c : rec.channels)
        out += ',' + quoted(printable(c.info.label())); // for people; names are in "# channel:"
    out += '\n';

    // k-way merge on the integer nanosecond time: one row per distinct time stamp.
    for (;;) {
        qint64 row = std::numeric_limits<qint64>::max();
        for (int c = 0; c < n; ++c) {
            if (next[size_t(c)] < end[size_t(c)])
                row = std::min(row, nanos(rec.channels[c].buffer.time(next[size_t(c)])));
        }
        if (row == std::numeric_limits<qint64>::max())
            break;
        out += timeText(row);
        for (int c = 0; c < n; ++c) {
            const TraceBuffer &b = rec.channels[c].buffer;
            out += ',';
            qint64 &k = next[size_t(c)];
            if (k < end[size_t(c)] && nanos(b.time(k)) == row)
                out += numberText(b.value(k++));
        }
        out += '\n';
        if (out.size() >= kChunkBytes) {
            if (device.write(out) != out.size())
                return false;
            out.clear();
        }
    }
    return device.write(out) == out.size();
}

} // namespace

QByteArray toCsv(const Recording &recording, double t0, double t1)
{
    QBuffer buffer;
    buffer.open(QIODevice::WriteOnly);
    writeCsv(buffer, recording, t0, t1);
    return buffer.data();
}

Result<void> save(const QString &fileName, const Recording &recording, double t0, double t1)
{
    db::files::removeStaleTemporaries(fileName); // what a killed writer left
    QSaveFile file(fileName);
    if (!file.open(QIODevice::WriteOnly))
        return Error(Error::Kind::Io,
                     Tr::tr("cannot write %1: %2").arg(fileName, file.errorString()));
    if (!writeCsv(file, recording, t0, t1) || !file.commit())
        return Error(Error::Kind::Io,
                     Tr::tr("cannot write %1: %2").arg(fileName, file.errorString()));
    return {};
}

Result<Recording> load(const QString &fileName)
{
    const Result<QByteArray> bytes =
        files::readAll(fileName, files::kRecordingLimit, Tr::tr("a recording"));
    if (!bytes)
        return bytes.error();
    Result<Recording> rec = fromCsv(*bytes);
    if (!rec)
        return rec.error().prefixed(fileName);
    return rec;
}

} // namespace db::scope::csv
