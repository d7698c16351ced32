// ParameterBackup and the 1010h/1011h helpers. ParameterRestore is in parameterrunner_restore.cpp.

#include "parameterrunner_p.h"

#include <QTimer>

namespace db {

namespace parameters {

Reply *storeParameters(DeviceConnection *connection)
{
    return connection->write(kStoreAll, QVariant::fromValue<qulonglong>(kStoreSignature));
}

Reply *restoreFactoryDefaults(DeviceConnection *connection)
{
    return connection->write(kRestoreDefaultsAll, QVariant::fromValue<qulonglong>(kLoadSignature));
}

} // namespace parameters

namespace {

// After this many timeouts in a row the device is taken as gone: a dead link would otherwise
// cost one request timeout per remaining object.
constexpr int kMaxConsecutiveTimeouts = 2;
constexpr int kMaxPipelineDepth = 8;
constexpr ObjectAddress kVendorId { 0x1018, 1 };
constexpr ObjectAddress kProductCode { 0x1018, 2 };

// The type of a value read from an object the description does not know.
DataType typeOfValue(const QVariant &raw)
{
    switch (raw.typeId()) {
    case QMetaType::Bool:
        return DataType::Boolean;
    case QMetaType::ULongLong:
    case QMetaType::UInt:
        return DataType::Unsigned64;
    case QMetaType::Double:
    case QMetaType::Float:
        return DataType::Real64;
    case QMetaType::QString:
        return DataType::VisibleString;
    case QMetaType::QByteArray:
        return DataType::OctetString;
    default:
        return DataType::Integer64;
    }
}

} // namespace

ParameterBackup::ParameterBackup(DeviceConnection *connection, QObject *parent)
    : QObject(parent)
    , m_connection(connection)
{ }

ParameterBackup::~ParameterBackup()
{
    for (const QPointer<Reply> &reply : std::as_const(m_inFlight))
        delete reply.data();
}

void ParameterBackup::setPipelineDepth(int depth)
{
    m_depth = qBound(1, depth, kMaxPipelineDepth);
}

void ParameterBackup::start()
{
    if (m_state == State::Reading)
        return;
    m_state = State::Reading;
    m_todo.clear();
    m_next = 0;
    m_done = 0;
    m_set = ParameterSet();
    m_error = Error();
    m_warnings.clear();
    m_failed.clear();
    m_timeoutsInRow = 0;
    if (!m_connection) {
        // finished() must not fire inside start().
        QTimer::singleShot(
            0, this, [this] { finish(Error(Error::Kind::Disconnected, tr("no connection"))); });
        return;
    }
    const ObjectDictionary &dict = m_connection->dictionary();
    if (!m_explicit.isEmpty()) {
        m_todo = m_explicit;
    } else {
        for (const ObjectDef &def : dict.objects()) {
            if (def.readable() && (m_scope == Scope::Readable || def.storable))
                m_todo.append(def.address);
        }
    }
    // The device's own vendor id and product code (1018h) name the set better than the
    // description's; read them first when the description has them and the scope does not.
    m_identityOnly.clear();
    for (const ObjectAddress a : { kVendorId, kProductCode }) {
        const ObjectDef *def = dict.find(a);
        if (m_explicit.isEmpty() && def && def->readable() && !m_todo.contains(a)) {
            m_todo.prepend(a);
            m_identityOnly.insert(a);
        }
    }
    m_set.identity = dict.identity;
    m_set.source = m_connection->uri().toString();
    m_set.created = QDateTime::currentDateTimeUtc();
    QTimer::singleShot(0, this, [this] {
        if (m_state != State::Reading)
            return;
        Q_EMIT progress(0, int(m_todo.size()));
        issueNext();
    });
}

void ParameterBackup::cancel()
{
    if (m_state == State::Reading)
        finish(Error(Error::Kind::Cancelled,
                     tr("backup cancelled after %1 of %2 objects").arg(m_done).arg(m_todo.size())));
}

Result<ParameterSet> ParameterBackup::result() const
{
    if (m_state != State::Finished)
        return Error(Error::Kind::Busy, tr("the backup has not finished"));
    if (m_error.isError())
        return m_error;
    return m_set;
}

void ParameterBackup::issueNext()
{
    while (m_state == State::Reading && m_inFlight.size() < m_depth && m_next < m_todo.size()) {
        if (!m_connection) {
            finish(Error(Error::Kind::Disconnected, tr("the connection was closed")));
            return;
        }
        Reply *reply = m_connection->read(m_todo.at(m_next++));
        m_inFlight.append(reply);
        connect(reply, &Reply::finished, this, [this, reply] { onReply(reply); });
    }
    if (m_state == State::Reading && m_inFlight.isEmpty() && m_next >= m_todo.size())
        finish({});
}

void ParameterBackup::onReply(Reply *reply)
{
    m_inFlight.removeAll(reply);
    reply->deleteLater();
    if (m_state != State::Reading)
        return;
    const ObjectAddress address = reply->address();
    const ObjectDef *def = m_connection ? m_connection->dictionary().find(address) : nullptr;
    const Error error = reply->error();
    if (error.isError()) {
        if (restore::isFatal(error)) {
            finish(error.prefixed(tr("reading %1").arg(address.toString())));
            return;
        }
        m_timeoutsInRow = error.kind() == Error::Kind::Timeout ? m_timeoutsInRow + 1 : 0;
        if (m_timeoutsInRow >= kMaxConsecutiveTimeouts) {
            finish(error.prefixed(
                tr("the device stopped answering; reading %1").arg(address.toString())));
            return;
        }
        m_failed.append(address);
        m_warnings.append(
            QStringLiteral("%1 %2: %3")
                .arg(address.toString(), def ? def->name : QString(), error.toString()));
    } else if (m_identityOnly.contains(address)) {
        m_timeoutsInRow = 0;
        (address == kVendorId ? m_set.identity.vendorId : m_set.identity.productCode) =
            quint32(reply->value().toULongLong());
    } else {
        m_timeoutsInRow = 0;
        const DataType type = def ? def->type : typeOfValue(reply->value());
        const auto raw = codec::normalize(type, reply->value());
        if (raw) {
            m_set.insert({ address, def ? def->name : QString(), type, raw.value(),
                           def ? def->unit : QString() });
        } else {
            m_failed.append(address);
            m_warnings.append(
                QStringLiteral("%1 %2: %3")
                    .arg(address.toString(), def ? def->name : QString(), raw.error().toString()));
        }
    }
    ++m_done;
    Q_EMIT progress(m_done, int(m_todo.size()));
    issueNext();
}

void ParameterBackup::finish(const Error &error)
{
    m_state = State::Finished;
    m_error = error;
    if (error.isError())
        m_set = ParameterSet(); // never hand out a partial set
    for (const QPointer<Reply> &reply : std::as_const(m_inFlight)) {
        if (reply) {
            reply->disconnect(this);
            reply->deleteLater();
        }
    }
    m_inFlight.clear();
    Q_EMIT finished();
}

} // namespace db
