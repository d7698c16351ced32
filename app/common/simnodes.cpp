#include "simnodes.h"

#include "canopen/device/simulatednode.h"
#include "description/devicedescription.h"
#include "resources/builtindescriptions.h"
#include "transport/device/slcanserver.h"
#include "transport/qtcanbus.h"
#include <QCoreApplication>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::common)
};
} // namespace

namespace db::app {

namespace {
constexpr int kVirtualCanOpenMs = 3000;
} // namespace

struct SimNodes::Private
{
    QList<canopen::SimulatedNode *> nodes; // owned by the SimNodes QObject
    std::unique_ptr<SlcanServer> slcan;
    std::unique_ptr<QtCanBus> virtualCan;
    bool started = false;
};

SimNodes::SimNodes(QObject *parent)
    : QObject(parent)
    , d(std::make_unique<Private>())
{ }

SimNodes::~SimNodes()
{
    qDeleteAll(d->nodes); // before the doors they are wired to
    d->nodes.clear();
}

Result<QList<quint8>> SimNodes::parseNodeList(const QString &text)
{
    QList<quint8> ids;
    for (const QString &item : text.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        bool ok = false;
        const uint id = item.trimmed().toUInt(&ok);
        if (!ok || id < 1 || id > 127)
            return Error(Error::Kind::InvalidArgument,
                         Tr::tr("'%1' is not a node id 1..127").arg(item.trimmed()));
        if (!ids.contains(quint8(id)))
            ids.append(quint8(id));
    }
    if (ids.isEmpty())
        return Error(Error::Kind::InvalidArgument, Tr::tr("no node ids given (e.g. 1,2,5)"));
    return ids;
}

Result<void> SimNodes::create(const SimNodesOptions &options)
{
    for (const quint8 id : options.nodes) {
        ObjectDictionary dictionary;
        if (options.descriptionFile.isEmpty()) {
            auto builtin = resources::builtinDescription(QStringLiteral("drivebench_testnode"));
            if (!builtin)
                return builtin.error();
            dictionary = builtin.value();
        } else {
            DescriptionOptions load;
            load.nodeId = id; // $NODEID in the file
            auto loaded = loadDeviceDescription(options.descriptionFile, load);
            if (!loaded)
                return loaded.error();
            dictionary = loaded->dictionary;
        }
        auto *node = new canopen::SimulatedNode(dictionary, id, this);
        if (options.descriptionFile.isEmpty()) {
            // Our test node states base COB-IDs; each node adds its id (CiA 301 7.3.5).
            canopen::ObjectValueStore *store = node->store();
            store->set({ 0x1018, 4 }, quint32(id));
            store->set({ 0x1014, 0 }, store->value({ 0x1014, 0 }).toUInt() + id);
            for (const quint16 comm : { 0x1400, 0x1401, 0x1800, 0x1801 })
                store->set({ comm, 1 }, store->value({ comm, 1 }).toUInt() + id);
        }
        node->setSdoNoReply(options.noReply.contains(id));
        d->nodes.append(node);
    }
    return {};
}

Result<void> SimNodes::startSlcan(quint16 port)
{
    d->slcan = std::make_unique<SlcanServer>();
    if (auto listening = d->slcan->listen(port); !listening)
        return listening;
    for (canopen::SimulatedNode *node : d->nodes) {
        connect(d->slcan.get(), &SlcanServer::frameReceived, node,
                &canopen::SimulatedNode::receive);
        connect(node, &canopen::SimulatedNode::transmit, d->slcan.get(), &SlcanServer::send);
    }
    if (!d->started) {
        d->started = true;
        for (canopen::SimulatedNode *node : d->nodes)
            node->start();
    }
    return {};
}

quint16 SimNodes::slcanPort() const
{
    return d->slcan ? d->slcan->port() : 0;
}

Result<void> SimNodes::startVirtualCan(const QString &interfaceName)
{
    d->virtualCan = std::make_unique<QtCanBus>(QStringLiteral("virtualcan"), interfaceName);
    QtCanBus *bus = d->virtualCan.get();
    if (auto opened = bus->openAndWait(kVirtualCanOpenMs); !opened)
        return opened.error();
    for (canopen::SimulatedNode *node : d->nodes)
        node->attach(bus);
    if (!d->started) {
        d->started = true;
        for (canopen::SimulatedNode *node : d->nodes)
            node->start();
    }
    return {};
}

QString SimNodes::describe() const
{
    QStringList ids;
    for (const canopen::SimulatedNode *node : d->nodes)
        ids.append(QString::number(node->nodeId()));
    return QStringLiteral("node%1 %2")
        .arg(ids.size() == 1 ? QString() : QStringLiteral("s"), ids.join(QLatin1String(", ")));
}

} // namespace db::app
