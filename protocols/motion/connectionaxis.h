#pragma once

#include "axisinterface.h"

#include "core/deviceconnection.h"

#include <QPointer>

namespace db::motion {

// What every axis over a DeviceConnection shares, whatever its family: the connection, the
// status taken from the connection's one StatusSource (no poller of its own), and what a lost
// connection means to the command model.
//
// Status: the axis holds the source while it exists, asking for a cycle at least every
// kStatusPollMs and for the objects it needs besides the family's own; every kIdleStatusPollMs
// only while the drive is switched off, stands still and no command of the axis runs (an idle
// window then costs little CPU and bus load). Any command of the axis asks for the fast rate at
// once. After every cycle the
// subclass decodes its Status from the source's values (takeStatus()); statusChanged() follows
// when it did. After its own commands the axis asks the source for values read after them
// (refreshStatus()), so the command model never judges a command by a status read before it.
//
// Connection lost: the status becomes invalid, the subclass ends what it runs
// (onDisconnected()), then connectionLost() carries the connection's error, or "connection to
// URI closed" when it has none, and statusChanged() follows.
class ConnectionAxis : public AxisInterface
{
    Q_OBJECT
public:
    static constexpr int kStatusPollMs = 20;
    static constexpr int kIdleStatusPollMs = 250;

    ~ConnectionAxis() override;

    DeviceConnection *connection() const { return m_connection; }
    StatusSource *statusSource() const { return m_source; }
    Status status() const override { return m_status; }
    bool isConnected() const override;

    // Why the connection is gone: its last error, or "connection to URI closed".
    static Error lossCause(const DeviceConnection &connection);

protected:
    // `connection` must outlive the axis.
    explicit ConnectionAxis(DeviceConnection *connection, QObject *parent = nullptr);

    // Takes status from `source` (normally the connection's; the subclass makes one when the
    // connection has none), which reads `objects` in every cycle besides its own.
    void attachStatus(StatusSource *source, const QList<ObjectAddress> &objects);
    // Updates `status` from the source after a cycle; false when the cycle lacks what a status
    // needs (then nothing is emitted and the status stays as it was).
    virtual bool takeStatus(const StatusSource &source, Status &status) = 0;
    // The connection went away: end what runs. The status is already invalid.
    virtual void onDisconnected() { }
    // A command of the axis is running (the status is then read at the fast rate).
    virtual bool commandRunning() const { return false; }
    // Values read after now: the source starts a cycle at once or right after the running one.
    void refreshStatus();
    // A reply of one of the axis's own commands: refreshStatus() when it finishes.
    Reply *refreshedAfter(Reply *reply);
    Status &mutableStatus() { return m_status; }

private:
    void onStateChanged(DeviceConnection::State state);
    void onUpdated();
    // Holds the source at the fast or the idle interval.
    void setPollInterval(int ms);
    bool isIdle() const;

    DeviceConnection *m_connection;
    QPointer<StatusSource> m_source;
    QList<ObjectAddress> m_objects;
    int m_intervalMs = kStatusPollMs;
    Status m_status;
};

} // namespace db::motion
