#pragma once

// The RefGo client (movingcap.md 3.1, 3.7): a FIFO of commands over a ByteStream, one in
// flight, each answer matched by its echo line; the queue, time limits and late-answer handling
// are the shared RequestEngine's.

#include "core/completion.h"
#include "core/reply.h"
#include "refgocodec.h"
#include "refgoframer.h"
#include "transport/requestengine.h"

#include <QObject>
#include <QStringList>

#include <functional>
#include <optional>

namespace db {
class ByteStream;
}

namespace db::refgo {

// Contract:
// - The stream is injected, not owned, and must outlive the client. The client never opens or
//   closes it; requests made while it is not open fail at once with Disconnected.
// - Every call returns a new Reply owned by the caller. It finishes exactly once: with the
//   value documented at the call, Timeout, Malformed (wrong echo, garbage), DeviceError (the
//   drive refused), or the stream's close error.
// - One command is on the wire at a time; the others wait in order. A command that timed out
//   is remembered: its late answer (the drive answers in order) is dropped and logged, never
//   given to the next request. After a timeout nothing is sent for kLateGraceMs; an answer
//   still missing then is taken as lost, so that a drive that dropped commands while it was
//   silent (a pulled cable) gets its next command's answer taken as that command's, even when
//   the lost one had the same text.
// - Device errors (the manual defines none, spec 3.7): a result line starting with "ERROR" or
//   containing '?'; for OW a result line not ending in ",OK"; for OR no numeric value field.
class RefgoClient : public QObject
{
    Q_OBJECT
public:
    static constexpr int kDefaultTimeoutMs = 1000; // the manual gives none; answers take < 80 ms
    static constexpr int kLateGraceMs = 100;
    // Timed-out commands whose answer may come.
    static constexpr int kMaxAbandoned = RequestEngineBase::kMaxAbandoned;

    explicit RefgoClient(ByteStream *stream, QObject *parent = nullptr);
    ~RefgoClient() override;

    int timeoutMs() const { return m_engine.timeoutMs(); }
    // Applies to requests sent from now on.
    void setTimeoutMs(int ms) { m_engine.setTimeoutMs(ms); }
    // Requests queued or in flight.
    int pendingCount() const { return m_engine.pendingCount(); }
    // Bytes of a partial answer held by the framer (bounded by Framer::kMaxAnswerBytes).
    qsizetype bufferedBytes() const { return m_engine.bufferedBytes(); }

    // Pass-through for the terminal: value is the result lines (QStringList). A command with
    // CR or LF in it, or an empty one, fails with InvalidArgument.
    Reply *execute(const QString &rawCommand);
    // Any command of the table but OR/OW; value as the typed calls below.
    Reply *send(Command command, std::optional<qint64> argument = std::nullopt);

    // Motion and settings (spec 3.3); their replies carry no value.
    Reply *go(std::optional<qint64> position = std::nullopt); // G / Gx
    Reply *goWay(std::optional<qint64> distance = std::nullopt); // GW / GWx
    Reply *setTargetPosition(qint64 position); // POx
    Reply *setWay(qint64 distance); // WAx
    Reply *stopMotion(); // SM
    Reply *powerContinue(); // PWC
    Reply *continueMotion(); // CM
    Reply *reference(int method); // REFx, e.g. 35, -18
    Reply *powerQuit(); // PQ
    Reply *speed(qint64 velocity); // SPx
    Reply *acceleration(qint64 value); // ACx
    Reply *deceleration(qint64 value); // DEx
    Reply *jerk(qint64 value); // ACVx
    Reply *jogPositive(std::optional<qint64> ms = std::nullopt); // JP / JPt
    Reply *jogNegative(std::optional<qint64> ms = std::nullopt); // JN / JNt
    Reply *repeatReverse(std::optional<qint64> distance = std::nullopt); // RR / RRx
    Reply *repeatWay(qint64 distance); // RWx
    Reply *waitRepeat(qint64 ms); // WTx
    Reply *setOutput(int output); // SOx
    Reply *clearOutput(int output); // COx

    // Queries.
    Reply *tellProcessStatus(); // TPSR; value: quint32 raw bits (see ProcessStatus)
    Reply *tellStatus(); // TS; value: int (SimpleStatus)
    Reply *tellPosition(); // TP; value: qlonglong
    Reply *tellInput(int input); // TIx; value: bool

    // Objects. objectRead's value is a qlonglong as the drive printed it (hex output is the
    // unsigned bit pattern); the reply's address is the object's. objectWrite carries no value.
    Reply *objectRead(ObjectAddress address, bool hexOutput = false);
    // The same value (or error) delivered to `done` with no Reply (see Completion).
    void objectRead(ObjectAddress address, Completion done, bool hexOutput = false);
    Reply *objectWrite(ObjectAddress address, const QVariant &value);

Q_SIGNALS:
    // One human-readable line per request, answer, drop or error, for the log console.
    void logLine(const QString &line);

protected:
    // logLine() is forwarded from the engine once someone listens, so that a client nobody
    // logs formats no log lines.
    void connectNotify(const QMetaMethod &signal) override;

private:
    // Turns the result lines of a matched answer to `command` into the reply's value. It gets
    // the command rather than capturing it, so that most decoders fit std::function's inline
    // storage and a request allocates no decoder.
    using Decoder =
        std::function<Result<QVariant>(const QString &command, const QStringList &lines)>;
    // RefGo for the request engine: answers framed by Framer, matched by their echo line.
    struct Protocol
    {
        using Answer = refgo::Answer;
        using Framer = refgo::Framer;
        struct Matcher
        {
            QString text; // the command as sent, which the drive echoes
            Decoder decode;
            Verdict operator()(const Answer &answer) const;
        };
        static QString summary(const Answer &answer);
        static QString identify(const Answer &answer) { return answer.echo; }
    };

    Reply *enqueue(const QString &text, Decoder decode, ObjectAddress address = {});
    void enqueue(const QString &text, Decoder decode, Completion done);
    static QByteArray line(const QString &text);
    static Decoder objectReadDecoder(ObjectAddress address);

    RequestEngine<Protocol> m_engine;
    bool m_forwardingLog = false;
};

} // namespace db::refgo
