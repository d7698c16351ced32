#include "acustatussource.h"

#include "core/connectionhealth.h"
#include "core/deviceconnection.h"
#include "core/groupreader.h"
#include "core/reply.h"

namespace db::bonfiglioli {

namespace {

constexpr ObjectAddress kStatusWord { 411, 0 };
constexpr ObjectAddress kCurrentFault { 260, 0 };
constexpr ObjectAddress kWarnings { 270, 0 };
constexpr ObjectAddress kApplicationWarnings { 274, 0 };
constexpr ObjectAddress kBusErrorBehaviour { 388, 0 };
constexpr quint32 kApplicationWarningBit = 0x8000; // 270 bit 15: see 274

// Shown in this order, where the description has them.
constexpr ObjectAddress kActualValues[] = { { 210, 0 }, { 211, 0 }, { 213, 0 },
                                            { 240, 0 }, { 228, 0 }, { 249, 0 } };

enum StatusBit : quint32 {
    Fault = 0x0008,
    VoltageEnabled = 0x0010,
    Warning = 0x0080,
    Remote = 0x0200,
    TargetReached = 0x0400,
    InternalLimit = 0x0800,
    Warning2 = 0x8000,
};

} // namespace

AcuStatusSource::AcuStatusSource(DeviceConnection *connection, QObject *parent)
    : StatusSource(connection, parent)
{
    setStatusWordAddress(kStatusWord);
    m_objects = { kStatusWord, kCurrentFault, kWarnings, kApplicationWarnings, kBusErrorBehaviour };
    for (ObjectAddress address : kActualValues) {
        if (!connection || connection->dictionary().find(address)) {
            m_actualValues.append(address);
            m_objects.append(address);
        }
    }
}

QString AcuStatusSource::statusWordLabel() const
{
    return tr("Status word (411):");
}

QList<StatusLamp> AcuStatusSource::lamps() const
{
    using K = StatusLamp::Kind;
    return { { TargetReached, tr("Target reached"), K::Ok },
             { VoltageEnabled, tr("Mains on"), K::Info },
             { Remote, tr("Remote"), K::Info },
             { Warning, tr("Warning"), K::Warning },
             { Warning2, tr("Warning 2"), K::Warning },
             { InternalLimit, tr("Internal limit"), K::Warning },
             { Fault, tr("Fault"), K::Error } };
}

QList<StatusValue> AcuStatusSource::actualValues() const
{
    QList<StatusValue> values;
    static const QHash<quint16, QString> keys = {
        { 210, QStringLiteral("frequency") }, { 211, QStringLiteral("current") },
        { 213, QStringLiteral("power") },     { 240, QStringLiteral("speed") },
        { 228, QStringLiteral("reference") }, { 249, QStringLiteral("dataSet") },
    };
    for (ObjectAddress address : m_actualValues) {
        const ObjectDef *def = connection() ? connection()->dictionary().find(address) : nullptr;
        const QString name = def ? def->displayName() : QString();
        values.append(makeValue(keys.value(address.index),
                                QStringLiteral("%1 (%2):").arg(name).arg(address.index), address));
    }
    return values;
}

QString AcuStatusSource::faultName(quint32 code)
{
    return QStringLiteral("F%1").arg(code, 4, 16, QLatin1Char('0')).toUpper();
}

StatusValue AcuStatusSource::fault() const
{
    StatusValue v = makeValue(QStringLiteral("fault"), tr("Current fault (260):"), kCurrentFault);
    if (v.raw.isValid()) {
        const auto code = quint32(v.raw.toULongLong());
        v.text = code ? faultName(code) : QStringLiteral("—");
    }
    return v;
}

QString AcuStatusSource::faultText() const
{
    const QVariant raw = value(kCurrentFault);
    if (!raw.isValid())
        return {};
    const auto code = quint32(raw.toULongLong());
    if (code == 0)
        return tr("No fault");
    if (connection()) {
        if (const auto known = connection()->dictionary().errorCode(code))
            return known->text;
    }
    return tr("Fault %1 (not in the fault table)").arg(faultName(code));
}

bool AcuStatusSource::faultActive() const
{
    const QVariant raw = value(kCurrentFault);
    return state() == State::Fault || state() == State::FaultReactionActive
        || (raw.isValid() && raw.toULongLong() != 0);
}

QStringList AcuStatusSource::warnings() const
{
    QStringList names;
    const auto add = [&](ObjectAddress address, quint32 ignore) {
        const QVariant raw = value(address);
        const quint32 bits = quint32(raw.toULongLong()) & ~ignore;
        const ObjectDef *def = connection() ? connection()->dictionary().find(address) : nullptr;
        for (int bit = 0; bit < 16; ++bit) {
            if (!(bits & (1u << bit)))
                continue;
            QString name = tr("%1 bit %2").arg(address.index).arg(bit);
            if (def) {
                for (const BitField &field : def->bitFields) {
                    if (field.bit == bit)
                        name = field.displayName();
                }
            }
            names.append(name);
        }
    };
    // 270 bit 15 only says that 274 has something; 274's bits name it.
    add(kWarnings, value(kApplicationWarnings).isValid() ? kApplicationWarningBit : 0);
    add(kApplicationWarnings, 0);
    return names;
}

QString AcuStatusSource::linkLossText() const
{
    const QVariant raw = value(kBusErrorBehaviour);
    if (!raw.isValid())
        return tr("When the link stops for 10 s the inverter reacts as parameter 388 says "
                  "(not read yet).");
    const int reaction = raw.toInt();
    QString what;
    switch (reaction) {
    case 0:
        what = tr("keeps its operating point");
        break;
    case 1:
        what = tr("goes to fault F2714 at once");
        break;
    case 2:
        what = tr("switches off (disable voltage, then switch on disabled)");
        break;
    case 3:
        what = tr("makes a quick stop, then switch on disabled");
        break;
    case 4:
        what = tr("stops, then goes to fault F2714");
        break;
    case 5:
        what = tr("makes a quick stop, then goes to fault F2714");
        break;
    default:
        what = tr("reacts in a way this program does not know");
        break;
    }
    return tr("When the link stops for 10 s the inverter %1 (parameter 388 = %2).")
        .arg(what)
        .arg(reaction);
}

int AcuStatusSource::blockDefinitions() const
{
    const GroupReader *reader = GroupReader::of(connection());
    return reader ? reader->definitions() : 0;
}

void AcuStatusSource::poll()
{
    const QList<ObjectAddress> objects = cycleObjects();
    GroupReader *reader = GroupReader::of(connection());
    // Joined again when the objects changed or somebody made the reader forget us.
    if (reader && (objects != m_joined || reader->heldFor(this).isEmpty())) {
        m_joined = objects;
        reader->join(this, objects);
    }
    const QList<ObjectAddress> held = reader ? reader->heldFor(this) : QList<ObjectAddress>();
    Reply *reply = reader && !held.isEmpty() ? reader->read(this) : nullptr;
    m_usedBlock = reply != nullptr;
    if (!reply) {
        readEach(dueObjects());
        return;
    }
    reply->setParent(this);
    const quint64 gen = generation();
    connect(reply, &Reply::finished, this, [this, reply, gen, held] {
        reply->deleteLater();
        if (gen != generation())
            return;
        if (!reply->ok()) {
            // The reader writes the definition again for the next cycle.
            for (ObjectAddress address : held)
                storeError(address, reply->error());
            m_usedBlock = false;
            if (ConnectionHealth::isNoAnswer(reply->error())) {
                // The rest one by one would each wait out its time limit in vain.
                for (ObjectAddress address : dueObjects())
                    if (!held.contains(address))
                        storeError(address, reply->error());
                finishCycle();
                return;
            }
        } else {
            const QVariantList values = reply->value().toList();
            for (qsizetype i = 0; i < held.size(); ++i)
                store(held.at(i), values.value(i));
        }
        // What the block does not hold one by one, when due; ends the cycle.
        QList<ObjectAddress> rest = dueObjects();
        for (ObjectAddress address : held)
            rest.removeAll(address);
        readEach(rest);
    });
}

} // namespace db::bonfiglioli
