#pragma once

// MovingCap over RefGo (TCP 10001) as a DeviceConnection: object reads/writes through OR/OW,
// raw commands for the terminal, store-to-NV and factory defaults through 1010h/1011h as on its
// CANopen side.

#include "core/deviceconnection.h"
#include "refgoclient.h"

#include <QTimer>

namespace db {
class ByteStream;
}

namespace db::refgo {

class RefgoConnection : public DeviceConnection
{
    Q_OBJECT
public:
    static constexpr int kDefaultPort = 10001;
    static constexpr int kDefaultReconnectIntervalMs = 2000;

    // Makes its own TcpStream to uri.host():uri.portOr(10001).
    explicit RefgoConnection(const ConnectionUri &uri, QObject *parent = nullptr);
    // For tests: an injected stream, not owned, that must outlive the connection.
    RefgoConnection(const ConnectionUri &uri, ByteStream *stream, QObject *parent = nullptr);
    ~RefgoConnection() override;

    QString protocolKey() const override { return QStringLiteral("refgo"); }
    Capabilities capabilities() const override
    {
        return Capability::RawCommands | Capability::StoreNonVolatile;
    }

    // A raw RefGo command; the reply's value is the result lines (QStringList). Caller owns it.
    Reply *command(const QString &raw);
    Reply *rawCommand(const QString &raw) override { return command(raw); }
    Reply *storeNonVolatile() override;
    Reply *restoreFactoryDefaults() override;

    // The engine, for typed commands (motion, TPSR, ...). Owned by the connection.
    RefgoClient *client() const { return m_client; }

    // After a lost link (not after close()), or a failed attempt, try open() again every
    // intervalMs. Off by default.
    void setAutoReconnect(bool enabled, int intervalMs = kDefaultReconnectIntervalMs);
    bool autoReconnect() const { return m_autoReconnect; }
    // True while waiting to try open() again (for a "reconnecting..." hint).
    bool isReconnectScheduled() const { return m_reconnectTimer.isActive(); }

protected:
    void doOpen() override;
    void doClose() override;
    void stopReconnecting() override { m_reconnectTimer.stop(); }
    void doRead(Reply *reply, const ObjectDef *def) override;
    void doWrite(Reply *reply, const QVariant &raw, const ObjectDef *def) override;

private:
    void init();
    void onOpened();
    void onClosed(const Error &error);

    ByteStream *m_stream = nullptr;
    RefgoClient *m_client = nullptr;
    QTimer m_reconnectTimer;
    bool m_autoReconnect = false;
};

} // namespace db::refgo
