#include "cia402statussource.h"

#include "core/deviceconnection.h"
#include "statusword.h"

namespace db::cia402 {

namespace {

constexpr ObjectAddress kStatusword { 0x6041, 0 };
constexpr ObjectAddress kModeDisplay { 0x6061, 0 };
constexpr ObjectAddress kPosition { 0x6064, 0 };
constexpr ObjectAddress kVelocity { 0x606C, 0 };
constexpr ObjectAddress kCurrent { 0x6078, 0 };
constexpr ObjectAddress kStatusRegister { 0x1002, 0 };
constexpr ObjectAddress kErrorCode { 0x603F, 0 };
constexpr ObjectAddress kInputs { 0x60FD, 0 };
constexpr ObjectAddress kOutputs { 0x60FE, 1 };

constexpr int kIoFirstBit = 16; // IN1 = 60FDh bit 16, OUT1 = 60FEh.1 bit 16 (movingcap.md 6.5)
constexpr int kErrorBitCount = 16; // 1002h bits 0-15 are errors, 16+ warnings (movingcap.md 7.2)

} // namespace

Cia402StatusSource::Cia402StatusSource(DeviceConnection *connection, QObject *parent)
    : StatusSource(connection, parent)
{
    setStatusWordAddress(kStatusword);
}

StatusSource *Cia402StatusSource::sourceOf(DeviceConnection *connection)
{
    if (!connection)
        return nullptr;
    if (!connection->statusSource())
        connection->setStatusSource(new Cia402StatusSource(connection));
    return connection->statusSource();
}

QList<ObjectAddress> Cia402StatusSource::objects()
{
    return { kStatusword,     kModeDisplay, kPosition, kVelocity, kCurrent,
             kStatusRegister, kErrorCode,   kInputs,   kOutputs };
}

QList<ObjectAddress> Cia402StatusSource::polledObjects() const
{
    QList<ObjectAddress> wanted = objects();
    if (const DeviceConnection *c = connection()) {
        const ObjectDictionary &dictionary = c->dictionary();
        wanted.removeIf([&dictionary](ObjectAddress a) { return !dictionary.contains(a); });
    }
    return wanted;
}

void Cia402StatusSource::poll()
{
    readEach(dueObjects());
}

QString Cia402StatusSource::statusWordLabel() const
{
    return tr("Statusword:");
}

QList<StatusLamp> Cia402StatusSource::lamps() const
{
    using K = StatusLamp::Kind;
    return { { sw::TargetReached, tr("Target reached"), K::Ok },
             { sw::Moving, tr("Moving"), K::Info },
             { sw::Warning, tr("Warning"), K::Warning },
             { sw::InternalLimitActive, tr("Internal limit"), K::Warning },
             { sw::Fault, tr("Fault"), K::Error } };
}

QList<StatusIoRow> Cia402StatusSource::ioRows() const
{
    return { { tr("Inputs (60FDh):"), QStringLiteral("IN"), kInputs, kIoFirstBit, kInputCount },
             { tr("Outputs (60FEh.1):"), QStringLiteral("OUT"), kOutputs, kIoFirstBit,
               kOutputCount } };
}

StatusValue Cia402StatusSource::mode() const
{
    StatusValue v = makeValue(QStringLiteral("mode"), tr("Mode:"), kModeDisplay);
    if (v.raw.isValid())
        v.text = QStringLiteral("%1 (%2)").arg(modeName(v.raw.toInt())).arg(v.raw.toInt());
    return v;
}

QList<StatusValue> Cia402StatusSource::actualValues() const
{
    return { makeValue(QStringLiteral("position"), tr("Position (6064h):"), kPosition),
             makeValue(QStringLiteral("velocity"), tr("Velocity (606Ch):"), kVelocity),
             makeValue(QStringLiteral("current"), tr("Current (6078h):"), kCurrent) };
}

StatusValue Cia402StatusSource::fault() const
{
    StatusValue v = makeValue(QStringLiteral("fault"), tr("Last error (603Fh):"), kErrorCode);
    if (!v.raw.isValid())
        return v;
    const quint32 c = quint32(v.raw.toULongLong());
    v.text = QStringLiteral("0x%1").arg(c, 4, 16, QLatin1Char('0'));
    if (c != 0 && connection()) {
        if (const auto known = connection()->dictionary().errorCode(c))
            v.text += QLatin1Char(' ') + known->name;
    }
    return v;
}

QString Cia402StatusSource::faultText() const
{
    const QVariant raw = value(kErrorCode);
    if (!raw.isValid())
        return {};
    const quint32 c = quint32(raw.toULongLong());
    if (c == 0)
        return tr("No error");
    return connection() ? connection()->dictionary().errorText(c) : QString();
}

bool Cia402StatusSource::faultActive() const
{
    return state() == State::Fault || state() == State::FaultReactionActive;
}

StatusValue Cia402StatusSource::faultRegister() const
{
    StatusValue v = makeValue(QStringLiteral("statusRegister"), tr("Status register (1002h):"),
                              kStatusRegister);
    if (v.raw.isValid())
        v.text = QStringLiteral("0x%1").arg(quint32(v.raw.toULongLong()), 8, 16, QLatin1Char('0'));
    return v;
}

QStringList Cia402StatusSource::registerBits(bool warnings) const
{
    const QVariant reg = value(kStatusRegister);
    const quint32 bits = quint32(reg.toULongLong());
    const ObjectDef *def =
        connection() ? connection()->dictionary().find(kStatusRegister) : nullptr;
    QStringList names;
    for (int bit = warnings ? kErrorBitCount : 0; bit < (warnings ? 32 : kErrorBitCount); ++bit) {
        if (!(bits & (1u << bit)))
            continue;
        QString name = tr("bit %1").arg(bit);
        if (def) {
            for (const BitField &field : def->bitFields) {
                if (field.bit == bit)
                    name = field.displayName();
            }
        }
        names.append(name);
    }
    return names;
}

QStringList Cia402StatusSource::errorBits() const
{
    return registerBits(false);
}

QStringList Cia402StatusSource::warnings() const
{
    return registerBits(true);
}

} // namespace db::cia402
