#pragma once

// Test rig: the simulated MovingCap (DemoDrive, real time) reached in-process ("sim"), over RefGo
// on loopback ("refgo") or over CANopen SDO through the SLCAN door ("canopen").

#include "common/demodrive.h"
#include "common/protocols.h"
#include "resources/builtindescriptions.h"
#include "simconnection.h"

#include <QSignalSpy>
#include <QTest>

#include <memory>

namespace db::test {

struct Rig
{
    std::unique_ptr<app::DemoDrive> demo;
    std::shared_ptr<DeviceConnection> connection;
    SimConnection *sim = nullptr; // set for "sim"

    sim::MovingCapDrive &drive() { return demo->drive(); }
};

inline std::unique_ptr<Rig> makeRig(const QString &kind,
                                    const QHash<ObjectAddress, QVariant> &initial = {})
{
    auto rig = std::make_unique<Rig>();
    rig->demo = std::make_unique<app::DemoDrive>(initial);
    if (kind == QLatin1String("sim")) {
        auto c = std::make_shared<SimConnection>(&rig->demo->drive());
        rig->sim = c.get();
        rig->connection = c;
    } else {
        QString uri;
        if (kind == QLatin1String("refgo")) {
            if (!rig->demo->startRefgo())
                return nullptr;
            uri = rig->demo->refgoUri();
        } else {
            if (!rig->demo->startSlcan())
                return nullptr;
            uri = rig->demo->slcanUri();
        }
        auto c = app::protocolRegistry().create(uri);
        if (!c)
            return nullptr;
        rig->connection = c.value();
        rig->connection->setDictionary(resources::movingCapDictionary());
    }
    rig->connection->open();
    if (!QTest::qWaitFor([&] { return rig->connection->isConnected(); }, 5000))
        return nullptr;
    return rig;
}

// Waits for a reply (owned here) and returns its result.
inline Result<QVariant> awaitReply(Reply *reply, int timeoutMs = 5000)
{
    std::unique_ptr<Reply> owner(reply);
    QSignalSpy spy(reply, &Reply::finished);
    if (!reply->isFinished() || spy.isEmpty())
        spy.wait(timeoutMs);
    if (!reply->isFinished())
        return Error(Error::Kind::Timeout, QStringLiteral("test: reply did not finish"));
    return reply->result();
}

} // namespace db::test
