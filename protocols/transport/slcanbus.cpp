#include "slcanbus.h"

#include <QCoreApplication>
#include <QLoggingCategory>
#include <QTimer>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::transport)
};
} // namespace

namespace db {

Q_LOGGING_CATEGORY(lcSlcan, "drivebench.transport.slcan")
Q_LOGGING_CATEGORY(lcSlcanRaw, "drivebench.transport.slcan.raw", QtWarningMsg)

namespace {
bool isTerminator(char c)
{
    return c == slcan::kCr || c == '\n';
}

// Frame lines (t/T/r/R at a line start) in bytes that start at a line start.
qint64 countFrameLines(QByteArrayView bytes)
{
    qint64 frames = 0;
    bool lineStart = true;
    for (const char c : bytes) {
        if (lineStart && (c == 't' || c == 'T' || c == 'r' || c == 'R'))
            ++frames;
        lineStart = isTerminator(c);
    }
    return frames;
}
} // namespace

SlcanBus::SlcanBus(ByteStream *stream, int bitrate, QObject *parent)
    : CanBus(parent)
    , m_stream(stream)
    , m_bitrate(bitrate)
{
    Q_ASSERT(stream);
    m_stream->setParent(this);
    connect(m_stream, &ByteStream::opened, this, &SlcanBus::onStreamOpened);
    connect(m_stream, &ByteStream::closed, this, &SlcanBus::onStreamClosed);
    connect(m_stream, &ByteStream::received, this, &SlcanBus::onReceived);
}

SlcanBus::~SlcanBus()
{
    m_stream->disconnect(this);
}

QString SlcanBus::name() const
{
    return QStringLiteral("slcan ") + m_stream->peerName();
}

void SlcanBus::doOpen()
{
    m_decoder.reset();
    m_backlog.clear();
    m_skipping = false;
    if (m_stream->isOpen())
        onStreamOpened();
    else
        m_stream->open();
}

void SlcanBus::doClose()
{
    if (m_stream->isOpen())
        m_stream->write(slcan::encodeCommand('C'));
    if (m_stream->state() == ByteStream::State::Closed)
        setClosed();
    else
        m_stream->close(); // closed() follows
}

void SlcanBus::doSend(const QCanBusFrame &frame)
{
    if (!slcan::encodeFrameInto(frame, m_sendLine)) {
        Q_EMIT warning(Tr::tr("%1: cannot send frame %2 over slcan (FD, error frame or "
                              "more than 8 bytes)")
                           .arg(name(), frame.toString()));
        return;
    }
    qCDebug(lcSlcanRaw) << name() << "->" << m_sendLine;
    m_stream->write(m_sendLine);
    reportSent(frame);
}

void SlcanBus::onStreamOpened()
{
    if (state() != State::Opening)
        return;
    // Spec 4.2 recommendation for the commissioning tool: C, S4, O once; answers are ignored.
    QByteArray setup = slcan::encodeCommand('C');
    if (const auto code = slcan::bitrateCode(m_bitrate))
        setup += slcan::encodeCommand('S', QByteArray::number(*code));
    else if (m_bitrate != 0)
        qCWarning(lcSlcan) << name() << ": no slcan code for" << m_bitrate
                           << "bit/s; leaving the adapter's bit rate";
    setup += slcan::encodeCommand('O');
    qCDebug(lcSlcanRaw) << name() << "->" << setup;
    m_stream->write(setup);
    qCDebug(lcSlcan) << name() << "open";
    setOpened();
}

void SlcanBus::onStreamClosed(const Error &error)
{
    if (error.isError())
        qCDebug(lcSlcan) << name() << "closed:" << error.toString();
    setClosed(error);
}

void SlcanBus::onReceived(const QByteArray &bytes)
{
    qCDebug(lcSlcanRaw) << name() << "<-" << bytes;
    if (m_backlog.isEmpty() && !m_skipping && !m_draining && bytes.size() <= kSliceBytes) {
        // The usual case, a few frames with nothing waiting: decoded as they are, not copied
        // through the backlog.
        m_peakBacklog = qMax(m_peakBacklog, bytes.size());
        m_draining = true;
        decode(bytes);
        return;
    }
    enqueue(bytes);
    drain();
}

// Appends whole lines while the backlog has room and drops the rest of the chunk, so the
// decoder never sees the front of one line glued to the end of another. The line that
// completes the backlog's last one is always kept (at most kMaxLineLength bytes over).
void SlcanBus::enqueue(const QByteArray &bytes)
{
    QByteArrayView rest(bytes);
    if (m_skipping) {
        qsizetype end = 0;
        while (end < rest.size() && !isTerminator(rest[end]))
            ++end;
        if (end == rest.size())
            return;
        m_skipping = false;
        rest = rest.sliced(end + 1);
    }
    const qsizetype room = kMaxBacklogBytes - m_backlog.size();
    qsizetype keep = rest.size();
    if (keep > room) {
        keep = qMin(rest.size(), qMax<qsizetype>(room, 0) + slcan::kMaxLineLength + 1);
        while (keep > 0 && !isTerminator(rest[keep - 1]))
            --keep;
        const QByteArrayView dropped = rest.sliced(keep);
        m_skipping = !isTerminator(dropped.back());
        reportDropped(countFrameLines(dropped));
    }
    m_backlog.append(rest.first(keep));
    m_peakBacklog = qMax(m_peakBacklog, m_backlog.size());
}

// Decodes one slice; the rest waits for the next event-loop pass so that timers and other
// sockets are served during a flood.
void SlcanBus::drain()
{
    if (m_draining)
        return; // a receiver's slot fed the stream again: the running drain goes on
    m_draining = true;
    const QByteArray slice = m_backlog.first(qMin(kSliceBytes, m_backlog.size()));
    m_backlog.remove(0, slice.size());
    decode(slice);
}

// Hands the messages of one slice to their receivers (m_draining is set), then schedules the
// rest of the backlog.
void SlcanBus::decode(const QByteArray &slice)
{
    m_decoder.feedEach(slice, [this](const slcan::Message &m) {
        handle(m);
        return state() == State::Open; // else a receiver closed the bus
    });
    m_draining = false;
    if (state() != State::Open) {
        m_backlog.clear();
        return;
    }
    if (!m_backlog.isEmpty() && !m_drainScheduled) {
        m_drainScheduled = true;
        QTimer::singleShot(0, this, [this] {
            m_drainScheduled = false;
            drain();
        });
    }
}

void SlcanBus::handle(const slcan::Message &m)
{
    switch (m.kind) {
    case slcan::Message::Kind::Frame:
        deliver(m.frame);
        break;
    case slcan::Message::Kind::Bell:
        Q_EMIT warning(
            Tr::tr("%1: the adapter answered BEL (command or frame refused)").arg(name()));
        break;
    case slcan::Message::Kind::Unknown:
        Q_EMIT warning(Tr::tr("%1: skipped a line that is not slcan: '%2'")
                           .arg(name(), QString::fromLatin1(m.line.toPercentEncoding(" "))));
        break;
    case slcan::Message::Kind::Ack:
    case slcan::Message::Kind::TransmitAck:
    case slcan::Message::Kind::Command:
        break; // spec 4.2: replies are ignored
    }
}

void SlcanBus::setConnectTimeoutMs(int ms)
{
    m_stream->setConnectTimeoutMs(ms);
}

} // namespace db
