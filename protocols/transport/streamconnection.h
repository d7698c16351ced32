#pragma once

#include "core/deviceconnection.h"

#include <QTimer>

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

    // After a lost link (not after close()), or a failed attempt, try open() again every
    // intervalMs. Off by default.
    void setAutoReconnect(bool enabled, int intervalMs = kDefaultReconnectIntervalMs);
    bool autoReconnect() const { return m_autoReconnect; }
    // True while waiting to try open() again (for a "reconnecting..." hint).
    bool isReconnectScheduled() const { return m_reconnectTimer.isActive(); }

protected:
    ByteStream *stream() const { return m_stream; }
    // The connection's state follows the stream's from now on. Call once, after the engine.
    void followStream();
    // The log line once the stream is open; a protocol may add what the device does from then on.
    virtual QString connectedLine() const;

    void doOpen() override;
    void doClose() override;
    void stopReconnecting() override { m_reconnectTimer.stop(); }

private:
    void initReconnect();
    void onOpened();
    void onClosed(const Error &error);

    ByteStream *m_stream = nullptr;
    QTimer m_reconnectTimer;
    bool m_autoReconnect = false;
};

} // namespace db
