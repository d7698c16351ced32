#pragma once

#include "core/error.h"
#include "core/result.h"

#include <QCanBusFrame>
#include <QObject>

namespace db {

// A CAN bus seen by one node: frames out, frames in. It knows no protocol (CANopen lives above).
// Implementations: QtCanBus (any Qt CAN plugin: socketcan, virtualcan, peakcan, ...) and
// SlcanBus (SLCAN ASCII over a ByteStream, e.g. TCP port 15001 of a MovingCap ETH drive).
//
// The base class owns the open/close state machine; subclasses implement doOpen()/doClose()/
// doSend() and report with setOpened()/setClosed()/deliver(). Signals come from the event loop.
//
// Receive path under load: a subclass hands over at most kReceiveSliceFrames frames per
// event-loop pass (so timers of the protocols above fire on time during a flood) and keeps at
// most about kMaxReceiveQueueFrames waiting; what does not fit is dropped and reported with
// reportDropped().
class CanBus : public QObject
{
    Q_OBJECT
public:
    enum class State { Closed, Opening, Open, Closing };
    Q_ENUM(State)

    static constexpr int kReceiveSliceFrames = 256;
    static constexpr int kMaxReceiveQueueFrames = 4096;
    // Overflow warnings are coalesced to one per this interval during a flood.
    static constexpr int kOverflowReportMs = 1000;

    using QObject::QObject;

    // For messages and the CAN monitor: "slcan 127.0.0.1:15001", "virtualcan can0".
    virtual QString name() const = 0;
    State state() const { return m_state; }
    bool isOpen() const { return m_state == State::Open; }
    // How long open() may take before it fails with a timeout (buses behind a connection).
    virtual void setConnectTimeoutMs(int ms) { Q_UNUSED(ms) }

    void open();
    // Blocks in a local event loop until open() has opened the bus or failed (for command-line
    // tools, benchmarks and tests only). The error is the bus's own, or a timeout.
    Result<void> openAndWait(int timeoutMs);
    void close();
    // Queues one frame; false (and no effect) unless open. frameSent() follows once it is out.
    bool send(const QCanBusFrame &frame);
    // Received frames dropped because the receive queue was full, since the bus was created.
    qint64 droppedFrames() const { return m_dropped; }

Q_SIGNALS:
    void opened();
    // After close() or a failure; error set when the bus failed (refused, bus off, link lost).
    void closed(const db::Error &error);
    void frameReceived(const QCanBusFrame &frame);
    // Every frame this node sent (for the CAN monitor's TX direction).
    void frameSent(const QCanBusFrame &frame);
    // Every frame in the order it crossed the bus, for monitors: a received frame is reported
    // before frameReceived() lets protocols answer it, so an answer never appears before the
    // frame that caused it. transmitted = sent by this node.
    void traffic(const QCanBusFrame &frame, bool transmitted);
    // A problem that does not close the bus (error frame, BEL from an SLCAN adapter, overrun).
    void warning(const QString &text);

protected:
    virtual void doOpen() = 0;
    virtual void doClose() = 0;
    virtual void doSend(const QCanBusFrame &frame) = 0;

    void setOpened();
    void setClosed(const Error &error = {});
    void deliver(const QCanBusFrame &frame);
    // Subclasses call this once a frame is out: emits traffic() and frameSent().
    void reportSent(const QCanBusFrame &frame);
    // Counts dropped received frames and reports them through warning() as "receive queue
    // overflow: N frames dropped": at once, then at most every kOverflowReportMs.
    void reportDropped(qint64 frames);

private:
    void flushDropReport();

    State m_state = State::Closed;
    qint64 m_dropped = 0;
    qint64 m_droppedUnreported = 0;
    qint64 m_lastReportMs = -1; // steady clock of the last overflow warning
    bool m_reportScheduled = false;
};

} // namespace db
