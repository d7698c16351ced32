#include "nodeguarding.h"

#include "transport/canbus.h"

#include <QCanBusFrame>
#include <QTimer>

namespace db::canopen {

NodeGuarding::NodeGuarding(CanBus *bus, QObject *parent)
    : QObject(parent)
    , m_bus(bus)
{ }

NodeGuarding::~NodeGuarding() = default;

void NodeGuarding::guard(NodeId node, int guardTimeMs)
{
    auto &timer = m_timers[node];
    if (!timer) {
        timer = std::make_unique<QTimer>();
        timer->setTimerType(Qt::PreciseTimer);
        connect(timer.get(), &QTimer::timeout, this, [this, node] { request(node); });
    }
    timer->start(qMax(1, guardTimeMs));
    request(node);
}

void NodeGuarding::unguard(NodeId node)
{
    m_timers.erase(node);
}

void NodeGuarding::request(NodeId node)
{
    if (!m_bus->isOpen())
        return;
    QCanBusFrame rtr(cob::heartbeat(node), QByteArray());
    rtr.setFrameType(QCanBusFrame::RemoteRequestFrame);
    m_bus->send(rtr);
}

} // namespace db::canopen
