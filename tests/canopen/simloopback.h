#pragma once

// Test helper: simulated nodes on a ScriptedCanBus. Every frame the master sends reaches every
// node at once; node frames come back to the master from the event loop (as from a real bus).

#include "canopen/device/simulatednode.h"
#include "resources/builtindescriptions.h"
#include "scriptedcanbus.h"

#include <QObject>

#include <memory>
#include <vector>

namespace db::test {

class SimLoopback
{
public:
    SimLoopback() { bus.open(); }

    // A node with the built-in test description (drivebench_testnode.json), started.
    canopen::SimulatedNode *addNode(canopen::NodeId id)
    {
        const auto dict = resources::builtinDescription(QStringLiteral("drivebench_testnode"));
        auto node = std::make_unique<canopen::SimulatedNode>(dict.valueOr(ObjectDictionary()), id);
        node->store()->set({ 0x1018, 4 }, quint32(0x1000 + id));
        for (const quint16 comm : { 0x1400, 0x1401, 0x1800, 0x1801 })
            node->store()->set({ comm, 1 }, node->store()->value({ comm, 1 }).toUInt() + id);
        attach(node.get());
        node->start();
        nodes.push_back(std::move(node));
        return nodes.back().get();
    }
    void attach(QObject *device)
    {
        if (auto *node = qobject_cast<canopen::SimulatedNode *>(device)) {
            QObject::connect(&bus, &ScriptedCanBus::frameWritten, node,
                             &canopen::SimulatedNode::receive);
            QObject::connect(node, &canopen::SimulatedNode::transmit, &bus,
                             [this](const QCanBusFrame &f) { bus.feedLater(f); });
        }
    }

    ScriptedCanBus bus;
    std::vector<std::unique_ptr<canopen::SimulatedNode>> nodes;
};

} // namespace db::test
