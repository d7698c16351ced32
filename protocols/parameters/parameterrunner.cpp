// ParameterBackup. ParameterRestore is in parameterrunner_restore.cpp.

#include "core/printable.h"
#include "parameterrunner_p.h"

#include <QTimer>

namespace db {

namespace {

// After this many timeouts in a row the device is taken as gone: a dead link would otherwise
// cost one request timeout per remaining object.
constexpr int kMaxConsecutiveTimeouts = 2;
constexpr int kMaxPipelineDepth = 8;
constexpr ObjectAddress kVendorId { 0x1018, 1 };
constexpr ObjectAddress kProductCode { 0x1018, 2 };
constexpr ObjectAddress kRevision { 0x1018, 3 };
constexpr ObjectAddress kSerialNumber { 0x1018, 4 };

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

// A failure line quotes the device's text: one line, at most this long.
constexpr qsizetype kMaxLineChars = 300;

} // namespace

QString BackupFailure::text() const
{
    QString line =
        QStringLiteral("%1 %2: %3").arg(addressFormat->format(address), name, error.toString());
    if (error.deviceCode() != 0)
        line += QStringLiteral(" (device code 0x%1)")
                    .arg(error.deviceCode(), 8, 16, QLatin1Char('0'))
                    .toUpper()
                    .replace(QLatin1String("0X"), QLatin1String("0x"));
    return oneLine(line, kMaxLineChars);
}

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
    m_failures.clear();
    m_skipped.clear();
    m_timeoutsInRow = 0;
    if (!m_connection) {
        // finished() must not fire inside start().
        QTimer::singleShot(
            0, this, [this] { finish(Error(Error::Kind::Disconnected, tr("no connection"))); });
        return;
    }
    const ObjectDictionary &dict = m_connection->dictionary();
    m_set.addressFormat = &m_connection->addressFormat();
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
    m_set.identity = dict.identity;
    for (const ObjectAddress a : { kSerialNumber, kRevision, kProductCode, kVendorId }) {
        const ObjectDef *def = dict.find(a);
        if (m_explicit.isEmpty() && def && def->readable() && !m_todo.contains(a)) {
            m_todo.prepend(a);
            m_identityOnly.insert(a);
            if (a == kRevision || a == kSerialNumber)
                continue; // the description's revision stays until the device has answered
            // Unknown until the device has answered: the description's number is not the
            // device's, and 0 would read as a product code.
            (a == kVendorId ? m_set.vendorIdKnown : m_set.productCodeKnown) = false;
            (a == kVendorId ? m_set.identity.vendorId : m_set.identity.productCode) = 0;
        }
    }
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
    if (m_failures.isEmpty() && m_set.isEmpty() && !m_skipped.isEmpty())
        return Error(Error::Kind::NotSupported,
                     tr("no object could be read (first: %1)").arg(m_skipped.first().text()));
    if (m_failures.isEmpty() && m_set.isEmpty())
        return Error(Error::Kind::NotSupported, tr("nothing to read: no readable object"));
    if (m_failures.isEmpty())
        return m_set;
    // The most common cause names the class of the failure; the first on a tie.
    QMap<Error::Kind, int> counts;
    Error::Kind kind = m_failures.first().error.kind();
    for (const BackupFailure &f : m_failures) {
        const int n = ++counts[f.error.kind()];
        if (n > counts.value(kind))
            kind = f.error.kind();
    }
    const QString first = m_failures.first().text();
    const QString message = m_set.isEmpty()
        ? tr("no object could be read (%1 tried; first: %2)").arg(m_todo.size()).arg(first)
        : tr("%1 of %2 objects could not be read (first: %3)")
              .arg(m_failures.size())
              .arg(m_todo.size())
              .arg(first);
    return Error(kind, message);
}

QStringList ParameterBackup::warnings() const
{
    QStringList out;
    for (const BackupFailure &f : m_failures)
        out.append(f.text());
    return out;
}

QList<ObjectAddress> ParameterBackup::failedAddresses() const
{
    QList<ObjectAddress> out;
    for (const BackupFailure &f : m_failures)
        out.append(f.address);
    return out;
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
    // A read carries no user input: a value outside the object's type is the device's bad
    // answer (the engines report it as OutOfRange, as for a value a user typed).
    const Error error = reply->error().kind() == Error::Kind::OutOfRange
        ? Error(Error::Kind::Malformed, reply->error().message(), reply->error().deviceCode())
        : reply->error();
    if (error.isError()) {
        if (restore::isFatal(error)) {
            fail(address, error);
            finish(error.prefixed(tr("reading %1").arg(m_set.addressFormat->format(address))));
            return;
        }
        m_timeoutsInRow = error.kind() == Error::Kind::Timeout ? m_timeoutsInRow + 1 : 0;
        if (m_scope == Scope::Readable && m_explicit.isEmpty()
            && error.kind() == Error::Kind::NotSupported)
            m_skipped.append({ address, def ? def->name : QString(), error, m_set.addressFormat });
        else
            fail(address, error);
        if (m_timeoutsInRow >= kMaxConsecutiveTimeouts) {
            finish(error.prefixed(tr("the device stopped answering; reading %1")
                                      .arg(m_set.addressFormat->format(address))));
            return;
        }
    } else if (m_identityOnly.contains(address)) {
        m_timeoutsInRow = 0;
        const bool vendor = address == kVendorId;
        const auto code = codec::normalize(DataType::Unsigned32, reply->value());
        if (code && (address == kRevision || address == kSerialNumber)) {
            (address == kRevision ? m_set.identity.revision : m_set.serialNumber) =
                ParameterSet::identityNumber(quint32(code->toULongLong()));
        } else if (code) {
            (vendor ? m_set.identity.vendorId : m_set.identity.productCode) =
                quint32(code->toULongLong());
            (vendor ? m_set.vendorIdKnown : m_set.productCodeKnown) = true;
        } else {
            fail(address,
                 Error(Error::Kind::Malformed,
                       tr("the device answered an identity that is not a UNSIGNED32: %1")
                           .arg(code.error().message())));
        }
    } else {
        m_timeoutsInRow = 0;
        const DataType type = def ? def->type : typeOfValue(reply->value());
        const auto raw = codec::normalize(type, reply->value());
        if (raw) {
            m_set.insert({ address, def ? def->name : QString(), type, raw.value(),
                           def ? def->unit : QString() });
        } else {
            // The device sent a value its own object cannot hold: a bad answer, not bad input.
            fail(address,
                 Error(Error::Kind::Malformed,
                       tr("the device answered a value that is not a %1: %2")
                           .arg(datatype::name(type), raw.error().message())));
        }
    }
    ++m_done;
    Q_EMIT progress(m_done, int(m_todo.size()));
    issueNext();
}

void ParameterBackup::fail(ObjectAddress address, const Error &error)
{
    const ObjectDef *def = m_connection ? m_connection->dictionary().find(address) : nullptr;
    m_failures.append({ address, def ? def->name : QString(), error, m_set.addressFormat });
}

void ParameterBackup::finish(const Error &error)
{
    m_state = State::Finished;
    m_error = error;
    if (error.kind() == Error::Kind::Cancelled) {
        m_set = ParameterSet();
    } else if (error.isError()) {
        // The objects never answered are failures too, so that a partial file lists them all.
        for (const QPointer<Reply> &reply : std::as_const(m_inFlight)) {
            if (reply)
                fail(reply->address(), error.prefixed(tr("not read")));
        }
        for (qsizetype i = m_next; i < m_todo.size(); ++i)
            fail(m_todo.at(i), error.prefixed(tr("not read")));
    }
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
