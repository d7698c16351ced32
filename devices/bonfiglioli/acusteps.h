#pragma once

// One multi-step request of the ACU axis (enable, a set-point handshake, homing, a table travel
// block) as a list of steps run one after the other on the event loop:
//
//   write(P, v) --ok--> next      waitStatus(pred) --411 read, pred true--> next
//                                 checkStatus(pred): the same with one read, no waiting
//        |                              |--fault bit or timeout--> fail
//        |                              |  (a 411 read still out at the timeout decides)
//        +--error--> fail          call(fn) --ok--> next, --error--> fail
//
// Writes go to the RAM data set (P:5). 411 comes from the axis's status source, read after the
// step asked for it (StatusSource::refresh): the source stays the connection's one reader of
// the status word. The result reply finishes when the last step is done, or fails with the
// first error; cancel() fails it at once and stops.

#include "core/reply.h"
#include "core/result.h"
#include "core/statussource.h"

#include <QElapsedTimer>
#include <QObject>
#include <QPointer>
#include <QTimer>

#include <functional>

namespace db::bonfiglioli {

class AcuAxis;

class AcuSteps : public QObject
{
    Q_OBJECT
public:
    static constexpr int kStatusReadMs = 10; // between two asks for 411 while waiting
    static constexpr quint8 kRamDataSet = 5; // data set 0 in RAM

    AcuSteps(AcuAxis *axis, const QString &name);

    QString name() const { return m_name; }
    void write(quint16 parameter, qint64 value);
    void control(quint16 word) { write(410, word); }
    // Waits until pred(411) holds; a fault (bit 3) ends the wait with the fault unless
    // faultOk, the timeout with `failText`.
    void waitStatus(std::function<bool(quint16)> pred, int timeoutMs, const QString &failText,
                    bool faultOk = false);
    // Reads 411 once; fails with `failText` unless pred(411) holds.
    void checkStatus(std::function<bool(quint16)> pred, const QString &failText);
    // Reads `parameter` (data set 0) once; fails with `failText` (Busy) unless pred(value).
    void checkValue(quint16 parameter, std::function<bool(qint64)> pred, const QString &failText);
    // 411 as the last wait or check step read it (0 before any): what the drive said when the
    // step went on, unlike the axis's polled status, which may be older.
    quint16 lastStatus() const { return m_lastStatus; }
    void call(std::function<Result<void>()> fn);
    // The reply's value when all steps are done.
    void setResult(std::function<QVariant()> fn) { m_result = std::move(fn); }

    // Starts the steps; the caller owns the reply. The steps delete themselves when done.
    Reply *start();
    void cancel(const Error &error);

private:
    struct Step
    {
        enum class Kind { Write, Wait, Check, Call } kind = Kind::Write;
        quint16 parameter = 0;
        std::function<bool(qint64)> valuePred;
        qint64 value = 0;
        std::function<bool(quint16)> pred;
        int timeoutMs = 0;
        QString failText;
        bool faultOk = false;
        std::function<Result<void>()> fn;
    };
    void next();
    void onDeadline();
    void readStatus();
    void onStatusUpdated();
    void onStatus(quint16 word);
    void readValue();
    void fail(const Error &error);

    AcuAxis *m_axis;
    QString m_name;
    QList<Step> m_steps;
    int m_index = -1;
    QPointer<Reply> m_reply;
    QTimer m_deadline;
    QTimer m_overdue; // bounds the wait for a 411 read still out at the deadline
    QElapsedTimer m_stepTimer;
    bool m_deadlinePassed = false; // the wait step now waits only for its 411 read
    QTimer m_retry;
    std::function<QVariant()> m_result;
    bool m_done = false;
    quint16 m_lastStatus = 0;
    QPointer<StatusSource> m_source;
    quint64 m_waitSerial = 0; // the source's cycle that brings 411 read after the ask
};

} // namespace db::bonfiglioli
