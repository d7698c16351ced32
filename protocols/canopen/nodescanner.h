#pragma once

// Node discovery: passive (boot-up and heartbeat through NodeMonitor) plus an
// active SDO probe of 1000h on a range of node ids, sent pipelined: the requests of a window
// (all 127 by default) go out at once, each with the SDO client's own timeout, so a full scan
// takes about one SDO timeout. Any answer, even an abort, shows a node. For each node found,
// 1018h.1-4 and 1008h are read (queued on the node's SDO channel, all nodes in parallel).
//
// Contracts: start() never blocks; finished() comes once per scan from the event loop, after
// every request has finished; nodes() is then the sorted result, including nodes only heard
// (heartbeat/boot-up) that did not answer SDO. The SDO client and monitor are not owned and
// must outlive the scanner.

#include "canopenids.h"

#include <QList>
#include <QMap>
#include <QObject>
#include <QSet>

namespace db::canopen {

class NodeMonitor;
class SdoClient;

struct NodeInfo
{
    NodeId id = 0;
    NmtState state = NmtState::Unknown; // from heartbeat/boot-up; Unknown if never heard
    bool answersSdo = false;
    quint32 deviceType = 0; // 1000h (0 when it answered with an abort)
    bool hasIdentity = false; // 1018h.1-4 read
    quint32 vendorId = 0;
    quint32 productCode = 0;
    quint32 revision = 0;
    quint32 serial = 0;
    QString name; // 1008h; empty when the node has none
    QStringList problems; // reads that failed, one readable line each

    // "  5  pre-operational  vendor 0x0000053B product 0x00000001 rev 0x00010000 serial
    // 0x00000005  "drivebench test node""
    QString toString() const;
};

class NodeScanner : public QObject
{
    Q_OBJECT
public:
    static constexpr int kDefaultWindow = kMaxNodeId; // every probe at once

    NodeScanner(SdoClient *sdo, NodeMonitor *monitor, QObject *parent = nullptr);

    void setRange(NodeId first, NodeId last);
    // Probes in flight at most (1..127).
    void setWindow(int requests) { m_window = qBound(1, requests, int(kMaxNodeId)); }
    // False (and nothing happens) while a scan runs.
    bool start();
    bool isRunning() const { return m_running; }
    QList<NodeInfo> nodes() const { return m_result; }

Q_SIGNALS:
    void nodeFound(const db::canopen::NodeInfo &node); // answered the probe (identity follows)
    void finished();

private:
    void launchProbes();
    void onProbe(NodeId id, bool found, quint32 deviceType);
    void readIdentity(NodeId id);
    void requestDone();

    SdoClient *m_sdo;
    NodeMonitor *m_monitor;
    NodeId m_first = kMinNodeId;
    NodeId m_last = kMaxNodeId;
    int m_window = kDefaultWindow;
    bool m_running = false;
    int m_nextId = 0;
    int m_outstanding = 0; // SDO requests not finished yet
    int m_probesInFlight = 0;
    QMap<NodeId, NodeInfo> m_found;
    QList<NodeInfo> m_result;
};

} // namespace db::canopen
