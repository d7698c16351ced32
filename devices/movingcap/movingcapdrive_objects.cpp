// MovingCapDrive: object access, computed objects and writes with side effects (spec 6, 9.9).
#include "movingcapdrive.h"

#include <QCoreApplication>
#include <cmath>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::simulation)
};
} // namespace

namespace db::sim {

namespace {
constexpr quint32 kSaveMagic = 0x65766173; // "save" (spec 9.9)
constexpr quint32 kLoadMagic = 0x64616F6C; // "load"

bool isInputFunctionObject(quint16 index)
{
    return index >= 0x3511 && index <= 0x351A;
}
} // namespace

Result<QVariant> MovingCapDrive::read(ObjectAddress address)
{
    catchUp();
    if (auto ok = m_store.checkRead(address); !ok)
        return ok.error();
    refreshComputed();
    return m_store.value(address);
}

Result<void> MovingCapDrive::write(ObjectAddress address, const QVariant &value)
{
    const Present present(this);
    auto raw = m_store.checkWrite(address, value);
    if (!raw)
        return raw.error();
    if (m_rejectedWrites.contains(address))
        return Error(
            Error::Kind::DeviceError,
            Tr::tr("%1 refused in the present device state (simulated)").arg(address.toString()),
            0x08000022);
    bool handled = false;
    if (auto special = writeSpecial(address, raw.value(), handled); !special)
        return special;
    if (!handled)
        m_store.set(address, raw.value());
    applyParameters();
    emitStatusIfChanged();
    return {};
}

void MovingCapDrive::refreshComputed()
{
    m_store.set({ 0x6041, 0 }, statusword());
    m_store.set({ 0x6061, 0 }, m_store.value({ 0x6060, 0 }));
    m_store.set({ 0x6064, 0 }, qRound64(shownPosition(m_axis.position())));
    m_store.set({ 0x606C, 0 }, qRound64(m_axis.measuredVelocity()));
    m_store.set({ 0x6078, 0 }, qRound64(m_axis.current()));
    m_store.set({ 0x60FC, 0 }, qRound64(m_axis.demandPosition() * userToIncrements()));
    m_store.set({ 0x60FD, 0 }, combinedInputs());
    m_store.set({ 0x60FE, 1 }, outputs());
    m_store.set({ 0x1001, 0 }, m_errorRegister);
    m_store.set({ 0x1002, 0 }, m_errorBits | m_warningBits);
    m_store.set({ 0x603F, 0 }, m_lastError);
    for (int i = 0; i < 4; ++i)
        m_store.set({ 0x1003, quint8(i + 1) }, i < m_history.size() ? m_history[i] : 0);
    m_store.set({ 0x3401, 0x0A }, qRound(m_temperature));
}

Result<void> MovingCapDrive::writeSpecial(ObjectAddress address, const QVariant &raw, bool &handled)
{
    handled = true;
    const quint32 key = address.key();
    if (key == ObjectAddress(0x6040, 0).key()) {
        applyControlword(quint16(raw.toULongLong()));
        return {};
    }
    if (key == ObjectAddress(0x6060, 0).key()) {
        setMode(int(raw.toLongLong()));
        return {};
    }
    if (key == ObjectAddress(0x1010, 1).key()) {
        if (raw.toULongLong() != kSaveMagic)
            return Error(Error::Kind::InvalidArgument,
                         Tr::tr("1010:1 expects 1702257011 ('save')"));
        m_store.storeToNvm();
        return {};
    }
    if (key == ObjectAddress(0x1011, 1).key()) {
        if (raw.toULongLong() != kLoadMagic)
            return Error(Error::Kind::InvalidArgument,
                         Tr::tr("1011:1 expects 1684107116 ('load')"));
        // Factory reset keeps the RABBIT motor parameters 3300h (spec 9.8).
        m_store.restoreFactory([](ObjectAddress a) { return a.index == 0x3300; });
        return {};
    }
    if (key == ObjectAddress(0x3510, 1).key()) {
        const quint32 before = combinedInputs();
        m_store.set(address, raw);
        processInputs(before);
        return {};
    }
    if (key == ObjectAddress(0x3510, 2).key()) {
        m_store.set(address, raw);
        const quint32 command = quint32(raw.toULongLong());
        const int input = int(command >> 8);
        if (input < 1 || input > 10)
            return Error(Error::Kind::OutOfRange,
                         Tr::tr("3510:2 input number %1 is not 1..10").arg(input));
        runInputFunction(input, int(command & 0xFF), true);
        return {};
    }
    if (key == ObjectAddress(0x60FE, 1).key()) {
        m_manualOutputs = quint32(raw.toULongLong()) & 0x000F0000u;
        return {};
    }
    if (key == ObjectAddress(0x60FF, 0).key()) {
        m_store.set(address, raw);
        if (m_machine.state() == cia402::State::OperationEnabled
            && m_store.integer({ 0x6060, 0 }) == 3 && !m_machine.halted())
            startVelocity(raw.toDouble());
        return {};
    }
    handled = false;
    if (isInputFunctionObject(address.index) && address.sub == 1) {
        m_store.set(address, raw);
        handled = true;
        evaluateSoftwareEnable();
    }
    return {};
}

double MovingCapDrive::accelerationToUser(qint64 raw) const
{
    if (!m_options.rotary)
        return double(raw) * 1000.0; // linear: [1000 units/s^2]
    // Rotary: [100 rpm/min] of the motor, i.e. raw * 100/3600 motor rev/s^2, through the gear
    // (6091h motor:shaft) and the feed (6092h units per shaft revolution).
    const double motorRevs = double(std::max<qint64>(1, m_store.integer({ 0x6091, 1 })));
    const double shaftRevs = double(std::max<qint64>(1, m_store.integer({ 0x6091, 2 })));
    const double feed = double(m_store.integer({ 0x6092, 1 }));
    const double feedRevs = double(std::max<qint64>(1, m_store.integer({ 0x6092, 2 })));
    return double(raw) * 100.0 / 3600.0 * shaftRevs / motorRevs * feed / feedRevs;
}

double MovingCapDrive::userToIncrements() const
{
    // Spec 9.7: Pos_internal = Pos_user * (608Fh.1 * 6091h.1 * 6092h.2)
    //                                    / (608Fh.2 * 6091h.2 * 6092h.1)
    const double num = double(m_store.integer({ 0x608F, 1 }))
        * double(m_store.integer({ 0x6091, 1 })) * double(m_store.integer({ 0x6092, 2 }));
    const double den = double(m_store.integer({ 0x608F, 2 }))
        * double(m_store.integer({ 0x6091, 2 })) * double(m_store.integer({ 0x6092, 1 }));
    return den != 0.0 ? num / den : 1.0;
}

} // namespace db::sim
