#pragma once

// SDO block transfers (CiA 301 7.2.4.3.9 - 7.2.4.3.16) as pure state machines, see sdotransfer.h.

#include "sdotransfer.h"

namespace db::canopen {

// Block download.
//   AwaitInitiate --A0|sc, blksize--> [send sub-block] AwaitAck
//   AwaitAck --A2 ackseq, blksize--> [ackseq short: resend from ackseq+1 | more data: next
//            sub-block | all acked: send end C1|n<<2 + CRC] ... AwaitEnd --A1--> Done
class SdoBlockDownload : public SdoTransfer
{
public:
    SdoBlockDownload(ObjectAddress address, QByteArray data);
    QString describe() const override;
    SdoStep start() override;
    SdoStep onFrame(const QByteArray &frame) override;
    qsizetype transferred() const override;

    // Number of sub-blocks that had to be sent again (lost segments reported by the server).
    int retransmissions() const { return m_retransmissions; }

private:
    enum class State { AwaitInitiate, AwaitAck, AwaitEnd };
    QByteArrayList subBlock();
    int segmentCount() const;

    QByteArray m_data;
    State m_state = State::AwaitInitiate;
    bool m_crc = false;
    int m_blockSize = 0; // segments per sub-block, set by the server
    int m_firstSegment = 0; // global index of the first segment of the current sub-block
    int m_sentInBlock = 0;
    int m_retransmissions = 0;
};

// Block upload.
//   AwaitInitiate --C0|sc|s, size--> [A3] AwaitSegments
//   AwaitSegments --seq == expected: keep; seq out of order: drop (lost segment)--> ...
//                 --seq == blksize or c=1--> [A2 ackseq = last in order, blksize]
//                 (server resends from ackseq+1; after an in-order c=1) --> AwaitEnd
//   AwaitEnd --C1|n<<2, CRC (checked)--> [A1] Done
class SdoBlockUpload : public SdoTransfer
{
public:
    SdoBlockUpload(ObjectAddress address, int blockSize);
    QString describe() const override;
    SdoStep start() override;
    SdoStep onFrame(const QByteArray &frame) override;
    qsizetype transferred() const override { return m_data.size(); }

    // Sub-blocks acknowledged short because a segment was lost.
    int lostSegmentAcks() const { return m_lostAcks; }

private:
    enum class State { AwaitInitiate, AwaitSegments, AwaitEnd };
    SdoStep onSegment(const QByteArray &frame);
    SdoStep onEnd(const QByteArray &frame);

    State m_state = State::AwaitInitiate;
    int m_blockSize;
    bool m_crc = false;
    bool m_sizeIndicated = false;
    quint32 m_size = 0;
    QByteArray m_data;
    int m_expected = 1; // next sequence number wanted in this sub-block
    bool m_gap = false; // a segment of this sub-block was lost
    bool m_lastReceived = false;
    int m_lostAcks = 0;
};

} // namespace db::canopen
