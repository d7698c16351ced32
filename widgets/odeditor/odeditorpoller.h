#pragma once

#include "core/deviceconnection.h"

#include <QElapsedTimer>
#include <QPointer>
#include <QSet>
#include <QTimer>

#include <functional>

namespace db::widgets {

class OdEditorModel;

// Reads values for the editor without flooding the device: at most kMaxInFlight requests at a
// time, queued addresses are never queued twice, and a refresh round starts only when the
// previous one has finished (a slow device lowers the rate instead of building a backlog).
//
// Two queues: `urgent` (read-backs after writes, the visible rows of a refresh round) before
// `background` (the one-time read of every object after connecting). Results go into the model
// with setValue()/setReadFailed(); nothing here ever writes.
//
// The drive's status objects (status word, faults, actual values: whatever the connection's
// StatusSource reads in its cycles) are not refreshed here: while such a row is visible the
// poller holds the source at its own period and takes the values from its cycles, so the
// device is polled for them once however many views show them.
class OdEditorPoller : public QObject
{
    Q_OBJECT
public:
    static constexpr int kMaxInFlight = 2;
    // Refresh periods offered by the editor (0 = off).
    static constexpr int kPeriodsMs[] = { 0, 250, 1000, 5000 };

    explicit OdEditorPoller(OdEditorModel *model, QObject *parent = nullptr);
    ~OdEditorPoller() override;

    void setConnection(DeviceConnection *connection);
    // Who is visible now; called at every refresh tick (empty or not set: nothing is refreshed).
    void setVisibleRows(std::function<QList<ObjectAddress>()> visibleRows)
    {
        m_visibleRows = std::move(visibleRows);
    }

    int periodMs() const { return m_periodMs; }
    void setPeriodMs(int ms); // 0 = off

    void readNow(const QList<ObjectAddress> &addresses, bool urgent = true);
    // Every readable object of the model, in the background.
    void readAll();
    // Drops what readAll() has not sent yet (what is in flight still lands).
    void cancelReadAll();
    void clear();

    int pending() const { return int(m_urgent.size() + m_background.size()); }
    int inFlight() const { return m_inFlight; }
    // Statistics for tests and the status line.
    int requestsSent() const { return m_sent; }
    int maxInFlightSeen() const { return m_maxInFlight; }
    // The status source is held for visible rows it reads.
    bool holdsStatusSource() const { return m_source && m_holding; }

Q_SIGNALS:
    // Emitted when a queue drains (e.g. the read-all pass has finished).
    void idle();
    // The progress of readAll(): objects answered of total; total 0 when it ended or was
    // cancelled.
    void readAllProgress(int done, int total);

private:
    void tick();
    void pump();
    void onReply(Reply *reply, quint64 generation);
    bool wanted(ObjectAddress address) const;
    // Follows the connection's status source (one may be set after the connection).
    void bindStatusSource();
    void holdStatusSource(bool on);
    void onStatusUpdated();

    OdEditorModel *m_model;
    QPointer<DeviceConnection> m_connection;
    QPointer<StatusSource> m_source;
    QMetaObject::Connection m_sourceUpdated;
    bool m_holding = false;
    std::function<QList<ObjectAddress>()> m_visibleRows;
    QTimer m_timer;
    int m_periodMs = 0;
    QList<ObjectAddress> m_urgent;
    QList<ObjectAddress> m_background;
    QSet<ObjectAddress> m_queued;
    int m_inFlight = 0;
    int m_sent = 0;
    int m_maxInFlight = 0;
    quint64 m_generation = 0;
    QSet<ObjectAddress> m_backgroundInFlight;
    int m_backgroundDone = 0;
    int m_backgroundTotal = 0;
    void backgroundFinished(ObjectAddress address);
};

} // namespace db::widgets
