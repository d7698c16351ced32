#pragma once

#include "deviceconnection.h"

#include <QDateTime>
#include <QObject>
#include <QPointer>
#include <QTimer>

namespace db {

// What the user may believe about one connection: whether the device itself answers, not only
// whether the link (TCP, CAN bus) is up. It watches the connection's state and the outcome of
// every request made on it (DeviceConnection::requestFinished), and tells apart a connection
// attempt that failed, a link that was lost, and one the user closed, with the cause.
//
// Contract: a connection is Responding only after the device answered a request (a value or a
// device error such as an SDO abort); kTimeoutsBeforeSilent timeouts in a row without an answer
// make it NotResponding, the next answer Responding again. While the link is up and no request
// finished for kProbeIntervalMs, the health reads probeAddress() itself, so that a connection
// nobody polls is judged too (one small read every kProbeIntervalMs, never more than one at a
// time). A new connection attempt clears the cause of the previous one.
//
// One per connection, a child of it: ConnectionHealth::of() finds it.
class ConnectionHealth : public QObject
{
    Q_OBJECT
public:
    enum class Status {
        Idle, // never opened
        Connecting,
        WaitingForAnswer, // link up, the device has not answered yet
        Responding,
        NotResponding, // link up, requests time out
        Failed, // the connection attempt failed (refused, no such host, no answer to the probe)
        Lost, // the link went down without the user asking
        ClosedByUser,
    };
    Q_ENUM(Status)

    static constexpr int kTimeoutsBeforeSilent = 3;
    static constexpr int kProbeIntervalMs = 2000;
    // While a device does not answer, pollers ask it this seldom: each round would only add
    // timeouts, and the probe notices when it answers again.
    static constexpr int kSilentPollIntervalMs = 5000;

    explicit ConnectionHealth(DeviceConnection *connection);

    // The health object of connection (made by whoever shows it), or null.
    static ConnectionHealth *of(const DeviceConnection *connection);
    // True when connection has a health and it says NotResponding.
    static bool isSilent(const DeviceConnection *connection);
    // The pause a poller of connection leaves before its next round: normalMs, or at least
    // kSilentPollIntervalMs while the device does not answer.
    static int pollIntervalMs(const DeviceConnection *connection, int normalMs);
    // A request that got no answer at all: the device was silent or the link failed (as opposed
    // to a value or the device's own refusal). Requests queued behind it would wait in vain.
    static bool isNoAnswer(const Error &error);

    DeviceConnection *connection() const { return m_connection; }
    Status status() const { return m_status; }
    bool isResponding() const { return m_status == Status::Responding; }
    // The error behind Failed, Lost and NotResponding; none otherwise.
    Error cause() const { return m_cause; }
    // When the device last answered (invalid before the first answer).
    QDateTime lastAnswer() const { return m_lastAnswer; }
    // What status() means, for a status bar ("connected", "not responding", ...), translated.
    static QString statusText(Status status);
    // statusText() with the cause when there is one.
    QString description() const;
    // The object probed when nothing else is asked: 1000h when the description has it or has no
    // objects, else 6041h, else its first readable object.
    ObjectAddress probeAddress() const;

Q_SIGNALS:
    void statusChanged(db::ConnectionHealth::Status status);

private:
    void onStateChanged(DeviceConnection::State state);
    void onRequestFinished(const Error &error);
    void probe();
    void setStatus(Status status, const Error &cause = {});

    QPointer<DeviceConnection> m_connection;
    Status m_status = Status::Idle;
    Error m_cause;
    Error m_linkError; // errorOccurred() since the last attempt began
    bool m_closing = false; // the user asked to close
    bool m_wasUp = false; // the link was up in this attempt
    int m_timeouts = 0;
    QDateTime m_lastAnswer;
    QTimer m_probeTimer;
    QPointer<Reply> m_probe;
};

} // namespace db
