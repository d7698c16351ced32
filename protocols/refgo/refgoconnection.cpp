#include "refgoconnection.h"

#include "canopen/storesignatures.h"

#include <QCoreApplication>

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
    : StreamConnection(uri, kDefaultPort, parent)
{
    init();
}

RefgoConnection::RefgoConnection(const ConnectionUri &uri, ByteStream *stream, QObject *parent)
    : StreamConnection(uri, stream, parent)
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
    m_client = new RefgoClient(stream(), this);
    connect(m_client, &RefgoClient::logLine, this, &DeviceConnection::logLine);
    followStream();
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
    // The reply is the request's context: deleted before it is sent, the read is withdrawn.
    m_client->objectRead(
        reply->address(),
        Completion::finishing(
            reply, [def = def ? std::optional<ObjectDef>(*def) : std::nullopt](const QVariant &v) {
                return convertRead(def ? &*def : nullptr, v.toLongLong());
            }));
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
