#pragma once

#include "reply.h"
#include "result.h"

#include <QPointer>
#include <QVariant>

#include <functional>

namespace db {

// Where an engine delivers the result of one request: a Reply (the general API, one QObject per
// request) or a handler with a context object (no object per request: for hot paths such as
// fixed-rate polling, and for connections that finish a reply of their own).
//
// Contract of the handler form:
// - The handler is called at most once, and not at all once its context has been deleted.
// - It is never called from inside the call that made the request. When the answer comes (or
//   the time limit runs out) it is called from the engine's receive or timer handler, after the
//   engine has finished with the request, so a request made from the handler goes out at once.
//   A request that fails at once (not connected, bad argument) or is cancelled is reported
//   from the event loop, by a queued call.
// - Like a directly connected slot of the engine's signals, the handler must not delete the
//   engine, its bus or its stream (deleteLater() is fine).
// - wanted() is false once the context (or the reply) is gone: engines skip such requests
//   while they are still queued, so a requester withdraws a read by deleting its context.
class Completion
{
public:
    using Handler = std::function<void(const Result<QVariant> &)>;

    Completion() = default;
    explicit Completion(Reply *reply)
        : m_target(reply)
    { }
    Completion(QObject *context, Handler handler)
        : m_target(context)
        , m_handler(std::move(handler))
    { }

    // Finishes `reply` with the result, its value passed through `convert`. The reply is the
    // context (a handler of its own): a request whose reply is deleted before it is sent is
    // withdrawn, so this suits reads; a write must go out even when its requester stops waiting.
    static Completion finishing(Reply *reply,
                                std::function<Result<QVariant>(const QVariant &)> convert);

    // Whether anyone still waits for the result.
    bool wanted() const { return !m_target.isNull(); }
    // The engine has the result: finishes the reply (its finished() comes from the loop) or
    // calls the handler now.
    void complete(const Result<QVariant> &result);
    // The same, from inside a request call or a cancellation: a handler is called from the
    // event loop.
    void completeLater(const Result<QVariant> &result);
    // Either of the two.
    void complete(const Result<QVariant> &result, bool later)
    {
        later ? completeLater(result) : complete(result);
    }

private:
    QPointer<QObject> m_target; // the reply, or the handler's context
    Handler m_handler; // empty for a reply
};

} // namespace db
