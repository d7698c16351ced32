#pragma once

// The candump log format of Linux can-utils (`candump -l`, read by `canplayer`, SavvyCAN,
// Wireshark), one frame per line:
//
//   (1700000000.123456) can0 5B2#4B41600027040000
//   (1700000000.200000) can0 18FF0032#0102          extended id: 8 hex digits
//   (1700000000.300000) can0 732#R                  remote request (DLC 0)
//
// Pure text helpers, no I/O. The format has no direction; the CAN monitor's log keeps it out.

#include <QCanBusFrame>
#include <QString>

#include <optional>

namespace db::widgets::candump {

struct Line
{
    qint64 epochUs = 0; // microseconds since 1970-01-01 UTC
    QString interface;
    QCanBusFrame frame;
};

// Without the line end.
QString formatLine(qint64 epochUs, const QString &interface, const QCanBusFrame &frame);
// Lines that are not a classic CAN frame in this format give nullopt.
std::optional<Line> parseLine(const QString &line);
// A name usable as the log's interface token: the last word of a bus name when it looks like
// one ("virtualcan can0" -> "can0"), else "can0".
QString interfaceName(const QString &busName);

} // namespace db::widgets::candump
