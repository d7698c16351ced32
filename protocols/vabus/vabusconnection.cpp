#include "vabusconnection.h"

#include "transport/tcpstream.h"
#include "vabuslogging.h"

namespace db::vabus {

namespace {

constexpr int kMaxNodeId = 63;

} // namespace

Result<quint8> VabusConnection::sysFromUri(const ConnectionUri &uri)
{
    if (!uri.hasQuery(QStringLiteral("sys")))
        return quint8(0);
    const auto node = uri.queryInt(QStringLiteral("sys"), 0, kMaxNodeId);
    if (!node)
        return node.error();
    return quint8(node.value() == 0 ? 0 : kSlaveSysBase + node.value());
}

Result<void> VabusConnection::checkUri(const ConnectionUri &uri)
{
    if (uri.host().isEmpty())
        return Error(Error::Kind::InvalidArgument,
                     QStringLiteral("%1 names no host").arg(uri.toString()));
    if (auto sys = sysFromUri(uri); !sys)
        return sys.error();
    return {};
}

VabusConnection::VabusConnection(const ConnectionUri &uri, QObject *parent)
    : DeviceConnection(uri, parent)
    , m_stream(new TcpStream(uri.host(), quint16(uri.portOr(kDefaultPort)), this))
{
    init();
}

VabusConnection::VabusConnection(const ConnectionUri &uri, ByteStream *stream, QObject *parent)
    : DeviceConnection(uri, parent)
    , m_stream(stream)
{
    init();
}

VabusConnection::~VabusConnection()
{
    // The client goes first: its replies fail with Cancelled while the stream still exists.
    delete m_client;
    m_client = nullptr;
}

void VabusConnection::init()
{
    m_client = new VabusClient(m_stream, this);
    const auto sys = sysFromUri(uri());
    m_client->setSys(sys ? sys.value() : 0);
    m_ram = uri().hasQuery(QStringLiteral("ram"));
    connect(m_client, &VabusClient::logLine, this, &DeviceConnection::logLine);
    connect(m_stream, &ByteStream::opened, this, &VabusConnection::onOpened);
    connect(m_stream, &ByteStream::closed, this, &VabusConnection::onClosed);
    m_retryTimer.setSingleShot(true);
    m_retryTimer.setInterval(kRetryIntervalMs);
    connect(&m_retryTimer, &QTimer::timeout, this, [this] {
        if (state() != State::Disconnected)
            return;
        Q_EMIT logLine(QStringLiteral("connecting to %1 again (the inverter may be starting up)")
                           .arg(m_stream->peerName()));
        open();
    });
}

void VabusConnection::setRetryAfterLoss(int windowMs, int intervalMs)
{
    m_retryWindowMs = qMax(0, windowMs);
    m_retryTimer.setInterval(qMax(1, intervalMs));
    if (m_retryWindowMs == 0)
        stopReconnecting();
}

void VabusConnection::stopReconnecting()
{
    m_retryTimer.stop();
    m_retryUntil.reset();
}

void VabusConnection::doOpen()
{
    Q_EMIT logLine(QStringLiteral("connecting to %1").arg(m_stream->peerName()));
    m_stream->setConnectTimeoutMs(connectTimeoutMs());
    m_retryTimer.stop();
    if (m_stream->isOpen())
        onOpened();
    else
        m_stream->open();
}

void VabusConnection::doClose()
{
    stopReconnecting(); // closed by us: no retry
    if (m_stream->state() == ByteStream::State::Closed)
        setState(State::Disconnected);
    else
        m_stream->close();
}

void VabusConnection::onOpened()
{
    qCInfo(lcVabus).noquote() << "connected to" << m_stream->peerName();
    Q_EMIT logLine(QStringLiteral("connected to %1; the inverter reacts as parameter 388 says "
                                  "10 s after the last exchange once the link stops")
                       .arg(m_stream->peerName()));
    m_retryUntil.reset();
    setState(State::Connected);
}

void VabusConnection::onClosed(const Error &error)
{
    const State previous = state();
    if (previous == State::Disconnected)
        return;
    if (previous == State::Closing) {
        Q_EMIT logLine(QStringLiteral("disconnected from %1").arg(m_stream->peerName()));
        setState(State::Disconnected);
        return;
    }
    const Error why = error.isError()
        ? error
        : Error(Error::Kind::Disconnected,
                QStringLiteral("connection to %1 closed").arg(m_stream->peerName()));
    Q_EMIT logLine(QStringLiteral("! ") + why.message());
    if (previous == State::Connected && m_retryWindowMs > 0)
        m_retryUntil = QDeadlineTimer(m_retryWindowMs);
    setState(State::Disconnected, why);
    if (m_retryUntil && !m_retryUntil->hasExpired() && state() == State::Disconnected)
        m_retryTimer.start();
    else
        m_retryUntil.reset();
}

std::optional<ObjectAddress> VabusConnection::ramAddress(ObjectAddress address) const
{
    if (address.sub > kMaxReadDataSet)
        return std::nullopt;
    return ObjectAddress(address.index, quint8(address.sub + kRamDataSetOffset));
}

const ObjectDef *VabusConnection::describe(ObjectAddress address) const
{
    if (const ObjectDef *def = dictionary().find(address))
        return def;
    if (address.sub > kMaxReadDataSet && address.sub <= kMaxWriteDataSet) {
        const ObjectAddress eeprom(address.index, quint8(address.sub - kRamDataSetOffset));
        if (const ObjectDef *def = dictionary().find(eeprom))
            return def;
    }
    return dictionary().find(ObjectAddress(address.index, 0));
}

void VabusConnection::doRead(Reply *reply, const ObjectDef *def)
{
    const ObjectAddress address = reply->address();
    if (!def)
        def = describe(address);
    std::optional<DataType> type;
    if (def)
        type = def->type;
    m_client->setTimeoutMs(requestTimeoutMs());
    Reply::forward(m_client->read(address.index, address.sub, type), reply, this);
}

void VabusConnection::doWrite(Reply *reply, const QVariant &raw, const ObjectDef *def)
{
    const ObjectAddress address = reply->address();
    QVariant value = raw;
    if (!def) {
        // A RAM data set, or a data set the description lists only as data set 0: checked
        // against that description here, as DeviceConnection::write() does for listed ones.
        def = describe(address);
        if (def) {
            if (!def->writable()) {
                reply->fail(Error(Error::Kind::AccessDenied,
                                  QStringLiteral("parameter %1 %2 is read-only")
                                      .arg(address.index)
                                      .arg(def->name)));
                return;
            }
            auto checked = def->validate(raw, addressFormat());
            if (!checked) {
                reply->fail(checked.error());
                return;
            }
            value = checked.value();
        }
    }
    DataType type = DataType::VisibleString;
    if (def) {
        type = def->type;
    } else if (raw.typeId() != QMetaType::QString) {
        reply->fail(Error(Error::Kind::NotSupported,
                          QStringLiteral("parameter %1 is not in the description, so its size "
                                         "on the wire is unknown; give its type (e.g. --type "
                                         "i16, u16 or i32)")
                              .arg(address.index)));
        return;
    }
    quint8 dataSet = address.sub;
    if (m_ram && dataSet <= kMaxReadDataSet)
        dataSet += kRamDataSetOffset;
    m_client->setTimeoutMs(requestTimeoutMs());
    Reply::forward(m_client->write(address.index, dataSet, type, value), reply, this);
}

} // namespace db::vabus
