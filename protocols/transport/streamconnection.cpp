#include "streamconnection.h"

#include "tcpstream.h"

#include <QCoreApplication>
#include <QLoggingCategory>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::transport)
};
} // namespace

namespace db {

Q_LOGGING_CATEGORY(lcStreamConnection, "drivebench.transport.connection")

StreamConnection::StreamConnection(const ConnectionUri &uri, quint16 defaultPort, QObject *parent)
    : DeviceConnection(uri, parent)
    , m_stream(new TcpStream(uri.host(), quint16(uri.portOr(defaultPort)), this))
{
    initReconnect();
}

StreamConnection::StreamConnection(const ConnectionUri &uri, ByteStream *stream, QObject *parent)
    : DeviceConnection(uri, parent)
    , m_stream(stream)
{
    initReconnect();
}

void StreamConnection::followStream()
{
    connect(m_stream, &ByteStream::opened, this, &StreamConnection::onOpened);
    connect(m_stream, &ByteStream::closed, this, &StreamConnection::onClosed);
}

void StreamConnection::initReconnect()
{
    m_reconnectTimer.setSingleShot(true);
    m_reconnectTimer.setInterval(kDefaultReconnectIntervalMs);
    connect(&m_reconnectTimer, &QTimer::timeout, this, [this] {
        if (state() != State::Disconnected)
            return;
        Q_EMIT logLine(reconnectingLine());
        open();
    });
}

void StreamConnection::setAutoReconnect(bool enabled, int intervalMs, int windowMs)
{
    m_autoReconnect = enabled;
    m_windowMs = qMax(0, windowMs);
    m_reconnectTimer.setInterval(qMax(1, intervalMs));
    if (!enabled)
        stopReconnecting();
}

void StreamConnection::stopReconnecting()
{
    m_reconnectTimer.stop();
    m_reconnectUntil.reset();
}

QString StreamConnection::reconnectingLine() const
{
    return Tr::tr("reconnecting to %1").arg(m_stream->peerName());
}

QString StreamConnection::connectedLine() const
{
    return Tr::tr("connected to %1").arg(m_stream->peerName());
}

void StreamConnection::doOpen()
{
    m_reconnectTimer.stop();
    Q_EMIT logLine(Tr::tr("connecting to %1").arg(m_stream->peerName()));
    m_stream->setConnectTimeoutMs(connectTimeoutMs());
    if (m_stream->isOpen())
        onOpened();
    else
        m_stream->open();
}

void StreamConnection::doClose()
{
    stopReconnecting(); // closed by us: no reconnect
    if (m_stream->state() == ByteStream::State::Closed)
        setState(State::Disconnected);
    else
        m_stream->close();
}

void StreamConnection::onOpened()
{
    qCInfo(lcStreamConnection).noquote() << protocolKey() << "connected to" << m_stream->peerName();
    Q_EMIT logLine(connectedLine());
    m_reconnectUntil.reset();
    setState(State::Connected);
}

void StreamConnection::onClosed(const Error &error)
{
    const State previous = state();
    if (previous == State::Disconnected)
        return;
    if (previous == State::Closing) {
        Q_EMIT logLine(Tr::tr("disconnected from %1").arg(m_stream->peerName()));
        setState(State::Disconnected);
        return;
    }
    const Error why = error.isError()
        ? error
        : Error(Error::Kind::Disconnected,
                Tr::tr("connection to %1 closed").arg(m_stream->peerName()));
    Q_EMIT logLine(QStringLiteral("! ") + why.message());
    if (m_autoReconnect && m_windowMs > 0 && previous == State::Connected)
        m_reconnectUntil = QDeadlineTimer(m_windowMs);
    setState(State::Disconnected, why);
    if (!m_autoReconnect || state() != State::Disconnected)
        return;
    if (m_windowMs == 0 || (m_reconnectUntil && !m_reconnectUntil->hasExpired()))
        m_reconnectTimer.start();
    else
        m_reconnectUntil.reset();
}

} // namespace db
