#include "movingcapfaults.h"

#include <array>

namespace db::sim::faults {

MovingCapFault lookup(quint16 code)
{
    // movingcap.md 7.1 (error register byte) and 7.2 (1002h bit).
    static const std::array<MovingCapFault, 13> table { {
        { OverCurrent, 11, 0x05, false },
        { OverVoltage, 0, 0x05, false },
        { UnderVoltage, 1, 0x05, false },
        { OverTemperature, 3, 0x09, false },
        { Derating, 4, 0x05, false },
        { Acknowledge, 2, 0x09, false },
        { Stroke, 6, 0x10, false },
        { Communication, 7, 0x10, false },
        { Sensor, 8, 0x10, false },
        { SoftwareEnable, 9, 0x10, false },
        { ExternalTorque, 12, 0x10, false },
        { NeedsReset, 13, 0x10, true },
        { AbortConnection, 5, 0x11, false }, // generic + communication
    } };
    for (const MovingCapFault &f : table) {
        if (f.code == code)
            return f;
    }
    return MovingCapFault { code, -1, 0x01, false };
}

QByteArray emergencyData(quint16 code, quint8 errorRegister)
{
    QByteArray data(8, '\0');
    data[0] = char(code & 0xFF);
    data[1] = char(code >> 8);
    data[2] = char(errorRegister);
    return data;
}

} // namespace db::sim::faults
