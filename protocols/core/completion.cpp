#include "completion.h"

#include <QMetaObject>

namespace db {

Completion Completion::finishing(Reply *reply,
                                 std::function<Result<QVariant>(const QVariant &)> convert)
{
    return Completion(reply, [reply, convert = std::move(convert)](const Result<QVariant> &r) {
        Completion(reply).complete(r.ok() ? convert(r.value()) : r);
    });
}

namespace {

// Finishes the reply (its finished() comes from the loop) or calls the handler, now or from the
// loop; nothing when the target is gone. Either way the completion is spent.
void deliver(QPointer<QObject> &target, Completion::Handler &handler,
             const Result<QVariant> &result, bool later)
{
    QObject *context = std::exchange(target, nullptr).data();
    if (!context)
        return;
    if (!handler) {
        auto *reply = static_cast<Reply *>(context);
        result.ok() ? reply->finish(result.value()) : reply->fail(result.error());
        return;
    }
    // Moved out first: the handler may destroy whatever holds this completion.
    Completion::Handler call = std::exchange(handler, {});
    if (!later) {
        call(result);
        return;
    }
    QMetaObject::invokeMethod(
        context, [call = std::move(call), result] { call(result); }, Qt::QueuedConnection);
}

} // namespace

void Completion::complete(const Result<QVariant> &result)
{
    deliver(m_target, m_handler, result, false);
}

void Completion::completeLater(const Result<QVariant> &result)
{
    deliver(m_target, m_handler, result, true);
}

} // namespace db
