#pragma once

#include "core/result.h"

#include <QList>
#include <QObject>

#include <memory>

namespace db::app {

// The simulated CANopen nodes of `drivebench-sim canopen`: a set of SimulatedNodes driven by one
// device description (by default our test node, resources/devices/drivebench_testnode.json),
// served on SLCAN-over-TCP (127.0.0.1) and/or a Qt virtualcan interface. Each node gets its own
// serial number (1018h.4 = node id) and node-id-based COB-IDs (EMCY, PDOs).
struct SimNodesOptions
{
    QList<quint8> nodes; // 1..127
    QString descriptionFile; // EDS/DCF/XDD/XDC/JSON; empty = the built-in test node
    QList<quint8> noReply; // nodes whose SDO server stays silent (failure mode)
};

class SimNodes : public QObject
{
    Q_OBJECT
public:
    explicit SimNodes(QObject *parent = nullptr);
    ~SimNodes() override;

    // Builds the nodes (boot-up follows once a door is open). InvalidArgument / Io for bad ids
    // or an unreadable description.
    Result<void> create(const SimNodesOptions &options);
    // SLCAN over TCP on 127.0.0.1:port (0 = chosen by the OS).
    Result<void> startSlcan(quint16 port = 0);
    quint16 slcanPort() const;
    // Joins the Qt virtualcan interface (e.g. "can0"); waits for it to open (up to 3 s).
    Result<void> startVirtualCan(const QString &interfaceName);
    // "node 1, 2, 5"
    QString describe() const;

    // "1,2,5" -> {1, 2, 5}; InvalidArgument names the bad item.
    static Result<QList<quint8>> parseNodeList(const QString &text);

private:
    struct Private;
    std::unique_ptr<Private> d;
};

} // namespace db::app
