#include "nm17xlinemodel.h"

#include "core/reply.h"
#include "devices/nm17x/nm17xcodes.h"

#include <QTimer>

namespace db::widgets {

using namespace db::nm17x;

namespace {
// After a failed read of the error word, the next one waits at least this long (TxPDO2 may
// come every few milliseconds; a display that does not answer would keep its SDO channel busy).
constexpr int kErrorReadRetryMs = 1000;
} // namespace

Nm17xLineModel::Nm17xLineModel(QObject *parent)
    : QAbstractTableModel(parent)
{ }

void Nm17xLineModel::setLine(Nm17xLine *line)
{
    disconnect(m_pdo1);
    disconnect(m_pdo2);
    m_line = line;
    m_readingErrors.clear();
    m_errorReadFailures.clear();
    if (!line)
        return;
    m_pdo1 = connect(line, &Nm17xLine::tpdo1, this, [this](canopen::NodeId node, const Tpdo1 &p) {
        update(node, [&p](DisplayState &s) {
            s.position = p.position;
            s.status = p.status;
            s.errors = p.errors;
        });
    });
    m_pdo2 = connect(line, &Nm17xLine::tpdo2, this, [this](canopen::NodeId node, const Tpdo2 &p) {
        const int row = rowOf(node);
        if (row < 0)
            return;
        m_corrections[row] = p.correction;
        const bool error = p.status & status::Error;
        const bool errorKnown = m_rows.at(row).errors != 0;
        update(node, [&p, error](DisplayState &s) {
            s.position = p.position;
            s.status = p.status;
            if (!error)
                s.errors = 0;
        });
        if (error && !errorKnown)
            readErrors(node);
    });
}

void Nm17xLineModel::readErrors(canopen::NodeId node)
{
    if (!m_line || m_readingErrors.contains(node))
        return;
    const auto failed = m_errorReadFailures.constFind(node);
    if (failed != m_errorReadFailures.cend() && !failed->retry.hasExpired())
        return;
    m_readingErrors.insert(node);
    refresh(node); // "reading"
    Reply *reply = m_line->read(node, { 0x204E, 2 });
    connect(reply, &Reply::finished, this, [this, reply, node] {
        reply->deleteLater();
        m_readingErrors.remove(node);
        if (!reply->ok()) {
            m_errorReadFailures.insert(
                node,
                { tr("reading the error word 204Eh:02: %1").arg(reply->error().toString()),
                  QDeadlineTimer(kErrorReadRetryMs) });
            refresh(node);
            // Displays send their PDOs on change: do not wait for the next one to try again.
            QTimer::singleShot(kErrorReadRetryMs, this, [this, node] {
                const int row = rowOf(node);
                if (row >= 0 && (m_rows.at(row).status & status::Error) && !m_rows.at(row).errors)
                    readErrors(node);
            });
            return;
        }
        m_errorReadFailures.remove(node);
        const auto errors = quint16(reply->value().toUInt());
        update(node, [errors](DisplayState &s) {
            if (s.status & status::Error)
                s.errors = errors;
        });
    });
}

void Nm17xLineModel::setDisplays(const QList<DisplayState> &displays)
{
    beginResetModel();
    m_rows = displays;
    m_errorReadFailures.clear();
    m_corrections = QList<qint16>(displays.size(), 0);
    endResetModel();
}

void Nm17xLineModel::setSetpoint(canopen::NodeId node, qint32 value)
{
    m_setpoints.insert(node, value);
    const int row = rowOf(node);
    if (row >= 0)
        Q_EMIT dataChanged(index(row, Setpoint), index(row, Setpoint));
}

int Nm17xLineModel::rowOf(canopen::NodeId node) const
{
    for (int i = 0; i < m_rows.size(); ++i) {
        if (m_rows.at(i).node == node)
            return i;
    }
    return -1;
}

void Nm17xLineModel::update(canopen::NodeId node, const std::function<void(DisplayState &)> &change)
{
    const int row = rowOf(node);
    if (row < 0)
        return;
    change(m_rows[row]);
    Q_EMIT dataChanged(index(row, Position), index(row, Errors));
}

void Nm17xLineModel::refresh(canopen::NodeId node)
{
    update(node, [](DisplayState &) {});
}

int Nm17xLineModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_rows.size());
}

int Nm17xLineModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant Nm17xLineModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() >= m_rows.size())
        return {};
    const DisplayState &s = m_rows.at(index.row());
    if (role == Qt::ToolTipRole && index.column() == Errors) {
        if (s.errors == 0 && (s.status & status::Error))
            return m_errorReadFailures.value(s.node).cause;
        QStringList remedies;
        for (const DisplayError &e : activeErrors(s.errors))
            remedies.append(QStringLiteral("%1: %2").arg(e.code, e.remedy));
        return remedies.join(u'\n');
    }
    if (role == Qt::TextAlignmentRole
        && (index.column() == Position || index.column() == Correction))
        return int(Qt::AlignRight | Qt::AlignVCenter);
    if (role != Qt::DisplayRole)
        return {};
    switch (index.column()) {
    case Node:
        return s.node;
    case Variant:
        return variantName(s.variant);
    case Serial:
        return QStringLiteral("0x%1").arg(
            QString::number(s.serial, 16).toUpper().rightJustified(8, u'0'));
    case Setpoint:
        return m_setpoints.contains(s.node) ? formatPosition(m_setpoints.value(s.node), s.inch)
                                            : QStringLiteral("-");
    case Position:
        return formatPosition(s.position, s.inch);
    case Correction:
        return formatPosition(m_corrections.value(index.row()), s.inch);
    case Status: {
        // The operator's view: the flags, with the direction instead of the output pins.
        constexpr quint16 kPins = status::In1Left | status::In2Right | status::In3 | status::In4;
        QString text = statusText(s.status & ~kPins);
        if (s.status & status::In2Right)
            text += tr(" (right)");
        else if (s.status & status::In1Left)
            text += tr(" (left)");
        return text;
    }
    case Errors: {
        const QString text = errorText(s.errors);
        if (!text.isEmpty())
            return text;
        if (!(s.status & status::Error))
            return QStringLiteral("-");
        // The status says "error" but the error word is not known (yet).
        if (m_errorReadFailures.contains(s.node)) // also while it is read again
            return tr("error (its code could not be read)");
        if (m_readingErrors.contains(s.node))
            return tr("error (reading its code…)");
        return tr("error (code unknown)");
    }
    default:
        return {};
    }
}

QVariant Nm17xLineModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case Node:
        return tr("Node");
    case Variant:
        return tr("Variant");
    case Serial:
        return tr("Serial number");
    case Setpoint:
        return tr("Setpoint");
    case Position:
        return tr("Position");
    case Correction:
        return tr("Correction");
    case Status:
        return tr("Status");
    case Errors:
        return tr("Errors");
    default:
        return {};
    }
}

} // namespace db::widgets
