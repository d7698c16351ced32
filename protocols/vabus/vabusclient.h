#pragma once

// The VABus/TCP client (chapter 7): one telegram on the wire at a time over a ByteStream, every
// answer checked against its request; queue, time limits, retransmissions, late answers and the
// keep-alive are the shared RequestEngine's.

#include "core/datatype.h"
#include "core/reply.h"
#include "transport/requestengine.h"
#include "vabuscodec.h"
#include "vabusframer.h"

#include <QObject>

#include <optional>

namespace db {
class ByteStream;
}

namespace db::vabus {

// Contract:
// - The stream is injected, not owned, and must outlive the client. The client never opens or
//   closes it; requests made while it is not open fail at once with Disconnected.
// - Every call returns a new Reply owned by the caller that finishes exactly once: with the
//   value documented at the call, DeviceError (an E = 1 answer; deviceCode() is the VABus error
//   code, the message its text), Malformed (garbage, NAK or wrong data in every transmission),
//   Timeout, InvalidArgument (nothing sent), or the stream's close error.
// - An answer belongs to a request when it has the request's R/W bit, SYS, data set and
//   parameter number. Anything else is no answer to it: it is logged and dropped, and the
//   request is sent again when its time runs out. A NAK byte, garbage, a write echo whose data
//   differs from what was sent, or a read value whose size does not fit the parameter's type
//   fail that transmission: the request goes out again at once. At most kMaxTransmissions in
//   all (7.1.2: "in total three transmissions"). After a timeout the client waits kLateGraceMs
//   for late answers before it sends anything else.
// - Keep-alive: while the stream is open, parameter 411 (status word) is read whenever nothing
//   has been sent for keepAliveIdleMs(), so that the inverter's 10 s communication watchdog
//   (parameter 388) never fires while we are connected.
class VabusClient : public QObject
{
    Q_OBJECT
public:
    static constexpr int kDefaultTimeoutMs = 1000; // the protocol defines none; well below 10 s
    static constexpr int kMaxTransmissions = 3;
    // After a request failed with a timeout nothing is sent for this long; an answer that has
    // not come by then is taken as lost (the inverter answers in order, and an identical
    // request would otherwise take its late answer for its own).
    static constexpr int kLateGraceMs = 200;
    static constexpr int kWatchdogMs = 10000; // the inverter's supervision of the PLC port
    static constexpr int kDefaultKeepAliveIdleMs = 3000; // leaves room for 2 lost keep-alives
    static constexpr quint16 kKeepAliveParameter = 411;

    explicit VabusClient(ByteStream *stream, QObject *parent = nullptr);
    ~VabusClient() override;

    int timeoutMs() const { return m_engine.timeoutMs(); }
    // Applies to requests sent from now on.
    void setTimeoutMs(int ms) { m_engine.setTimeoutMs(ms); }
    // SYS byte: 0x00 for the inverter behind the module, 0x40 + id for system bus slave id.
    quint8 sys() const { return m_sys; }
    void setSys(quint8 sys);
    // 0 turns the keep-alive off.
    int keepAliveIdleMs() const { return m_keepAliveIdleMs; }
    void setKeepAliveIdleMs(int ms);
    bool isKeepAliveScheduled() const { return m_engine.isKeepAliveScheduled(); }
    int pendingCount() const { return m_engine.pendingCount(); }
    qsizetype bufferedBytes() const { return m_engine.bufferedBytes(); }

    // Reads parameter:dataSet (data set 0-4). Value: the raw value of `type` (codec's
    // canonical C++ type), or, without a type, as typeForSize() of the answer's data.
    Reply *read(quint16 parameter, quint8 dataSet, std::optional<DataType> type = std::nullopt,
                ObjectAddress address = {});
    // The same value (or error) delivered to `done` with no Reply (see Completion).
    void read(quint16 parameter, quint8 dataSet, std::optional<DataType> type, Completion done);
    // Writes a raw value of `type` to parameter:dataSet (0-9; 5-9 are RAM). No value.
    Reply *write(quint16 parameter, quint8 dataSet, DataType type, const QVariant &raw,
                 ObjectAddress address = {});
    // Writes the data bytes as they are (for strings and block telegrams). No value.
    Reply *writeData(quint16 parameter, quint8 dataSet, const QByteArray &data,
                     ObjectAddress address = {});

Q_SIGNALS:
    // One human-readable line per request, answer, drop or error, for the log console.
    void logLine(const QString &line);

protected:
    // logLine() is forwarded from the engine once someone listens, so that a client nobody
    // logs formats no log lines.
    void connectNotify(const QMetaMethod &signal) override;

private:
    struct Protocol
    {
        using Answer = Frame;
        using Framer = vabus::Framer;
        struct Matcher
        {
            Telegram request;
            std::optional<DataType> type; // reads: how to decode the value
            Verdict operator()(const Answer &answer) const;
        };
        static QString summary(const Answer &answer);
        static QString identify(const Answer &answer);
    };

    Reply *submit(const Telegram &request, std::optional<DataType> type, ObjectAddress address);
    void submit(const Telegram &request, std::optional<DataType> type, Completion done);
    void updateKeepAlive();

    RequestEngine<Protocol> m_engine;
    quint8 m_sys = 0;
    int m_keepAliveIdleMs = kDefaultKeepAliveIdleMs;
    bool m_forwardingLog = false;
};

// "372:2" (parameter:data set), for messages.
QString label(const Telegram &telegram);

} // namespace db::vabus
