#pragma once

#include "core/deviceconnection.h"

#include <QDeadlineTimer>
#include <QTimer>

#include <optional>

namespace db {

class ByteStream;

// A DeviceConnection over one byte stream to the device (TCP): its state follows the stream's,
// a stream that closes by itself ends the connection with the stream's cause, and an automatic
// reconnect may try again after a pause. Subclasses put their protocol's request engine on
// stream(), then call followStream() (so that the engine sees the stream open and close before
// the connection reports it), and implement doRead()/doWrite(); they delete that engine in their
// destructor, so that its pending replies fail with Cancelled while the stream still exists.
class StreamConnection : public DeviceConnection
{
    Q_OBJECT
public:
    static constexpr int kDefaultReconnectIntervalMs = 2000;

    // Makes its own TcpStream to uri.host():uri.portOr(defaultPort).
    StreamConnection(const ConnectionUri &uri, quint16 defaultPort, QObject *parent = nullptr);
    // For tests: an injected stream, not owned, that must outlive the connection.
    StreamConnection(const ConnectionUri &uri, ByteStream *stream, QObject *parent = nullptr);

    // After a lost link (not after close()), try open() again every intervalMs. windowMs 0: for
    // as long as it takes, and a failed attempt (a first open() too) is tried again as well.
    // windowMs > 0: only for a link that was up, and for that long after it was lost (a device
    // that restarts). Off by default.
    void setAutoReconnect(bool enabled, int intervalMs = kDefaultReconnectIntervalMs,
                          int windowMs = 0);
    bool autoReconnect() const { return m_autoReconnect; }
    int reconnectWindowMs() const { return m_windowMs; }
    // True while waiting to try open() again (for a "reconnecting..." hint).
    bool isReconnectScheduled() const { return m_reconnectTimer.isActive(); }

protected:
    ByteStream *stream() const { return m_stream; }
    // The connection's state follows the stream's from now on. Call once, after the engine.
    void followStream();
    // The log line once the stream is open; a protocol may add what the device does from then on.
    virtual QString connectedLine() const;
    // The log line before an automatic reconnect attempt.
    virtual QString reconnectingLine() const;

    void doOpen() override;
    void doClose() override;
    void stopReconnecting() override;

private:
    void initReconnect();
    void onOpened();
    void onClosed(const Error &error);

    ByteStream *m_stream = nullptr;
    QTimer m_reconnectTimer;
    bool m_autoReconnect = false;
    int m_windowMs = 0;
    std::optional<QDeadlineTimer> m_reconnectUntil; // set when a link that was up is lost
};

} // namespace db
