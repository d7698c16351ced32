#include "clientthrottle.h"

#include <QTcpSocket>

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

} // namespace db
