#pragma once

// Creates the CanBus a CANopen URI names. Only app/ (the composition root) and tests call this;
// everything else receives a CanBus* through its constructor (ARCHITECTURE.md habit 7).
//   canopen+socketcan://IFACE?node=N&bitrate=B   QtCanBus("socketcan", IFACE, B)
//   canopen+virtualcan://IFACE?node=N            QtCanBus("virtualcan", IFACE)
//   canopen+slcan://HOST[:PORT]?node=N[&bitrate=B] SlcanBus over a TcpStream, default port 15001
//   canopen+<plugin>://IFACE?...                 any other installed Qt CAN plugin

#include "core/connectionuri.h"

namespace db {
class CanBus;
}

namespace db::canopen {

class CanBusFactory
{
public:
    static constexpr int kDefaultSlcanPort = 15001;
    static constexpr int kDefaultSlcanBitrate = 125000;

    // A new, closed bus; the caller owns it (parent may be null). InvalidArgument for a scheme
    // that is not canopen+..., a missing host/interface or a bad bitrate; NotSupported when the
    // build has no SLCAN transport.
    static Result<CanBus *> makeBus(const ConnectionUri &uri, QObject *parent = nullptr);
    // Whether the interface a Qt CAN plugin URI names is there (QtCanBus::checkInterface);
    // nothing to check for SLCAN, whose host answers or not only when the bus opens.
    static Result<void> checkInterface(const ConnectionUri &uri);
    // "socketcan" for "canopen+socketcan"; empty when the scheme is not a CANopen one.
    static QString transportOf(const ConnectionUri &uri);
    // The ?bitrate= of a URI (1000..8000000), 0 when not given; InvalidArgument names a bad one.
    static Result<int> bitrateOf(const ConnectionUri &uri);
};

} // namespace db::canopen
