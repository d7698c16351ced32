#pragma once

// Drive-side supervision of the tool: configures a CANopen drive so that it stops by itself
// when the tool stops talking to it (process killed, PC asleep, cable pulled), whatever the
// tool's own event loop does.
//
// - Heartbeat, when the dictionary has 1016h: the network's HeartbeatProducer (node
//   HeartbeatProducer::nodeId(), every kPeriodMs) and the drive's consumer heartbeat time
//   1016h:01 = that node, kReactionMs.
// - Node guarding, when it has 100Ch/100Dh but no 1016h (the MovingCap, movingcap.md 4.4): guard
//   time 100Ch = kPeriodMs, life time factor 100Dh = kLifeTimeFactor (node life time
//   kReactionMs) and the network's NodeGuarding for the node.
// - In both cases 6007h (abort connection option code, CiA 402) := 3, quick stop, when it is
//   described; otherwise the drive's own reaction to the event applies.
//
// arm() reads the previous values, writes the new ones (6007h first, supervision last, so a
// failure part-way never starts the supervision) and then starts our side; disarm() writes the
// previous values back and stops our side. Destroying an armed supervision stops our side
// without restoring anything: the drive reacts as if the tool had died.
// Replies belong to the caller; one arm()/disarm() at a time.

#include "canopenids.h"
#include "core/deviceconnection.h"

#include <QObject>
#include <QPointer>

#include <functional>
#include <memory>

namespace db::canopen {

class CanNetwork;

class DriveSupervision : public QObject
{
    Q_OBJECT
public:
    static constexpr int kPeriodMs = 100; // our heartbeat period, guard time
    static constexpr int kLifeTimeFactor = 5;
    // The drive reacts this long after the last heartbeat / guard request it got.
    static constexpr int kReactionMs = kPeriodMs * kLifeTimeFactor;
    static constexpr int kAbortQuickStop = 3; // 6007h value

    enum class Mode { None, Heartbeat, Guarding };

    // connection is not owned; it must stay alive while an arm()/disarm() runs.
    explicit DriveSupervision(DeviceConnection *connection, QObject *parent = nullptr);
    ~DriveSupervision() override;

    // What this connection's drive offers (None for a non-CANopen connection).
    static Mode modeFor(const DeviceConnection *connection);
    Mode mode() const { return m_mode; }
    bool isArmed() const { return m_armed; }
    // For the GUI and the CLI: what stops the drive when the tool goes away.
    QString description() const;

    Reply *arm();
    Reply *disarm();

private:
    struct Step
    {
        std::function<Reply *()> start; // may return nullptr: a step without a request
        std::function<void(const QVariant &)> done; // value of a successful request
    };
    struct Run
    {
        QList<Step> steps;
        QPointer<Reply> result;
        QString what;
    };
    Reply *run(const QList<Step> &steps, const QString &what);
    void runFrom(const std::shared_ptr<Run> &run, int step);
    void startOurSide();
    void stopOurSide();
    bool hasAbortOption() const;

    QPointer<DeviceConnection> m_connection;
    // Kept apart from the connection: our side must stop even when the connection goes first.
    QPointer<CanNetwork> m_network;
    NodeId m_node = 0;
    Mode m_mode = Mode::None;
    bool m_armed = false;
    bool m_ourSideRunning = false;
    QVariant m_previousAbort;
    QVariant m_previousConsumer;
    QVariant m_previousGuardTime;
    QVariant m_previousLifeFactor;
};

} // namespace db::canopen
