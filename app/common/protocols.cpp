#include "protocols.h"

#include "canopen/canbusfactory.h"
#include "canopen/cannetworkpool.h"
#include "canopen/canopenconnection.h"
#include "cia402/cia402statussource.h"
#include "description/devicedescription.h"
#include "descriptions.h"
#include "devices/bonfiglioli/acudescription.h"
#include "devices/bonfiglioli/acustatussource.h"
#include "refgo/refgoconnection.h"
#include "resources/builtindescriptions.h"
#include "vabus/vabusconnection.h"

#include <QCanBus>
#include <QCoreApplication>
#include <QDebug>

namespace db::app {

namespace {

struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(protocols)
};

// The dictionary a CANopen connection starts with: the file named by ?eds=PATH (EDS, DCF, XDD,
// XDC or our JSON), else the MovingCap description for node 50 behind SLCAN (the MovingCap ETH
// CANopen door, movingcap.md 4), else an empty one, which the connection replaces with the
// description library's match for the node's identity once it has read 1018h.
Result<ObjectDictionary> canopenDictionary(const ConnectionUri &uri)
{
    const QString eds = uri.queryValue(QStringLiteral("eds"));
    if (!eds.isEmpty()) {
        const auto node = canopen::CanopenConnection::nodeFromUri(uri);
        DescriptionOptions options;
        if (node)
            options.nodeId = *node;
        auto loaded = loadDeviceDescription(eds, options);
        if (!loaded)
            return loaded.error().prefixed(QStringLiteral("eds=%1").arg(eds));
        return loaded->dictionary;
    }
    if (uri.scheme() == QLatin1String("canopen+slcan")
        && uri.queryValue(QStringLiteral("node")) == QLatin1String("50"))
        return resources::movingCapDictionary();
    return ObjectDictionary();
}

// Cheap: no file is read, nothing is opened (the connection dialog checks as the user types).
Result<void> checkCanopen(const ConnectionUri &uri)
{
    if (auto node = canopen::CanopenConnection::nodeFromUri(uri); !node)
        return node.error();
    if (auto tool = canopen::CanopenConnection::toolNodeFromUri(uri); !tool)
        return tool.error();
    if (uri.host().isEmpty())
        return Error(Error::Kind::InvalidArgument,
                     Tr::tr("%1 names no interface or host").arg(uri.toString()));
    if (auto bitrate = canopen::CanBusFactory::bitrateOf(uri); !bitrate)
        return bitrate.error();
    if (auto mode =
            canopen::CanopenConnection::sdoModeFromText(uri.queryValue(QStringLiteral("sdo")));
        !mode)
        return mode.error();
    return {};
}

Result<void> prepareCanopen(ConnectionPlan &plan)
{
    // A missing interface is named now: some plugins would open another one instead.
    if (auto present = canopen::CanBusFactory::checkInterface(plan.uri); !present)
        return present.error();
    auto dictionary = canopenDictionary(plan.uri);
    if (!dictionary)
        return dictionary.error();
    plan.dictionary = std::move(dictionary).value();
    plan.hasDictionary = true;
    return {};
}

// Every CANopen connection of this process: connections to nodes of the same bus share its
// network (one socket or interface, one NMT master and node monitor).
canopen::CanNetworkPool &networks()
{
    static canopen::CanNetworkPool pool;
    return pool;
}

using DescriptionChoice = canopen::CanopenConnection::DescriptionChoice;

// The description library's answer for a node that did not come with one.
DescriptionChoice chooseDescription(const IdentityNumbers &identity, quint8 node)
{
    DescriptionLibrary &library = descriptionLibrary();
    library.setFolder(descriptionFolder()); // the user may have added files since
    library.rescan();
    for (const QString &warning : library.warnings())
        qWarning().noquote() << "description library:" << warning;
    const auto entry = library.match(identity);
    if (!entry) {
        const QString folder = library.folder();
        return { std::nullopt,
                 folder.isEmpty()
                     ? Tr::tr("no description matches node %1 (%2); its objects are read by "
                              "index (give ?eds=FILE)")
                           .arg(node)
                           .arg(identity.toString())
                     : Tr::tr("no description matches node %1 (%2); its objects are read by "
                              "index (give ?eds=FILE, or put the device's EDS into %3)")
                           .arg(node)
                           .arg(identity.toString(), folder) };
    }
    auto loaded = entry->load(node);
    if (!loaded)
        return { std::nullopt,
                 Tr::tr("the description %1 for node %2 does not load: %3")
                     .arg(entry->origin)
                     .arg(node)
                     .arg(loaded.error().toString()) };
    return { loaded.value(),
             Tr::tr("description for node %1 (%2): %3 (%4)")
                 .arg(node)
                 .arg(identity.toString(), entry->name, entry->origin) };
}

Result<std::unique_ptr<DeviceConnection>> makeCanopen(const ConnectionPlan &plan)
{
    auto network = networks().networkFor(plan.uri);
    if (!network)
        return network.error();
    auto connection = std::make_unique<canopen::CanopenConnection>(plan.uri, network.value());
    connection->setDictionary(plan.dictionary);
    if (plan.dictionary.isEmpty())
        connection->setDescriptionChooser(chooseDescription);
    // Polls only what the description has, also one chosen later from the device's identity.
    connection->setStatusSource(new cia402::Cia402StatusSource(connection.get()));
    return std::unique_ptr<DeviceConnection>(std::move(connection));
}

ProtocolInfo canopenProtocol(const QString &transport, const QString &title, const QString &pattern,
                             int defaultPort)
{
    return { QStringLiteral("canopen+") + transport,
             QStringLiteral("canopen"),
             title,
             pattern,
             defaultPort,
             makeCanopen,
             checkCanopen,
             prepareCanopen };
}

ProtocolRegistry makeRegistry()
{
    ProtocolRegistry registry;
    registry.add({
        QStringLiteral("refgo"),
        QStringLiteral("refgo"),
        Tr::tr("MovingCap RefGo (ASCII over TCP)"),
        QStringLiteral("refgo://HOST[:PORT]"),
        refgo::RefgoConnection::kDefaultPort,
        [](const ConnectionPlan &plan) -> Result<std::unique_ptr<DeviceConnection>> {
            auto connection = std::make_unique<refgo::RefgoConnection>(plan.uri);
            connection->setDictionary(resources::movingCapDictionary());
            connection->setStatusSource(new cia402::Cia402StatusSource(connection.get()));
            return std::unique_ptr<DeviceConnection>(std::move(connection));
        },
        {},
        {},
    });
    registry.add({
        .scheme = QStringLiteral("vabus"),
        .key = QStringLiteral("vabus"),
        .title = Tr::tr("Bonfiglioli ACTIVE Cube over VABus/TCP"),
        .uriPattern = QStringLiteral("vabus://HOST[:PORT][?sys=N][&ram]"),
        .defaultPort = vabus::VabusConnection::kDefaultPort,
        .create = [](const ConnectionPlan &plan) -> Result<std::unique_ptr<DeviceConnection>> {
            auto connection = std::make_unique<vabus::VabusConnection>(plan.uri);
            connection->setDictionary(plan.hasDictionary ? plan.dictionary
                                                         : bonfiglioli::acuDictionary());
            connection->setStatusSource(new bonfiglioli::AcuStatusSource(connection.get()));
            return std::unique_ptr<DeviceConnection>(std::move(connection));
        },
        .check = vabus::VabusConnection::checkUri,
        .prepare = {},
        .addressFormat = &AddressFormat::parameter(),
    });
    registry.add(canopenProtocol(QStringLiteral("slcan"),
                                 Tr::tr("CANopen over SLCAN in TCP (MovingCap ETH: node 50)"),
                                 QStringLiteral("canopen+slcan://HOST[:PORT]?node=N[&eds=FILE]"),
                                 canopen::CanBusFactory::kDefaultSlcanPort));
    // Every Qt CAN plugin installed on this machine (socketcan, virtualcan, peakcan, ...).
    for (const QString &plugin : QCanBus::instance()->plugins()) {
        registry.add(canopenProtocol(
            plugin, Tr::tr("CANopen over Qt CAN plugin '%1'").arg(plugin),
            QStringLiteral("canopen+%1://IFACE?node=N[&bitrate=B][&eds=FILE]").arg(plugin), -1));
    }
    return registry;
}

} // namespace

const ProtocolRegistry &protocolRegistry()
{
    static const ProtocolRegistry registry = makeRegistry();
    return registry;
}

} // namespace db::app
