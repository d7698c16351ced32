#include "refgoconnection.h"

#include "canopen/storesignatures.h"

#include "refgologging.h"
#include "transport/tcpstream.h"

#include <QCoreApplication>
#include <QPointer>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::refgo)
};
} // namespace

namespace db::refgo {

namespace {

// OR/OW carry integers in decimal or hex text only (spec 3.2).
bool carriedByRefgo(DataType type)
{
    return datatype::isInteger(type) || type == DataType::Boolean;
}

Error notSupported(const ObjectDef &def)
{
    return Error(Error::Kind::NotSupported,
                 Tr::tr("%1 %2 is %3: RefGo OR/OW carry integers only (use the CANopen "
                        "SLCAN port for strings, domains and reals)")
                     .arg(def.address.toString(), def.name, datatype::name(def.type)));
}

// The drive prints what it has: hex output is an unsigned bit pattern (spec 3.2, errata 14),
// and an unsigned object might come back as a negative decimal. Fit either to the type's width
// before the codec's range check.
Result<QVariant> convertRead(const ObjectDef *def, qlonglong v)
{
    if (!def)
        return QVariant::fromValue<qlonglong>(v);
    const int bits = datatype::byteSize(def->type) * 8;
    QVariant candidate = QVariant::fromValue<qlonglong>(v);
    if (bits > 0 && bits < 64) {
        const quint64 mask = (quint64(1) << bits) - 1;
        const quint64 sign = quint64(1) << (bits - 1);
        if (datatype::isSignedInteger(def->type) && v > 0 && quint64(v) <= mask
            && (quint64(v) & sign))
            candidate = QVariant::fromValue<qlonglong>(qlonglong(quint64(v) | ~mask));
        else if (datatype::isUnsignedInteger(def->type) && v < 0 && v >= -qlonglong(sign))
            candidate = QVariant::fromValue<qulonglong>(quint64(v) & mask);
    } else if (bits == 64 && datatype::isUnsignedInteger(def->type)) {
        candidate = QVariant::fromValue<qulonglong>(quint64(v));
    }
    auto raw = codec::normalize(def->type, candidate);
    if (!raw)
        return raw.error().prefixed(Tr::tr("%1 %2").arg(def->address.toString(), def->name));
    return raw;
}

} // namespace

RefgoConnection::RefgoConnection(const ConnectionUri &uri, QObject *parent)
    : DeviceConnection(uri, parent)
    , m_stream(new TcpStream(uri.host(), quint16(uri.portOr(kDefaultPort)), this))
{
    init();
}

RefgoConnection::RefgoConnection(const ConnectionUri &uri, ByteStream *stream, QObject *parent)
    : DeviceConnection(uri, parent)
    , m_stream(stream)
{
    init();
}

RefgoConnection::~RefgoConnection()
{
    // The client goes first: its replies fail with Cancelled while the stream still exists.
    delete m_client;
    m_client = nullptr;
}

void RefgoConnection::init()
{
    m_client = new RefgoClient(m_stream, this);
    connect(m_client, &RefgoClient::logLine, this, &DeviceConnection::logLine);
    connect(m_stream, &ByteStream::opened, this, &RefgoConnection::onOpened);
    connect(m_stream, &ByteStream::closed, this, &RefgoConnection::onClosed);
    m_reconnectTimer.setSingleShot(true);
    m_reconnectTimer.setInterval(kDefaultReconnectIntervalMs);
    connect(&m_reconnectTimer, &QTimer::timeout, this, [this] {
        if (state() != State::Disconnected)
            return;
        Q_EMIT logLine(QStringLiteral("reconnecting to %1").arg(m_stream->peerName()));
        open();
    });
}

void RefgoConnection::setAutoReconnect(bool enabled, int intervalMs)
{
    m_autoReconnect = enabled;
    m_reconnectTimer.setInterval(intervalMs);
    if (!enabled)
        m_reconnectTimer.stop();
}

void RefgoConnection::doOpen()
{
    m_reconnectTimer.stop();
    Q_EMIT logLine(QStringLiteral("connecting to %1").arg(m_stream->peerName()));
    m_stream->setConnectTimeoutMs(connectTimeoutMs());
    if (m_stream->isOpen())
        onOpened();
    else
        m_stream->open();
}

void RefgoConnection::doClose()
{
    m_reconnectTimer.stop();
    if (m_stream->state() == ByteStream::State::Closed)
        setState(State::Disconnected);
    else
        m_stream->close();
}

void RefgoConnection::onOpened()
{
    qCInfo(lcRefgo).noquote() << "connected to" << m_stream->peerName();
    Q_EMIT logLine(QStringLiteral("connected to %1").arg(m_stream->peerName()));
    setState(State::Connected);
}

void RefgoConnection::onClosed(const Error &error)
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
                Tr::tr("connection to %1 closed").arg(m_stream->peerName()));
    Q_EMIT logLine(QStringLiteral("! ") + why.message());
    setState(State::Disconnected, why);
    if (m_autoReconnect)
        m_reconnectTimer.start();
}

Reply *RefgoConnection::storeNonVolatile()
{
    return write(canopen::store::kStoreAll,
                 QVariant::fromValue<qulonglong>(canopen::store::kSaveSignature));
}

Reply *RefgoConnection::restoreFactoryDefaults()
{
    return write(canopen::store::kRestoreDefaultsAll,
                 QVariant::fromValue<qulonglong>(canopen::store::kLoadSignature));
}

Reply *RefgoConnection::command(const QString &raw)
{
    if (!isConnected())
        return Reply::failed(
            {},
            Error(Error::Kind::Disconnected, Tr::tr("not connected to %1").arg(uri().toString())));
    m_client->setTimeoutMs(requestTimeoutMs());
    return m_client->execute(raw);
}

void RefgoConnection::doRead(Reply *reply, const ObjectDef *def)
{
    if (def && !carriedByRefgo(def->type)) {
        reply->fail(notSupported(*def));
        return;
    }
    m_client->setTimeoutMs(requestTimeoutMs());
    Reply::forward(m_client->objectRead(reply->address()), reply, this,
                   [def = def ? std::optional<ObjectDef>(*def) : std::nullopt](const QVariant &v) {
                       return convertRead(def ? &*def : nullptr, v.toLongLong());
                   });
}

void RefgoConnection::doWrite(Reply *reply, const QVariant &raw, const ObjectDef *def)
{
    if (def && !carriedByRefgo(def->type)) {
        reply->fail(notSupported(*def));
        return;
    }
    m_client->setTimeoutMs(requestTimeoutMs());
    Reply::forward(m_client->objectWrite(reply->address(), raw), reply, this);
}

} // namespace db::refgo
