#pragma once

// Reply::wait() blocks until finished() arrives; when an earlier wait() already delivered a
// reply's queued finished() it sits out its safety time instead. Tests that hold several
// replies use this: wait for isFinished(), take the result, delete the reply.

#include "core/reply.h"

#include <QTest>

#include <memory>

namespace db::test {

inline Result<QVariant> await(Reply *reply, int timeoutMs = 5000)
{
    std::unique_ptr<Reply> owner(reply);
    if (!QTest::qWaitFor([reply] { return reply->isFinished(); }, timeoutMs))
        return Error(Error::Kind::Timeout, QStringLiteral("test: reply did not finish"));
    return reply->result();
}

} // namespace db::test
