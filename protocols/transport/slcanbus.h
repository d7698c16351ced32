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

protected:
    void doOpen() override;
    void doClose() override;
    void doSend(const QCanBusFrame &frame) override;

private:
    void onStreamOpened();
    void onStreamClosed(const Error &error);
    void onReceived(const QByteArray &bytes);

    ByteStream *m_stream;
    int m_bitrate;
    slcan::Decoder m_decoder;
};

} // namespace db
