#include "protocols.h"

#include "refgo/refgoconnection.h"
#include "resources/builtindescriptions.h"

#include <QCoreApplication>

namespace db::app {

namespace {

ProtocolRegistry makeRegistry()
{
    ProtocolRegistry registry;
    registry.add({
        QStringLiteral("refgo"),
        QStringLiteral("refgo"),
        QCoreApplication::translate("protocols", "MovingCap RefGo (ASCII over TCP)"),
        QStringLiteral("refgo://HOST[:PORT]"),
        10001,
        [](const ConnectionUri &uri) -> std::unique_ptr<DeviceConnection> {
            auto connection = std::make_unique<refgo::RefgoConnection>(uri);
            connection->setDictionary(resources::movingCapDictionary());
            return connection;
        },
    });
    return registry;
}

} // namespace

const ProtocolRegistry &protocolRegistry()
{
    static const ProtocolRegistry registry = makeRegistry();
    return registry;
}

} // namespace db::app
