#include "tcpstream.h"

#include <QCoreApplication>
#include <QLoggingCategory>

#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <unistd.h>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::transport)
};

bool wouldBlock(int code)
{
    return code == EAGAIN || code == EWOULDBLOCK || code == EINTR;
}
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
    connect(&m_socket, &QTcpSocket::errorOccurred, this, &TcpStream::onSocketError);
    connect(&m_socket, &QTcpSocket::disconnected, this, &TcpStream::onDisconnected);
}

TcpStream::~TcpStream()
{
    // Nothing of the socket reaches this object any more: its destructor still emits
    // disconnected() after the timer member is gone.
    m_socket.disconnect(this);
    release();
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
    if (m_fd >= 0) {
        // The kernel sends what it has taken before it closes; only bytes it never took (a
        // peer that stopped reading) are dropped.
        if (!m_unsent.isEmpty())
            qCDebug(lcTcp) << peerName() << "closed with" << m_unsent.size() << "bytes unsent";
        release();
        setClosed();
        return;
    }
    m_socket.abort(); // not connected yet: nothing to send
    setClosed();
}

void TcpStream::doWrite(const QByteArray &bytes)
{
    qCDebug(lcTcpRaw) << peerName() << "->" << bytes;
    if (m_fd < 0 || m_writeError)
        return;
    if (!m_unsent.isEmpty()) {
        m_unsent += bytes;
        return;
    }
    const ssize_t n = ::send(m_fd, bytes.constData(), size_t(bytes.size()), MSG_NOSIGNAL);
    if (n == bytes.size())
        return;
    if (n < 0 && !wouldBlock(errno)) {
        m_writeError = errno; // reported from the loop: the socket is writable at once
    } else {
        m_unsent = bytes.mid(qMax<qsizetype>(n, 0));
    }
    m_writable->setEnabled(true);
}

void TcpStream::onConnected()
{
    m_connectTimer.stop();
    // A descriptor of our own; then the socket closes its own (a plain close, no shutdown: the
    // connection lives on in ours).
    const int fd = ::fcntl(int(m_socket.socketDescriptor()), F_DUPFD_CLOEXEC, 0);
    const int dupError = errno;
    m_handingOver = true;
    m_socket.abort();
    m_handingOver = false;
    if (fd < 0) {
        setClosed(Error(Error::Kind::Io,
                        Tr::tr("%1: cannot take over the connection: %2")
                            .arg(peerName(), QString::fromLocal8Bit(std::strerror(dupError)))));
        return;
    }
    m_fd = fd;
    const int one = 1;
    ::setsockopt(m_fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
    ::setsockopt(m_fd, SOL_SOCKET, SO_KEEPALIVE, &one, sizeof one);
    ::fcntl(m_fd, F_SETFL, ::fcntl(m_fd, F_GETFL) | O_NONBLOCK);
    m_readable = std::make_unique<QSocketNotifier>(qintptr(m_fd), QSocketNotifier::Read);
    connect(m_readable.get(), &QSocketNotifier::activated, this, &TcpStream::onReadable);
    m_writable = std::make_unique<QSocketNotifier>(qintptr(m_fd), QSocketNotifier::Write);
    m_writable->setEnabled(false);
    connect(m_writable.get(), &QSocketNotifier::activated, this, &TcpStream::onWritable);
    qCDebug(lcTcp) << "connected to" << peerName();
    setOpened();
}

void TcpStream::onReadable()
{
    // One read of at most kReadBufferBytes per pass; what is left wakes the notifier again.
    const ssize_t n = ::recv(m_fd, m_readChunk.get(), size_t(kReadBufferBytes), 0);
    if (n > 0) {
        // The bytes go out in one array that is kept for the next read: resize() reuses its
        // storage unless a receiver kept a copy, which it then leaves to that receiver. A
        // receiver that runs an event loop of its own still holds that array while the reads
        // meanwhile come here again: those get arrays of their own.
        const bool outer = !m_delivering;
        QByteArray nested;
        QByteArray &bytes = outer ? m_received : nested;
        bytes.resize(n);
        std::memcpy(bytes.data(), m_readChunk.get(), size_t(n));
        qCDebug(lcTcpRaw) << peerName() << "<-" << bytes;
        m_delivering = true;
        deliver(bytes);
        if (outer)
            m_delivering = false;
        return;
    }
    if (n < 0 && wouldBlock(errno))
        return;
    fail(n == 0 ? 0 : errno); // 0: the peer closed the connection
}

void TcpStream::onWritable()
{
    if (m_writeError) {
        fail(m_writeError);
        return;
    }
    const ssize_t n = ::send(m_fd, m_unsent.constData(), size_t(m_unsent.size()), MSG_NOSIGNAL);
    if (n < 0) {
        if (!wouldBlock(errno))
            fail(errno);
        return;
    }
    m_unsent.remove(0, n);
    if (m_unsent.isEmpty())
        m_writable->setEnabled(false);
}

void TcpStream::release()
{
    m_readable.reset();
    m_writable.reset();
    if (m_fd >= 0)
        ::close(m_fd);
    m_fd = -1;
    m_unsent.clear();
    m_writeError = 0;
}

void TcpStream::fail(int code)
{
    release();
    if (state() == State::Closing) {
        setClosed();
        return;
    }
    const Error e = describeErrno(code);
    qCDebug(lcTcp) << e.toString();
    setClosed(e);
}

void TcpStream::onSocketError(QAbstractSocket::SocketError error)
{
    if (m_handingOver)
        return;
    m_connectTimer.stop();
    if (error == QAbstractSocket::RemoteHostClosedError && state() == State::Closing)
        return; // orderly close we asked for
    const Error e = describe(error);
    qCDebug(lcTcp) << e.toString();
    m_socket.abort();
    setClosed(e);
}

void TcpStream::onDisconnected()
{
    if (m_handingOver)
        return;
    m_connectTimer.stop();
    if (state() == State::Closing)
        setClosed();
    else
        setClosed(
            Error(Error::Kind::Disconnected, Tr::tr("%1 closed the connection").arg(peerName())));
}

Error TcpStream::describeErrno(int code) const
{
    switch (code) {
    case 0:
    case ECONNRESET:
    case EPIPE:
        return Error(Error::Kind::Disconnected, Tr::tr("%1 closed the connection").arg(peerName()));
    case ETIMEDOUT:
    case EHOSTUNREACH:
    case ENETUNREACH:
    case ENETDOWN:
        return Error(Error::Kind::Disconnected,
                     Tr::tr("%1: network error: %2")
                         .arg(peerName(), QString::fromLocal8Bit(std::strerror(code))));
    default:
        return Error(Error::Kind::Io,
                     Tr::tr("%1: %2").arg(peerName(), QString::fromLocal8Bit(std::strerror(code))));
    }
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
