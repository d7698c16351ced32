#pragma once

#include "core/deviceconnection.h"

#include <QHash>

namespace db::test {

// A DeviceConnection test double for widget tests: answers reads and writes from a scripted
// object table, after replyDelayMs on the event loop. Requests can be made to fail per object,
// and the device can go away. It counts requests and the largest number in flight, so tests
// can check that a poller never floods the device.
class FakeConnection : public DeviceConnection
{
    Q_OBJECT
public:
    explicit FakeConnection(const QString &uri = QStringLiteral("fake://device"),
                            QObject *parent = nullptr);

    QString protocolKey() const override { return QStringLiteral("fake"); }
    // CANopen's hex INDEX:SUB unless a test gives another format (e.g. parameter numbers).
    const AddressFormat &addressFormat() const override { return *m_addressFormat; }
    void setAddressFormat(const AddressFormat &format) { m_addressFormat = &format; }

    // The object table (raw values).
    void setValue(ObjectAddress address, const QVariant &raw) { m_objects.insert(address, raw); }
    QVariant value(ObjectAddress address) const { return m_objects.value(address); }
    // Every request for `address` fails with `error` until clearFailure().
    void setFailure(ObjectAddress address, const Error &error)
    {
        m_failures.insert(address, error);
    }
    void clearFailure(ObjectAddress address) { m_failures.remove(address); }
    // A failed open: the next open() ends in Disconnected with this error.
    void refuseNextOpen(const Error &error) { m_refusal = error; }
    // The link breaks: pending requests fail, state goes to Disconnected.
    void goAway();

    int replyDelayMs = 0;
    int readCount = 0;
    int inFlight = 0;
    int maxInFlight = 0;
    QList<std::pair<ObjectAddress, QVariant>> writes;

protected:
    void doOpen() override;
    void doClose() override;
    void doRead(Reply *reply, const ObjectDef *def) override;
    void doWrite(Reply *reply, const QVariant &raw, const ObjectDef *def) override;

private:
    void answerLater(Reply *reply, std::function<void(Reply *)> answer);

    QHash<ObjectAddress, QVariant> m_objects;
    QHash<ObjectAddress, Error> m_failures;
    Error m_refusal;
    const AddressFormat *m_addressFormat = &AddressFormat::canopen();
};

} // namespace db::test
