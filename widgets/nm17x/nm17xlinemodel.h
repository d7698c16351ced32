#pragma once

// The table of the NM17x line panel: one row per display (node, variant, serial, setpoint,
// position, correction, status, errors), filled by Nm17xLine::findDisplays() and kept live from the
// displays' TxPDO1/TxPDO2. TxPDO2 carries only the error bit of the status; when it comes on,
// the model reads the display's error word (204Eh:02) by SDO. Until that read has answered the
// Errors column says so (never "-", which means no error); a failed read is named there and
// tried again a second later. Nothing is written back.

#include "devices/nm17x/nm17xline.h"

#include <QAbstractTableModel>
#include <QDeadlineTimer>
#include <QHash>
#include <QPointer>
#include <QSet>

namespace db::widgets {

class Nm17xLineModel : public QAbstractTableModel
{
    Q_OBJECT
public:
    enum Column {
        Node,
        Variant,
        Serial,
        Setpoint,
        Position,
        Correction,
        Status,
        Errors,
        ColumnCount
    };

    explicit Nm17xLineModel(QObject *parent = nullptr);

    // The line whose PDOs update the rows (not owned; nullptr detaches).
    void setLine(nm17x::Nm17xLine *line);
    void setDisplays(const QList<nm17x::DisplayState> &displays);
    const QList<nm17x::DisplayState> &displays() const { return m_rows; }
    // The setpoint last sent to a node from this panel (shown until the next one).
    void setSetpoint(canopen::NodeId node, qint32 value);
    // The row of a node, -1 when it is not listed.
    int rowOf(canopen::NodeId node) const;

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

private:
    void update(canopen::NodeId node, const std::function<void(nm17x::DisplayState &)> &change);
    void readErrors(canopen::NodeId node);
    // The row's cells again (what the model knows about it changed, not the display's state).
    void refresh(canopen::NodeId node);

    QList<nm17x::DisplayState> m_rows;
    QList<qint16> m_corrections; // from TxPDO2, per row
    QHash<canopen::NodeId, qint32> m_setpoints; // sent from the panel
    QMetaObject::Connection m_pdo1;
    QMetaObject::Connection m_pdo2;
    QPointer<nm17x::Nm17xLine> m_line;
    QSet<canopen::NodeId> m_readingErrors;
    struct ReadFailure
    {
        QString cause;
        QDeadlineTimer retry;
    };
    QHash<canopen::NodeId, ReadFailure> m_errorReadFailures; // the last read of 204Eh:02 failed
};

} // namespace db::widgets
