#include "clientthrottle.h"

#include <QCoreApplication>
#include <QTcpSocket>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::transport)
};
} // namespace

namespace db {

ClientThrottle::ClientThrottle(QTcpSocket *socket, const Limits &limits)
    : QObject(socket)
    , m_socket(socket)
    , m_limits(limits)
{
    m_socket->setReadBufferSize(kReadSliceBytes);
    m_stall.setSingleShot(true);
    m_stall.setInterval(m_limits.stallTimeoutMs);
    connect(&m_stall, &QTimer::timeout, this,
            [this] { Q_EMIT stalled(m_socket->bytesToWrite(), m_limits.stallTimeoutMs); });
    connect(m_socket, &QTcpSocket::bytesWritten, this, &ClientThrottle::onBytesWritten);
}

qint64 ClientThrottle::queued()
{
    const qint64 bytes = m_socket->bytesToWrite();
    if (!m_paused && bytes > m_limits.maxQueuedBytes) {
        m_paused = true;
        m_stall.start();
    }
    return bytes;
}

void ClientThrottle::onBytesWritten()
{
    if (!m_paused || m_socket->bytesToWrite() > m_limits.maxQueuedBytes / 2)
        return;
    m_paused = false;
    m_stall.stop();
    Q_EMIT resumed();
}

QString ClientThrottle::drop(QTcpSocket *socket, QObject *receiver, qint64 queuedBytes,
                             int pausedMs)
{
    const QString why = Tr::tr("dropping client %1:%2: it has not read its answers for "
                               "%3 ms (%4 bytes queued)")
                            .arg(socket->peerAddress().toString())
                            .arg(socket->peerPort())
                            .arg(pausedMs)
                            .arg(queuedBytes);
    socket->disconnect(receiver);
    socket->abort();
    socket->deleteLater();
    return why;
}

} // namespace db
