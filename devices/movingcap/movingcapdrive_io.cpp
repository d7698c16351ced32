// MovingCapDrive: digital inputs with input functions, outputs with output functions (spec 8).
#include "movingcapdrive.h"

#include "movingcapfaults.h"

#include <cmath>

namespace db::sim {

namespace {
constexpr int kInputs = 10;
constexpr int kOutputs = 4;

quint32 inputBit(int input)
{
    return 1u << (15 + input); // IN1 = bit 16 (spec 6.5)
}

quint16 inputObject(int input)
{
    return quint16(0x3510 + input); // 3511h = IN1 ... 351Ah = IN10
}

quint16 outputObject(int output)
{
    return quint16(0x3610 + output); // 3611h = OUT1 ... 3614h = OUT4
}
} // namespace

void MovingCapDrive::setPhysicalInput(int number, bool high)
{
    const Present present(this);
    if (number < 1 || number > kInputs)
        return;
    const quint32 before = combinedInputs();
    m_physicalInputs =
        high ? (m_physicalInputs | inputBit(number)) : (m_physicalInputs & ~inputBit(number));
    processInputs(before);
}

quint32 MovingCapDrive::combinedInputs() const
{
    // Virtual inputs simulate a high level: OR-combined with the physical ones (spec 8.4 [R]).
    return m_physicalInputs | quint32(m_store.integer({ 0x3510, 1 }));
}

void MovingCapDrive::processInputs(quint32 before)
{
    const quint32 now = combinedInputs();
    evaluateSoftwareEnable();
    for (int n = 1; n <= kInputs; ++n) {
        const quint32 bit = inputBit(n);
        if ((before ^ now) & bit) {
            const bool rising = now & bit;
            const quint16 config = quint16(m_store.integer({ inputObject(n), 1 }));
            // HiByte runs on the rising edge, LoByte on the falling edge (spec 8.2).
            runInputFunction(n, rising ? config >> 8 : config & 0xFF, rising);
        }
    }
    emitStatusIfChanged();
}

void MovingCapDrive::evaluateSoftwareEnable()
{
    // Function 9: 0900h = enabled while high, 0009h = enabled while low (spec 8.3).
    bool enabled = true;
    const quint32 in = combinedInputs();
    for (int n = 1; n <= kInputs; ++n) {
        const quint16 config = quint16(m_store.integer({ inputObject(n), 1 }));
        if ((config >> 8) == 9 && !(in & inputBit(n)))
            enabled = false;
        if ((config & 0xFF) == 9 && (in & inputBit(n)))
            enabled = false;
    }
    m_machine.setSoftwareEnable(enabled);
}

bool MovingCapDrive::teachActive() const
{
    const quint32 in = combinedInputs();
    for (int n = 1; n <= kInputs; ++n) {
        if ((m_store.integer({ inputObject(n), 1 }) >> 8) == 8 && (in & inputBit(n)))
            return true;
    }
    return false;
}

void MovingCapDrive::runInputFunction(int input, int function, bool rising)
{
    const quint16 obj = inputObject(input);
    const qint64 position = qRound64(m_axis.position());
    const double delay = std::max<qint64>(0, m_store.integer({ obj, 5 })) / 1000.0;
    switch (function) {
    case 1: // capture position -> Result 1
        m_store.set({ obj, 3 }, position);
        break;
    case 2: // capture position -> Result 2
        m_store.set({ obj, 4 }, position);
        break;
    case 3: // counter in Result 1
        m_store.set({ obj, 3 }, m_store.integer({ obj, 3 }) + 1);
        break;
    case 4: // timed motion absolute; teach target while a function 8 input is high
        if (teachActive()) {
            m_store.set({ obj, 8 }, position);
            break;
        }
        ++m_motionGeneration;
        schedule(delay, [this, input] { timedMotion(input, false); });
        break;
    case 5: // quick stop, 605Ah := 6 first
        m_store.set({ 0x605A, 0 }, 6);
        m_machine.setQuickStopOption(6);
        handle(m_machine.quickStop(6));
        break;
    case 6: // timed motion relative
        ++m_motionGeneration;
        schedule(delay, [this, input] { timedMotion(input, true); });
        break;
    case 7: { // set home / homing with this input's parameters
        ++m_motionGeneration;
        schedule(delay, [this, obj] {
            const int method = int(m_store.integer({ obj, 9 }));
            if (!ensureOperational(6))
                return;
            m_store.set({ 0x6098, 0 }, method);
            startHoming(method, double(m_store.integer({ obj, 8 })));
        });
        break;
    }
    case 10: // jog positive / 11: jog negative, hold-to-run
    case 11: {
        const double acc = accelerationToUser(m_store.integer({ obj, 7 }));
        const double dec = accelerationToUser(m_store.integer({ obj, 9 }));
        if (rising) {
            if (!ensureOperational(3))
                return;
            const qint64 speed = std::abs(m_store.integer({ obj, 6 }));
            const qint64 velocity = function == 10 ? speed : -speed;
            m_store.set({ 0x60FF, 0 }, velocity);
            m_axis.moveVelocity(double(velocity), acc, dec);
        } else if (m_store.integer({ 0x6060, 0 }) == 3) {
            m_store.set({ 0x60FF, 0 }, 0); // not a quick stop: the configured deceleration
            m_axis.moveVelocity(0.0, acc, dec);
        }
        break;
    }
    default: // 0 none, 8 teach and 9 software enable act on levels
        break;
    }
}

void MovingCapDrive::timedMotion(int input, bool relative)
{
    const quint16 obj = inputObject(input);
    if (!ensureOperational(1))
        return;
    const double value = double(m_store.integer({ obj, 8 }));
    const double target = relative ? relativeBase() + value : value;
    const auto orDefault = [this](qint64 v, ObjectAddress fallback) {
        return v > 0 ? v : m_store.integer(fallback);
    };
    startPositionMove(target, true, double(orDefault(m_store.integer({ obj, 6 }), { 0x6081, 0 })),
                      accelerationToUser(orDefault(m_store.integer({ obj, 7 }), { 0x6083, 0 })),
                      accelerationToUser(orDefault(m_store.integer({ obj, 9 }), { 0x6084, 0 })));
    m_store.set({ obj, 3 }, qRound64(target * userToIncrements())); // last target, increments
    m_store.set({ obj, 4 }, m_store.integer({ obj, 4 }) + 1); // moves triggered
    m_inputTargets.insert(input, target);
}

bool MovingCapDrive::outputFunction(int output, int function) const
{
    const quint16 obj = outputObject(output);
    const qint64 p2 = m_store.integer({ obj, 2 });
    const double position = m_axis.position();
    const auto inWindow = [&](double target) {
        return position >= target - double(m_store.integer({ obj, 6 }))
            && position <= target + double(m_store.integer({ obj, 5 }));
    };
    const bool healthy =
        !(statusword() & (cia402::sw::Warning | cia402::sw::Fault)) && (m_errorBits & 0xFFFF) == 0;
    switch (function) {
    case 1: // statusword monitor: all bits of the mask (spec 8.5 [R])
        return p2 != 0 && (statusword() & p2) == p2;
    case 2: // 1002h monitor
        return p2 != 0 && ((m_errorBits | m_warningBits) & quint32(p2)) == quint32(p2);
    case 3: { // limit monitoring right (1) / left (2)
        const double v = m_axis.velocity();
        const double right = double(m_store.integer({ obj, 3 }));
        const double left = double(m_store.integer({ obj, 4 }));
        const bool r = (p2 & 1) && v > 0 && position >= right
            && position <= right + double(m_store.integer({ obj, 5 }));
        const bool l = (p2 & 2) && v < 0 && position <= left
            && position >= left - double(m_store.integer({ obj, 6 }));
        return r || l;
    }
    case 4:
    case 6: {
        bool held = false;
        if (p2 == 0) {
            held = inWindow(m_lastTarget);
        } else if (p2 == 255) { // bit-coded: binary number of the input whose target is held
            for (auto it = m_inputTargets.cbegin(); it != m_inputTargets.cend(); ++it) {
                if (inWindow(it.value()) && ((it.key() >> (output - 1)) & 1))
                    held = true;
            }
        } else {
            held = m_inputTargets.contains(int(p2)) && inWindow(m_inputTargets.value(int(p2)));
        }
        return function == 4 ? held : held && healthy;
    }
    case 5: // drive without fault or warning
        return healthy;
    default:
        break;
    }
    return false;
}

quint32 MovingCapDrive::outputs() const
{
    quint32 value = m_manualOutputs;
    for (int k = 1; k <= kOutputs; ++k) {
        const int function = int(m_store.integer({ outputObject(k), 1 }));
        if (function == 0)
            continue;
        const quint32 bit = 1u << (15 + k);
        value = outputFunction(k, function) ? (value | bit) : (value & ~bit);
    }
    return value;
}

} // namespace db::sim
