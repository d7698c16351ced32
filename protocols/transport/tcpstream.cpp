#include "tcpstream.h"

#include <QCoreApplication>
#include <QLoggingCategory>

#include <cstring>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::transport)
};
} // namespace

namespace db {

Q_LOGGING_CATEGORY(lcTcp, "drivebench.transport.tcp")
Q_LOGGING_CATEGORY(lcTcpRaw, "drivebench.transport.tcp.raw", QtWarningMsg)

TcpStream::TcpStream(const QString &host, quint16 port, QObject *parent)
    : ByteStream(parent)
    , m_host(host)
    , m_port(port)
    , m_readChunk(std::make_unique<char[]>(kReadBufferBytes))
{
    m_connectTimer.setSingleShot(true);
    // A coarse timer may fire 5 % early; the limit the user gave is a promise.
    m_connectTimer.setTimerType(Qt::PreciseTimer);
    connect(&m_connectTimer, &QTimer::timeout, this, [this] {
        m_socket.abort();
        setClosed(Error(Error::Kind::Timeout,
                        Tr::tr("no TCP connection to %1 within %2 ms")
                            .arg(peerName())
                            .arg(m_connectTimeoutMs)));
    });
    connect(&m_socket, &QTcpSocket::connected, this, &TcpStream::onConnected);
    connect(&m_socket, &QTcpSocket::errorOccurred, this,
            [this](QAbstractSocket::SocketError error) {
                if (!m_writing) {
                    onSocketError(error);
                    return;
                }
                QTimer::singleShot(0, this, [this, error] { onSocketError(error); });
            });
    connect(&m_socket, &QTcpSocket::disconnected, this, &TcpStream::onDisconnected);
    // One read of at most kReadBufferBytes per pass; what is left makes readyRead come again.
    connect(&m_socket, &QTcpSocket::readyRead, this, [this] {
        const qint64 n = m_socket.read(m_readChunk.get(), kReadBufferBytes);
        if (n < 0) {
            // An unbuffered socket reports the peer's close (or a reset) only here, with no
            // disconnected() signal.
            const auto error = m_socket.error();
            m_socket.abort();
            if (state() == State::Closing)
                setClosed();
            else
                setClosed(describe(error));
            return;
        }
        if (n == 0)
            return;
        // The bytes go out in one array that is kept for the next read: resize() reuses its
        // storage unless a receiver kept a copy, which it then leaves to that receiver. A
        // receiver that runs an event loop of its own gets no further read meanwhile (the
        // socket does not emit readyRead() inside its own readyRead()).
        m_received.resize(n);
        std::memcpy(m_received.data(), m_readChunk.get(), size_t(n));
        qCDebug(lcTcpRaw) << peerName() << "<-" << m_received;
        deliver(m_received);
    });
}

QString TcpStream::peerName() const
{
    return m_host.contains(QLatin1Char(':')) ? QStringLiteral("[%1]:%2").arg(m_host).arg(m_port)
                                             : QStringLiteral("%1:%2").arg(m_host).arg(m_port);
}

void TcpStream::doOpen()
{
    qCDebug(lcTcp) << "connecting to" << peerName();
    m_connectTimer.start(m_connectTimeoutMs);
    m_socket.connectToHost(m_host, m_port, QIODevice::ReadWrite | QIODevice::Unbuffered);
}

void TcpStream::doClose()
{
    m_connectTimer.stop();
    if (m_socket.state() == QAbstractSocket::UnconnectedState) {
        setClosed();
        return;
    }
    m_socket.disconnectFromHost(); // flushes queued bytes; disconnected() follows
    if (m_socket.state() == QAbstractSocket::UnconnectedState)
        setClosed();
}

void TcpStream::doWrite(const QByteArray &bytes)
{
    qCDebug(lcTcpRaw) << peerName() << "->" << bytes;
    m_writing = true;
    m_socket.write(bytes);
    m_writing = false;
}

void TcpStream::onConnected()
{
    m_connectTimer.stop();
    m_socket.setSocketOption(QAbstractSocket::LowDelayOption, 1);
    m_socket.setSocketOption(QAbstractSocket::KeepAliveOption, 1);
    qCDebug(lcTcp) << "connected to" << peerName();
    setOpened();
}

void TcpStream::onSocketError(QAbstractSocket::SocketError error)
{
    m_connectTimer.stop();
    if (error == QAbstractSocket::RemoteHostClosedError && state() == State::Closing)
        return; // orderly close we asked for
    const Error e = describe(error);
    qCDebug(lcTcp) << e.toString();
    m_socket.abort();
    setClosed(e);
}

TcpStream::~TcpStream()
{
    // Members die in reverse order: m_connectTimer before m_socket, whose destructor still
    // emits disconnected(). Nothing of the socket reaches this object any more.
    m_socket.disconnect(this);
}

void TcpStream::onDisconnected()
{
    m_connectTimer.stop();
    if (state() == State::Closing)
        setClosed();
    else
        setClosed(
            Error(Error::Kind::Disconnected, Tr::tr("%1 closed the connection").arg(peerName())));
}

Error TcpStream::describe(QAbstractSocket::SocketError error) const
{
    switch (error) {
    case QAbstractSocket::ConnectionRefusedError:
        return Error(
            Error::Kind::ConnectionRefused,
            Tr::tr("%1 refused the connection (nothing listens on that port)").arg(peerName()));
    case QAbstractSocket::HostNotFoundError:
        return Error(Error::Kind::HostNotFound, Tr::tr("host '%1' not found").arg(m_host));
    case QAbstractSocket::RemoteHostClosedError:
        return Error(Error::Kind::Disconnected, Tr::tr("%1 closed the connection").arg(peerName()));
    case QAbstractSocket::SocketTimeoutError:
        return Error(Error::Kind::Timeout, Tr::tr("%1: socket timeout").arg(peerName()));
    case QAbstractSocket::NetworkError:
        return Error(Error::Kind::Disconnected,
                     Tr::tr("%1: network error: %2").arg(peerName(), m_socket.errorString()));
    default:
        return Error(Error::Kind::Io, Tr::tr("%1: %2").arg(peerName(), m_socket.errorString()));
    }
}

} // namespace db
