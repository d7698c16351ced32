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
// Display priority, highest first, by 204Eh:02 bit.
constexpr int kPriority[] = { 12, 13, 3, 0, 1, 2, 4, 5, 8, 9, 10, 11 };
} // namespace

QList<BitText> statusBits()
{
    return {
        { 0, Tr::tr("Moving") },
        { 1, Tr::tr("Manual positioning abort") },
        { 2, Tr::tr("Oscillation active") },
        { 3, Tr::tr("Takten active") },
        { 4, Tr::tr("ExternPosi active") },
        { 5, Tr::tr("Left key pressed") },
        { 6, Tr::tr("Right key pressed") },
        { 8, Tr::tr("Speed output IN4") },
        { 9, Tr::tr("Speed output IN3") },
        { 10, Tr::tr("Direction output IN2 (right)") },
        { 11, Tr::tr("Direction output IN1 (left)") },
        { 12, Tr::tr("Arrows active") },
        { 14, Tr::tr("Error") },
        { 15, Tr::tr("In Position") },
    };
}

QList<DisplayError> displayErrors()
{
    return {
        { 0, QStringLiteral("Er 1"), Tr::tr("end limit MAX violated"),
          Tr::tr("Move into the allowed range") },
        { 1, QStringLiteral("Er 2"), Tr::tr("end limit MIN violated"),
          Tr::tr("Move into the allowed range") },
        { 2, QStringLiteral("Er 3"), Tr::tr("shaft does not turn despite the drive signal"),
          Tr::tr("Check motor, cable and mechanics") },
        { 3, QStringLiteral("Er 4"), Tr::tr("motor fault (overcurrent)"),
          Tr::tr("Fix the motor fault") },
        { 4, QStringLiteral("Er 5"), Tr::tr("target window not reached"),
          Tr::tr("Enlarge the tolerance window or switch to creep speed earlier") },
        { 5, QStringLiteral("Er 6"), Tr::tr("direction error: the spindle turns the wrong way"),
          Tr::tr("Check the motor direction setting and the motor wiring") },
        { 8, QStringLiteral("Er 8"), Tr::tr("setpoint above end limit MAX (motor does not start)"),
          Tr::tr("Send a valid setpoint (mind the loop travel)") },
        { 9, QStringLiteral("Er 9"), Tr::tr("setpoint below end limit MIN (motor does not start)"),
          Tr::tr("Send a valid setpoint (mind the loop travel)") },
        { 10, QStringLiteral("Er A"), Tr::tr("collision limit violated"),
          Tr::tr("Move into the allowed range") },
        { 11, QStringLiteral("Er b"), Tr::tr("setpoint between end limit and collision limit"),
          Tr::tr("Send a valid setpoint (mind the loop travel)") },
        { 12, QStringLiteral("Er C"), Tr::tr("no encoder signal: the position cannot be read"),
          Tr::tr("Check the sensor and its cable") },
        { 13, QStringLiteral("Er d"), Tr::tr("the encoder reports an error: the position is wrong"),
          Tr::tr("Fix the sensor") },
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
