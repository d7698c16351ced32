#include "connectionaxis.h"

#include <QCoreApplication>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::motion)
};
} // namespace

namespace db::motion {

ConnectionAxis::ConnectionAxis(DeviceConnection *connection, QObject *parent)
    : AxisInterface(parent)
    , m_connection(connection)
{
    connect(connection, &DeviceConnection::stateChanged, this, &ConnectionAxis::onStateChanged);
    connect(connection, &DeviceConnection::supervisionLost, this, &AxisInterface::supervisionLost);
}

ConnectionAxis::~ConnectionAxis()
{
    if (m_source)
        m_source->release(this);
}

bool ConnectionAxis::isConnected() const
{
    return m_connection->isConnected();
}

Error ConnectionAxis::lossCause(const DeviceConnection &connection)
{
    const Error error = connection.lastError();
    if (error.isError())
        return error;
    return Error(Error::Kind::Disconnected,
                 Tr::tr("connection to %1 closed").arg(connection.uri().toString()));
}

void ConnectionAxis::attachStatus(StatusSource *source, const QList<ObjectAddress> &objects)
{
    if (m_source) {
        m_source->release(this);
        disconnect(m_source, nullptr, this, nullptr);
    }
    m_source = source;
    if (!source)
        return;
    connect(source, &StatusSource::updated, this, &ConnectionAxis::onUpdated);
    m_objects = objects;
    m_intervalMs = kStatusPollMs;
    source->acquire(this, m_intervalMs, objects);
}

void ConnectionAxis::setPollInterval(int ms)
{
    if (ms == m_intervalMs)
        return;
    m_intervalMs = ms;
    if (m_source)
        m_source->acquire(this, ms, m_objects);
}

bool ConnectionAxis::isIdle() const
{
    return m_status.valid && !m_status.powered && !m_status.moving && !m_status.quickStopActive
        && !commandRunning();
}

void ConnectionAxis::refreshStatus()
{
    setPollInterval(kStatusPollMs);
    if (m_source)
        m_source->refresh(this); // the status word and the axis's objects
}

Reply *ConnectionAxis::refreshedAfter(Reply *reply)
{
    setPollInterval(kStatusPollMs); // the command changes the drive: watch it closely
    connect(reply, &Reply::finished, this, &ConnectionAxis::refreshStatus);
    return reply;
}

void ConnectionAxis::onUpdated()
{
    if (!m_source || !m_connection->isConnected())
        return;
    if (takeStatus(*m_source, m_status))
        Q_EMIT statusChanged();
    setPollInterval(isIdle() ? kIdleStatusPollMs : kStatusPollMs);
}

void ConnectionAxis::onStateChanged(DeviceConnection::State state)
{
    if (state != DeviceConnection::State::Disconnected)
        return;
    m_status.valid = false;
    onDisconnected();
    Q_EMIT connectionLost(lossCause(*m_connection));
    Q_EMIT statusChanged();
}

} // namespace db::motion
