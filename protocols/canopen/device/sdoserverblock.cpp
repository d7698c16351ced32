#include "sdoserver.h"

#include "canopen/sdoabort.h"
#include "canopen/sdocodec.h"

#include <QtEndian>

// SDO block download and upload of SdoServer (CiA 301 7.2.4.3.9 - 7.2.4.3.16), split from
// sdoserver.cpp to keep files short.

namespace db::canopen {

// ---- block download (7.2.4.3.9 - 7.2.4.3.12) ----

void SdoServer::blockDownloadInitiate(const QByteArray &d)
{
    enter(State::Idle);
    const auto cmd = quint8(d.at(0));
    m_address = sdocodec::address(d);
    m_download = true;
    if (const quint32 code = lookup(m_address, true))
        return abortTransfer(code);
    m_size = (cmd & 0x02) ? qint64(sdocodec::u32(d, 4)) : -1;
    if (const quint32 code = m_size >= 0 ? lengthCheck(m_size, true) : 0)
        return abortTransfer(code);
    m_crc = cmd & 0x04;
    m_sequence = 0;
    m_lastReceived = false;
    m_blockSize = m_ownBlockSize;
    send(0xA4, QByteArray(1, char(m_blockSize))); // scs 5, sc = 1 (we check CRCs), blksize
    enter(State::BlockDownload);
}

void SdoServer::blockDownloadSegment(const QByteArray &d)
{
    const auto cmd = quint8(d.at(0));
    const int sequence = cmd & 0x7F;
    const bool last = cmd & 0x80;
    if (sequence == m_sequence + 1 && !m_lastReceived) {
        m_data += d.mid(1, kSegmentBytes);
        m_sequence = sequence;
        m_lastReceived = last;
        if (m_data.size() > kMaxTransferBytes)
            return abortTransfer(abort::OutOfMemory);
    }
    if (!last && sequence < m_blockSize)
        return;
    // End of a sub-block: acknowledge the last segment received in order; the client repeats
    // the rest in the next sub-block, numbered from 1 again.
    QByteArray payload(8, '\0');
    payload[0] = char(0xA2);
    payload[1] = char(m_sequence);
    payload[2] = char(m_ownBlockSize);
    sendRaw(payload);
    m_sequence = 0;
    m_blockSize = m_ownBlockSize;
    if (m_lastReceived)
        enter(State::BlockDownloadEnd);
}

void SdoServer::blockDownloadEnd(const QByteArray &d)
{
    const int unused = (quint8(d.at(0)) >> 2) & 7;
    if (unused > m_data.size())
        return abortTransfer(abort::InvalidCommand);
    m_data.chop(unused);
    if (m_size >= 0 && m_data.size() != m_size)
        return abortTransfer(abort::LengthMismatch);
    if (m_crc && qFromLittleEndian<quint16>(d.constData() + 1) != sdocodec::crc16(m_data))
        return abortTransfer(abort::CrcError);
    if (const quint32 code = commitWrite(m_data))
        return abortTransfer(code);
    QByteArray payload(8, '\0');
    payload[0] = char(0xA1);
    sendRaw(payload);
    finish(true);
}

// ---- block upload (7.2.4.3.13 - 7.2.4.3.16) ----

void SdoServer::blockUploadInitiate(const QByteArray &d)
{
    enter(State::Idle);
    m_address = sdocodec::address(d);
    m_download = false;
    if (const quint32 code = lookup(m_address, false))
        return abortTransfer(code);
    const int blockSize = quint8(d.at(4));
    const int threshold = quint8(d.at(5));
    if (blockSize < 1 || blockSize > sdo::kMaxBlockSize)
        return abortTransfer(abort::InvalidBlockSize);
    if (const quint32 code = readBytes(m_data))
        return abortTransfer(code);
    if (threshold > 0 && m_data.size() <= threshold)
        return respondUpload(); // protocol switch: answer as a normal upload
    m_crc = quint8(d.at(0)) & 0x04;
    m_blockSize = blockSize;
    m_offset = 0;
    send(0xC6, sdocodec::u32Bytes(quint32(m_data.size()))); // scs 6, sc = 1, size indicated
    enter(State::BlockUploadStart);
}

void SdoServer::blockUploadRequest(const QByteArray &d)
{
    const int cs = quint8(d.at(0)) & 3;
    if (cs == 3 && m_state == State::BlockUploadStart) {
        enter(State::BlockUpload);
        return sendSubBlock();
    }
    if (cs == 1 && m_state == State::BlockUploadEnd)
        return finish(false);
    if (cs != 2 || m_state != State::BlockUpload)
        return abortTransfer(abort::InvalidCommand);
    const int acked = quint8(d.at(1));
    const int blockSize = quint8(d.at(2));
    if (acked > m_segmentsSent)
        return abortTransfer(abort::InvalidSequence);
    if (blockSize < 1 || blockSize > sdo::kMaxBlockSize)
        return abortTransfer(abort::InvalidBlockSize);
    m_offset = qMin(m_offset + qsizetype(acked) * kSegmentBytes, m_data.size());
    m_blockSize = blockSize;
    if (acked < m_segmentsSent || !m_lastInBlock)
        return sendSubBlock();
    const qsizetype segments =
        qMax<qsizetype>(1, (m_data.size() + kSegmentBytes - 1) / kSegmentBytes);
    const qsizetype unused = segments * kSegmentBytes - m_data.size();
    QByteArray payload(8, '\0');
    payload[0] = char(0xC1 | (unused << 2));
    if (m_crc)
        qToLittleEndian(sdocodec::crc16(m_data), payload.data() + 1);
    sendRaw(payload);
    enter(State::BlockUploadEnd);
}

void SdoServer::sendSubBlock()
{
    m_segmentsSent = 0;
    m_lastInBlock = false;
    for (int sequence = 1; sequence <= m_blockSize && !m_lastInBlock; ++sequence) {
        const qsizetype at = m_offset + qsizetype(sequence - 1) * kSegmentBytes;
        m_lastInBlock = at + kSegmentBytes >= m_data.size();
        QByteArray payload(8, '\0');
        payload[0] = char((m_lastInBlock ? 0x80 : 0) | sequence);
        const QByteArray chunk = m_data.mid(at, kSegmentBytes);
        payload.replace(1, chunk.size(), chunk);
        sendRaw(payload);
        m_segmentsSent = sequence;
    }
}

} // namespace db::canopen
