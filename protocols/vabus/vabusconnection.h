#pragma once

// A Bonfiglioli ACTIVE Cube with a CM-VABus/TCP module as a DeviceConnection.
//
// Addresses are parameter number and data set (ObjectAddress index and sub, written 372:2 by
// AddressFormat::parameter()). Data set 0 is a single parameter, or all four data sets of a
// data-set parameter; 1-4 are the EEPROM data sets, 5-9 their RAM copies (0-4 + 5).
// URI: vabus://HOST[:PORT][?sys=N][&ram]
//   sys=N  a system bus slave with node id N (1-63) behind the module (SYS byte 0x40 + N);
//          0 or absent: the inverter carrying the module (SYS 0x00)
//   ram    writes to data sets 0-4 go to their RAM copies (5-9), sparing the EEPROM

#include "transport/streamconnection.h"
#include "vabusblockreader.h"
#include "vabusclient.h"

namespace db::vabus {

class VabusConnection : public StreamConnection
{
    Q_OBJECT
public:
    static constexpr int kDefaultPort = 17220; // the PLC port of the module
    // After power-on the inverter and its module need up to 20 s before they communicate (3.2).
    static constexpr int kPowerUpWindowMs = 20000;
    static constexpr int kRetryIntervalMs = 1000;

    // Makes its own TcpStream to uri.host():uri.portOr(17220).
    explicit VabusConnection(const ConnectionUri &uri, QObject *parent = nullptr);
    // For tests: an injected stream, not owned, that must outlive the connection.
    VabusConnection(const ConnectionUri &uri, ByteStream *stream, QObject *parent = nullptr);
    ~VabusConnection() override;

    QString protocolKey() const override { return QStringLiteral("vabus"); }
    const AddressFormat &addressFormat() const override { return AddressFormat::parameter(); }

    // Refuses a bad ?sys= (cheap; for the protocol registry's check).
    static Result<void> checkUri(const ConnectionUri &uri);
    // The SYS byte ?sys= asks for.
    static Result<quint8> sysFromUri(const ConnectionUri &uri);

    // Data sets 0-4 -> 5-9.
    std::optional<ObjectAddress> ramAddress(ObjectAddress address) const override;

    // True when writes to data sets 0-4 go to RAM (?ram).
    bool writesToRam() const { return m_ram; }
    void setWritesToRam(bool ram) { m_ram = ram; }

    // When a link that was up is lost (not closed by us), open() is tried again every intervalMs
    // for windowMs: an inverter that was switched off and on answers again within 20 s. 0 turns
    // it off. A first open() that fails is not retried. On by default (kPowerUpWindowMs).
    void setRetryAfterLoss(int windowMs, int intervalMs = kRetryIntervalMs)
    {
        setAutoReconnect(windowMs > 0, intervalMs, windowMs);
    }
    int retryWindowMs() const { return autoReconnect() ? reconnectWindowMs() : 0; }
    // True while waiting for the next attempt.
    bool isRetryScheduled() const { return isReconnectScheduled(); }

    // The engine, for diagnostics. Owned by the connection. Block reads go through
    // blockReader(), the one owner of the block definition.
    VabusClient *client() const { return m_client; }
    // Owned by the connection (a child, also found by GroupReader::of()).
    BlockReader *blockReader() const { return m_blocks; }

    // The description of a parameter at this address: the address's own, else that of the
    // EEPROM data set a RAM data set copies, else data set 0's.
    const ObjectDef *describe(ObjectAddress address) const;

protected:
    QString connectedLine() const override;
    QString reconnectingLine() const override;
    void doRead(Reply *reply, const ObjectDef *def) override;
    void doWrite(Reply *reply, const QVariant &raw, const ObjectDef *def) override;

private:
    void init();

    VabusClient *m_client = nullptr;
    BlockReader *m_blocks = nullptr;
    bool m_ram = false;
};

} // namespace db::vabus
