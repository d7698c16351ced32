#include "slcanbus.h"

#include <QLoggingCategory>

namespace db {

Q_LOGGING_CATEGORY(lcSlcan, "drivebench.transport.slcan")
Q_LOGGING_CATEGORY(lcSlcanRaw, "drivebench.transport.slcan.raw", QtWarningMsg)

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
    const QByteArray line = slcan::encodeFrame(frame);
    if (line.isEmpty()) {
        Q_EMIT warning(QStringLiteral("%1: cannot send frame %2 over slcan (FD, error frame or "
                                      "more than 8 bytes)")
                           .arg(name(), frame.toString()));
        return;
    }
    qCDebug(lcSlcanRaw) << name() << "->" << line;
    m_stream->write(line);
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
    for (const slcan::Message &m : m_decoder.feed(bytes)) {
        switch (m.kind) {
        case slcan::Message::Kind::Frame:
            deliver(m.frame);
            break;
        case slcan::Message::Kind::Bell:
            Q_EMIT warning(QStringLiteral("%1: the adapter answered BEL (command or frame refused)")
                               .arg(name()));
            break;
        case slcan::Message::Kind::Unknown:
            Q_EMIT warning(QStringLiteral("%1: skipped a line that is not slcan: '%2'")
                               .arg(name(), QString::fromLatin1(m.line.toPercentEncoding(" "))));
            break;
        case slcan::Message::Kind::Ack:
        case slcan::Message::Kind::TransmitAck:
        case slcan::Message::Kind::Command:
            break; // spec 4.2: replies are ignored
        }
    }
}

void SlcanBus::setConnectTimeoutMs(int ms)
{
    m_stream->setConnectTimeoutMs(ms);
}

} // namespace db
