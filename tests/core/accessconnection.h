#pragma once

// Test helper: a DeviceConnection straight into in-process objects (a simulated MovingCap, a
// simulated CANopen node) through two functions, so the runners can be tested without a
// transport. Failure modes: reject (writes to these objects fail as a device error), ignore
// (writes accepted but not applied), silent (reads time out), goAway() (the link breaks).

#include "canopen/storesignatures.h"
#include "core/deviceconnection.h"

#include <QSet>

#include <functional>

namespace db::test {

class AccessConnection : public DeviceConnection
{
    Q_OBJECT
public:
    using ReadFn = std::function<Result<QVariant>(ObjectAddress)>;
    using WriteFn = std::function<Result<void>(ObjectAddress, const QVariant &)>;

    AccessConnection(const ObjectDictionary &dictionary, ReadFn read, WriteFn write,
                     QObject *parent = nullptr)
        : DeviceConnection(ConnectionUri::parse(QStringLiteral("refgo://127.0.0.1")).value(),
                           parent)
        , m_read(std::move(read))
        , m_write(std::move(write))
    {
        setDictionary(dictionary);
    }

    QString protocolKey() const override { return QStringLiteral("test"); }
    // Stores and restores defaults as a CiA 301 device does (1010h / 1011h).
    Capabilities capabilities() const override { return Capability::StoreNonVolatile; }
    Reply *storeNonVolatile() override
    {
        return write(canopen::store::kStoreAll,
                     QVariant::fromValue<qulonglong>(canopen::store::kSaveSignature));
    }
    Reply *restoreFactoryDefaults() override
    {
        return write(canopen::store::kRestoreDefaultsAll,
                     QVariant::fromValue<qulonglong>(canopen::store::kLoadSignature));
    }

    QSet<ObjectAddress> reject;
    QSet<ObjectAddress> silent; // reads fail at once as timeouts (the engine's time limit)
    QSet<ObjectAddress> ignore;
    int reads = 0;
    int writes = 0;

    void goAway()
    {
        setState(State::Disconnected,
                 Error(Error::Kind::Disconnected, QStringLiteral("simulated link broke")));
    }

protected:
    void doOpen() override { setState(State::Connected); }
    void doClose() override { setState(State::Disconnected); }
    void doRead(Reply *reply, const ObjectDef *) override
    {
        ++reads;
        if (silent.contains(reply->address())) {
            reply->fail(Error(Error::Kind::Timeout, QStringLiteral("no answer within 1000 ms")));
            return;
        }
        auto r = m_read(reply->address());
        if (r)
            reply->finish(r.value());
        else
            reply->fail(r.error());
    }
    void doWrite(Reply *reply, const QVariant &raw, const ObjectDef *) override
    {
        ++writes;
        if (reject.contains(reply->address())) {
            reply->fail(Error(Error::Kind::DeviceError,
                              QStringLiteral("SDO abort 08000022: present device state"),
                              0x08000022));
            return;
        }
        if (ignore.contains(reply->address())) {
            reply->finish();
            return;
        }
        auto r = m_write(reply->address(), raw);
        if (r)
            reply->finish();
        else
            reply->fail(r.error());
    }

private:
    ReadFn m_read;
    WriteFn m_write;
};

} // namespace db::test
