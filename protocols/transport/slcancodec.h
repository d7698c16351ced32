#pragma once

// Pure codec for the slcan ASCII set (Lawicel / VSCOM "ASCII command set"; movingcap.md 4.2).
// Bytes in, messages out; no I/O, no timers. Used by SlcanBus (host side) and SlcanServer
// (adapter side, for the simulators), so it parses both directions without knowing its role:
// "V" is a version query, "V1013" a version reply; "Z" alone is an extended-frame transmit ack,
// "Z1" the timestamp command.

#include <QByteArray>
#include <QCanBusFrame>
#include <QList>

#include <optional>
#include <type_traits>

namespace db::slcan {

constexpr char kCr = '\r';
constexpr char kBell = '\a';
// A line longer than this without terminator is garbage (the longest valid line, an extended
// frame with 8 bytes and a timestamp, has 1 + 8 + 1 + 16 + 4 = 30 characters).
constexpr qsizetype kMaxLineLength = 64;

struct Message
{
    enum class Kind {
        Frame, // t/T/r/R line: frame (and timestamp when present)
        Ack, // empty line: "\r" = OK
        TransmitAck, // "z" (standard) or "Z" (extended): frame queued by the adapter
        Bell, // BEL (0x07): the adapter refused the last command
        Command, // a letter with an argument: O, C, L, Sn, sxxyy, V[xxxx], N[xxxx], F[xx], Zn
        Unknown, // anything else (line kept in `line`); skipped by the users
    };

    Kind kind = Kind::Unknown;
    QCanBusFrame frame; // Frame
    std::optional<quint16> timestamp; // Frame, when a 4-hex-digit timestamp followed (ms)
    char command = 0; // Command letter; 'z'/'Z' for TransmitAck
    QByteArray argument; // Command: text after the letter ("4" for S4, "0314" for s0314)
    QByteArray line; // the line without its terminator (for logs and Unknown); empty for Frame
};

// Splits a byte stream into messages. Tolerant: lines may end in "\r", "\r\n" or "\n"; an
// empty line ended by "\n" is ignored (only "\r" acknowledges); BEL is a message of its own
// wherever it occurs; bytes past kMaxLineLength without terminator are dropped and reported as
// one Unknown message. Input may be split anywhere.
class Decoder
{
public:
    QList<Message> feed(const QByteArray &bytes);
    // The same, without a list: calls onMessage(const Message &) for each message as soon as
    // it is complete. onMessage returns false to stop: the rest of bytes and any partial line
    // are then discarded. Lines that lie whole in bytes are parsed in place (no copy), which is
    // what a receiver of every frame wants.
    template<typename F>
    void feedEach(QByteArrayView bytes, F &&onMessage)
    {
        feed(bytes, &Decoder::call<std::remove_reference_t<F>>, &onMessage);
    }
    qsizetype pendingBytes() const { return m_line.size(); }
    void reset();

private:
    using Sink = bool (*)(void *context, const Message &message);
    template<typename F>
    static bool call(void *context, const Message &message)
    {
        return (*static_cast<F *>(context))(message);
    }
    void feed(QByteArrayView bytes, Sink sink, void *context);

    QByteArray m_line;
    bool m_overflow = false;
};

// One complete line (without terminator) -> message. Frames must have exactly DLC data bytes
// and optionally 4 more hex digits of timestamp; ids above 7FF (t/r) or 1FFFFFFF (T/R), DLC
// above 8 and non-hex digits make the line Unknown.
Message parseLine(QByteArrayView line);

// "t63284041600000000000\r": uppercase hex, terminator included; timestamp appended when given.
// Frames that cannot be expressed (FD, error frames, more than 8 bytes) give an empty array.
QByteArray encodeFrame(const QCanBusFrame &frame, std::optional<quint16> timestamp = {});
// The same into `line`, whose storage is reused when nothing else holds it (no allocation per
// frame); false, and `line` empty, for a frame that cannot be expressed.
bool encodeFrameInto(const QCanBusFrame &frame, QByteArray &line,
                     std::optional<quint16> timestamp = {});
// "S4\r", "O\r"
QByteArray encodeCommand(char command, const QByteArray &argument = {});

// Sn codes of movingcap.md 4.2: 125000 -> 4. S9 (83.3k) is left out: not every adapter has it.
std::optional<int> bitrateCode(int bitsPerSecond);
std::optional<int> bitrateForCode(int code);

} // namespace db::slcan
