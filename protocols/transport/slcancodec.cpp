#include "slcancodec.h"

#include <array>
#include <cstring>

namespace db::slcan {

namespace {

// Value of each hex digit, -1 for every other byte (looked up for every digit received).
constexpr auto kHexDigits = [] {
    std::array<qint8, 256> table {};
    for (int c = 0; c < 256; ++c) {
        if (c >= '0' && c <= '9')
            table[c] = qint8(c - '0');
        else if (c >= 'A' && c <= 'F')
            table[c] = qint8(c - 'A' + 10);
        else if (c >= 'a' && c <= 'f')
            table[c] = qint8(c - 'a' + 10);
        else
            table[c] = -1;
    }
    return table;
}();

std::optional<quint32> hexValue(QByteArrayView text)
{
    if (text.isEmpty())
        return std::nullopt;
    quint32 value = 0;
    int invalid = 0;
    for (const char c : text) {
        const int digit = kHexDigits[uchar(c)];
        invalid |= digit;
        value = (value << 4) | quint32(digit & 0xF);
    }
    if (invalid < 0)
        return std::nullopt;
    return value;
}

bool isHex(QByteArrayView text)
{
    return text.isEmpty() || hexValue(text).has_value();
}

Message unknown(QByteArrayView line)
{
    Message m;
    m.kind = Message::Kind::Unknown;
    m.line = line.toByteArray();
    return m;
}

// t/T/r/R lines (movingcap.md 4.2): id, DLC, data (not for r/R), optional 4-digit timestamp.
Message parseFrame(QByteArrayView line)
{
    const char type = line.at(0);
    const bool extended = type == 'T' || type == 'R';
    const bool remote = type == 'r' || type == 'R';
    const int idDigits = extended ? 8 : 3;
    if (line.size() < 1 + idDigits + 1)
        return unknown(line);
    const auto id = hexValue(line.sliced(1, idDigits));
    const char dlcChar = line.at(1 + idDigits);
    if (!id || *id > (extended ? 0x1FFFFFFFu : 0x7FFu) || dlcChar < '0' || dlcChar > '8')
        return unknown(line);
    const int dlc = dlcChar - '0';
    const qsizetype dataStart = 1 + idDigits + 1;
    const qsizetype dataDigits = remote ? 0 : 2 * dlc;
    const qsizetype rest = line.size() - dataStart - dataDigits;
    if (rest != 0 && rest != 4)
        return unknown(line);
    QByteArray payload;
    if (remote) {
        payload = QByteArray(dlc, '\0'); // Qt carries the DLC of a remote frame as payload size
    } else {
        // Decoded in place (this runs for every received frame): no copies of the hex digits.
        payload = QByteArray(dlc, Qt::Uninitialized);
        const char *hex = line.constData() + dataStart;
        char *out = payload.data();
        int invalid = 0;
        for (int i = 0; i < dlc; ++i) {
            const int high = kHexDigits[uchar(hex[2 * i])];
            const int low = kHexDigits[uchar(hex[2 * i + 1])];
            invalid |= high | low;
            out[i] = char(((high & 0xF) << 4) | (low & 0xF));
        }
        if (invalid < 0)
            return unknown(line);
    }
    Message m;
    if (rest == 4) {
        const auto stamp = hexValue(line.last(4));
        if (!stamp)
            return unknown(line);
        m.timestamp = quint16(*stamp);
    }
    m.kind = Message::Kind::Frame;
    m.frame = QCanBusFrame(*id, payload);
    m.frame.setExtendedFrameFormat(extended);
    if (remote)
        m.frame.setFrameType(QCanBusFrame::RemoteRequestFrame);
    return m;
}

Message command(QByteArrayView line)
{
    Message m;
    m.kind = Message::Kind::Command;
    m.command = line.at(0);
    m.argument = line.sliced(1).toByteArray();
    m.line = line.toByteArray();
    return m;
}

} // namespace

Message parseLine(QByteArrayView line)
{
    if (line.isEmpty()) {
        Message m;
        m.kind = Message::Kind::Ack;
        return m;
    }
    const char letter = line.at(0);
    const QByteArrayView arg = line.sliced(1);
    switch (letter) {
    case 't':
    case 'T':
    case 'r':
    case 'R':
        return parseFrame(line);
    case 'z':
    case 'Z':
        if (arg.isEmpty()) {
            Message m;
            m.kind = Message::Kind::TransmitAck;
            m.command = letter;
            // The adapter sends this for every frame: the line is a constant, not a copy.
            static const QByteArray kSmall = QByteArray::fromRawData("z", 1);
            static const QByteArray kExtended = QByteArray::fromRawData("Z", 1);
            m.line = letter == 'z' ? kSmall : kExtended;
            return m;
        }
        return letter == 'Z' && (arg == "0" || arg == "1") ? command(line) : unknown(line);
    case 'O':
    case 'C':
    case 'L':
        return arg.isEmpty() ? command(line) : unknown(line);
    case 'S':
        return arg.size() == 1 && arg.at(0) >= '0' && arg.at(0) <= '9' ? command(line)
                                                                       : unknown(line);
    case 's':
        return arg.size() == 4 && isHex(arg) ? command(line) : unknown(line);
    case 'V':
    case 'N':
        return arg.isEmpty() || arg.size() == 4 ? command(line) : unknown(line);
    case 'F':
        return arg.isEmpty() || (arg.size() == 2 && isHex(arg)) ? command(line) : unknown(line);
    default:
        return unknown(line);
    }
}

QList<Message> Decoder::feed(const QByteArray &bytes)
{
    QList<Message> out;
    feedEach(bytes, [&out](const Message &m) {
        out.append(m);
        return true;
    });
    return out;
}

void Decoder::feed(QByteArrayView bytes, Sink sink, void *context)
{
    const auto stop = [this] {
        reset();
    }; // the receiver said stop: drop the rest
    const char *const end = bytes.end();
    for (const char *p = bytes.begin(); p != end; ++p) {
        const char c = *p;
        if (c == kBell) {
            Message m;
            m.kind = Message::Kind::Bell;
            if (!sink(context, m))
                return stop();
        } else if (c == kCr || c == '\n') {
            bool go = true;
            if (m_overflow) {
                go = sink(context, unknown(m_line));
                m_overflow = false;
            } else if (c == kCr || !m_line.isEmpty()) {
                // an empty line ended by "\n" acknowledges nothing
                go = sink(context, parseLine(m_line));
            }
            m_line.resize(0); // keeps the capacity for the next partial line
            if (!go)
                return stop();
        } else if (m_line.size() < kMaxLineLength) {
            // The run of ordinary bytes up to the next terminator or BEL.
            const char *runEnd = p + 1;
            while (runEnd != end && *runEnd != kCr && *runEnd != '\n' && *runEnd != kBell)
                ++runEnd;
            if (m_line.isEmpty() && runEnd != end && *runEnd != kBell
                && runEnd - p <= kMaxLineLength) {
                // A whole line with its terminator: parsed where it lies.
                if (!sink(context, parseLine(QByteArrayView(p, runEnd))))
                    return stop();
                p = runEnd;
                continue;
            }
            const qsizetype take = qMin<qsizetype>(runEnd - p, kMaxLineLength - m_line.size());
            m_line.append(p, take);
            if (take < runEnd - p)
                m_overflow = true; // keep the first kMaxLineLength bytes for the report
            p = runEnd - 1;
        } else {
            m_overflow = true; // keep the first kMaxLineLength bytes for the report
        }
    }
}

void Decoder::reset()
{
    m_line.clear();
    m_overflow = false;
}

bool encodeFrameInto(const QCanBusFrame &frame, QByteArray &line, std::optional<quint16> timestamp)
{
    const bool remote = frame.frameType() == QCanBusFrame::RemoteRequestFrame;
    const QByteArray payload = frame.payload();
    if ((frame.frameType() != QCanBusFrame::DataFrame && !remote)
        || frame.hasFlexibleDataRateFormat() || payload.size() > 8) {
        line.resize(0);
        return false;
    }
    // Written digit by digit: this runs for every frame sent.
    static constexpr char kDigits[] = "0123456789ABCDEF";
    const bool extended = frame.hasExtendedFrameFormat();
    const int idDigits = extended ? 8 : 3;
    char text[1 + 8 + 1 + 16 + 4 + 1];
    qsizetype n = 0;
    text[n++] = extended ? (remote ? 'R' : 'T') : (remote ? 'r' : 't');
    const quint32 id = frame.frameId();
    for (int shift = 4 * (idDigits - 1); shift >= 0; shift -= 4)
        text[n++] = kDigits[(id >> shift) & 0xF];
    text[n++] = char('0' + payload.size());
    if (!remote) {
        for (const char byte : payload) {
            text[n++] = kDigits[(uchar(byte) >> 4) & 0xF];
            text[n++] = kDigits[uchar(byte) & 0xF];
        }
    }
    if (timestamp) {
        for (int shift = 12; shift >= 0; shift -= 4)
            text[n++] = kDigits[(*timestamp >> shift) & 0xF];
    }
    text[n++] = kCr;
    line.resize(n);
    std::memcpy(line.data(), text, size_t(n));
    return true;
}

QByteArray encodeFrame(const QCanBusFrame &frame, std::optional<quint16> timestamp)
{
    QByteArray line;
    encodeFrameInto(frame, line, timestamp);
    return line;
}

QByteArray encodeCommand(char command, const QByteArray &argument)
{
    return QByteArray(1, command) + argument + kCr;
}

namespace {
constexpr int kBitrates[] = {
    10000, 20000, 50000, 100000, 125000, 250000, 500000, 800000, 1000000
};
} // namespace

std::optional<int> bitrateCode(int bitsPerSecond)
{
    for (int code = 0; code < int(std::size(kBitrates)); ++code) {
        if (kBitrates[code] == bitsPerSecond)
            return code;
    }
    return std::nullopt;
}

std::optional<int> bitrateForCode(int code)
{
    if (code < 0 || code >= int(std::size(kBitrates)))
        return std::nullopt;
    return kBitrates[code];
}

} // namespace db::slcan
