#pragma once

#include "bytestream.h"
#include "canbus.h"
#include "slcancodec.h"

#include <memory>

namespace db {

// CAN over the slcan ASCII protocol on a byte stream, e.g. TCP port 15001 of a MovingCap ETH
// drive (movingcap.md 4): "canopen+slcan://HOST:15001?node=50".
//
// Open: opens the stream, then sends "C\r", "S<n>\r" (from the bitrate; left out when the
// bitrate has no slcan code or is 0) and "O\r" once, and is open as soon as they are written:
// as spec 4.2 recommends it never waits for the adapter's answers, because the drive only
// speaks "similar to" slcan. Replies "\r", "z\r", "Z\r" and V/N/F answers are ignored; BEL and
// unparsable lines are reported through warning() and skipped; only t/T/r/R lines become
// frameReceived(). Close sends "C\r" and closes the stream; a stream that fails closes the bus
// with the stream's error.
//
// Receive queue: received bytes wait in a backlog of at most kMaxBacklogBytes (whole lines;
// about CanBus::kMaxReceiveQueueFrames frames) and are decoded kSliceBytes per event-loop pass.
// Lines that arrive while the backlog is full are dropped and reported (reportDropped()).
class SlcanBus : public CanBus
{
    Q_OBJECT
public:
    static constexpr int kDefaultBitrate = 125000; // Kickdrive's setting for the drive (4.1)

    // Takes ownership of stream (it becomes a child of the bus). bitrate in bit/s.
    explicit SlcanBus(ByteStream *stream, int bitrate = kDefaultBitrate, QObject *parent = nullptr);
    ~SlcanBus() override;

    QString name() const override; // "slcan 127.0.0.1:15001"
    ByteStream *stream() const { return m_stream; }
    void setConnectTimeoutMs(int ms) override;
    int bitrate() const { return m_bitrate; }

    static constexpr qsizetype kSliceBytes = CanBus::kReceiveSliceFrames * 16;
    static constexpr qsizetype kMaxBacklogBytes = CanBus::kMaxReceiveQueueFrames * 16;
    // Received bytes not decoded yet, and the most there ever were.
    qsizetype backlogBytes() const { return m_backlog.size(); }
    qsizetype peakBacklogBytes() const { return m_peakBacklog; }

protected:
    void doOpen() override;
    void doClose() override;
    void doSend(const QCanBusFrame &frame) override;

private:
    void onStreamOpened();
    void onStreamClosed(const Error &error);
    void onReceived(const QByteArray &bytes);
    void enqueue(const QByteArray &bytes);
    void drain();
    void decode(const QByteArray &slice);
    void handle(const slcan::Message &m);

    ByteStream *m_stream;
    int m_bitrate;
    slcan::Decoder m_decoder;
    QByteArray m_backlog; // received, not decoded yet
    QByteArray m_sendLine; // the line of the frame being sent; its storage is reused
    qsizetype m_peakBacklog = 0;
    bool m_skipping = false; // dropping the rest of a line that did not fit
    bool m_drainScheduled = false;
    bool m_draining = false;
};

} // namespace db
