#include "connectionhealth.h"

#include <QCoreApplication>

namespace {
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::ConnectionHealth)
};

constexpr db::ObjectAddress kDeviceType(0x1000, 0);
constexpr db::ObjectAddress kStatusword(0x6041, 0);

// A request that reached the device and came back: a value, or the device's own refusal.
bool isAnswer(const db::Error &error)
{
    return !error.isError() || error.kind() == db::Error::Kind::DeviceError;
}
} // namespace

namespace db {

ConnectionHealth::ConnectionHealth(DeviceConnection *connection)
    : QObject(connection)
    , m_connection(connection)
{
    m_probeTimer.setSingleShot(true);
    m_probeTimer.setInterval(kProbeIntervalMs);
    connect(&m_probeTimer, &QTimer::timeout, this, &ConnectionHealth::probe);
    connect(connection, &DeviceConnection::stateChanged, this, &ConnectionHealth::onStateChanged);
    connect(connection, &DeviceConnection::errorOccurred, this,
            [this](const Error &error) { m_linkError = error; });
    connect(connection, &DeviceConnection::requestFinished, this,
            [this](ObjectAddress, const Error &error) { onRequestFinished(error); });
    if (connection->state() != DeviceConnection::State::Disconnected)
        onStateChanged(connection->state());
}

ConnectionHealth *ConnectionHealth::of(const DeviceConnection *connection)
{
    return connection
        ? connection->findChild<ConnectionHealth *>(QString(), Qt::FindDirectChildrenOnly)
        : nullptr;
}

bool ConnectionHealth::isSilent(const DeviceConnection *connection)
{
    const ConnectionHealth *health = of(connection);
    return health && health->status() == Status::NotResponding;
}

int ConnectionHealth::pollIntervalMs(const DeviceConnection *connection, int normalMs)
{
    return isSilent(connection) ? qMax(normalMs, kSilentPollIntervalMs) : normalMs;
}

bool ConnectionHealth::isNoAnswer(const Error &error)
{
    switch (error.kind()) {
    case Error::Kind::Timeout:
    case Error::Kind::Disconnected:
    case Error::Kind::ConnectionRefused:
    case Error::Kind::HostNotFound:
    case Error::Kind::Io:
        return true;
    default:
        return false;
    }
}

void ConnectionHealth::onStateChanged(DeviceConnection::State state)
{
    switch (state) {
    case DeviceConnection::State::Connecting:
        m_closing = false;
        m_wasUp = false;
        m_linkError = {};
        m_timeouts = 0;
        setStatus(Status::Connecting);
        break;
    case DeviceConnection::State::Connected:
        m_wasUp = true;
        m_timeouts = 0;
        setStatus(Status::WaitingForAnswer);
        m_probeTimer.start();
        break;
    case DeviceConnection::State::Closing:
        // close() by the user; a failed probe passes through Closing with an error after it.
        m_closing = true;
        m_linkError = {};
        m_probeTimer.stop();
        break;
    case DeviceConnection::State::Disconnected:
        m_probeTimer.stop();
        if (m_linkError.isError())
            setStatus(m_wasUp ? Status::Lost : Status::Failed, m_linkError);
        else if (m_closing)
            setStatus(Status::ClosedByUser);
        else
            setStatus(m_wasUp ? Status::Lost : Status::Failed,
                      Error(Error::Kind::Disconnected,
                            Tr::tr("the link to %1 closed").arg(m_connection->uri().toString())));
        break;
    }
}

void ConnectionHealth::onRequestFinished(const Error &error)
{
    if (!m_connection || !m_connection->isConnected())
        return;
    if (isAnswer(error)) {
        m_timeouts = 0;
        m_lastAnswer = QDateTime::currentDateTime();
        setStatus(Status::Responding);
    } else if (error.kind() == Error::Kind::Timeout) {
        // The first timeout that made it silent stays the cause until the device answers.
        if (++m_timeouts >= kTimeoutsBeforeSilent && m_status != Status::NotResponding)
            setStatus(Status::NotResponding, error);
    }
    m_probeTimer.start(); // the next probe only when nothing else asks the device
}

void ConnectionHealth::probe()
{
    if (!m_connection || !m_connection->isConnected())
        return;
    if (m_probe && !m_probe->isFinished()) {
        m_probeTimer.start();
        return;
    }
    m_probe = m_connection->read(probeAddress());
    m_probe->setParent(this); // dies with the health (and its connection) if it never finishes
    connect(m_probe, &Reply::finished, m_probe, &QObject::deleteLater);
}

ObjectAddress ConnectionHealth::probeAddress() const
{
    const ObjectDictionary &dict = m_connection->dictionary();
    if (dict.isEmpty() || dict.contains(kDeviceType))
        return kDeviceType;
    if (dict.contains(kStatusword))
        return kStatusword;
    for (const ObjectDef &def : dict.objects()) {
        if (def.readable())
            return def.address;
    }
    return kDeviceType;
}

void ConnectionHealth::setStatus(Status status, const Error &cause)
{
    const bool changed = status != m_status || cause != m_cause;
    m_status = status;
    m_cause = cause;
    if (changed)
        Q_EMIT statusChanged(status);
}

QString ConnectionHealth::statusText(Status status)
{
    switch (status) {
    case Status::Idle:
        return Tr::tr("not connected");
    case Status::Connecting:
        return Tr::tr("connecting…");
    case Status::WaitingForAnswer:
        return Tr::tr("waiting for the device to answer");
    case Status::Responding:
        return Tr::tr("connected");
    case Status::NotResponding:
        return Tr::tr("not responding");
    case Status::Failed:
        return Tr::tr("connection failed");
    case Status::Lost:
        return Tr::tr("connection lost");
    case Status::ClosedByUser:
        return Tr::tr("disconnected by you");
    }
    return {};
}

QString ConnectionHealth::description() const
{
    const QString text = statusText(m_status);
    return m_cause.isError() ? Tr::tr("%1: %2").arg(text, m_cause.message()) : text;
}

} // namespace db
