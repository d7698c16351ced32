#pragma once

// The PDO configuration of one node as a table: one row per RPDO and TPDO with enabled, COB-ID,
// transmission type, inhibit time, event timer and mapping ("6041:0/16 6064:0/32"). Read asks
// the node (PdoClient::readAll, the numbers its description has); the user edits cells; Write
// sends the rows that differ from what was read, one PDO after the other, each in the safe order
// of PdoClient::configure (disable the PDO, disable the mapping, write the entries, enable), then
// reads back. A row that does not parse is named with its problem and nothing is written.

#include "canopen/canopenids.h"
#include "canopen/pdomapping.h"
#include "core/result.h"

#include <QPointer>
#include <QWidget>

class QLabel;
class QPushButton;
class QTableWidget;

namespace db {
class ChangeLog;
}
namespace db::canopen {
class CanNetwork;
class PdoClient;
} // namespace db::canopen

namespace db::widgets {

class PdoPanel : public QWidget
{
    Q_OBJECT
public:
    enum Column { Pdo, Enabled, CobId, Type, Inhibit, Event, Mapping, ColumnCount };

    explicit PdoPanel(QWidget *parent = nullptr);
    ~PdoPanel() override;

    // Not owned; nullptr detaches. The table empties when the network or node changes.
    void setNetwork(canopen::CanNetwork *network);
    void setNode(canopen::NodeId node);
    canopen::NodeId node() const { return m_node; }
    // Every PDO written goes to this log (old and new configuration, outcome). Not owned.
    void setChangeLog(ChangeLog *log);

    QTableWidget *table() const { return m_table; }
    // As read from the node (the last read).
    QList<canopen::PdoConfig> configs() const { return m_configs; }
    // The table's rows as configurations; InvalidArgument names the PDO and the cell.
    Result<QList<canopen::PdoConfig>> edited() const;
    bool isBusy() const { return m_busy; }
    QString status() const;

    // "6041:0/16 6064:0/32" and back; bits may be left out for objects the dictionary describes.
    static QString mappingText(const QList<canopen::PdoMappingEntry> &entries);
    static Result<QList<canopen::PdoMappingEntry>> parseMapping(const QString &text,
                                                                const ObjectDictionary &dictionary);

public Q_SLOTS:
    // False while busy, without a node or while the bus is closed; readFinished() follows.
    bool read();
    // False while busy, when a row does not parse or nothing changed; writeFinished() follows.
    bool write();

Q_SIGNALS:
    void readFinished(bool ok);
    void writeFinished(bool ok);

private:
    void fill(const QList<canopen::PdoConfig> &configs);
    // The rest of a write to `node` (kept when another node is selected meanwhile).
    void writeNext(canopen::NodeId node, QList<canopen::PdoConfig> todo, int written);
    void setBusy(bool busy);
    void showStatus(const QString &text, bool error);
    ObjectDictionary dictionary() const;

    QPointer<canopen::CanNetwork> m_network;
    QPointer<ChangeLog> m_changeLog;
    canopen::PdoClient *m_client = nullptr;
    canopen::NodeId m_node = 0;
    QList<canopen::PdoConfig> m_configs;
    bool m_busy = false;
    bool m_filling = false;
    QLabel *m_title;
    QPushButton *m_readButton;
    QPushButton *m_writeButton;
    QTableWidget *m_table;
    QLabel *m_status;
};

} // namespace db::widgets
