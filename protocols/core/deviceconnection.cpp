#include "deviceconnection.h"

#include "logging.h"
#include "statussource.h"

#include <QCoreApplication>
#include <QEventLoop>
#include <QTimer>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::core)
};
} // namespace

namespace db {

DeviceConnection::DeviceConnection(const ConnectionUri &uri, QObject *parent)
    : QObject(parent)
    , m_uri(uri)
{
    qRegisterMetaType<db::Error>();
    qRegisterMetaType<db::DeviceConnection::State>();
}

DeviceConnection::~DeviceConnection()
{
    delete m_statusSource; // before its replies fail: it must not see a half-destroyed connection
    failPending(Error(Error::Kind::Cancelled, Tr::tr("connection deleted")));
}

void DeviceConnection::setStatusSource(StatusSource *source)
{
    if (m_statusSource == source)
        return;
    delete m_statusSource;
    m_statusSource = source;
    if (source)
        source->setParent(this);
}

void DeviceConnection::open()
{
    if (m_state != State::Disconnected)
        return;
    m_lastError = {};
    setState(State::Connecting);
    doOpen();
}

Result<void> DeviceConnection::openAndWait(int timeoutMs)
{
    QEventLoop loop;
    connect(this, &DeviceConnection::stateChanged, &loop, [&loop](State s) {
        if (s == State::Connected || s == State::Disconnected)
            loop.quit();
    });
    bool timedOut = false;
    // The transport's own timeout names the peer; this one is the last resort.
    setConnectTimeoutMs(timeoutMs);
    QTimer::singleShot(timeoutMs + kOpenGraceMs, &loop, [&] {
        timedOut = true;
        loop.quit();
    });
    open();
    if (m_state == State::Connecting)
        loop.exec();
    if (isConnected())
        return {};
    if (timedOut)
        return Error(
            Error::Kind::Timeout,
            Tr::tr("no connection to %1 within %2 ms").arg(m_uri.toString()).arg(timeoutMs));
    return m_lastError.isError()
        ? m_lastError
        : Error(Error::Kind::Disconnected, Tr::tr("cannot connect to %1").arg(m_uri.toString()));
}

void DeviceConnection::close()
{
    if (m_state == State::Disconnected) {
        stopReconnecting();
        return;
    }
    if (m_state == State::Closing)
        return;
    failPending(Error(Error::Kind::Cancelled, Tr::tr("connection closed by the user")));
    setState(State::Closing);
    doClose();
}

Reply *DeviceConnection::read(ObjectAddress address)
{
    if (m_state != State::Connected)
        return Reply::failed(
            address,
            Error(Error::Kind::Disconnected, Tr::tr("not connected to %1").arg(m_uri.toString())));
    const ObjectDef *def = m_dictionary.find(address);
    if (def && !def->readable())
        return Reply::failed(
            address,
            Error(Error::Kind::AccessDenied,
                  Tr::tr("%1 %2 is write-only").arg(addressFormat().format(address), def->name)));
    Reply *reply = track(new Reply(address));
    doRead(reply, def);
    return reply;
}

Reply *DeviceConnection::write(ObjectAddress address, const QVariant &raw)
{
    if (m_state != State::Connected)
        return Reply::failed(
            address,
            Error(Error::Kind::Disconnected, Tr::tr("not connected to %1").arg(m_uri.toString())));
    const ObjectDef *def = m_dictionary.find(address);
    QVariant value = raw;
    if (def) {
        if (!def->writable())
            return Reply::failed(
                address,
                Error(
                    Error::Kind::AccessDenied,
                    Tr::tr("%1 %2 is read-only").arg(addressFormat().format(address), def->name)));
        auto checked = def->validate(raw, addressFormat());
        if (!checked)
            return Reply::failed(address, checked.error());
        value = checked.value();
    }
    Reply *reply = track(new Reply(address));
    connect(reply, &Reply::finished, this, [this, reply] {
        if (reply->ok())
            Q_EMIT objectWritten(reply->address());
    });
    doWrite(reply, value, def);
    return reply;
}

void DeviceConnection::setState(State state, const Error &error)
{
    if (error.isError()) {
        m_lastError = error;
        qCWarning(lcCore).noquote() << m_uri.toString() << error.toString();
    }
    if (state == State::Disconnected)
        failPending(error.isError()
                        ? error
                        : Error(Error::Kind::Disconnected,
                                Tr::tr("connection to %1 closed").arg(m_uri.toString())));
    if (error.isError())
        Q_EMIT errorOccurred(error);
    if (state != m_state) {
        m_state = state;
        Q_EMIT stateChanged(state);
    }
}

Reply *DeviceConnection::track(Reply *reply)
{
    m_pending.removeIf([](const QPointer<Reply> &p) { return !p || p->isFinished(); });
    m_pending.append(reply);
    connect(reply, &Reply::finished, this,
            [this, reply] { Q_EMIT requestFinished(reply->address(), reply->error()); });
    return reply;
}

void DeviceConnection::failPending(const Error &error)
{
    const auto pending = std::exchange(m_pending, {});
    for (const QPointer<Reply> &reply : pending) {
        if (reply)
            reply->fail(error);
    }
}

QString stateName(DeviceConnection::State state)
{
    switch (state) {
    case DeviceConnection::State::Disconnected:
        return QObject::tr("disconnected");
    case DeviceConnection::State::Connecting:
        return QObject::tr("connecting");
    case DeviceConnection::State::Connected:
        return QObject::tr("connected");
    case DeviceConnection::State::Closing:
        return QObject::tr("closing");
    }
    return {};
}

Reply *DeviceConnection::storeNonVolatile()
{
    return Reply::failed(
        {},
        Error(Error::Kind::NotSupported,
              Tr::tr("%1 cannot store parameters permanently").arg(m_uri.toString())));
}

Reply *DeviceConnection::restoreFactoryDefaults()
{
    return Reply::failed({},
                         Error(Error::Kind::NotSupported,
                               Tr::tr("%1 cannot restore factory defaults").arg(m_uri.toString())));
}

Reply *DeviceConnection::rawCommand(const QString &command)
{
    Q_UNUSED(command)
    return Reply::failed({},
                         Error(Error::Kind::NotSupported,
                               Tr::tr("%1 takes no raw protocol commands").arg(m_uri.toString())));
}

} // namespace db
