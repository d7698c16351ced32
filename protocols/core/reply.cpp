#include "reply.h"

#include <QCoreApplication>
#include <QEventLoop>
#include <QPointer>
#include <QTimer>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::core)
};
} // namespace

namespace db {

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
    QMetaObject::invokeMethod(
        this,
        [this] {
            m_delivered = true;
            Q_EMIT finished();
        },
        Qt::QueuedConnection);
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
