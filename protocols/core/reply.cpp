#include "reply.h"

#include <QAbstractEventDispatcher>
#include <QBasicTimer>
#include <QCoreApplication>
#include <QEventLoop>
#include <QPointer>
#include <QTimer>
#include <QTimerEvent>

#include <memory>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::core)
};
} // namespace

namespace db {

// Emits finished() of the replies of one thread from its event loop, in the order they
// finished. A posted event per reply would wake the event dispatcher (a write and a read on its
// wake-up descriptor and one more poll) for every request, and even one zero timer costs a pass
// of the loop with a poll of its own (and registering and unregistering it, for every request):
// so the replies are delivered when the loop is about to wait (QAbstractEventDispatcher::
// aboutToBlock, between two passes, with no handler of anyone else on the stack), or, in loops
// that never wait (processEvents() without WaitForMoreEvents), when the next pass starts
// (QAbstractEventDispatcher::awake, which every pass emits that does not wait). Every pass of
// every loop emits one of the two. A zero timer is left only for replies finished by a
// finished() handler, which come in the next pass.
class Reply::FinishedQueue : public QObject
{
public:
    static void add(Reply *reply)
    {
        thread_local std::unique_ptr<FinishedQueue> queue;
        if (!queue)
            queue = std::make_unique<FinishedQueue>();
        queue->m_pending.append(reply);
        queue->watchDispatcher();
        if ((queue->m_delivering || !queue->m_dispatcher) && !queue->m_timer.isActive())
            queue->m_timer.start(0, queue.get());
    }

protected:
    void timerEvent(QTimerEvent *event) override
    {
        if (event->timerId() == m_timer.timerId())
            deliver();
    }

private:
    void watchDispatcher()
    {
        if (m_dispatcher)
            return;
        m_dispatcher = QAbstractEventDispatcher::instance(thread());
        if (m_dispatcher) {
            connect(m_dispatcher, &QAbstractEventDispatcher::aboutToBlock, this,
                    &FinishedQueue::deliver, Qt::DirectConnection);
            connect(m_dispatcher, &QAbstractEventDispatcher::awake, this, &FinishedQueue::deliver,
                    Qt::DirectConnection);
        }
    }

    void deliver()
    {
        if (m_pending.isEmpty())
            return;
        // Replies finished by a finished() handler wait for the next pass. The two lists swap
        // roles and keep their capacity, so a round trip allocates nothing here; a handler that
        // runs a nested event loop delivers from a list of its own.
        QList<QPointer<Reply>> nested;
        QList<QPointer<Reply>> &due = m_delivering ? nested : m_spare;
        const bool outer = !m_delivering;
        m_delivering = true;
        due.swap(m_pending);
        for (const QPointer<Reply> &reply : std::as_const(due)) {
            if (reply) // the requester may have deleted it meanwhile
                reply->deliverFinished();
        }
        due.clear();
        if (outer)
            m_delivering = false;
        if (m_pending.isEmpty())
            m_timer.stop();
    }

    QList<QPointer<Reply>> m_pending;
    QList<QPointer<Reply>> m_spare; // the list being delivered, empty between passes
    bool m_delivering = false;
    QBasicTimer m_timer;
    QPointer<QAbstractEventDispatcher> m_dispatcher;
};

Reply::Reply(ObjectAddress address, QObject *parent)
    : QObject(parent)
    , m_address(address)
{ }

Result<QVariant> Reply::result() const
{
    if (!m_finished)
        return Error(Error::Kind::Busy, Tr::tr("request still pending"));
    if (m_error.isError())
        return m_error;
    return m_value;
}

bool Reply::finish(const QVariant &value)
{
    if (m_finished)
        return false;
    m_finished = true;
    m_value = value;
    scheduleFinished();
    return true;
}

bool Reply::fail(const Error &error)
{
    if (m_finished)
        return false;
    m_finished = true;
    m_error = error.isError() ? error : Error(Error::Kind::DeviceError, Tr::tr("failed"));
    scheduleFinished();
    return true;
}

void Reply::scheduleFinished()
{
    FinishedQueue::add(this);
}

void Reply::deliverFinished()
{
    m_delivered = true;
    Q_EMIT finished();
}

Reply *Reply::failed(ObjectAddress address, const Error &error)
{
    auto *reply = new Reply(address);
    reply->fail(error);
    return reply;
}

void Reply::forward(Reply *inner, Reply *outer, QObject *owner,
                    std::function<Result<QVariant>(const QVariant &)> convert)
{
    inner->setParent(owner);
    QPointer<Reply> target(outer);
    QObject::connect(inner, &Reply::finished, owner, [inner, target, convert] {
        inner->deleteLater();
        if (!target)
            return;
        if (!inner->ok()) {
            target->fail(inner->error());
            return;
        }
        const Result<QVariant> value =
            convert ? convert(inner->value()) : Result<QVariant>(inner->value());
        if (value)
            target->finish(*value);
        else
            target->fail(value.error());
    });
}

Result<QVariant> Reply::wait(Reply *reply, int safetyMs)
{
    QPointer<Reply> guard(reply);
    // Even a finished reply has its finished() still queued: spin until it is delivered, so the
    // reply can be deleted with no queued call left pointing at it.
    if (!reply->m_delivered) {
        QEventLoop loop;
        QObject::connect(reply, &Reply::finished, &loop, &QEventLoop::quit);
        QTimer::singleShot(safetyMs, &loop, &QEventLoop::quit);
        loop.exec();
    }
    if (!guard)
        return Error(Error::Kind::Cancelled, Tr::tr("request was deleted"));
    Result<QVariant> result = reply->isFinished()
        ? reply->result()
        : Result<QVariant>(
            Error(Error::Kind::Timeout, Tr::tr("no answer within %1 ms").arg(safetyMs)));
    reply->deleteLater();
    return result;
}

} // namespace db
