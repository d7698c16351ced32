#pragma once

// The CAN monitor's frames as a table: time, direction, COB-ID, length, data
// and their CANopen reading. Bounded: a ring of capacity() frames; the oldest go first.
//
// Frames are not inserted one by one: they queue and join the table in one batch per
// kFlushIntervalMs (5 Hz: a log that scrolls faster cannot be read, and each batch repaints the
// whole table), so a busy bus costs one row insertion (and one repaint) per tick. While paused,
// frames keep queueing (up to capacity(), oldest dropped) and appear on resume: pause freezes the
// view, not the capture. No widgets here; CanMonitor is the view.

#include "canopen/framedecoder.h"
#include "transport/canbus.h"

#include <QAbstractTableModel>
#include <QFont>
#include <QPointer>
#include <QTimer>

#include <vector>

namespace db::widgets {

class CanMonitorModel : public QAbstractTableModel
{
    Q_OBJECT
public:
    enum Column { Time, Direction, Id, Length, Data, Service, Node, Decoded, ColumnCount };
    static constexpr int kDefaultCapacity = 100000;
    static constexpr int kFlushIntervalMs = 200;

    struct Entry
    {
        qint64 epochUs = 0; // wall clock, for the candump log
        qint64 elapsedUs = 0; // since the monitor started (or was cleared)
        bool transmitted = false;
        QCanBusFrame frame;
        canopen::DecodedFrame decoded;
    };

    explicit CanMonitorModel(QObject *parent = nullptr);
    ~CanMonitorModel() override;

    // Frames of this bus (received and sent) are recorded until detached or the bus is
    // destroyed. Not owned; nullptr detaches. Recorded frames stay.
    void setBus(CanBus *bus);
    CanBus *bus() const { return m_bus; }
    canopen::FrameDecoder &decoder() { return m_decoder; }

    int capacity() const { return m_capacity; }
    // Drops the oldest frames when the new capacity is smaller.
    void setCapacity(int frames);
    bool isPaused() const { return m_paused; }
    void setPaused(bool paused);
    // Frames dropped since the last clear() because the buffer was full.
    qint64 droppedCount() const { return m_dropped; }
    int pendingCount() const { return int(m_pending.size()); }

    // Records one frame (what the bus signals call). Joins the table at the next flush.
    void record(const QCanBusFrame &frame, bool transmitted);
    // Moves the queued frames into the table now (unless paused).
    void flush();
    void clear();

    const Entry &entry(int row) const { return m_ring[physical(row)]; }

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

Q_SIGNALS:
    // After each batch joined the table (for autoscroll and the status line).
    void flushed();

private:
    size_t physical(int row) const { return (m_head + size_t(row)) % m_ring.size(); }
    void dropOldest(int count);

    QPointer<CanBus> m_bus;
    QList<QMetaObject::Connection> m_busConnections;
    canopen::FrameDecoder m_decoder;
    std::vector<Entry> m_ring; // grows to m_capacity, then wraps
    size_t m_head = 0; // physical index of row 0
    int m_count = 0;
    int m_capacity = kDefaultCapacity;
    QList<Entry> m_pending;
    QTimer m_flushTimer;
    bool m_paused = false;
    qint64 m_dropped = 0;
    qint64 m_startUs = 0;
    QFont m_mono; // asked for on every paint: made once
};

} // namespace db::widgets
