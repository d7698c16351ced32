#include "acustatussource.h"

#include "core/deviceconnection.h"
#include "vabus/vabusblock.h"
#include "vabus/vabusconnection.h"

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

QList<vabus::BlockItem> blockItems(const ObjectDictionary &dictionary,
                                   const QList<ObjectAddress> &objects)
{
    QList<vabus::BlockItem> items;
    for (ObjectAddress address : objects) {
        if (const ObjectDef *def = dictionary.find(address))
            items.append({ address, def->type });
    }
    return vabus::packBlock(items);
}

QList<ObjectAddress> addressesOf(const QList<vabus::BlockItem> &items)
{
    QList<ObjectAddress> addresses;
    for (const auto &item : items)
        addresses.append(item.address);
    return addresses;
}

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
    // Made on a link that is up already: connectionMade() has no state change to follow.
    m_blockUsable = qobject_cast<vabus::VabusConnection *>(connection) != nullptr;
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

void AcuStatusSource::connectionMade()
{
    // A new TCP connection may be to a reset inverter: the block definition is volatile.
    m_blockDefined = false;
    m_blockFailures = 0;
    m_blockUsable = qobject_cast<vabus::VabusConnection *>(connection()) != nullptr;
}

void AcuStatusSource::poll()
{
    if (!m_blockUsable) {
        readEach(dueObjects());
        return;
    }
    // One telegram costs the same whatever it holds: the block always holds every object some
    // consumer wants, so its definition stays as long as the consumers do.
    const QList<ObjectAddress> objects = cycleObjects();
    // A holder's objects changed what the block must hold: define it again.
    if (!m_blockDefined
        || addressesOf(blockItems(connection()->dictionary(), objects)) != m_blockAddresses)
        defineBlock(objects);
    else
        readBlock(objects);
}

void AcuStatusSource::defineBlock(const QList<ObjectAddress> &objects)
{
    auto *vabus = qobject_cast<vabus::VabusConnection *>(connection());
    const auto items = blockItems(vabus->dictionary(), objects);
    const auto text = vabus::blockDefinition(items);
    if (!text) {
        m_blockUsable = false;
        readEach(dueObjects());
        return;
    }
    ++m_definitions;
    m_blockDefined = false;
    // Data set 0 on purpose: 17 is volatile (lost at reset), never an EEPROM write.
    Reply *reply = vabus->client()->writeData(vabus::kBlockDefinitionParameter, 0, text.value(),
                                              ObjectAddress(vabus::kBlockDefinitionParameter, 0));
    reply->setParent(this);
    const quint64 gen = generation();
    connect(reply, &Reply::finished, this, [this, reply, gen, objects, items] {
        reply->deleteLater();
        if (gen != generation())
            return;
        if (reply->ok()) {
            m_blockDefined = true;
            m_blockFailures = 0;
            m_blockAddresses = addressesOf(items);
            readBlock(objects);
            return;
        }
        if (++m_blockFailures >= kMaxBlockFailures)
            m_blockUsable = false;
        readEach(dueObjects()); // this cycle one by one; the next tries the block again
    });
}

void AcuStatusSource::readBlock(const QList<ObjectAddress> &objects)
{
    auto *vabus = qobject_cast<vabus::VabusConnection *>(connection());
    const auto items = blockItems(vabus->dictionary(), objects);
    Reply *reply = vabus->client()->read(vabus::kBlockReadParameter, 0, DataType::VisibleString,
                                         ObjectAddress(vabus::kBlockReadParameter, 0));
    reply->setParent(this);
    const quint64 gen = generation();
    connect(reply, &Reply::finished, this, [this, reply, gen, objects, items] {
        reply->deleteLater();
        if (gen != generation())
            return;
        Result<QList<QVariant>> values = reply->ok()
            ? vabus::decodeBlock(reply->value().toString().toLatin1(), items)
            : Result<QList<QVariant>>(reply->error());
        if (!values) {
            for (const auto &item : items)
                storeError(item.address, values.error());
            // A device error (e.g. an inverter reset lost the definition) or an answer that
            // does not fit: define the block again next cycle.
            m_blockDefined = false;
        } else {
            for (qsizetype i = 0; i < items.size(); ++i)
                store(items.at(i).address, values.value().at(i));
        }
        // What a block cannot hold (parameters from 1000 on) one by one, when due; ends the
        // cycle.
        QList<ObjectAddress> rest = dueObjects();
        for (const auto &item : items)
            rest.removeAll(item.address);
        readEach(rest);
    });
}

} // namespace db::bonfiglioli
