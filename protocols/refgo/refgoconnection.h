#pragma once

// MovingCap over RefGo (TCP 10001) as a DeviceConnection: object reads/writes through OR/OW,
// raw commands for the terminal, store-to-NV and factory defaults through 1010h/1011h as on its
// CANopen side.

#include "refgoclient.h"
#include "transport/streamconnection.h"

namespace db::refgo {

class RefgoConnection : public StreamConnection
{
    Q_OBJECT
public:
    static constexpr int kDefaultPort = 10001;

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

protected:
    void doRead(Reply *reply, const ObjectDef *def) override;
    void doWrite(Reply *reply, const QVariant &raw, const ObjectDef *def) override;

private:
    void init();

    RefgoClient *m_client = nullptr;
};

} // namespace db::refgo
