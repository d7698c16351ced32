#pragma once

#include "core/deviceconnection.h"

#include <QHash>
#include <QSet>

#include <functional>

namespace db::test {

// The DeviceConnection test double, simulated at the connection seam. Values come from an object
// table (setValue) or from a model with read/write functions (a simulated drive or node,
// setModel). Answers come from the event loop after replyDelayMs, or inside the call itself
// when `immediate` is set. Failure modes: per-object device errors, silence (timeouts),
// refused and ignored writes, a refused open, a link that breaks now or in the middle of a
// later request, and slow answers. Counters let tests check that nothing floods the device.
class FakeConnection : public DeviceConnection
{
    Q_OBJECT
public:
    using ReadFn = std::function<Result<QVariant>(ObjectAddress)>;
    using WriteFn = std::function<Result<void>(ObjectAddress, const QVariant &)>;

    explicit FakeConnection(const QString &uri = QStringLiteral("fake://device"),
                            QObject *parent = nullptr);

    QString protocolKey() const override { return m_protocolKey; }
    void setProtocolKey(const QString &key) { m_protocolKey = key; }
    // With Capability::StoreNonVolatile, storing and restoring write the CiA 301 signatures
    // to 1010h:1 / 1011h:1 (through write(), so they show in the counters and in `writes`).
    Capabilities capabilities() const override { return m_capabilities; }
    void setCapabilities(Capabilities capabilities) { m_capabilities = capabilities; }
    Reply *storeNonVolatile() override;
    Reply *restoreFactoryDefaults() override;
    // The dictionary's (CANopen's hex INDEX:SUB for an empty one) unless a test gives another
    // format (e.g. parameter numbers).
    const AddressFormat &addressFormat() const override
    {
        return m_addressFormat ? *m_addressFormat : DeviceConnection::addressFormat();
    }
    void setAddressFormat(const AddressFormat &format) { m_addressFormat = &format; }

    // The object table (raw values), used while no model is set.
    void setValue(ObjectAddress address, const QVariant &raw) { m_objects.insert(address, raw); }
    QVariant value(ObjectAddress address) const { return m_objects.value(address); }
    // Requests go to these functions instead of the object table.
    void setModel(ReadFn read, WriteFn write);
    // Any object with Result<QVariant> read(ObjectAddress) and
    // Result<void> write(ObjectAddress, const QVariant &); it must outlive the connection.
    template<typename Model>
    void setModel(Model *model)
    {
        setModel([model](ObjectAddress a) { return model->read(a); },
                 [model](ObjectAddress a, const QVariant &v) { return model->write(a, v); });
    }

    // Timing. immediate: open, close and every answer happen inside the call (no event loop
    // needed). Otherwise they come from the event loop, answers after replyDelayMs.
    bool immediate = false;
    int replyDelayMs = 0;

    // Failure modes.
    // Every request for `address` fails with `error` until clearFailure().
    void setFailure(ObjectAddress address, const Error &error)
    {
        m_failures.insert(address, error);
    }
    void clearFailure(ObjectAddress address) { m_failures.remove(address); }
    // Requests for these objects get no answer: they fail as a timeout after
    // requestTimeoutMs() (at once when immediate), as a protocol engine would report it.
    QSet<ObjectAddress> silent;
    // Writes to these objects fail as a device refusal (SDO abort 08000022).
    QSet<ObjectAddress> rejectWrites;
    // Writes to these objects are acknowledged but never applied.
    QSet<ObjectAddress> ignoreWrites;
    // Every write is acknowledged and none is applied (a drive that never changes state).
    bool ignoreAllWrites = false;
    // A failed open: the next open() ends in Disconnected with this error.
    void refuseNextOpen(const Error &error) { m_refusal = error; }
    // The link breaks now: pending requests fail, state goes to Disconnected.
    void goAway();
    // The link breaks while the n-th request from now is pending (n >= 1; 0 = never).
    void goAwayDuringRequest(int n) { m_requestsUntilGone = n; }

    // Counters: every read and write request, answers outstanding, and the writes applied.
    int readCount = 0;
    int writeCount = 0;
    int inFlight = 0;
    int maxInFlight = 0;
    QList<std::pair<ObjectAddress, QVariant>> writes;

protected:
    void doOpen() override;
    void doClose() override;
    void doRead(Reply *reply, const ObjectDef *def) override;
    void doWrite(Reply *reply, const QVariant &raw, const ObjectDef *def) override;

private:
    void later(int delayMs, std::function<void()> action);
    // Runs answer(reply) after the reply delay (or now), unless a failure mode answers first.
    void answer(Reply *reply, std::function<void(Reply *)> answer);
    Result<QVariant> readValue(ObjectAddress address) const;
    Result<void> writeValue(ObjectAddress address, const QVariant &raw);

    QString m_protocolKey = QStringLiteral("fake");
    Capabilities m_capabilities;
    QHash<ObjectAddress, QVariant> m_objects;
    ReadFn m_read;
    WriteFn m_write;
    QHash<ObjectAddress, Error> m_failures;
    Error m_refusal;
    int m_requestsUntilGone = 0;
    const AddressFormat *m_addressFormat = nullptr;
};

} // namespace db::test
