#include "pdosource.h"

#include "canopen/cannetwork.h"
#include "canopen/pdoclient.h"
#include "transport/canbus.h"

#include <QCoreApplication>
#include <cmath>
#include <cstring>

namespace db::scope {

namespace {

struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::scope::PdoSource)
};

int sizeOf(DataType type)
{
    return datatype::isNumeric(type) ? datatype::byteSize(type) : 0;
}

// A gap between two frames longer than this many periods counts missed frames.
constexpr double kLateFactor = 1.5;

CanBus *busOf(const DeviceConnection *connection)
{
    const canopen::NetworkNode at = canopen::networkNodeOf(connection);
    return at ? at.network->bus() : nullptr;
}

} // namespace

PdoSource::PdoSource(CanBus *bus, QObject *parent)
    : TraceSource(parent)
    , m_bus(bus)
{
    if (bus)
        m_device = bus->name();
}

PdoSource::PdoSource(DeviceConnection *connection, QObject *parent)
    : PdoSource(busOf(connection), parent)
{
    if (connection)
        m_device = connection->uri().toString();
}

PdoSource::~PdoSource() = default;

Result<int> PdoSource::addChannel(const ChannelInfo &info, const Mapping &mapping)
{
    if (m_running)
        return Error(Error::Kind::InvalidArgument, Tr::tr("cannot add a channel while sampling"));
    const int size = sizeOf(mapping.type);
    if (size == 0)
        return Error(Error::Kind::InvalidArgument,
                     Tr::tr("%1: only numeric types can be sampled from a PDO").arg(info.id));
    if (mapping.byteOffset < 0 || mapping.byteOffset + size > 8)
        return Error(Error::Kind::InvalidArgument,
                     Tr::tr("%1: bytes %2..%3 do not fit into a CAN frame of 8 bytes")
                         .arg(info.id)
                         .arg(mapping.byteOffset)
                         .arg(mapping.byteOffset + size - 1));
    if (mapping.cobId > 0x1FFFFFFF || mapping.expectedPeriodMs < 0)
        return Error(Error::Kind::InvalidArgument, Tr::tr("%1: bad COB-ID or period").arg(info.id));
    Entry entry { info, mapping, -1 };
    if (entry.info.device.isEmpty())
        entry.info.device = m_device;
    if (entry.info.sourceRateMs == 0)
        entry.info.sourceRateMs = mapping.expectedPeriodMs;
    m_entries.append(entry);
    m_byCobId[mapping.cobId].append(int(m_entries.size()) - 1);
    Q_EMIT channelsChanged();
    return int(m_entries.size()) - 1;
}

Result<QList<int>> PdoSource::addPdo(const canopen::PdoConfig &config,
                                     const ObjectDictionary &dictionary, const QString &device,
                                     int expectedPeriodMs)
{
    if (!config.isEnabled())
        return Error(Error::Kind::InvalidArgument,
                     Tr::tr("%1 is not enabled (COB-ID bit 31 set)").arg(config.name()));
    QList<int> added;
    int bit = 0;
    for (const canopen::PdoMappingEntry &entry : config.entries) {
        const int at = bit;
        bit += entry.bits;
        if (entry.isDummy() || at % 8 != 0 || entry.bits % 8 != 0)
            continue;
        const ObjectDef *def = dictionary.find(entry.address);
        Mapping mapping;
        mapping.cobId = config.canId();
        mapping.byteOffset = at / 8;
        mapping.expectedPeriodMs = expectedPeriodMs;
        if (def && datatype::byteSize(def->type) * 8 == entry.bits)
            mapping.type = def->type;
        else if (entry.bits == 8)
            mapping.type = DataType::Unsigned8;
        else if (entry.bits == 16)
            mapping.type = DataType::Unsigned16;
        else if (entry.bits == 32)
            mapping.type = DataType::Unsigned32;
        else
            continue;
        auto index = addChannel(ChannelInfo::forObject(entry.address, dictionary,
                                                       device.isEmpty() ? m_device : device,
                                                       expectedPeriodMs),
                                mapping);
        if (!index)
            return index.error();
        added.append(*index);
    }
    return added;
}

void PdoSource::removeChannel(int channel)
{
    if (m_running || channel < 0 || channel >= m_entries.size())
        return;
    m_entries.removeAt(channel);
    m_byCobId.clear();
    for (int i = 0; i < m_entries.size(); ++i)
        m_byCobId[m_entries[i].mapping.cobId].append(i);
    Q_EMIT channelsChanged();
}

PdoSource::Mapping PdoSource::mapping(int channel) const
{
    return m_entries.value(channel).mapping;
}

QList<ChannelInfo> PdoSource::channels() const
{
    QList<ChannelInfo> list;
    for (const Entry &e : m_entries)
        list.append(e.info);
    return list;
}

void PdoSource::start(const QElapsedTimer &timeBase)
{
    if (m_running)
        return;
    m_timeBase = timeBase;
    m_frames = 0;
    for (Entry &e : m_entries)
        e.lastTime = -1;
    m_running = true;
    Q_EMIT runningChanged(true);
    if (!m_bus || !m_bus->isOpen()) {
        stop();
        Q_EMIT errorOccurred(Error(Error::Kind::Disconnected,
                                   Tr::tr("cannot sample PDOs: the CAN bus is not open")));
        return;
    }
    connect(m_bus.data(), &CanBus::frameReceived, this, &PdoSource::onFrame);
    connect(m_bus.data(), &CanBus::closed, this, &PdoSource::onBusClosed);
}

void PdoSource::stop()
{
    if (!m_running)
        return;
    m_running = false;
    if (m_bus)
        m_bus->disconnect(this);
    Q_EMIT runningChanged(false);
}

std::optional<double> PdoSource::decodeValue(const QByteArray &payload, const Mapping &mapping)
{
    const int size = sizeOf(mapping.type);
    if (size == 0 || mapping.byteOffset < 0 || payload.size() < mapping.byteOffset + size)
        return std::nullopt;
    quint64 bits = 0;
    for (int i = size - 1; i >= 0; --i)
        bits = (bits << 8) | quint8(payload[mapping.byteOffset + i]);
    switch (mapping.type) {
    case DataType::Real32: {
        float f;
        const auto u = quint32(bits);
        std::memcpy(&f, &u, sizeof f);
        return double(f);
    }
    case DataType::Real64: {
        double d;
        std::memcpy(&d, &bits, sizeof d);
        return d;
    }
    case DataType::Boolean:
        return bits ? 1.0 : 0.0;
    default:
        break;
    }
    if (datatype::isSignedInteger(mapping.type) && size < 8) {
        const quint64 sign = quint64(1) << (size * 8 - 1);
        if (bits & sign)
            bits |= ~((sign << 1) - 1); // sign-extend
    }
    return datatype::isSignedInteger(mapping.type) ? double(qint64(bits)) : double(bits);
}

void PdoSource::onFrame(const QCanBusFrame &frame)
{
    if (!m_running || frame.frameType() != QCanBusFrame::DataFrame)
        return;
    const auto it = m_byCobId.constFind(frame.frameId());
    if (it == m_byCobId.cend())
        return;
    ++m_frames;
    const double t = double(m_timeBase.nsecsElapsed()) * 1e-9;
    const QByteArray payload = frame.payload();
    for (int index : *it) {
        Entry &e = m_entries[index];
        if (e.mapping.expectedPeriodMs > 0 && e.lastTime >= 0) {
            const double period = e.mapping.expectedPeriodMs * 1e-3;
            const double gap = t - e.lastTime;
            if (gap > kLateFactor * period) {
                const auto missed = qint64(std::llround(gap / period)) - 1;
                if (missed > 0)
                    Q_EMIT samplesLost(index, missed);
            }
        }
        e.lastTime = t;
        if (const auto value = decodeValue(payload, e.mapping))
            Q_EMIT samplesReady(index, TraceSamples { { t, *value } });
        else
            Q_EMIT samplesLost(index, 1); // PDO shorter than the channel's bytes
        if (!m_running)
            return; // a receiver stopped us
    }
}

void PdoSource::onBusClosed(const Error &error)
{
    if (!m_running)
        return;
    stop();
    Q_EMIT errorOccurred(error.isError()
                             ? error.prefixed(Tr::tr("PDO sampling stopped"))
                             : Error(Error::Kind::Disconnected,
                                     Tr::tr("PDO sampling stopped: the CAN bus was closed")));
}

Result<canopen::PdoConfig> tpdoConfigFor(canopen::NodeId node, int tpdoNumber,
                                         const QList<ObjectAddress> &objects,
                                         const ObjectDictionary &dictionary, int eventTimerMs,
                                         quint32 cobId)
{
    using canopen::PdoConfig;
    if (tpdoNumber < 0 || tpdoNumber >= PdoConfig::kMaxPerDirection)
        return Error(Error::Kind::InvalidArgument, Tr::tr("TPDO number out of range"));
    if (cobId == 0 && tpdoNumber > 3)
        return Error(Error::Kind::InvalidArgument,
                     Tr::tr("TPDO%1 has no predefined COB-ID; give one").arg(tpdoNumber + 1));
    if (node < canopen::kMinNodeId || node > canopen::kMaxNodeId)
        return Error(Error::Kind::InvalidArgument, Tr::tr("node id must be 1..127"));
    if (eventTimerMs < 0 || eventTimerMs > 0xFFFF)
        return Error(Error::Kind::InvalidArgument, Tr::tr("event timer must be 0..65535 ms"));
    if (objects.isEmpty())
        return Error(Error::Kind::InvalidArgument, Tr::tr("no objects to map"));
    PdoConfig config;
    config.direction = canopen::PdoDirection::Transmit;
    config.number = tpdoNumber;
    config.cobId =
        (cobId ? cobId : 0x180u + 0x100u * quint32(tpdoNumber) + node) | PdoConfig::kNoRtrBit;
    config.transmissionType = 0xFF;
    config.eventTimer = quint16(eventTimerMs);
    int bits = 0;
    for (ObjectAddress address : objects) {
        const ObjectDef *def = dictionary.find(address);
        const int size = def ? sizeOf(def->type) : 0;
        if (size == 0)
            return Error(
                Error::Kind::InvalidArgument,
                Tr::tr("%1 is not a numeric object of the description").arg(address.toString()));
        bits += size * 8;
        config.entries.append({ address, quint8(size * 8) });
    }
    if (bits > 64)
        return Error(Error::Kind::InvalidArgument,
                     Tr::tr("the objects need %1 bits; a PDO carries at most 64").arg(bits));
    return config;
}

Reply *configureTpdo(canopen::PdoClient *client, canopen::NodeId node, int tpdoNumber,
                     const QList<ObjectAddress> &objects, const ObjectDictionary &dictionary,
                     int eventTimerMs, quint32 cobId)
{
    const ObjectAddress comm(quint16(0x1800 + std::max(0, tpdoNumber)), 1);
    auto config = tpdoConfigFor(node, tpdoNumber, objects, dictionary, eventTimerMs, cobId);
    if (!config)
        return Reply::failed(comm, config.error());
    if (!client)
        return Reply::failed(comm, Error(Error::Kind::InvalidArgument, Tr::tr("no PDO client")));
    auto *outer = new Reply(comm);
    const canopen::PdoConfig written = *config;
    Reply::forward(
        client->configure(node, written), outer, client,
        [written](const QVariant &) -> Result<QVariant> { return QVariant::fromValue(written); });
    return outer;
}

} // namespace db::scope
