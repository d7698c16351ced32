#pragma once

// Device side of SDO (CiA 301 7.2.4), used by the simulated nodes: expedited, segmented and
// block download and upload (block with CRC-16), toggle and sequence checks, the abort codes of
// sdoabort.h, and a timeout per transfer.

#include "canopen/canopenids.h"
#include "core/objectdictionary.h"

#include <QCanBusFrame>
#include <QObject>
#include <QTimer>

namespace db::canopen {

// What an SDO server reads and writes: the device's objects by address, described by a
// dictionary. Values are raw QVariants in the codec's canonical types (core/valuecodec.h).
// The server checks existence, access, length and the dictionary's range before it calls
// write(); implementations add device rules. An Error whose deviceCode() is set is sent as that
// abort code; otherwise the server maps the Error's kind.
class ObjectAccess
{
public:
    virtual ~ObjectAccess() = default;
    virtual const ObjectDictionary &dictionary() const = 0;
    virtual Result<QVariant> read(ObjectAddress address) = 0;
    virtual Result<void> write(ObjectAddress address, const QVariant &raw) = 0;
};

// One SDO server channel (requests on 0x600 + node, responses on 0x580 + node). The owner
// passes every frame of the request COB-ID to handleRequest() and puts response() frames on the
// bus; all responses have DLC 8. Runs on the event loop; handleRequest() answers synchronously.
//
// States (graph):
//   Idle --initiate download, segmented--> DownloadSegmented --last segment--> Idle
//   Idle --initiate upload, segmented--> UploadSegmented --last segment sent--> Idle
//   Idle --block download initiate--> BlockDownload --last segment acked--> BlockDownloadEnd
//        --end (CRC ok)--> Idle
//   Idle --block upload initiate--> BlockUploadStart --start--> BlockUpload --all acked-->
//        BlockUploadEnd --end response--> Idle
// Any state: abort from the client -> Idle; timeout (kDefaultTimeoutMs of silence) -> abort
// 05040000 -> Idle; an initiate request starts over. Expedited transfers never leave Idle.
class SdoServer : public QObject
{
    Q_OBJECT
public:
    static constexpr int kDefaultTimeoutMs = 1000;
    static constexpr int kSegmentBytes = 7;
    // A download longer than this is refused with 05040005 (out of memory).
    static constexpr qsizetype kMaxTransferBytes = 16 * 1024 * 1024;

    enum class State {
        Idle,
        DownloadSegmented,
        UploadSegmented,
        BlockDownload,
        BlockDownloadEnd,
        BlockUploadStart,
        BlockUpload,
        BlockUploadEnd,
    };
    Q_ENUM(State)

    // access must outlive the server.
    SdoServer(ObjectAccess *access, NodeId node, QObject *parent = nullptr);

    NodeId nodeId() const { return m_node; }
    void setNodeId(NodeId node) { m_node = node; }
    State state() const { return m_state; }
    // Silence after which a started transfer is aborted with 05040000.
    void setTimeoutMs(int ms) { m_timer.setInterval(ms); }
    // Segments per sub-block the server asks for in block download (1..127).
    void setBlockSize(int segments)
    {
        m_ownBlockSize = qBound(1, segments, int(sdo::kMaxBlockSize));
    }

    // One request frame (its payload; DLC below 8 is padded with zeros).
    void handleRequest(const QCanBusFrame &frame);
    // Ends a running transfer without a frame (e.g. NMT reset).
    void reset();

Q_SIGNALS:
    // A frame for the bus (COB-ID 0x580 + node, DLC 8).
    void response(const QCanBusFrame &frame);
    // A transfer ended; abortCode 0 = success (sent or received by the server).
    void transferFinished(db::ObjectAddress address, bool download, quint32 abortCode);

private:
    void initiateDownload(const QByteArray &d);
    void downloadSegment(const QByteArray &d);
    void initiateUpload(const QByteArray &d);
    void respondUpload();
    void uploadSegment(const QByteArray &d);
    void blockDownloadInitiate(const QByteArray &d);
    void blockDownloadSegment(const QByteArray &d);
    void blockDownloadEnd(const QByteArray &d);
    void blockUploadInitiate(const QByteArray &d);
    void blockUploadRequest(const QByteArray &d);
    void sendSubBlock();

    quint32 lookup(ObjectAddress address, bool forWrite) const; // 0 or an abort code
    quint32 lengthCheck(qsizetype size, bool final) const;
    quint32 commitWrite(const QByteArray &bytes);
    quint32 readBytes(QByteArray &bytes);
    quint32 mapError(const Error &error, bool forWrite, const QVariant &raw) const;

    void send(quint8 command, const QByteArray &data = {});
    void sendRaw(const QByteArray &payload);
    void abortTransfer(quint32 code);
    void finish(bool download);
    void enter(State state);

    ObjectAccess *m_access;
    NodeId m_node;
    State m_state = State::Idle;
    QTimer m_timer;

    ObjectAddress m_address;
    QByteArray m_data; // download: received so far; upload: the whole value
    qsizetype m_offset = 0; // upload: first byte not yet acknowledged / sent
    qint64 m_size = -1; // indicated size, -1 = not indicated
    bool m_toggle = false;
    bool m_crc = false; // both sides use the block CRC
    int m_ownBlockSize = sdo::kMaxBlockSize;
    int m_blockSize = 0; // segments in the current sub-block
    int m_sequence = 0; // block download: last segment received in order
    bool m_lastReceived = false; // block download: the segment with c = 1 arrived in order
    int m_segmentsSent = 0; // block upload: segments in the sub-block just sent
    bool m_lastInBlock = false; // block upload: that sub-block ends the value
    bool m_download = false; // direction of the current (or last) transfer
};

} // namespace db::canopen
