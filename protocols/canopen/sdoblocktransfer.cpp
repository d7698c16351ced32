#include "sdoblocktransfer.h"

#include "canopenids.h"
#include "sdoabort.h"
#include "sdocodec.h"

namespace db::canopen {

using namespace sdocodec;

// --- SdoBlockDownload --------------------------------------------------------------------------

SdoBlockDownload::SdoBlockDownload(ObjectAddress address, QByteArray data)
    : SdoTransfer(address)
    , m_data(std::move(data))
{ }

QString SdoBlockDownload::describe() const
{
    return QStringLiteral("block download of %1 (%2 bytes)")
        .arg(address().toString())
        .arg(m_data.size());
}

qsizetype SdoBlockDownload::transferred() const
{
    return qMin<qsizetype>(qsizetype(m_firstSegment) * kSegmentMax, m_data.size());
}

int SdoBlockDownload::segmentCount() const
{
    // An empty download still sends one (empty, last) segment.
    return qMax(1, int((m_data.size() + kSegmentMax - 1) / kSegmentMax));
}

SdoStep SdoBlockDownload::start()
{
    m_state = State::AwaitInitiate;
    return SdoStep::send({ initiateBlockDownload(address(), quint32(m_data.size())) });
}

// Segments m_firstSegment .. +blksize, numbered 1..blksize (CiA 301 7.2.4.3.10).
QByteArrayList SdoBlockDownload::subBlock()
{
    QByteArrayList frames;
    const int total = segmentCount();
    m_sentInBlock = 0;
    for (int seq = 1; seq <= m_blockSize && m_firstSegment + seq - 1 < total; ++seq) {
        const int segment = m_firstSegment + seq - 1;
        frames.append(blockSegment(seq, m_data.mid(qsizetype(segment) * kSegmentMax, kSegmentMax),
                                   segment == total - 1));
        ++m_sentInBlock;
    }
    return frames;
}

SdoStep SdoBlockDownload::onFrame(const QByteArray &frame)
{
    if (isAbort(frame))
        return serverAbort(frame);
    const bool blockReply = specifier(frame) == sdo::ScsBlockDownload;
    switch (m_state) {
    case State::AwaitInitiate: {
        if (!echoMatches(frame))
            return SdoStep::ignore();
        if (!blockReply || serverSubcommand(frame) != 0)
            return unexpected(frame);
        m_crc = serverCrc(frame);
        m_blockSize = byteAt(frame, 4);
        if (m_blockSize < 1 || m_blockSize > sdo::kMaxBlockSize)
            return abortWith(
                abort::InvalidBlockSize, Error::Kind::Malformed,
                QStringLiteral("server asked for %1 segments per block").arg(m_blockSize));
        m_firstSegment = 0;
        m_state = State::AwaitAck;
        return SdoStep::send(subBlock());
    }
    case State::AwaitAck: {
        if (!blockReply || serverSubcommand(frame) != 2)
            return unexpected(frame);
        const int ackSeq = byteAt(frame, 1);
        const int nextSize = byteAt(frame, 2);
        if (ackSeq > m_sentInBlock)
            return abortWith(abort::InvalidSequence, Error::Kind::Malformed,
                             QStringLiteral("server acknowledged segment %1 of %2")
                                 .arg(ackSeq)
                                 .arg(m_sentInBlock));
        if (nextSize < 1 || nextSize > sdo::kMaxBlockSize)
            return abortWith(
                abort::InvalidBlockSize, Error::Kind::Malformed,
                QStringLiteral("server asked for %1 segments per block").arg(nextSize));
        if (ackSeq < m_sentInBlock)
            ++m_retransmissions; // the rest goes again, renumbered from 1
        m_firstSegment += ackSeq;
        m_blockSize = nextSize;
        if (m_firstSegment >= segmentCount()) {
            const int used = int(m_data.size() - qsizetype(segmentCount() - 1) * kSegmentMax);
            m_state = State::AwaitEnd;
            return SdoStep::send(
                { endBlockDownload(kSegmentMax - used, m_crc ? crc16(m_data) : quint16(0)) });
        }
        return SdoStep::send(subBlock());
    }
    case State::AwaitEnd:
        if (!blockReply || serverSubcommand(frame) != 1)
            return unexpected(frame);
        return SdoStep::done();
    }
    return unexpected(frame);
}

// --- SdoBlockUpload ----------------------------------------------------------------------------

SdoBlockUpload::SdoBlockUpload(ObjectAddress address, int blockSize)
    : SdoTransfer(address)
    , m_blockSize(qBound(1, blockSize, sdo::kMaxBlockSize))
{ }

QString SdoBlockUpload::describe() const
{
    return QStringLiteral("block upload of %1").arg(address().toString());
}

SdoStep SdoBlockUpload::start()
{
    m_state = State::AwaitInitiate;
    m_data.clear();
    return SdoStep::send({ initiateBlockUpload(address(), m_blockSize) });
}

SdoStep SdoBlockUpload::onFrame(const QByteArray &frame)
{
    // In AwaitSegments every first byte is a valid segment header, but seqno 0 is not: 0x80 is
    // an abort there too.
    if (isAbort(frame))
        return serverAbort(frame);
    switch (m_state) {
    case State::AwaitInitiate: {
        if (!echoMatches(frame))
            return SdoStep::ignore();
        // scs=6, sc (bit 2), s (bit 1), ss=0 (bit 0).
        if (specifier(frame) != sdo::ScsBlockUpload || (byteAt(frame, 0) & 0x01))
            return unexpected(frame);
        m_crc = serverCrc(frame);
        m_sizeIndicated = byteAt(frame, 0) & 0x02;
        m_size = m_sizeIndicated ? u32(frame, 4) : 0;
        if (m_size > SdoUpload::kMaxSize)
            return abortWith(abort::OutOfMemory, Error::Kind::Malformed,
                             QStringLiteral("announced size %1 bytes is too large").arg(m_size));
        m_data.reserve(m_size + kSegmentMax);
        m_expected = 1;
        m_gap = false;
        m_state = State::AwaitSegments;
        return SdoStep::send({ startBlockUpload() });
    }
    case State::AwaitSegments:
        return onSegment(frame);
    case State::AwaitEnd:
        return onEnd(frame);
    }
    return unexpected(frame);
}

SdoStep SdoBlockUpload::onSegment(const QByteArray &frame)
{
    const int seq = segmentSequence(frame);
    const bool last = segmentLast(frame);
    if (seq == m_expected && !m_gap) {
        m_data += frame.mid(1, kSegmentMax);
        if (m_data.size() > SdoUpload::kMaxSize)
            return abortWith(abort::OutOfMemory, Error::Kind::Malformed,
                             QStringLiteral("more than %1 bytes").arg(SdoUpload::kMaxSize));
        ++m_expected;
        m_lastReceived = last;
    } else if (seq < 1) {
        return abortWith(abort::InvalidSequence, Error::Kind::Malformed,
                         QStringLiteral("segment with sequence number 0"));
    } else {
        m_gap = true; // lost segment: everything after it in this sub-block is dropped
    }
    if (seq < m_blockSize && !last)
        return SdoStep::send({}); // more of this sub-block to come (resets the timer)
    // End of the sub-block: acknowledge what arrived in order (CiA 301 7.2.4.3.14).
    const int ackSeq = m_expected - 1;
    if (m_gap)
        ++m_lostAcks;
    m_expected = 1;
    m_gap = false;
    if (m_lastReceived)
        m_state = State::AwaitEnd;
    return SdoStep::send({ blockUploadAck(ackSeq, m_blockSize) });
}

SdoStep SdoBlockUpload::onEnd(const QByteArray &frame)
{
    if (specifier(frame) != sdo::ScsBlockUpload || (byteAt(frame, 0) & 0x03) != 0x01) {
        // A repeated last segment (our ack was late) is harmless.
        if (segmentLast(frame))
            return SdoStep::send({});
        return unexpected(frame);
    }
    const int unused = endUnused(frame);
    m_data.chop(unused);
    if (m_sizeIndicated && m_data.size() != qsizetype(m_size))
        return abortWith(
            abort::LengthMismatch, Error::Kind::Malformed,
            QStringLiteral("server sent %1 bytes, announced %2").arg(m_data.size()).arg(m_size));
    if (m_crc) {
        const quint16 mine = crc16(m_data);
        if (mine != endCrc(frame))
            return abortWith(abort::CrcError, Error::Kind::Malformed,
                             QStringLiteral("CRC mismatch: server 0x%1, data 0x%2")
                                 .arg(endCrc(frame), 4, 16, QLatin1Char('0'))
                                 .arg(mine, 4, 16, QLatin1Char('0')));
    }
    return SdoStep::done(m_data, { endBlockUploadResponse() });
}

} // namespace db::canopen
