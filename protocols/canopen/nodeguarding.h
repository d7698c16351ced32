#pragma once

// Node guarding master (CiA 301 7.2.8.3.2.1): a remote frame on 700h + node every guard time
// for each guarded node, so that a node with a life time (100Ch x 100Dh) sees its master go away
// when the guard requests stop. The node's answers (state + toggle bit) reach the NodeMonitor
// like heartbeats. Requests go out only while the bus is open.

#include "canopenids.h"

#include <QObject>

#include <map>
#include <memory>

namespace db {
class CanBus;
}
class QTimer;

namespace db::canopen {

class NodeGuarding : public QObject
{
    Q_OBJECT
public:
    // The bus is not owned and must outlive this object.
    explicit NodeGuarding(CanBus *bus, QObject *parent = nullptr);
    ~NodeGuarding() override;

    // Starts (or re-times) guarding node every guardTimeMs; the first request goes out at once.
    void guard(NodeId node, int guardTimeMs);
    void unguard(NodeId node);
    bool isGuarding(NodeId node) const { return m_timers.contains(node); }

private:
    void request(NodeId node);

    CanBus *m_bus;
    std::map<NodeId, std::unique_ptr<QTimer>> m_timers;
};

} // namespace db::canopen
