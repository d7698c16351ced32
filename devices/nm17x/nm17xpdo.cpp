#include "nm17xpdo.h"

#include <QCoreApplication>
#include <QtEndian>

namespace db::nm17x {

namespace {

constexpr int kPdoBytes = 8;

Error tooShort(const char *what, const QByteArray &payload)
{
    return Error(Error::Kind::Malformed,
                 QCoreApplication::translate("Nm17x", "%1 has %2 bytes, 8 expected")
                     .arg(QLatin1String(what))
                     .arg(payload.size()));
}

// One allowed combination: the bits that matter and their values. Bits 10..13 and 15 never
// matter (in the device's table they are "X"); the "X" bits of a row are outside its mask.
struct Row
{
    quint16 mask;
    quint16 value;
    Command command;
    bool speed; // bits 3..4 carry a speed (01b, 10b, 11b)
};
constexpr quint16 kFixed = 0x43FF; // bits 0..9 and 14
constexpr quint16 kSpeedBits = 0x0018;
constexpr Row kRows[] = {
    { 0x43FF, 0x0000, Command::None, false },
    { 0x43E1, 0x0021, Command::WriteD3, false },
    { 0x43E1, 0x0041, Command::Reserved, false },
    { 0x43E1, 0x0061, Command::Reserved, false },
    { 0x43E7, 0x0007, Command::SetpointDirect, false },
    { kFixed, 0x0001, Command::Setpoint, false },
    { kFixed, 0x0003, Command::SetpointRelease, false },
    { kFixed & ~kSpeedBits, 0x0001, Command::Einsaegen, true },
    { kFixed & ~kSpeedBits, 0x0003, Command::EinsaegenRelease, true },
    { kFixed & ~kSpeedBits, 0x0081, Command::JogRight, true },
    { kFixed & ~kSpeedBits, 0x0101, Command::JogLeft, true },
    { kFixed, 0x0201, Command::ClampOpen, false },
    { kFixed, 0x0203, Command::ClampClose, false },
};

bool takesSpeed(Command c)
{
    return c == Command::Einsaegen || c == Command::EinsaegenRelease || c == Command::JogRight
        || c == Command::JogLeft;
}

} // namespace

QByteArray encodeBroadcast(const Broadcast &b)
{
    QByteArray d(kPdoBytes, '\0');
    d[0] = char(b.control);
    qToLittleEndian(b.index, d.data() + 1);
    d[3] = char(b.subIndex);
    qToLittleEndian(b.data, d.data() + 4);
    return d;
}

Result<Broadcast> decodeBroadcast(const QByteArray &payload)
{
    if (payload.size() < kPdoBytes)
        return tooShort("RxPDO1", payload);
    return Broadcast { quint8(payload.at(0)), qFromLittleEndian<quint16>(payload.constData() + 1),
                       quint8(payload.at(3)), qFromLittleEndian<quint32>(payload.constData() + 4) };
}

bool isBroadcastObject(quint16 index, quint8 subIndex)
{
    switch (index) {
    case 0x2001:
    case 0x2008:
    case 0x2015:
    case 0x6003:
        return subIndex == 0;
    case 0x204D:
        return subIndex == 1 || subIndex == 2;
    default:
        return false;
    }
}

QByteArray encodePositionCommand(const PositionCommand &c)
{
    QByteArray d(kPdoBytes, '\0');
    qToLittleEndian(c.setpoint, d.data());
    qToLittleEndian(c.correction, d.data() + 4);
    qToLittleEndian(c.control, d.data() + 6);
    return d;
}

Result<PositionCommand> decodePositionCommand(const QByteArray &payload)
{
    if (payload.size() < kPdoBytes)
        return tooShort("RxPDO2", payload);
    return PositionCommand { qFromLittleEndian<qint32>(payload.constData()),
                             qFromLittleEndian<qint16>(payload.constData() + 4),
                             qFromLittleEndian<quint16>(payload.constData() + 6) };
}

Result<Tpdo1> decodeTpdo1(const QByteArray &payload)
{
    if (payload.size() < kPdoBytes)
        return tooShort("TxPDO1", payload);
    return Tpdo1 { qFromLittleEndian<qint32>(payload.constData()),
                   qFromLittleEndian<quint16>(payload.constData() + 4),
                   qFromLittleEndian<quint16>(payload.constData() + 6) };
}

Result<Tpdo2> decodeTpdo2(const QByteArray &payload)
{
    if (payload.size() < kPdoBytes)
        return tooShort("TxPDO2", payload);
    return Tpdo2 { qFromLittleEndian<qint32>(payload.constData()),
                   qFromLittleEndian<qint16>(payload.constData() + 4),
                   qFromLittleEndian<quint16>(payload.constData() + 6) };
}

QByteArray encodeTpdo1(const Tpdo1 &t)
{
    QByteArray d(kPdoBytes, '\0');
    qToLittleEndian(t.position, d.data());
    qToLittleEndian(t.status, d.data() + 4);
    qToLittleEndian(t.errors, d.data() + 6);
    return d;
}

QByteArray encodeTpdo2(const Tpdo2 &t)
{
    QByteArray d(kPdoBytes, '\0');
    qToLittleEndian(t.position, d.data());
    qToLittleEndian(t.correction, d.data() + 4);
    qToLittleEndian(t.status, d.data() + 6);
    return d;
}

Result<quint16> controlWord(Command command, std::optional<Speed> speed)
{
    if (takesSpeed(command) && !speed)
        return Error(Error::Kind::InvalidArgument,
                     QCoreApplication::translate("Nm17x", "%1 needs a speed (slow, medium, fast)")
                         .arg(commandName(command)));
    if (!takesSpeed(command) && speed)
        return Error(
            Error::Kind::InvalidArgument,
            QCoreApplication::translate("Nm17x", "%1 takes no speed").arg(commandName(command)));
    if (command == Command::Stop)
        return control::Stop;
    if (command == Command::Reserved)
        return Error(
            Error::Kind::InvalidArgument,
            QCoreApplication::translate("Nm17x", "the reserved combinations have no function"));
    for (const Row &row : kRows) {
        if (row.command == command)
            return quint16(row.value | (speed ? int(*speed) << control::SpeedShift : 0));
    }
    return Error(Error::Kind::InvalidArgument,
                 QCoreApplication::translate("Nm17x", "unknown command"));
}

Result<Classified> classify(quint16 word)
{
    if (word & control::Stop)
        return Classified { Command::Stop, {} };
    for (const Row &row : kRows) {
        if ((word & row.mask) != row.value)
            continue;
        if (!row.speed)
            return Classified { row.command, {} };
        const int bits = (word & kSpeedBits) >> control::SpeedShift;
        if (bits != 0)
            return Classified { row.command, Speed(bits) };
    }
    return Error(Error::Kind::InvalidArgument,
                 QCoreApplication::translate("Nm17x",
                                             "control word 0x%1 is not an allowed combination; "
                                             "the display would reject it with EMCY 8230h")
                     .arg(word, 4, 16, QLatin1Char('0')));
}

QString commandName(Command command)
{
    switch (command) {
    case Command::None:
        return QCoreApplication::translate("Nm17x", "no function");
    case Command::WriteD3:
        return QCoreApplication::translate("Nm17x", "write D3");
    case Command::Reserved:
        return QCoreApplication::translate("Nm17x", "reserved");
    case Command::SetpointDirect:
        return QCoreApplication::translate("Nm17x", "direct setpoint");
    case Command::Setpoint:
        return QCoreApplication::translate("Nm17x", "setpoint");
    case Command::SetpointRelease:
        return QCoreApplication::translate("Nm17x", "setpoint with release");
    case Command::Einsaegen:
        return QCoreApplication::translate("Nm17x", "plunge-cut setpoint");
    case Command::EinsaegenRelease:
        return QCoreApplication::translate("Nm17x", "plunge-cut setpoint with release");
    case Command::JogRight:
        return QCoreApplication::translate("Nm17x", "jog right");
    case Command::JogLeft:
        return QCoreApplication::translate("Nm17x", "jog left");
    case Command::ClampOpen:
        return QCoreApplication::translate("Nm17x", "open clamp");
    case Command::ClampClose:
        return QCoreApplication::translate("Nm17x", "close clamp");
    case Command::Stop:
        return QCoreApplication::translate("Nm17x", "stop");
    }
    return {};
}

QString speedName(Speed speed)
{
    switch (speed) {
    case Speed::Slow:
        return QStringLiteral("slow");
    case Speed::Medium:
        return QStringLiteral("medium");
    case Speed::Fast:
        return QStringLiteral("fast");
    }
    return {};
}

std::optional<Speed> parseSpeed(const QString &text)
{
    for (const Speed s : { Speed::Slow, Speed::Medium, Speed::Fast }) {
        if (text.compare(speedName(s), Qt::CaseInsensitive) == 0)
            return s;
    }
    return std::nullopt;
}

} // namespace db::nm17x
