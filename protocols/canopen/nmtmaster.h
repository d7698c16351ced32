#pragma once

// NMT master (CiA 301 7.2.8.3.1): unconfirmed commands on COB 000h, [command, node], node 0 =
// every node. Watch the result with NodeMonitor (heartbeat / boot-up).

#include "canopenids.h"

#include <QCanBusFrame>
#include <QObject>

namespace db {
class CanBus;
}

namespace db::canopen {

class NmtMaster : public QObject
{
    Q_OBJECT
public:
    static constexpr NodeId kAllNodes = 0;

    // The bus is not owned and must outlive the master.
    explicit NmtMaster(CanBus *bus, QObject *parent = nullptr);

    // The 2-byte NMT frame (pure).
    static QCanBusFrame frame(NmtCommand command, NodeId node);
    static QString commandName(NmtCommand command); // "start", "reset node", ...

    // False when the bus is not open or the node id is not 0..127. node 0 = broadcast.
    bool send(NmtCommand command, NodeId node);
    bool start(NodeId node = kAllNodes) { return send(NmtCommand::Start, node); }
    bool stop(NodeId node = kAllNodes) { return send(NmtCommand::Stop, node); }
    bool enterPreOperational(NodeId node = kAllNodes)
    {
        return send(NmtCommand::EnterPreOperational, node);
    }
    bool resetNode(NodeId node = kAllNodes) { return send(NmtCommand::ResetNode, node); }
    bool resetCommunication(NodeId node = kAllNodes)
    {
        return send(NmtCommand::ResetCommunication, node);
    }

Q_SIGNALS:
    void commandSent(db::canopen::NmtCommand command, db::canopen::NodeId node);

private:
    CanBus *m_bus;
};

QString nmtStateName(NmtState state); // "operational", "pre-operational", ...

} // namespace db::canopen
