#include "canmonitormodel.h"

#include "transport/canbus.h"
#include "widgets/common/widgetstyle.h"

#include <chrono>

namespace db::widgets {

namespace {

qint64 nowUs()
{
    using namespace std::chrono;
    return duration_cast<microseconds>(system_clock::now().time_since_epoch()).count();
}

bool isSdoAbort(const CanMonitorModel::Entry &e)
{
    using canopen::Service;
    const QByteArray &p = e.frame.payload();
    return (e.decoded.service == Service::SdoRequest || e.decoded.service == Service::SdoResponse)
        && e.decoded.hasAddress && !p.isEmpty() && quint8(p.at(0)) == 0x80;
}

} // namespace

CanMonitorModel::CanMonitorModel(QObject *parent)
    : QAbstractTableModel(parent)
    , m_startUs(nowUs())
    , m_mono(style::monospaceFont())
{
    m_flushTimer.setSingleShot(true);
    m_flushTimer.setInterval(kFlushIntervalMs);
    connect(&m_flushTimer, &QTimer::timeout, this, &CanMonitorModel::flush);
}

CanMonitorModel::~CanMonitorModel() = default;

void CanMonitorModel::setBus(CanBus *bus)
{
    for (const auto &c : std::as_const(m_busConnections))
        disconnect(c);
    m_busConnections.clear();
    m_bus = bus;
    m_decoder.reset();
    if (!bus)
        return;
    // traffic() keeps the order of the wire: a request sent from inside a protocol's receive
    // handler is listed after the frame that caused it.
    m_busConnections.append(connect(bus, &CanBus::traffic, this, &CanMonitorModel::record));
}

void CanMonitorModel::setCapacity(int frames)
{
    frames = qMax(1, frames);
    beginResetModel();
    std::vector<Entry> kept;
    const int keep = qMin(m_count, frames);
    kept.reserve(size_t(keep));
    for (int row = m_count - keep; row < m_count; ++row)
        kept.push_back(std::move(m_ring[physical(row)]));
    m_dropped += m_count - keep;
    m_ring = std::move(kept);
    m_head = 0;
    m_count = keep;
    m_capacity = frames;
    endResetModel();
}

void CanMonitorModel::setPaused(bool paused)
{
    if (m_paused == paused)
        return;
    m_paused = paused;
    if (!paused)
        flush();
}

void CanMonitorModel::record(const QCanBusFrame &frame, bool transmitted)
{
    Entry e;
    e.epochUs = nowUs();
    e.elapsedUs = e.epochUs - m_startUs;
    e.transmitted = transmitted;
    e.frame = frame;
    // Decoded in arrival order: the SDO transfer state of the decoder depends on it.
    e.decoded = m_decoder.decode(frame);
    m_pending.append(std::move(e));
    if (m_pending.size() > m_capacity) {
        m_pending.removeFirst();
        ++m_dropped;
    }
    if (!m_paused && !m_flushTimer.isActive())
        m_flushTimer.start();
}

void CanMonitorModel::flush()
{
    m_flushTimer.stop();
    if (m_paused || m_pending.isEmpty())
        return;
    const int n = int(m_pending.size());
    const int overflow = m_count + n - m_capacity;
    if (overflow > 0) {
        if (int(m_ring.size()) < m_capacity)
            m_ring.resize(size_t(m_capacity)); // head is 0 until the ring is full
        dropOldest(overflow);
    }
    beginInsertRows({}, m_count, m_count + n - 1);
    for (Entry &e : m_pending) {
        if (int(m_ring.size()) < m_capacity)
            m_ring.push_back(std::move(e));
        else
            m_ring[physical(m_count)] = std::move(e);
        ++m_count;
    }
    m_pending.clear();
    endInsertRows();
    Q_EMIT flushed();
}

void CanMonitorModel::dropOldest(int count)
{
    count = qMin(count, m_count);
    if (count <= 0)
        return;
    beginRemoveRows({}, 0, count - 1);
    m_head = (m_head + size_t(count)) % m_ring.size();
    m_count -= count;
    m_dropped += count;
    endRemoveRows();
}

void CanMonitorModel::clear()
{
    beginResetModel();
    m_ring.clear();
    m_head = 0;
    m_count = 0;
    m_pending.clear();
    m_dropped = 0;
    m_startUs = nowUs();
    endResetModel();
    Q_EMIT flushed();
}

int CanMonitorModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : m_count;
}

int CanMonitorModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant CanMonitorModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() >= m_count)
        return {};
    const Entry &e = entry(index.row());
    const bool remote = e.frame.frameType() == QCanBusFrame::RemoteRequestFrame;
    switch (role) {
    case Qt::DisplayRole:
        switch (index.column()) {
        case Time:
            return QString::number(double(e.elapsedUs) / 1e6, 'f', 6);
        case Direction:
            return e.transmitted ? QStringLiteral("TX") : QStringLiteral("RX");
        case Id:
            return QStringLiteral("%1")
                .arg(e.frame.frameId(), e.frame.hasExtendedFrameFormat() ? 8 : 3, 16,
                     QLatin1Char('0'))
                .toUpper();
        case Length:
            return int(e.frame.payload().size());
        case Data:
            return remote ? tr("remote request") : canopen::hexBytes(e.frame.payload());
        case Service:
            return canopen::FrameDecoder::serviceName(e.decoded.service, e.decoded.pdoNumber);
        case Node:
            if (e.decoded.service == canopen::Service::Nmt && e.decoded.node == 0)
                return QStringLiteral("all");
            return e.decoded.node ? QVariant(int(e.decoded.node)) : QVariant();
        case Decoded:
            return e.decoded.detail; // service and node have their own columns
        }
        break;
    case Qt::ToolTipRole:
        return index.column() == Decoded ? e.decoded.text : QVariant();
    case Qt::FontRole:
        if (index.column() != Service && index.column() != Decoded)
            return m_mono;
        break;
    case Qt::TextAlignmentRole:
        if (index.column() == Time || index.column() == Node)
            return int(Qt::AlignRight | Qt::AlignVCenter);
        if (index.column() == Length || index.column() == Direction)
            return int(Qt::AlignCenter);
        return int(Qt::AlignLeft | Qt::AlignVCenter);
    case Qt::ForegroundRole:
        if (e.decoded.service == canopen::Service::Emcy
            && !e.frame.payload().startsWith(QByteArray(2, '\0')))
            return style::errorColor();
        if (isSdoAbort(e))
            return style::errorColor();
        if (e.decoded.service == canopen::Service::BootUp)
            return style::warningColor();
        if (index.column() == Direction && e.transmitted)
            return style::inactiveColor();
        break;
    }
    return {};
}

QVariant CanMonitorModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case Time:
        return tr("Time (s)");
    case Direction:
        return tr("Dir");
    case Id:
        return tr("ID");
    case Length:
        return tr("Len");
    case Data:
        return tr("Data");
    case Service:
        return tr("Service");
    case Node:
        return tr("Node");
    case Decoded:
        return tr("CANopen");
    }
    return {};
}

} // namespace db::widgets
