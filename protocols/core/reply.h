#pragma once

#include "error.h"
#include "objectaddress.h"
#include "result.h"

#include <QObject>
#include <QVariant>

#include <functional>

namespace db {

// The answer to one asynchronous request (read, write, raw command), like QModbusReply.
//
// Contract:
// - It finishes exactly once: with a value (finish) or an Error (fail). Later calls are ignored.
// - finished() is emitted from the event loop, never from inside finish()/fail(), so a requester
//   that connects to it right after getting the reply never misses it.
// - The requester owns the reply and deletes it (deleteLater() in its finished handler is fine).
//   Producers keep only a QPointer and must cope with a reply deleted early.
class Reply : public QObject
{
    Q_OBJECT
public:
    explicit Reply(ObjectAddress address = {}, QObject *parent = nullptr);

    ObjectAddress address() const { return m_address; }
    bool isFinished() const { return m_finished; }
    bool ok() const { return m_finished && !m_error.isError(); }
    Error error() const { return m_error; }
    // Raw value for reads; the command's result for protocol commands; invalid for writes.
    QVariant value() const { return m_value; }
    Result<QVariant> result() const;

    // Producer side. Returns false when the reply had already finished.
    bool finish(const QVariant &value = {});
    bool fail(const Error &error);

    // A reply that fails at once (e.g. "not connected"); finished() still comes from the loop.
    static Reply *failed(ObjectAddress address, const Error &error);

    // Finishes `outer` when `inner` (an engine's reply, given to `owner`) finishes: with inner's
    // error, or with inner's value passed through `convert` (as it is when convert is empty).
    // Safe when outer is deleted first, and inner is not leaked when owner goes first.
    static void forward(Reply *inner, Reply *outer, QObject *owner,
                        std::function<Result<QVariant>(const QVariant &)> convert = {});

    // Blocks in a local event loop until the reply finishes (for the CLI and tests only) and
    // deletes it. Every protocol request has its own timeout; safetyMs is a last resort.
    static Result<QVariant> wait(Reply *reply, int safetyMs = 60000);

Q_SIGNALS:
    void finished();

private:
    class FinishedQueue;

    void scheduleFinished();
    void deliverFinished();

    ObjectAddress m_address;
    QVariant m_value;
    Error m_error;
    bool m_finished = false;
    bool m_delivered = false; // finished() has been emitted
};

} // namespace db
