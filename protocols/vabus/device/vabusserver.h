#pragma once

// Device side of VABus/TCP (used by the simulated ACU): the module's PLC port as a TCP server
// on loopback (StreamServer: a client that does not read its answers is paused, then dropped).
// It frames requests by NoB, hands each to a DeviceHandler and writes its answer.
//
// Contracts:
// - One PLC connection at a time (the module has one logical connection per port). A second
//   client is closed at once, with a log line that names it.
// - A request whose NoB cannot be right (below 4, above 103) is a structurally broken telegram:
//   the buffered bytes are dropped and nothing is answered. A header with bits 5..0 set, or an
//   enquiry whose NoB is not 4, is answered with error 13 (syntax error) without asking the
//   handler.
// - Failure modes for tests (setFailure): stay silent, answer garbage, answer late, drop the
//   connection after N answers, or send every answer in 1-byte TCP segments.

#include "core/result.h"
#include "vabus/vabuscodec.h"

#include <QHostAddress>
#include <QObject>

#include <optional>

namespace db::vabus {

// What a simulated device answers to one well-formed request (SYS, DS and parameter echoed by
// the handler). nullopt: no answer.
class DeviceHandler
{
public:
    virtual ~DeviceHandler() = default;
    virtual std::optional<Telegram> handle(const Telegram &request) = 0;
};

class Server : public QObject
{
    Q_OBJECT
public:
    enum class Failure { None, Silent, Garbage, Slow, DropAfter, SplitBytes };
    Q_ENUM(Failure)
    struct FailureMode
    {
        Failure failure = Failure::None;
        int slowMs = 2000; // Slow: delay of every answer
        int dropAfter = 1; // DropAfter: answers before the connection is closed
    };

    // The handler must outlive the server.
    explicit Server(DeviceHandler *handler, QObject *parent = nullptr);
    ~Server() override;

    // Listens on address:port (port 0 = chosen by the OS). Loopback only by default.
    Result<void> listen(quint16 port = 0, const QHostAddress &address = QHostAddress::LocalHost);
    quint16 port() const;
    void close();
    bool hasClient() const;
    void setFailure(const FailureMode &mode);
    // "silent", "garbage", "slow", "drop-after", "split" (and "none").
    static std::optional<Failure> failureFromName(const QString &name);

Q_SIGNALS:
    // Every telegram received from the PLC connection (well-formed or not): the device's
    // communication watchdog counts these as exchanges.
    void exchanged();
    void requestHandled(const db::vabus::Telegram &request,
                        const std::optional<db::vabus::Telegram> &answer);
    // One line per event worth telling the person running the simulator (refused client).
    void logLine(const QString &line);

private:
    class Private;
    Private *d;
};

} // namespace db::vabus
