#pragma once

#include "addressformat.h"
#include "connectionuri.h"
#include "objectdictionary.h"
#include "reply.h"
#include "statussource.h"

#include <QList>
#include <QObject>
#include <QPointer>

namespace db {

// One connected device, whatever the protocol: the plugin instance interface
// (ARCHITECTURE.md, protocols/core). Widgets and the CLI work only through this.
//
// Threading: everything runs on the owning thread's event loop; no call blocks.
// Subclasses implement doOpen/doClose/doRead/doWrite and report with setState()/finishes.
class DeviceConnection : public QObject
{
    Q_OBJECT
public:
    enum class State { Disconnected, Connecting, Connected, Closing };
    Q_ENUM(State)

    // Optional abilities beyond read/write.
    enum class Capability {
        StoreNonVolatile = 0x1, // storeNonVolatile() and restoreFactoryDefaults()
        RawCommands = 0x2, // rawCommand(): protocol commands as text (RefGo)
    };
    Q_DECLARE_FLAGS(Capabilities, Capability)

    // openAndWait() gives the transport this much longer than its own connect timeout, so that
    // the transport's error (which names the peer) comes first.
    static constexpr int kOpenGraceMs = 250;

    explicit DeviceConnection(const ConnectionUri &uri, QObject *parent = nullptr);
    ~DeviceConnection() override;

    virtual QString protocolKey() const = 0;
    virtual Capabilities capabilities() const { return {}; }

    const ConnectionUri &uri() const { return m_uri; }
    State state() const { return m_state; }
    bool isConnected() const { return m_state == State::Connected; }
    // The error that ended the last connection or connection attempt.
    Error lastError() const { return m_lastError; }

    // Non-blocking: stateChanged(Connecting) now, then Connected, or Disconnected with
    // errorOccurred() when the attempt fails. Ignored unless Disconnected.
    void open();
    // Blocks in a local event loop until open() has connected or failed (for the CLI,
    // benchmarks and tests only, like Reply::wait). The error names the cause: the link's own
    // error (the transport gets timeoutMs as its connect timeout), or a timeout after timeoutMs.
    Result<void> openAndWait(int timeoutMs);
    // Non-blocking: pending requests fail with Error::Kind::Cancelled; ends in Disconnected.
    // Also stops an automatic reconnect that is waiting for its next attempt.
    void close();

    const ObjectDictionary &dictionary() const { return m_dictionary; }
    void setDictionary(const ObjectDictionary &dictionary) { m_dictionary = dictionary; }

    // Per-request time limit in ms used by the protocol engine.
    int requestTimeoutMs() const { return m_timeoutMs; }
    void setRequestTimeoutMs(int ms) { m_timeoutMs = ms; }
    // How long the transport may take to connect (TCP connect, bus open) before open() fails
    // with a timeout that names the peer. openAndWait() sets it to its own limit.
    int connectTimeoutMs() const { return m_connectTimeoutMs; }
    void setConnectTimeoutMs(int ms) { m_connectTimeoutMs = qMax(1, ms); }

    // Reads one object. The reply's value is the raw value (codec's canonical type; the
    // dictionary's type, or a qlonglong for objects the description does not know).
    // The caller owns the reply. It always finishes: value, device error, timeout or disconnect.
    Reply *read(ObjectAddress address);
    // Writes one raw value after checking it against the dictionary (type, range, access).
    // Objects missing from the description are written as given.
    Reply *write(ObjectAddress address, const QVariant &raw);

    // Saves the device's current parameters permanently, the way its protocol does it. The
    // caller owns the reply; without Capability::StoreNonVolatile it fails with NotSupported.
    virtual Reply *storeNonVolatile();
    // Makes the device take its factory defaults (often only after its next reset). Ask the
    // user first. Same contract as storeNonVolatile().
    virtual Reply *restoreFactoryDefaults();
    // One protocol command as text; the reply's value is the answer lines (QStringList). The
    // caller owns the reply; without Capability::RawCommands it fails with NotSupported.
    virtual Reply *rawCommand(const QString &command);

    // The fieldbus network the device is on (a canopen::CanNetwork for CANopen) and its address
    // there (the node id), for the services that work on the bus: PDO sampling, the CAN monitor,
    // the node list. Null and 0 for protocols without one.
    virtual QObject *network() const { return nullptr; }
    virtual int networkAddress() const { return 0; }

    // How addresses of this device are written and read (hex INDEX:SUB for CANopen and RefGo,
    // decimal NUMBER:DATASET for inverter parameters). Everything that shows or parses an
    // address for this connection goes through it.
    // The default is the dictionary's (CANopen's unless its description says otherwise).
    virtual const AddressFormat &addressFormat() const { return m_dictionary.addressFormat(); }

    // The address that changes the same parameter in the device's working memory only (lost
    // at power-off, sparing its EEPROM), for devices whose protocol has one (a VABus data set n
    // is n + 5 in RAM); none otherwise. write() to it is checked as the parameter itself.
    virtual std::optional<ObjectAddress> ramAddress(ObjectAddress) const { return std::nullopt; }

    // The drive's live status (state, faults, actual values) as its device family reads it, one
    // per connection and shared by everyone who shows it; null when nobody provided one. The
    // connection owns the source (it becomes its child); a new one replaces the old.
    StatusSource *statusSource() const { return m_statusSource; }
    void setStatusSource(StatusSource *source);

Q_SIGNALS:
    void stateChanged(db::DeviceConnection::State state);
    // Connection-level problems (refused, lost, garbage); request errors go to their replies.
    void errorOccurred(const db::Error &error);
    // Human-readable traffic/events for the log console (one line each).
    void logLine(const QString &line);
    // The device's own supervision says it is gone while the link is still up (a CANopen node
    // whose heartbeat stopped): motion must be treated as out of control.
    void supervisionLost(const QString &why);
    // A write() the device accepted: its value is in the device's RAM, not yet stored
    // permanently (storeNonVolatile()). Emitted once per successful write, before the reply's
    // finished() reaches other receivers connected later.
    void objectWritten(db::ObjectAddress address);
    // Every read or write that was handed to the protocol finished: ok (no error), the device's
    // refusal, a timeout, or cancelled by a disconnect. Emitted before the reply's finished()
    // reaches receivers connected later (ConnectionHealth judges the device by these).
    void requestFinished(db::ObjectAddress address, const db::Error &error);

protected:
    virtual void doOpen() = 0;
    virtual void doClose() = 0;
    // def is null for objects the dictionary does not know.
    virtual void doRead(Reply *reply, const ObjectDef *def) = 0;
    virtual void doWrite(Reply *reply, const QVariant &raw, const ObjectDef *def) = 0;
    // close() while already Disconnected: drop any scheduled automatic reconnect.
    virtual void stopReconnecting() { }

    // Subclasses report progress here. Entering Disconnected fails every pending reply with
    // `error` (or Disconnected/Cancelled) and emits errorOccurred() when error is set.
    void setState(State state, const Error &error = {});

private:
    Reply *track(Reply *reply);
    void failPending(const Error &error);

    ConnectionUri m_uri;
    State m_state = State::Disconnected;
    Error m_lastError;
    ObjectDictionary m_dictionary;
    int m_timeoutMs = 1000;
    int m_connectTimeoutMs = 3000;
    QList<QPointer<Reply>> m_pending;
    QPointer<StatusSource> m_statusSource;
};

Q_DECLARE_OPERATORS_FOR_FLAGS(DeviceConnection::Capabilities)

QString stateName(DeviceConnection::State state);

} // namespace db
