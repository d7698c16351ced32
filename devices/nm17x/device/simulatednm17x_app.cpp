// The application side of a simulated NM17x display: the device's own checks on SDO writes,
// the effects of writes, broadcasts and positioning commands on the spindle, and the values the
// device computes (position, status, errors).
#include "simulatednm17x.h"

#include "devices/nm17x/nm17xcodes.h"

#include "canopen/sdoabort.h"
#include "canopen/storesignatures.h"

#include <QCoreApplication>

#include <cmath>

namespace db::nm17x {

using namespace db::canopen;

namespace {
constexpr quint16 kInvalidControlWord = 0x8230;
constexpr quint16 kNotInConversionTable = 0x8220;
constexpr quint8 kSub1 = 1;
constexpr quint8 kSubFifo = 2;

Error abortWith(quint32 code, const QString &text)
{
    return Error(Error::Kind::InvalidArgument, text, code);
}

bool isJogCode(quint32 v)
{
    return (v >= 11 && v <= 13) || (v >= 21 && v <= 23);
}
} // namespace

qint32 SimulatedNm17x::position() const
{
    return qint32(qRound(m_spindle.position() + stepsToPosition(m_acceptedGlitch)));
}

double SimulatedNm17x::stepsToPosition(double steps) const
{
    return steps * m_scaling / 1e7;
}

void SimulatedNm17x::disturbSensor(double steps, int readings)
{
    wake();
    m_glitchSteps = steps;
    m_glitchReadings = qMax(0, readings);
}

// The device's filter against position jumps (2005h:01 width in sensor steps, 2005h:02 count): a
// reading that differs from the last accepted one by more than the width is discarded, up to
// `count` times in a row; the next is taken (a real jump), and a reading within the width resets
// the count. The spindle moves continuously (hand and motor travel stay far below the width per
// reading), so only the sensor's disturbance can jump; our reading of width 0: no filter.
void SimulatedNm17x::readSensor()
{
    const double width = u32({ 0x2005, 1 });
    const int count = int(u32({ 0x2005, 2 }));
    const double jump = m_glitchSteps - m_acceptedGlitch;
    if (width > 0 && std::abs(jump) > width && m_discarded < count) {
        ++m_discarded;
        ++m_filteredJumps;
    } else {
        m_acceptedGlitch = m_glitchSteps;
        m_discarded = 0;
    }
    if (m_glitchReadings > 0 && --m_glitchReadings == 0)
        m_glitchSteps = 0; // the disturbance is over
    else if (m_glitchReadings == 0 && m_glitchSteps != 0 && m_acceptedGlitch == m_glitchSteps) {
        // A lasting jump, once taken, is where the display believes the spindle is.
        m_spindle.setPosition(m_spindle.position() + stepsToPosition(m_glitchSteps));
        m_glitchSteps = 0;
        m_acceptedGlitch = 0;
    }
}

// Scaling 2004h: the position is sensor steps x scaling, plus the preset offset. A new scaling
// keeps the steps (the shaft did not move) and so changes the position; 0 leaves it where it is.
void SimulatedNm17x::applyScaling(quint32 scaling)
{
    if (scaling == m_scaling)
        return;
    if (scaling != 0 && m_scaling != 0) {
        const double raw = m_spindle.position() - m_presetOffset;
        m_spindle.setPosition(m_presetOffset + raw * double(scaling) / double(m_scaling));
        m_spindle.turnByHand(0, settings()); // In Position only if still inside the window
    }
    m_scaling = scaling;
}

quint16 SimulatedNm17x::statusWord() const
{
    const quint16 s = m_spindle.status(settings()) | (errorWord() ? status::Error : 0)
        | (m_oscillating ? status::Oscillating : 0) | inputStatus()
        | (m_keyDown < 0 ? status::LeftKey : 0) | (m_keyDown > 0 ? status::RightKey : 0);
    return hasMotor(m_variant) ? s : (s & status::ArrowsActive);
}

quint16 SimulatedNm17x::errorWord() const
{
    return hasMotor(m_variant) ? m_spindle.errors() : 0;
}

SpindleSettings SimulatedNm17x::settings() const
{
    SpindleSettings s;
    const auto i32 = [this](ObjectAddress a, qint32 fallback) {
        return m_dictionary.contains(a) ? m_store->value(a).toInt() : fallback;
    };
    s.loop = i32({ 0x2002, 0 }, 0);
    s.approachDown = u32({ 0x2000, 1 }) == 1;
    const quint32 arrows = u32({ 0x2000, 3 });
    s.arrowsWithoutLoop = arrows == 2 || arrows == 3;
    s.tolerance = i32({ 0x2003, 0 }, 5);
    s.slowPoint = i32({ 0x2042, 1 }, 0);
    s.creepPoint = i32({ 0x2042, 2 }, 150);
    s.switchOff = i32({ 0x2042, 3 }, 0);
    s.endMin = i32({ 0x2043, 1 }, kMinPosition);
    s.endMax = i32({ 0x2043, 2 }, kMaxPosition);
    s.collision = m_dictionary.contains({ 0x2041, 1 }) && u32({ 0x2041, 1 }) == 0;
    s.collisionMin = i32({ 0x2044, 1 }, kMinPosition);
    s.collisionMax = i32({ 0x2044, 2 }, kMaxPosition);
    s.dwellMs = i32({ 0x2047, 1 }, 10) * 100;
    s.followingErrorMs = i32({ 0x2047, 2 }, 30) * 100;
    s.preShutdown = m_dictionary.contains({ 0x2041, 2 }) && u32({ 0x2041, 2 }) == 1;
    // 2047h:03: 1..799 clamp delay; 801..899 and 901..999 with holding torque, delay = the last
    // two digits; 0, 800 and 900 no clamp handling.
    const int clamp = i32({ 0x2047, 3 }, 0);
    s.clampMs = (clamp > 0 && clamp < 800) ? clamp * 100 : (clamp % 100) * 100;
    return s;
}

Result<QVariant> SimulatedNm17x::read(ObjectAddress address)
{
    if (!m_dictionary.contains(address))
        return Error(Error::Kind::InvalidArgument, tr("no such object"), abort::NoSuchObject);
    switch ((quint32(address.index) << 8) | address.sub) {
    case 0x600400:
        return QVariant(position());
    case 0x204E01:
        return QVariant(statusWord());
    case 0x204E02:
        return QVariant(errorWord());
    case 0x100200:
        return QVariant(quint32(statusWord()));
    case 0x101001:
    case 0x101002:
    case 0x101101:
    case 0x101102:
        return QVariant(1u);
    case 0x204D03:
        return QVariant(m_spindle.isJogging() ? quint8(m_store->value(address).toUInt())
                                              : quint8(0));
    case 0x204800: {
        const quint32 clamp = u32({ 0x2047, 3 });
        if (clamp == 0 || clamp >= 800)
            return QVariant(quint8(0));
        return QVariant(quint8(m_spindle.isMoving() ? 1 : 2));
    }
    default:
        return m_store->value(address);
    }
}

// The checks the device makes beyond type and access (SDO abort codes as the device sends them).
Result<void> SimulatedNm17x::checkWrite(ObjectAddress address, const QVariant &raw)
{
    const ObjectDef *def = m_dictionary.find(address);
    const auto valid = def->validate(raw);
    if (!valid)
        return abortWith(abort::InvalidValue, valid.error().message());
    const quint32 v = quint32(raw.toULongLong());
    const quint32 key = (quint32(address.index) << 8) | address.sub;
    switch (key) {
    case 0x1F8000:
        if (v != 0 && v != 8)
            return abortWith(abort::InvalidValue, tr("only 0 and 8 are allowed"));
        break;
    case 0x100300:
        if (v != 0)
            return abortWith(abort::InvalidValue, tr("only 0 clears the history"));
        break;
    case 0x101001:
    case 0x101002:
        if (v != store::kSaveSignature)
            return abortWith(abort::CannotStore, tr("wrong signature"));
        break;
    case 0x101101:
    case 0x101102:
        if (v != store::kLoadSignature)
            return abortWith(abort::CannotStore, tr("wrong signature"));
        break;
    case 0x180002:
    case 0x180102:
        if (v > 0xF0 && v < 0xFE)
            return abortWith(abort::InvalidValue, tr("transmission type not supported"));
        break;
    case 0x200700:
        if (raw.toString().size() != 12)
            return abortWith(abort::InvalidValue, tr("exactly 12 characters"));
        break;
    case 0x204D03:
        if (!isJogCode(v))
            return abortWith(abort::InvalidValue, tr("11..13 or 21..23"));
        break;
    case 0x204503:
        if (u32({ 0x2041, 3 }) == 2 && m_inputF)
            return abortWith(abort::General, tr("D3 cannot be written while input F is active"));
        m_d3Released = true; // a written D3 may be used once, at once
        break;
    default:
        break;
    }
    return {};
}

Result<void> SimulatedNm17x::write(ObjectAddress address, const QVariant &raw)
{
    wake();
    if (!m_dictionary.contains(address))
        return Error(Error::Kind::InvalidArgument, tr("no such object"), abort::NoSuchObject);
    if (auto ok = checkWrite(address, raw); !ok)
        return ok;
    const QVariant value = m_dictionary.find(address)->validate(raw).value();
    const quint16 index = address.index;
    if (index < 0x2000 || index == 0x2100 || index == 0x2101) {
        // Communication objects: handled by the interface controller at once.
        if (address == ObjectAddress(0x1003, 0)) {
            for (quint8 s = 0; s <= 8; ++s)
                m_store->set({ 0x1003, s }, 0u);
            return {};
        }
        if (index == 0x1010) {
            for (const ObjectDef &def : m_dictionary.objects()) {
                if (def.address.index < 0x2000 && def.writable() && def.address.index != 0x1003
                    && def.address.index != 0x1010 && def.address.index != 0x1011)
                    m_flash.insert(def.address, m_store->value(def.address));
            }
            return {};
        }
        if (index == 0x1011) {
            m_restorePending = true; // defaults at the next Reset Node
            return {};
        }
        setValue(address, value);
        if (index == 0x1016)
            m_errorControl.configure();
        if (index == 0x1017)
            setState(m_state);
        return {};
    }
    if (index == 0x2500 || index == 0x2501) {
        m_store->set(address, value); // readable, no function
        return {};
    }
    if (m_writes.size() >= kWriteQueueSize) {
        raiseEmergency(kNotInConversionTable, kSubFifo);
        return abortWith(abort::HardwareError, tr("write queue to the application is full"));
    }
    if (storageOf(address) != Storage::None)
        m_store->set(address, value); // readable back at once
    m_writes.enqueue({ address, value });
    return {};
}

void SimulatedNm17x::startSetpoint(qint32 target, bool release, bool loop,
                                   std::optional<Speed> speed)
{
    const SpindleSettings s = settings();
    const quint16 refused = m_spindle.setTarget(target, loop, speed, s);
    if (release && !refused)
        m_spindle.release(s);
}

// Oscillation (spec 6.10, mode 0): continuous positioning between D1 (lower) and D2 (upper),
// each leg direct (no loop) with the usual speed stages; our reading: the first leg goes to D2
// unless the spindle is at or above it. The external mode switch (inputs F/G) is taken to be in
// its "no oscillation" position, so the command is accepted in input modes 0 and 3. Stopping
// positions back to the current setpoint 2020h:01 (with loop).
void SimulatedNm17x::setOscillation(bool on, bool byInputs)
{
    const quint32 mode = u32({ 0x2041, 3 });
    // Over CAN only in modes 0 and 3, and in mode 0 only while the switch is at 00: the switch
    // has priority.
    const bool switchOwns = mode == 0 && (m_inputF || m_inputG);
    if (!byInputs && (switchOwns || (on && mode != 0 && mode != 3)))
        return;
    if (!hasMotor(m_variant) || on == m_oscillating)
        return;
    m_oscillating = on;
    if (!on) {
        m_spindle.stop();
        return startSetpoint(m_store->value({ 0x2020, 1 }).toInt(), true, true, {});
    }
    m_towardsD2 = position() < m_store->value({ 0x2045, 2 }).toInt();
    const qint32 target = m_store->value({ 0x2045, m_towardsD2 ? quint8(2) : quint8(1) }).toInt();
    if (m_spindle.start(target, false, {}, settings()))
        m_oscillating = false; // Er 8/9/b: the reversal point is out of the limits
}

void SimulatedNm17x::oscillate()
{
    if (!m_oscillating || m_spindle.isMoving())
        return;
    m_towardsD2 = !m_towardsD2;
    const qint32 target = m_store->value({ 0x2045, m_towardsD2 ? quint8(2) : quint8(1) }).toInt();
    if (m_spindle.start(target, false, {}, settings()))
        m_oscillating = false;
}

void SimulatedNm17x::setCorrection(qint16 correction)
{
    if (correction != kKeepCorrection)
        m_store->set({ 0x2010, 0 }, qint32(correction));
}

// The effect of a write on the application, one per 10 ms cycle (and broadcasts at once).
void SimulatedNm17x::applyWrite(ObjectAddress address, const QVariant &raw)
{
    m_showNodeId = false; // any write ends the special display modes
    if (inputsOwnAxis() && (address.index == 0x2020 || address.index == 0x204D)) {
        // Only the official stop gets through, and only in ExternPosi (spec 6.10).
        const bool stop = address == ObjectAddress(0x204D, 1) && raw.toLongLong() == 0;
        if (!(stop && u32({ 0x2041, 3 }) == 2))
            return;
    }
    const qint32 v = raw.toInt();
    const auto speed = [this] {
        return std::optional(Speed(u32({ 0x2020, 8 }) + 1));
    };
    switch ((quint32(address.index) << 8) | address.sub) {
    case 0x202001:
        m_store->set({ 0x2020, 2 }, v);
        return startSetpoint(v, false, true, {});
    case 0x202002:
        m_store->set({ 0x2020, 1 }, v);
        return startSetpoint(v, true, true, {});
    case 0x202003:
        return startSetpoint(v, false, true, {});
    case 0x202004:
        return startSetpoint(v, true, true, {});
    case 0x202005:
        return startSetpoint(v, true, false, {});
    case 0x202006:
        return startSetpoint(v, false, true, speed());
    case 0x202007:
        return startSetpoint(v, true, true, speed());
    case 0x201000:
        m_store->set(address, v);
        return;
    case 0x200400:
        return applyScaling(quint32(v));
    case 0x600300: {
        // The actual value (with correction) becomes the preset.
        const qint32 correction = u32({ 0x2000, 6 }) ? m_store->value({ 0x2010, 0 }).toInt() : 0;
        const double position = double(v - correction);
        m_presetOffset += position - m_spindle.position();
        m_spindle.setPosition(position);
        m_spindle.turnByHand(0, settings()); // In Position only if still inside the window
        m_store->set(address, v);
        return;
    }
    case 0x201500:
        switch (v) {
        case 2:
            m_spindle.setPosition(m_presetOffset);
            return;
        case 4:
            m_store->set({ 0x2010, 0 }, 0);
            return;
        case 6:
            m_spindle.setPosition(m_spindle.position() - m_presetOffset);
            m_presetOffset = 0;
            return;
        default: // 1, 3: application defaults; 5: controller reset
            for (const ObjectDef &def : m_dictionary.objects()) {
                if (storageOf(def.address) == Storage::Eeprom && def.address.index != 0x6003
                    && (v != 5) && (def.address.index != 0x2010 || v == 3))
                    m_store->set(def.address, def.defaultValue);
            }
            if (v == 3) {
                m_spindle.setPosition(m_spindle.position() - m_presetOffset);
                m_presetOffset = 0;
            }
            if (v != 5)
                applyScaling(u32({ 0x2004, 0 }));
            m_spindle.stop();
            return;
        }
    case 0x200800:
        m_showNodeId = v == 1;
        return;
    case 0x204D01:
        if (v == 0) {
            m_oscillating = false; // the official stop ends everything
            return m_spindle.stop();
        }
        if (quint32(v) == u32({ 0x2040, 4 }) + 1)
            m_spindle.release(settings());
        return;
    case 0x204D02:
        m_store->set(address, v);
        return setOscillation(v == 1);
    case 0x204D03:
        m_oscillating = false;
        m_store->set(address, v);
        return m_spindle.jog(v < 20 ? 1 : -1, Speed(v % 10), settings());
    default:
        if (storageOf(address) == Storage::None)
            m_store->set(address, raw);
        return;
    }
}

// RxPDO1: one SDO write to every display at once, Operational only, mirrored in 2500h.
void SimulatedNm17x::handleBroadcast(const QByteArray &d)
{
    const auto b = decodeBroadcast(d);
    if (!b)
        return;
    m_store->set({ 0x2500, 1 }, b->control);
    m_store->set({ 0x2500, 2 }, b->index);
    m_store->set({ 0x2500, 3 }, b->subIndex);
    m_store->set({ 0x2500, 4 }, b->data);
    const ObjectAddress address(b->index, b->subIndex);
    if (!isBroadcastObject(b->index, b->subIndex))
        return raiseEmergency(kNotInConversionTable, kSub1);
    const ObjectDef *def = m_dictionary.find(address);
    if (!def)
        return; // a drive command to a display without motor
    const auto raw = def->validate(def->type == DataType::Integer32 ? QVariant(qint32(b->data))
                                                                    : QVariant(b->data));
    if (!raw)
        return;
    if (storageOf(address) != Storage::None)
        m_store->set(address, raw.value());
    applyWrite(address, raw.value());
}

// RxPDO2: setpoint, correction and control word, checked against the allowed combinations.
void SimulatedNm17x::handleRpdo2(const QByteArray &d)
{
    const auto c = decodePositionCommand(d);
    if (!c)
        return raiseEmergency(0x8210, kSub1);
    m_store->set({ 0x2501, 1 }, quint32(c->setpoint));
    m_store->set({ 0x2501, 2 }, quint16(c->correction));
    m_store->set({ 0x2501, 3 }, c->control);
    const auto what = classify(c->control);
    if (!what)
        return raiseEmergency(kInvalidControlWord, kSub1);
    const bool motor = hasMotor(m_variant);
    const SpindleSettings s = settings();
    if (inputsOwnAxis() && what->command != Command::Stop && what->command != Command::WriteD3)
        return; // Takten / ExternPosi own the axis
    switch (what->command) {
    case Command::None:
    case Command::Reserved:
        return;
    case Command::Stop:
        m_oscillating = false;
        return m_spindle.stop();
    case Command::WriteD3:
        setCorrection(c->correction);
        if (motor && !(u32({ 0x2041, 3 }) == 2 && m_inputF)) {
            m_store->set({ 0x2045, 3 }, c->setpoint);
            m_d3Released = true;
        }
        return;
    case Command::SetpointDirect:
        setCorrection(c->correction);
        return startSetpoint(c->setpoint, true, false, {});
    case Command::Setpoint:
    case Command::SetpointRelease:
        setCorrection(c->correction);
        m_store->set({ 0x2020, 1 }, c->setpoint);
        return startSetpoint(c->setpoint, what->command == Command::SetpointRelease, true, {});
    case Command::Einsaegen:
    case Command::EinsaegenRelease:
        setCorrection(c->correction);
        return startSetpoint(c->setpoint, what->command == Command::EinsaegenRelease, true,
                             what->speed);
    case Command::JogRight:
    case Command::JogLeft:
        return m_spindle.jog(what->command == Command::JogRight ? 1 : -1, *what->speed, s);
    case Command::ClampOpen:
    case Command::ClampClose:
        return; // the clamp state follows the motion; manual clamping is not simulated
    }
}

} // namespace db::nm17x
