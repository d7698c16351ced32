#pragma once

// Splits a VABus/TCP byte stream into telegrams (chapter 7.1: a telegram is NoB + 2 bytes; TCP
// adds no length prefix and may split or join telegrams anywhere). Pure: bytes in, frames out.

#include "core/result.h"
#include "vabuscodec.h"

#include <vector>

namespace db::vabus {

// One unit the framer found in the stream.
struct Frame
{
    enum class Kind {
        Telegram, // a well-formed telegram
        Nak, // a single NAK byte (0x15): the device refused the telegram
        Garbage, // bytes that are no telegram; the framer dropped them
    };
    Kind kind = Kind::Telegram;
    Telegram telegram; // for Kind::Telegram
    QByteArray bytes; // as received
    QString problem; // for Nak and Garbage: what was wrong, for messages

    friend bool operator==(const Frame &, const Frame &) = default;
};

// Framing rules:
// - A byte 0x15 where a telegram would start is a NAK on its own.
// - A header with bits 5..0 set, a NoB below 4 or above 103, or an error answer whose NoB is
//   not 6 makes everything buffered garbage: the framer cannot find the next telegram start
//   in a binary stream, so it drops what it holds and starts afresh with the next bytes.
// - Otherwise bytes are held until NoB + 2 of them have arrived (at most kMaxTelegramBytes).
class Framer
{
public:
    // Bytes may be split anywhere. Returns the frames they complete, in order.
    std::vector<Result<Frame>> feed(const QByteArray &bytes);
    // Forgets a partial telegram (after a disconnect or a timed-out transmission).
    void reset() { m_buffer.clear(); }
    qsizetype bufferedBytes() const { return m_buffer.size(); }

private:
    QByteArray m_buffer;
};

} // namespace db::vabus
