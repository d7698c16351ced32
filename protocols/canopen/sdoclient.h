#pragma once

// The SDO client (CiA 301 7.2.4): expedited, segmented and block upload/download to any node
// on one CanBus, through the default SDO channel (600h/580h + node id).
//
// Contracts:
// - upload()/download() never block and return a Reply the caller owns; it always finishes
//   (value, SDO abort as Error::Kind::DeviceError with abortText() and the code, Timeout,
//   Malformed, Disconnected). An upload's value is the QByteArray received.
// - One transfer in flight per node; later requests to the same node wait in a FIFO queue.
//   Different nodes run in parallel.
// - The timeout is per response: it restarts with every server frame that moves the transfer
//   on, so long block transfers do not need a long timeout. On timeout an abort (05040000) is
//   sent and the node's channel stays quiet for kLateGraceMs before the next request, so a late
//   answer cannot be taken for the next request's.
// - Frames that belong to no transfer (late, foreign, wrong echo) are dropped and logged.
// - The next frame goes out from the receive handler (no timer hop), so the round-trip rate is
//   bound by the link, not the engine.

#include "canopenids.h"
#include "core/completion.h"
#include "core/reply.h"
#include "sdotransfer.h"

#include <QPointer>

#include <map>
#include <memory>

namespace db {
class CanBus;
}
class QCanBusFrame;

namespace db::canopen {

class SdoClient : public QObject
{
    Q_OBJECT
public:
    enum class Mode {
        Auto, // expedited <= 4 bytes, else segmented; block for large data when enabled
        Expedited, // download: 1..4 bytes only; upload: the server chooses (same as Segmented)
        Segmented,
        Block,
    };
    Q_ENUM(Mode)

    static constexpr int kDefaultTimeoutMs = 1000;
    static constexpr int kDefaultBlockThreshold = 64; // bytes: Auto uses block above this
    static constexpr int kDefaultBlockSize = 127; // segments per sub-block we ask for (upload)
    static constexpr int kLateGraceMs = 20; // after a timeout, before the node's next request

    // The bus is not owned and must outlive the client.
    explicit SdoClient(CanBus *bus, QObject *parent = nullptr);
    ~SdoClient() override;

    // Applies to requests made afterwards.
    int timeoutMs() const { return m_timeoutMs; }
    void setTimeoutMs(int ms) { m_timeoutMs = qMax(1, ms); }
    // Whether Auto may choose block transfers (off by default: not every server has them).
    bool blockEnabled() const { return m_blockEnabled; }
    void setBlockEnabled(bool enabled) { m_blockEnabled = enabled; }
    int blockThreshold() const { return m_blockThreshold; }
    void setBlockThreshold(int bytes) { m_blockThreshold = qMax(0, bytes); }
    int blockSize() const { return m_blockSize; }
    void setBlockSize(int segments);

    // expectedSize: what the caller knows of the object's size (-1 unknown, e.g. a string or
    // domain); with Auto and block enabled, unknown or large objects go by block upload.
    Reply *upload(NodeId node, ObjectAddress address, Mode mode = Mode::Auto,
                  int expectedSize = -1);
    Reply *download(NodeId node, ObjectAddress address, const QByteArray &data,
                    Mode mode = Mode::Auto);
    // The same results delivered to `done` with no Reply (see Completion).
    void upload(NodeId node, ObjectAddress address, Completion done, Mode mode = Mode::Auto,
                int expectedSize = -1);
    void download(NodeId node, ObjectAddress address, const QByteArray &data, Completion done,
                  Mode mode = Mode::Auto);

    // Requests in flight or queued for a node.
    int pending(NodeId node) const;
    // Server frames dropped because they belonged to no transfer (for tests and the monitor).
    int droppedFrames() const { return m_dropped; }
    // Fails every queued and running transfer (no abort frames are sent).
    void cancelAll(const Error &error);
    // The same for one node's transfers only (its connection closes; others go on).
    void cancelNode(NodeId node, const Error &error);

Q_SIGNALS:
    // One readable line per notable event (abort, timeout, dropped frame) for the log console.
    void logLine(const QString &line);

private:
    struct Job;
    struct Channel;

    void enqueue(NodeId node, std::unique_ptr<SdoTransfer> transfer, Completion done, bool upload);
    Channel &channel(NodeId node);
    void startNext(Channel &ch);
    void onFrame(const QCanBusFrame &frame);
    void apply(Channel &ch, const SdoStep &step);
    bool sendAll(Channel &ch, const QByteArrayList &frames);
    // later: a handler is called from the loop (a cancellation, or inside a request call).
    void finishActive(Channel &ch, const Error &error, const QByteArray &data = {},
                      bool later = false);
    void onTimeout(Channel &ch);
    void cancelChannel(Channel &ch, const Error &error);
    void drop(NodeId node, const QByteArray &payload, const QString &why);

    CanBus *m_bus;
    std::map<NodeId, std::unique_ptr<Channel>> m_channels;
    int m_timeoutMs = kDefaultTimeoutMs;
    bool m_blockEnabled = false;
    int m_blockThreshold = kDefaultBlockThreshold;
    int m_blockSize = kDefaultBlockSize;
    int m_dropped = 0;
    bool m_submitting = false; // inside upload()/download(): handlers are called from the loop
};

} // namespace db::canopen
