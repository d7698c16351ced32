#pragma once

#include "core/error.h"

#include <QByteArray>
#include <QObject>

namespace db {

// A bidirectional byte stream (TCP now; a serial port could follow). It knows no protocol.
//
// The base class owns the open/close state machine; subclasses implement doOpen()/doClose()/
// doWrite() and report with setOpened()/setClosed()/deliver() (as QCanBusDevice does).
// Signals are emitted from the event loop; no call blocks.
class ByteStream : public QObject
{
    Q_OBJECT
public:
    enum class State { Closed, Opening, Open, Closing };
    Q_ENUM(State)

    using QObject::QObject;

    State state() const { return m_state; }
    bool isOpen() const { return m_state == State::Open; }
    // Where the stream goes, for messages: "127.0.0.1:10001".
    virtual QString peerName() const = 0;
    // How long open() may take before it fails with a timeout (streams that connect).
    virtual void setConnectTimeoutMs(int ms) { Q_UNUSED(ms) }

    void open();
    void close();
    // Queues bytes for sending; false (and no effect) unless open.
    bool write(const QByteArray &bytes);

Q_SIGNALS:
    void opened();
    // After close() or a lost link; error is set when the stream failed (refused, reset, ...).
    void closed(const db::Error &error);
    void received(const QByteArray &bytes);

protected:
    virtual void doOpen() = 0;
    virtual void doClose() = 0;
    virtual void doWrite(const QByteArray &bytes) = 0;

    void setOpened();
    void setClosed(const Error &error = {});
    void deliver(const QByteArray &bytes);

private:
    State m_state = State::Closed;
};

} // namespace db
