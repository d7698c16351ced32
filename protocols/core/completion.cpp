#include "completion.h"

#include <QMetaObject>

namespace db {

Completion Completion::finishing(Reply *reply,
                                 std::function<Result<QVariant>(const QVariant &)> convert)
{
    return Completion(reply, [reply, convert = std::move(convert)](const Result<QVariant> &r) {
        const Result<QVariant> value = r.ok() ? convert(r.value()) : r;
        value.ok() ? reply->finish(value.value()) : reply->fail(value.error());
    });
}

void Completion::complete(const Result<QVariant> &result)
{
    QObject *target = std::exchange(m_target, nullptr).data();
    if (!target)
        return;
    if (!m_handler) {
        auto *reply = static_cast<Reply *>(target);
        result.ok() ? reply->finish(result.value()) : reply->fail(result.error());
        return;
    }
    const Handler handler = std::exchange(m_handler, {});
    handler(result);
}

void Completion::completeLater(const Result<QVariant> &result)
{
    QObject *target = std::exchange(m_target, nullptr).data();
    if (!target)
        return;
    if (!m_handler) {
        auto *reply = static_cast<Reply *>(target);
        result.ok() ? reply->finish(result.value()) : reply->fail(result.error());
        return;
    }
    QMetaObject::invokeMethod(
        target, [handler = std::exchange(m_handler, {}), result] { handler(result); },
        Qt::QueuedConnection);
}

} // namespace db
