#pragma once

// The CAN networks open in one process, one per bus: connections to several nodes of the same bus
// (the same URI but for ?node= and the per-node options) share one CanNetwork and so one socket
// or CAN interface. The pool holds its networks weakly: a network lives as long as a connection
// (or another holder) keeps it.

#include "cannetwork.h"
#include "core/connectionuri.h"

#include <map>
#include <memory>

namespace db::canopen {

class CanNetworkPool
{
public:
    // The network of the bus `uri` names: the one already in use, or a new one with a closed bus
    // made by CanBusFactory. InvalidArgument when the URI names no bus, or names a bus in use at
    // another bitrate; the bus factory's own error otherwise.
    Result<std::shared_ptr<CanNetwork>> networkFor(const ConnectionUri &uri);

    // How a URI's bus is told apart: "slcan://127.0.0.1:15001", "virtualcan://can0" (pure).
    static QString busKey(const ConnectionUri &uri);
    // Networks still alive.
    int size() const;

private:
    mutable std::map<QString, std::weak_ptr<CanNetwork>> m_networks;
};

} // namespace db::canopen
