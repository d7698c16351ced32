#include "fakeconnection.h"

#include <QPointer>
#include <QTimer>

namespace db::test {

FakeConnection::FakeConnection(const QString &uri, QObject *parent)
    : DeviceConnection(ConnectionUri::parse(uri).value(), parent)
{ }

void FakeConnection::goAway()
{
    setState(State::Disconnected,
             Error(Error::Kind::Disconnected, QStringLiteral("fake device went away")));
}

void FakeConnection::doOpen()
{
    QTimer::singleShot(0, this, [this] {
        if (state() != State::Connecting)
            return;
        if (m_refusal.isError())
            setState(State::Disconnected, std::exchange(m_refusal, {}));
        else
            setState(State::Connected);
    });
}

void FakeConnection::doClose()
{
    QTimer::singleShot(0, this, [this] { setState(State::Disconnected); });
}

void FakeConnection::answerLater(Reply *reply, std::function<void(Reply *)> answer)
{
    ++inFlight;
    maxInFlight = qMax(maxInFlight, inFlight);
    QPointer<Reply> guard(reply);
    QTimer::singleShot(replyDelayMs, this, [this, guard, answer = std::move(answer)] {
        --inFlight;
        if (guard && !guard->isFinished() && state() == State::Connected)
            answer(guard.data());
    });
}

void FakeConnection::doRead(Reply *reply, const ObjectDef *)
{
    ++readCount;
    const ObjectAddress address = reply->address();
    answerLater(reply, [this, address](Reply *r) {
        if (m_failures.contains(address))
            r->fail(m_failures.value(address));
        else if (!m_objects.contains(address))
            r->fail(Error(
                Error::Kind::DeviceError,
                QStringLiteral("ERROR %1 does not exist").arg(addressFormat().format(address))));
        else
            r->finish(m_objects.value(address));
    });
}

void FakeConnection::doWrite(Reply *reply, const QVariant &raw, const ObjectDef *)
{
    const ObjectAddress address = reply->address();
    answerLater(reply, [this, address, raw](Reply *r) {
        if (m_failures.contains(address)) {
            r->fail(m_failures.value(address));
            return;
        }
        writes.append({ address, raw });
        m_objects.insert(address, raw);
        r->finish();
    });
}

} // namespace db::test
