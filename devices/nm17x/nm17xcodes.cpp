#include "nm17xcodes.h"

#include <QCoreApplication>
#include <QStringList>

#include <algorithm>

namespace db::nm17x {

namespace {
QString tr(const char *text)
{
    return QCoreApplication::translate("Nm17x", text);
}
// Display priority, highest first, by 204Eh:02 bit.
constexpr int kPriority[] = { 12, 13, 3, 0, 1, 2, 4, 5, 8, 9, 10, 11 };
} // namespace

QList<BitText> statusBits()
{
    return {
        { 0, tr("Moving") },
        { 1, tr("Manual positioning abort") },
        { 2, tr("Oscillation active") },
        { 3, tr("Takten active") },
        { 4, tr("ExternPosi active") },
        { 5, tr("Left key pressed") },
        { 6, tr("Right key pressed") },
        { 8, tr("Speed output IN4") },
        { 9, tr("Speed output IN3") },
        { 10, tr("Direction output IN2 (right)") },
        { 11, tr("Direction output IN1 (left)") },
        { 12, tr("Arrows active") },
        { 14, tr("Error") },
        { 15, tr("In Position") },
    };
}

QList<DisplayError> displayErrors()
{
    return {
        { 0, QStringLiteral("Er 1"), tr("end limit MAX violated"),
          tr("Move into the allowed range") },
        { 1, QStringLiteral("Er 2"), tr("end limit MIN violated"),
          tr("Move into the allowed range") },
        { 2, QStringLiteral("Er 3"), tr("shaft does not turn despite the drive signal"),
          tr("Check motor, cable and mechanics") },
        { 3, QStringLiteral("Er 4"), tr("motor fault (overcurrent)"), tr("Fix the motor fault") },
        { 4, QStringLiteral("Er 5"), tr("target window not reached"),
          tr("Enlarge the tolerance window or switch to creep speed earlier") },
        { 5, QStringLiteral("Er 6"), tr("direction error: the spindle turns the wrong way"),
          tr("Check the motor direction setting and the motor wiring") },
        { 8, QStringLiteral("Er 8"), tr("setpoint above end limit MAX (motor does not start)"),
          tr("Send a valid setpoint (mind the loop travel)") },
        { 9, QStringLiteral("Er 9"), tr("setpoint below end limit MIN (motor does not start)"),
          tr("Send a valid setpoint (mind the loop travel)") },
        { 10, QStringLiteral("Er A"), tr("collision limit violated"),
          tr("Move into the allowed range") },
        { 11, QStringLiteral("Er b"), tr("setpoint between end limit and collision limit"),
          tr("Send a valid setpoint (mind the loop travel)") },
        { 12, QStringLiteral("Er C"), tr("no encoder signal: the position cannot be read"),
          tr("Check the sensor and its cable") },
        { 13, QStringLiteral("Er d"), tr("the encoder reports an error: the position is wrong"),
          tr("Fix the sensor") },
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
        { 0x8100, 0, tr("CAN communication error") },
        { 0x8110, 0, tr("CAN buffer overflow") },
        { 0x8120, 0, tr("CAN error passive") },
        { 0x8130, 0, tr("heartbeat error") },
        { 0x8140, 0, tr("recovered from bus-off") },
        { 0x8150, 0, tr("CAN-ID collision") },
        { 0x8210, 1, tr("RxPDO does not exist") },
        { 0x8220, 1,
          tr("object not found in the conversion table (broadcast object not allowed)") },
        { 0x8220, 2, tr("transmit memory (FIFO) to the application controller too small") },
        { 0x8220, 3, tr("data type not correct") },
        { 0x8230, 1, tr("RxPDO2: invalid value in the control word") },
        { 0x8301, 1, tr("FIFO between the internal controllers too small") },
        { 0x8310, 1, tr("position, status and errors could not be read several times") },
        { 0x8310, 2, tr("transfer to the application controller failed: no valid response") },
        { 0x8310, 3, tr("faulty data read from the application controller") },
        { 0x8310, 4, tr("position, status and errors could not be read more than 3 times") },
        { 0x8310, 5, tr("unknown state of the application state machine") },
        { 0x8320, 1, tr("buffer overflow when sending to the application controller") },
        { 0x8320, 2, tr("motor stop command could not be sent") },
        { 0x8320, 3, tr("addressing commands could not be sent to the application controller") },
        { 0x8320, 4, tr("unknown state of the application state machine while writing data") },
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
