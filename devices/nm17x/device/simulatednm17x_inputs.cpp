// SimulatedNm17x: the external inputs F and G and their operating modes (spec 6.10, 2041h:03).
// Our readings where the manual leaves a gap: the debounce times (390 ms Takten, 16 ms
// ExternPosi) are not simulated, an input edge acts in the next call; in mode 0 one input
// travels like a held key at the speed of 2000h:08 (0 "Key": slow) until released.
#include "simulatednm17x.h"

#include "devices/nm17x/nm17xcodes.h"

namespace db::nm17x {

namespace {
constexpr quint32 kModeStandard = 0;
constexpr quint32 kModeTakten = 1;
constexpr quint32 kModeExternPosi = 2;
} // namespace

bool SimulatedNm17x::inputsOwnAxis() const
{
    if (!hasMotor(m_variant))
        return false;
    const quint32 mode = u32({ 0x2041, 3 });
    return (mode == kModeTakten && m_inputF != m_inputG) || (mode == kModeExternPosi && m_inputF);
}

quint16 SimulatedNm17x::inputStatus() const
{
    if (!hasMotor(m_variant))
        return 0;
    const quint32 mode = u32({ 0x2041, 3 });
    quint16 bits = 0;
    if (mode == kModeTakten && m_inputF != m_inputG)
        bits |= status::Takten;
    if (mode == kModeExternPosi && m_inputF)
        bits |= status::ExternPosi;
    return bits;
}

void SimulatedNm17x::setInputs(bool f, bool g)
{
    wake();
    const bool oldF = m_inputF;
    const bool oldG = m_inputG;
    m_inputF = f;
    m_inputG = g;
    if (!hasMotor(m_variant))
        return;
    const auto d = [this](quint8 sub) {
        return m_store->value({ 0x2045, sub }).toInt();
    };
    switch (u32({ 0x2041, 3 })) {
    case kModeStandard:
        if (f && g) {
            setOscillation(true, true);
        } else if (oldF && oldG) {
            setOscillation(false, true); // back to the setpoint
        } else if (f != g) {
            const quint32 speed = u32({ 0x2000, 8 });
            m_spindle.jog(f ? 1 : -1, speed == 0 ? Speed::Slow : Speed(speed), settings());
        } else if (oldF != oldG) {
            m_spindle.stop();
        }
        return;
    case kModeTakten:
        // A rising edge of exactly one input positions to its point like a setpoint.
        if (f && !oldF && !g)
            startSetpoint(d(1), true, true, {});
        else if (g && !oldG && !f)
            startSetpoint(d(2), true, true, {});
        return;
    case kModeExternPosi:
        if (f && !oldF && m_d3Released) {
            m_externPosiRunning = true;
            startSetpoint(d(3), true, true, {});
        } else if (!f && oldF && m_externPosiRunning) {
            // Released before the target: stop, and D3 must be written again.
            m_spindle.stop();
            m_externPosiRunning = false;
            m_d3Released = false;
        }
        return;
    default:
        return; // 3: inputs ignored
    }
}

void SimulatedNm17x::followExternPosi()
{
    if (m_externPosiRunning && !m_spindle.isMoving()) {
        m_externPosiRunning = false;
        m_d3Released = false; // the release is cleared at the target
    }
}

} // namespace db::nm17x
