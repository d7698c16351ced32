#include "nm17xcodes.h"

#include <QCoreApplication>
#include <QStringList>

#include <algorithm>

namespace db::nm17x {

namespace {
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(Nm17x)
};
BitText bitText(int bit, const char *english)
{
    return { bit, Tr::tr(english), QString::fromLatin1(english) };
}

DisplayError displayError(int bit, const char *code, const char *text, const char *remedy)
{
    return { bit, QString::fromLatin1(code), Tr::tr(text), Tr::tr(remedy),
             QString::fromLatin1(text) };
}

// Display priority, highest first, by 204Eh:02 bit.
constexpr int kPriority[] = { 12, 13, 3, 0, 1, 2, 4, 5, 8, 9, 10, 11 };
} // namespace

QList<BitText> statusBits()
{
    return {
        bitText(0, QT_TRANSLATE_NOOP("Nm17x", "Moving")),
        bitText(1, QT_TRANSLATE_NOOP("Nm17x", "Manual positioning abort")),
        bitText(2, QT_TRANSLATE_NOOP("Nm17x", "Oscillation active")),
        bitText(3, QT_TRANSLATE_NOOP("Nm17x", "Takten active")),
        bitText(4, QT_TRANSLATE_NOOP("Nm17x", "ExternPosi active")),
        bitText(5, QT_TRANSLATE_NOOP("Nm17x", "Left key pressed")),
        bitText(6, QT_TRANSLATE_NOOP("Nm17x", "Right key pressed")),
        bitText(8, QT_TRANSLATE_NOOP("Nm17x", "Speed output IN4")),
        bitText(9, QT_TRANSLATE_NOOP("Nm17x", "Speed output IN3")),
        bitText(10, QT_TRANSLATE_NOOP("Nm17x", "Direction output IN2 (right)")),
        bitText(11, QT_TRANSLATE_NOOP("Nm17x", "Direction output IN1 (left)")),
        bitText(12, QT_TRANSLATE_NOOP("Nm17x", "Arrows active")),
        bitText(14, QT_TRANSLATE_NOOP("Nm17x", "Error")),
        bitText(15, QT_TRANSLATE_NOOP("Nm17x", "In Position")),
    };
}

QList<DisplayError> displayErrors()
{
    return {
        displayError(0, "Er 1", QT_TRANSLATE_NOOP("Nm17x", "end limit MAX violated"),
                     QT_TRANSLATE_NOOP("Nm17x", "Move into the allowed range")),
        displayError(1, "Er 2", QT_TRANSLATE_NOOP("Nm17x", "end limit MIN violated"),
                     QT_TRANSLATE_NOOP("Nm17x", "Move into the allowed range")),
        displayError(2, "Er 3",
                     QT_TRANSLATE_NOOP("Nm17x", "shaft does not turn despite the drive signal"),
                     QT_TRANSLATE_NOOP("Nm17x", "Check motor, cable and mechanics")),
        displayError(3, "Er 4", QT_TRANSLATE_NOOP("Nm17x", "motor fault (overcurrent)"),
                     QT_TRANSLATE_NOOP("Nm17x", "Fix the motor fault")),
        displayError(4, "Er 5", QT_TRANSLATE_NOOP("Nm17x", "target window not reached"),
                     QT_TRANSLATE_NOOP(
                         "Nm17x", "Enlarge the tolerance window or switch to creep speed earlier")),
        displayError(
            5, "Er 6",
            QT_TRANSLATE_NOOP("Nm17x", "direction error: the spindle turns the wrong way"),
            QT_TRANSLATE_NOOP("Nm17x", "Check the motor direction setting and the motor wiring")),
        displayError(
            8, "Er 8",
            QT_TRANSLATE_NOOP("Nm17x", "setpoint above end limit MAX (motor does not start)"),
            QT_TRANSLATE_NOOP("Nm17x", "Send a valid setpoint (mind the loop travel)")),
        displayError(
            9, "Er 9",
            QT_TRANSLATE_NOOP("Nm17x", "setpoint below end limit MIN (motor does not start)"),
            QT_TRANSLATE_NOOP("Nm17x", "Send a valid setpoint (mind the loop travel)")),
        displayError(10, "Er A", QT_TRANSLATE_NOOP("Nm17x", "collision limit violated"),
                     QT_TRANSLATE_NOOP("Nm17x", "Move into the allowed range")),
        displayError(11, "Er b",
                     QT_TRANSLATE_NOOP("Nm17x", "setpoint between end limit and collision limit"),
                     QT_TRANSLATE_NOOP("Nm17x", "Send a valid setpoint (mind the loop travel)")),
        displayError(12, "Er C",
                     QT_TRANSLATE_NOOP("Nm17x", "no encoder signal: the position cannot be read"),
                     QT_TRANSLATE_NOOP("Nm17x", "Check the sensor and its cable")),
        displayError(
            13, "Er d",
            QT_TRANSLATE_NOOP("Nm17x", "the encoder reports an error: the position is wrong"),
            QT_TRANSLATE_NOOP("Nm17x", "Fix the sensor")),
    };
}

QList<DisplayError> activeErrors(quint16 errors)
{
    const QList<DisplayError> all = displayErrors();
    QList<DisplayError> active;
    for (const int bit : kPriority) {
        if (!(errors & (1u << bit)))
            continue;
        const auto it = std::find_if(all.cbegin(), all.cend(),
                                     [bit](const DisplayError &e) { return e.bit == bit; });
        if (it != all.cend())
            active.append(*it);
    }
    return active;
}

QString statusText(quint16 status)
{
    QStringList names;
    for (const BitText &b : statusBits()) {
        if (status & (1u << b.bit))
            names.append(b.name);
    }
    return names.isEmpty() ? QStringLiteral("-") : names.join(QLatin1String(", "));
}

QString errorText(quint16 errors)
{
    QStringList parts;
    for (const DisplayError &e : activeErrors(errors))
        parts.append(QStringLiteral("%1 (%2)").arg(e.code, e.text));
    return parts.join(QLatin1String(", "));
}

QList<EmcyCode> emcyCodes()
{
    return {
        { 0x8100, 0, Tr::tr("CAN communication error") },
        { 0x8110, 0, Tr::tr("CAN buffer overflow") },
        { 0x8120, 0, Tr::tr("CAN error passive") },
        { 0x8130, 0, Tr::tr("heartbeat error") },
        { 0x8140, 0, Tr::tr("recovered from bus-off") },
        { 0x8150, 0, Tr::tr("CAN-ID collision") },
        { 0x8210, 1, Tr::tr("RxPDO does not exist") },
        { 0x8220, 1,
          Tr::tr("object not found in the conversion table (broadcast object not allowed)") },
        { 0x8220, 2, Tr::tr("transmit memory (FIFO) to the application controller too small") },
        { 0x8220, 3, Tr::tr("data type not correct") },
        { 0x8230, 1, Tr::tr("RxPDO2: invalid value in the control word") },
        { 0x8301, 1, Tr::tr("FIFO between the internal controllers too small") },
        { 0x8310, 1, Tr::tr("position, status and errors could not be read several times") },
        { 0x8310, 2, Tr::tr("transfer to the application controller failed: no valid response") },
        { 0x8310, 3, Tr::tr("faulty data read from the application controller") },
        { 0x8310, 4, Tr::tr("position, status and errors could not be read more than 3 times") },
        { 0x8310, 5, Tr::tr("unknown state of the application state machine") },
        { 0x8320, 1, Tr::tr("buffer overflow when sending to the application controller") },
        { 0x8320, 2, Tr::tr("motor stop command could not be sent") },
        { 0x8320, 3,
          Tr::tr("addressing commands could not be sent to the application controller") },
        { 0x8320, 4, Tr::tr("unknown state of the application state machine while writing data") },
    };
}

QString emcyText(quint16 code, quint8 subCode)
{
    QString first;
    for (const EmcyCode &e : emcyCodes()) {
        if (e.code != code)
            continue;
        if (e.subCode == subCode)
            return e.text;
        if (first.isEmpty())
            first = e.text;
    }
    return first;
}

} // namespace db::nm17x
