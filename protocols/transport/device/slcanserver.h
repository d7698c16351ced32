#pragma once

// Device side of slcan over TCP (used by the simulators): a loopback TCP server that behaves as
// movingcap.md 4.2 recommends for a simulator. It accepts O, C, L, Sn, sxxyy, Z0/Z1 and answers
// "\r"; V, N and F get "V1013\r", "N0001\r", "F00\r"; a t/T/r/R frame gets the transmit ack
// ("z\r"/"Z\r" by default) and is passed to the device through frameReceived(); anything it
// cannot parse gets BEL. Device frames from send() go to every connected client (with a
// timestamp for clients that sent Z1). Sockets use TCP_NODELAY. Every client is throttled
// (ClientThrottle): one that does not read is paused, gets no device frames while its output
// queue is full (they are counted in droppedFrames()), and is finally dropped.

#include "core/result.h"
#include "transport/clientthrottle.h"

#include <QCanBusFrame>
#include <QHostAddress>
#include <QObject>

#include <memory>

namespace db {

class SlcanServer : public QObject
{
    Q_OBJECT
public:
    // What a transmitted frame is acknowledged with.
    enum class TransmitAck {
        Lawicel, // "z\r" for t/r, "Z\r" for T/R (python-can, Kickdrive)
        Cr, // "\r"
        None,
    };
    Q_ENUM(TransmitAck)

    explicit SlcanServer(QObject *parent = nullptr);
    ~SlcanServer() override;

    // Listens on address:port (port 0 = chosen by the OS). Loopback only by default.
    Result<void> listen(quint16 port = 0, const QHostAddress &address = QHostAddress::LocalHost);
    quint16 port() const;
    bool isListening() const;
    // Stops listening and drops every client.
    void close();
    // Aborts every client connection (RST, no goodbye) and keeps listening: a cut cable as the
    // clients see it. Returns how many were dropped.
    int dropClients();
    int clientCount() const;
    // Applies to clients that connect afterwards.
    void setClientLimits(const ClientThrottle::Limits &limits);
    // The longest output queue any client had so far, in bytes.
    qint64 peakQueuedBytes() const;
    // Device frames not sent to a client because its output queue was full.
    qint64 droppedFrames() const;

    void setTransmitAck(TransmitAck ack);
    TransmitAck transmitAck() const;
    // When set, frames are exchanged only with clients that sent "O" (and not "C" since), and a
    // frame from a closed channel gets BEL, as a Lawicel adapter does. Off by default: the drive's
    // behaviour is not documented (spec 4.1), and a client that never sends O still works.
    void setRequireOpen(bool require);
    // The simulated bus's bit rate (0, the default: any). A client whose Sn command names another
    // one exchanges no frames, as a node at the wrong bit rate on a real bus; a client that sent
    // no Sn is taken to be right.
    void setBusBitrate(int bitsPerSecond);
    int busBitrate() const;

    // Device -> clients. Returns how many clients got the frame.
    int send(const QCanBusFrame &frame);
    // Raw bytes to every client (failure injection: garbage on the stream).
    void sendRaw(const QByteArray &bytes);

Q_SIGNALS:
    // A frame a client transmitted (the device receives it). Emitted once per frame.
    void frameReceived(const QCanBusFrame &frame);
    void clientConnected();
    void clientDisconnected();
    // A line the server answered with BEL.
    void refused(const QByteArray &line);

private:
    struct Private;
    std::unique_ptr<Private> d;
};

} // namespace db
