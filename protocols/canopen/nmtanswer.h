#pragma once

// Whether a node followed an NMT command (CiA 301 7.2.8.3.1). NMT commands are not answered
// by protocol; the node's heartbeat (700h + id) is: after start, stop or enter pre-operational
// its next heartbeats carry the new state, after a reset it sends a boot-up message. A node
// that sent no heartbeat before the command cannot confirm it (finished() says so, as not an
// error); a node that did and then stays silent or in another state did not follow.

#include "canopenids.h"
#include "core/error.h"

#include <QObject>
#include <QPointer>
#include <QTimer>

class QCanBusFrame;

namespace db {
class CanBus;
}

namespace db::canopen {

class NodeMonitor;

class NmtAnswer : public QObject
{
    Q_OBJECT
public:
    // How long a node with a heartbeat gets when its consumer time is unknown.
    static constexpr int kDefaultWaitMs = 3000;

    // Watches `node` (1..127) on `bus` from now on; `monitor` tells whether the node was heard
    // and its consumer time (the wait: that time, else kDefaultWaitMs). Neither is owned.
    NmtAnswer(CanBus *bus, const NodeMonitor *monitor, NmtCommand command, NodeId node,
              QObject *parent = nullptr);

    // The state a heartbeat shows once the command was followed (BootUp after a reset).
    static NmtState expectedState(NmtCommand command);
    bool isFinished() const { return m_finished; }
    bool confirmed() const { return m_confirmed; }
    // Why it is not confirmed: empty when confirmed; a note (no heartbeat to confirm with) or
    // the error (Timeout) otherwise.
    QString note() const { return m_note; }

Q_SIGNALS:
    // Once: ok, or the error naming what was heard instead (Error::Kind::Timeout).
    void finished(const db::Error &error);

private:
    void onFrame(const QCanBusFrame &frame);
    void finish(const Error &error, const QString &note = {});

    QPointer<CanBus> m_bus;
    NodeId m_node;
    NmtState m_expected;
    NmtState m_seen = NmtState::Unknown; // the last state heard since the command
    QTimer m_timer;
    bool m_finished = false;
    bool m_confirmed = false;
    QString m_note;
};

} // namespace db::canopen
