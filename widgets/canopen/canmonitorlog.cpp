#include "canmonitorlog.h"

#include <QRegularExpression>

namespace db::widgets::candump {

QString formatLine(qint64 epochUs, const QString &interface, const QCanBusFrame &frame)
{
    const QString id = frame.hasExtendedFrameFormat()
        ? QStringLiteral("%1").arg(frame.frameId(), 8, 16, QLatin1Char('0'))
        : QStringLiteral("%1").arg(frame.frameId(), 3, 16, QLatin1Char('0'));
    const QString data = frame.frameType() == QCanBusFrame::RemoteRequestFrame
        ? QStringLiteral("R")
        : QString::fromLatin1(frame.payload().toHex());
    return QStringLiteral("(%1.%2) %3 %4#%5")
        .arg(epochUs / 1000000)
        .arg(epochUs % 1000000, 6, 10, QLatin1Char('0'))
        .arg(interface, id.toUpper(), data.toUpper());
}

std::optional<Line> parseLine(const QString &line)
{
    static const QRegularExpression re(QStringLiteral(
        R"(^\s*\((\d+)\.(\d{6})\)\s+(\S+)\s+([0-9A-Fa-f]{3}|[0-9A-Fa-f]{8})#(R\d?|(?:[0-9A-Fa-f]{2}){0,8})\s*$)"));
    const auto m = re.match(line);
    if (!m.hasMatch())
        return std::nullopt;
    Line out;
    out.epochUs = m.captured(1).toLongLong() * 1000000 + m.captured(2).toLongLong();
    out.interface = m.captured(3);
    const QString id = m.captured(4);
    out.frame.setFrameId(id.toUInt(nullptr, 16));
    out.frame.setExtendedFrameFormat(id.size() == 8);
    const QString data = m.captured(5);
    if (data.startsWith(QLatin1Char('R')))
        out.frame.setFrameType(QCanBusFrame::RemoteRequestFrame);
    else
        out.frame.setPayload(QByteArray::fromHex(data.toLatin1()));
    return out;
}

QString interfaceName(const QString &busName)
{
    static const QRegularExpression word(QStringLiteral("^[a-z]+[0-9]+$"));
    const QString last = busName.section(QLatin1Char(' '), -1);
    return word.match(last).hasMatch() ? last : QStringLiteral("can0");
}

} // namespace db::widgets::candump
