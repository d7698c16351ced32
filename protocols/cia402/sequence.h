#pragma once

#include "core/deviceconnection.h"
#include "core/statussource.h"

#include <QElapsedTimer>
#include <QPointer>
#include <QTimer>

#include <functional>

namespace db::cia402 {

// The statusword 6041h object every CiA 402 procedure watches.
constexpr ObjectAddress kStatusword { 0x6041, 0 };
constexpr ObjectAddress kControlword { 0x6040, 0 };

// What a wait step makes of one statusword.
enum class WaitVerdict { Pending, Reached, Failed };

// A CiA 402 procedure as a list of steps run one after the other over any DeviceConnection
// (RefGo OR/OW or CANopen SDO): writes, and waits on the statusword with a time limit.
//
// A wait takes the statusword from the connection's status source (a CiA 402 one is made when
// the connection has none), asking it for a value read after now (StatusSource::refresh): the
// source stays the one reader of 6041h on the connection, and every view sees what the
// procedure sees.
//
//   Idle --start()--> Running(step i) --write ok / wait Reached--> Running(step i+1) ...
//                        |   wait Pending: ask for 6041h again after kPollIntervalMs
//                        |   wait deadline passed       --> Failed (Timeout, names the step)
//                        |     ... but its status read still out: judged by that read when it
//                        |         comes (Reached: next step; Pending: Failed; read failed:
//                        |         Failed with the read's error, e.g. no answer)
//                        |   write/read error, Failed   --> Failed (the cause)
//                        |   cancel()                   --> Failed (the given error)
//                        +-- after the last step        --> Finished (value: last statusword)
//
// The reply from start() finishes exactly once; the caller owns it. The sequence deletes
// itself after it has finished (deleteLater), so callers keep only a QPointer.
class Sequence : public QObject
{
    Q_OBJECT
public:
    static constexpr int kPollIntervalMs = 10;
    static constexpr int kDefaultStepTimeoutMs = 1000;

    using Check = std::function<WaitVerdict(quint16 statusword, QString &why)>;

    explicit Sequence(DeviceConnection *connection, QString name, QObject *parent = nullptr);
    ~Sequence() override;

    Sequence *write(ObjectAddress address, const QVariant &raw);
    Sequence *controlword(quint16 value) { return write(kControlword, value); }
    // Polls 6041h until check says Reached (next step) or Failed, or timeoutMs passes.
    Sequence *waitFor(QString what, Check check, int timeoutMs = kDefaultStepTimeoutMs);
    // Runs code between steps (e.g. to decide the next steps from the last statusword).
    Sequence *call(std::function<void(Sequence *)> action);

    Reply *start();
    void cancel(const Error &error);
    bool isRunning() const { return m_reply && !m_reply->isFinished(); }
    quint16 lastStatusword() const { return m_statusword; }
    const QString &name() const { return m_name; }

private:
    struct Step
    {
        enum class Kind { Write, Wait, Call } kind;
        ObjectAddress address;
        QVariant value;
        QString what;
        Check check;
        int timeoutMs = 0;
        std::function<void(Sequence *)> action;
    };

    void runStep();
    void poll();
    void onDeadline();
    void failNoAnswer();
    void failNotReached();
    void onStatusUpdated();
    void onStatus(quint16 statusword);
    void next();
    void fail(const Error &error);
    void finishOk();

    DeviceConnection *m_connection;
    QString m_name;
    QList<Step> m_steps;
    int m_index = 0;
    QPointer<Reply> m_reply;
    QPointer<Reply> m_request; // the write in flight
    QPointer<StatusSource> m_source;
    quint64 m_waitSerial = 0; // the source's cycle that brings a statusword read after the ask
    QTimer m_pollTimer;
    QTimer m_deadline;
    QTimer m_overdue; // bounds the wait for a status read still out at the deadline
    QElapsedTimer m_stepTimer;
    quint16 m_statusword = 0;
    bool m_answeredInStep = false; // a status read of the current wait step was answered
    bool m_deadlinePassed = false; // ... and the step now waits only for its status read
};

// Convenience checks.
Sequence::Check bitsSet(quint16 mask, bool failOnFault = true);
Sequence::Check bitsClear(quint16 mask, bool failOnFault = true);

} // namespace db::cia402
