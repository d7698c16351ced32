#pragma once

// The displays' own broadcast addressing, as a small state machine on a CAN network: every
// display on the bus is put into addressing mode at once, then node ids are offered one by one;
// for each, the operator turns the shaft (or presses a key) of the display that should take it,
// and that display answers. At the end all nodes are reset so that the new ids take effect.
//
//   Idle --start()--> Offering(first)
//     (frames on entry: NMT stop all "02 00", LSS switch global "04 01", select 40h vendor ECh,
//      41h/42h/43h FFFFFFFFh -- the displays enter addressing mode without answering)
//   Offering(n) --"11 00" from a display--> Offering(n+1), or Finishing after `count` ids
//   Offering(n) --no answer within kStepTimeoutMs--> Finishing when no count was given and at
//                least one id was assigned, else Failed (Timeout)
//   Offering(n) --"11 ee", ee != 0--> Failed (DeviceError)
//   Finishing: LSS switch global "04 00", NMT reset node all "81 00" --> Done
//   cancel() from Offering --> Finishing (the ids assigned so far stay)
//
// Contracts: start() never blocks; offering() tells the operator which id is offered;
// assigned() follows each answer; finished() comes once, from the event loop.

#include "canopen/cannetwork.h"

#include <QList>
#include <QObject>
#include <QTimer>

namespace db::nm17x {

class BroadcastAddressing : public QObject
{
    Q_OBJECT
public:
    static constexpr int kStepTimeoutMs = 60000; // the operator's time to find the display
    enum class State { Idle, Offering, Finishing, Done, Failed };
    Q_ENUM(State)

    // The network is not owned and must outlive this object.
    explicit BroadcastAddressing(canopen::CanNetwork *network, QObject *parent = nullptr);

    void setStepTimeoutMs(int ms) { m_stepTimeoutMs = qMax(1, ms); }
    // first: the first node id (1..127); count: how many displays (0 = until a step times out).
    Result<void> start(canopen::NodeId first, int count = 0);
    void cancel();

    State state() const { return m_state; }
    QList<canopen::NodeId> assignedIds() const { return m_assigned; }
    Error error() const { return m_error; }

Q_SIGNALS:
    void offering(db::canopen::NodeId node);
    void assigned(db::canopen::NodeId node);
    void finished(bool ok);

private:
    void offer();
    void onFrame(const QCanBusFrame &frame);
    void onTimeout();
    void finish(const Error &error = {});
    bool send(quint32 id, const QByteArray &payload);

    canopen::CanNetwork *m_network;
    QTimer m_timer;
    State m_state = State::Idle;
    int m_stepTimeoutMs = kStepTimeoutMs;
    canopen::NodeId m_next = 0;
    int m_count = 0;
    QList<canopen::NodeId> m_assigned;
    Error m_error;
};

} // namespace db::nm17x
