#include "nmtmaster.h"

#include "canopenlogging.h"
#include "transport/canbus.h"

namespace db::canopen {

NmtMaster::NmtMaster(CanBus *bus, QObject *parent)
    : QObject(parent)
    , m_bus(bus)
{ }

QCanBusFrame NmtMaster::frame(NmtCommand command, NodeId node)
{
    QByteArray payload(2, '\0');
    payload[0] = char(command);
    payload[1] = char(node);
    return QCanBusFrame(cob::Nmt, payload);
}

QString NmtMaster::commandName(NmtCommand command)
{
    switch (command) {
    case NmtCommand::Start:
        return QStringLiteral("start");
    case NmtCommand::Stop:
        return QStringLiteral("stop");
    case NmtCommand::EnterPreOperational:
        return QStringLiteral("enter pre-operational");
    case NmtCommand::ResetNode:
        return QStringLiteral("reset node");
    case NmtCommand::ResetCommunication:
        return QStringLiteral("reset communication");
    }
    return QStringLiteral("command 0x%1").arg(quint8(command), 2, 16, QLatin1Char('0'));
}

bool NmtMaster::send(NmtCommand command, NodeId node)
{
    if (node > kMaxNodeId)
        return false;
    if (!m_bus->send(frame(command, node)))
        return false;
    qCInfo(lcCanopen).noquote() << "NMT" << commandName(command)
                                << (node == kAllNodes ? QStringLiteral("all nodes")
                                                      : QStringLiteral("node %1").arg(node));
    Q_EMIT commandSent(command, node);
    return true;
}

QString nmtStateName(NmtState state)
{
    switch (state) {
    case NmtState::BootUp:
        return QStringLiteral("boot-up");
    case NmtState::Stopped:
        return QStringLiteral("stopped");
    case NmtState::Operational:
        return QStringLiteral("operational");
    case NmtState::PreOperational:
        return QStringLiteral("pre-operational");
    case NmtState::Unknown:
        return QStringLiteral("unknown");
    }
    return QStringLiteral("state 0x%1").arg(quint8(state), 2, 16, QLatin1Char('0'));
}

} // namespace db::canopen
