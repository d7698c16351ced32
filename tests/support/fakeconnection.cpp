#include "fakeconnection.h"

#include "canopen/storesignatures.h"

#include <QPointer>
#include <QTimer>

namespace db::test {

FakeConnection::FakeConnection(const QString &uri, QObject *parent)
    : DeviceConnection(ConnectionUri::parse(uri).value(), parent)
{ }

void FakeConnection::setModel(ReadFn read, WriteFn write)
{
    m_read = std::move(read);
    m_write = std::move(write);
}

Reply *FakeConnection::storeNonVolatile()
{
    if (!(m_capabilities & Capability::StoreNonVolatile))
        return DeviceConnection::storeNonVolatile();
    return write(canopen::store::kStoreAll,
                 QVariant::fromValue<qulonglong>(canopen::store::kSaveSignature));
}

Reply *FakeConnection::restoreFactoryDefaults()
{
    if (!(m_capabilities & Capability::StoreNonVolatile))
        return DeviceConnection::restoreFactoryDefaults();
    return write(canopen::store::kRestoreDefaultsAll,
                 QVariant::fromValue<qulonglong>(canopen::store::kLoadSignature));
}

void FakeConnection::goAway()
{
    setState(State::Disconnected,
             Error(Error::Kind::Disconnected, QStringLiteral("fake device went away")));
}

void FakeConnection::later(int delayMs, std::function<void()> action)
{
    if (immediate)
        action();
    else
        QTimer::singleShot(delayMs, this, std::move(action));
}

void FakeConnection::doOpen()
{
    later(0, [this] {
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
    later(0, [this] { setState(State::Disconnected); });
}

void FakeConnection::answer(Reply *reply, std::function<void(Reply *)> answer)
{
    if (m_requestsUntilGone > 0 && --m_requestsUntilGone == 0) {
        // This request stays unanswered; the break fails it with every other pending one.
        later(0, [this] {
            if (state() == State::Connected)
                goAway();
        });
        return;
    }
    const ObjectAddress address = reply->address();
    int delayMs = replyDelayMs;
    if (silent.contains(address)) {
        delayMs = requestTimeoutMs();
        answer = [delayMs](Reply *r) {
            r->fail(
                Error(Error::Kind::Timeout, QStringLiteral("no answer within %1 ms").arg(delayMs)));
        };
    } else if (m_failures.contains(address)) {
        answer = [error = m_failures.value(address)](Reply *r) {
            r->fail(error);
        };
    }
    ++inFlight;
    maxInFlight = qMax(maxInFlight, inFlight);
    QPointer<Reply> guard(reply);
    later(delayMs, [this, guard, answer = std::move(answer)] {
        --inFlight;
        if (guard && !guard->isFinished() && state() == State::Connected)
            answer(guard.data());
    });
}

Result<QVariant> FakeConnection::readValue(ObjectAddress address) const
{
    if (m_read)
        return m_read(address);
    if (!m_objects.contains(address))
        return Error(
            Error::Kind::DeviceError,
            QStringLiteral("ERROR %1 does not exist").arg(addressFormat().format(address)));
    return m_objects.value(address);
}

Result<void> FakeConnection::writeValue(ObjectAddress address, const QVariant &raw)
{
    if (m_write) {
        if (auto r = m_write(address, raw); !r)
            return r;
    } else {
        m_objects.insert(address, raw);
    }
    writes.append({ address, raw });
    return {};
}

void FakeConnection::doRead(Reply *reply, const ObjectDef *)
{
    ++readCount;
    answer(reply, [this](Reply *r) {
        if (auto value = readValue(r->address()))
            r->finish(value.value());
        else
            r->fail(value.error());
    });
}

void FakeConnection::doWrite(Reply *reply, const QVariant &raw, const ObjectDef *)
{
    ++writeCount;
    answer(reply, [this, raw](Reply *r) {
        const ObjectAddress address = r->address();
        if (rejectWrites.contains(address)) {
            r->fail(Error(Error::Kind::DeviceError,
                          QStringLiteral("SDO abort 08000022: present device state"), 0x08000022));
        } else if (ignoreAllWrites || ignoreWrites.contains(address)) {
            r->finish();
        } else if (auto done = writeValue(address, raw)) {
            r->finish();
        } else {
            r->fail(done.error());
        }
    });
}

} // namespace db::test
