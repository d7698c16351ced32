#include "canbus.h"

#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QEventLoop>
#include <QTimer>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::transport)
};
} // namespace

namespace db {

void CanBus::open()
{
    if (m_state != State::Closed)
        return;
    m_state = State::Opening;
    doOpen();
}

void CanBus::close()
{
    if (m_state == State::Closed || m_state == State::Closing)
        return;
    m_state = State::Closing;
    doClose();
}

bool CanBus::send(const QCanBusFrame &frame)
{
    if (m_state != State::Open)
        return false;
    doSend(frame);
    return true;
}

void CanBus::setOpened()
{
    if (m_state != State::Opening)
        return;
    m_state = State::Open;
    Q_EMIT opened();
}

void CanBus::setClosed(const Error &error)
{
    if (m_state == State::Closed)
        return;
    m_state = State::Closed;
    Q_EMIT closed(error);
}

void CanBus::deliver(const QCanBusFrame &frame)
{
    if (m_state != State::Open)
        return;
    Q_EMIT traffic(frame, false);
    Q_EMIT frameReceived(frame);
}

void CanBus::reportSent(const QCanBusFrame &frame)
{
    Q_EMIT traffic(frame, true);
    Q_EMIT frameSent(frame);
}

void CanBus::reportDropped(qint64 frames)
{
    if (frames <= 0)
        return;
    m_dropped += frames;
    m_droppedUnreported += frames;
    if (m_reportScheduled)
        return;
    const qint64 now = QDeadlineTimer::current().deadline();
    const qint64 wait = m_lastReportMs < 0 ? 0 : m_lastReportMs + kOverflowReportMs - now;
    if (wait <= 0) {
        flushDropReport();
        return;
    }
    m_reportScheduled = true;
    QTimer::singleShot(int(wait), this, [this] {
        m_reportScheduled = false;
        flushDropReport();
    });
}

void CanBus::flushDropReport()
{
    if (m_droppedUnreported == 0)
        return;
    m_lastReportMs = QDeadlineTimer::current().deadline();
    const qint64 frames = std::exchange(m_droppedUnreported, 0);
    Q_EMIT warning(Tr::tr("%1: receive queue overflow: %2 frames dropped (%3 in all)")
                       .arg(name())
                       .arg(frames)
                       .arg(m_dropped));
}

Result<void> CanBus::openAndWait(int timeoutMs)
{
    Error failure;
    QEventLoop loop;
    connect(this, &CanBus::opened, &loop, &QEventLoop::quit);
    connect(this, &CanBus::closed, &loop, [&](const Error &error) {
        failure = error;
        loop.quit();
    });
    QTimer::singleShot(timeoutMs, &loop, &QEventLoop::quit);
    open();
    if (m_state == State::Opening)
        loop.exec();
    if (isOpen())
        return {};
    return failure.isError()
        ? failure
        : Error(Error::Kind::Timeout,
                Tr::tr("%1 did not open within %2 ms").arg(name()).arg(timeoutMs));
}

} // namespace db
