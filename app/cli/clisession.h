#pragma once

#include "core/deviceconnection.h"
#include "core/protocolregistry.h"

#include <QTextStream>

#include <memory>

namespace db::cli {

// Exit codes of drivebench-cli (README "CLI"): scripts can tell the causes apart.
enum ExitCode {
    ExitOk = 0,
    ExitFailure = 1, // anything not listed below
    ExitUsage = 2, // bad arguments, unknown command, invalid URI/address/value
    ExitConnection = 3, // refused, host not found, link lost
    ExitTimeout = 4, // no answer within the time limit
    ExitMalformed = 5, // the device's answer breaks the protocol
    ExitDeviceError = 6, // the device refused the request
    ExitSignalBase = 128, // + the signal's number: stopped by SIGINT (130) or SIGTERM (143)
};

int exitCodeFor(const Error &error);

// How the device at uriText writes its object addresses, known before anything is opened: the
// protocol's format (hex INDEX:SUB for CANopen and RefGo, decimal NUMBER:DATASET for inverter
// parameters). A URI that does not parse gives its own error: it is the real cause when an
// address in the wrong format would fail too.
Result<const AddressFormat *> addressFormatFor(const ProtocolRegistry &registry,
                                               const QString &uriText);

// An address typed on the command line, in the format of the device at uriText.
Result<ObjectAddress> parseAddressFor(const ProtocolRegistry &registry, const QString &uriText,
                                      const QString &addressText);

// Options shared by every command.
struct Options
{
    int requestTimeoutMs = 1000;
    int connectTimeoutMs = 3000;
    bool hex = false;
    bool verbose = false;
    QString sdoMode; // --sdo for CANopen connections: auto, expedited, segmented, block
    bool ram = false; // --ram for VABus connections: writes go to the RAM data sets (DS + 5)
};

// One connection for the duration of a command: opens it (waiting at most connectTimeoutMs),
// runs requests synchronously for the command, closes it cleanly.
class Session
{
public:
    Session(const ProtocolRegistry &registry, const Options &options);
    ~Session();

    Result<void> open(const QString &uriText);
    DeviceConnection *connection() const { return m_connection.get(); }
    // The open connection's address format (CANopen's before open()): every address printed
    // for this session goes through it.
    const AddressFormat &addressFormat() const;
    Result<QVariant> read(ObjectAddress address);
    Result<void> write(ObjectAddress address, const QVariant &raw);

private:
    const ProtocolRegistry &m_registry;
    Options m_options;
    std::shared_ptr<DeviceConnection> m_connection;
};

} // namespace db::cli
