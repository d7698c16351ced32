#pragma once

// Test rig: the simulated MovingCap (DemoDrive, real time) reached in-process ("sim", through a
// FakeConnection that answers at once), over RefGo on loopback ("refgo") or over CANopen SDO
// through the SLCAN door ("canopen"). Header-only: tests that use it link drivebench_appcommon,
// drivebench_movingcap_sim and drivebench_resources.

#include "common/demodrive.h"
#include "common/protocols.h"
#include "devices/movingcap/movingcapdrive.h"
#include "fakeconnection.h"
#include "resources/builtindescriptions.h"
#include "wait.h"

#include <QSignalSpy>
#include <QTest>

#include <memory>

namespace db::test {

struct Rig
{
    std::unique_ptr<app::DemoDrive> demo;
    std::shared_ptr<DeviceConnection> connection;
    FakeConnection *sim = nullptr; // set for "sim"

    sim::MovingCapDrive &drive() { return demo->drive(); }
};

inline std::unique_ptr<Rig> makeRig(const QString &kind,
                                    const QHash<ObjectAddress, QVariant> &initial = {})
{
    auto rig = std::make_unique<Rig>();
    rig->demo = std::make_unique<app::DemoDrive>(initial);
    if (kind == QLatin1String("sim")) {
        auto c = std::make_shared<FakeConnection>(QStringLiteral("refgo://127.0.0.1"));
        c->setProtocolKey(QStringLiteral("sim"));
        c->setDictionary(rig->demo->drive().dictionary());
        c->setModel(&rig->demo->drive());
        c->immediate = true;
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
    if (!waitUntil(rig->connection.get(), &DeviceConnection::stateChanged,
                   [&] { return rig->connection->isConnected(); }))
        return nullptr;
    return rig;
}

} // namespace db::test
