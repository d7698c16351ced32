#include "sdocodec.h"

namespace db::canopen::sdocodec {

namespace {

QByteArray frameWith(quint8 command, ObjectAddress address)
{
    QByteArray frame(kFrameSize, '\0');
    frame[0] = char(command);
    frame[1] = char(address.index & 0xFF);
    frame[2] = char(address.index >> 8);
    frame[3] = char(address.sub);
    return frame;
}

QByteArray frameWith(quint8 command)
{
    QByteArray frame(kFrameSize, '\0');
    frame[0] = char(command);
    return frame;
}

} // namespace

ObjectAddress address(const QByteArray &frame)
{
    if (frame.size() < 4)
        return {};
    return ObjectAddress(quint16(quint8(frame.at(1)) | (quint8(frame.at(2)) << 8)),
                         quint8(frame.at(3)));
}

quint32 u32(const QByteArray &frame, int offset)
{
    quint32 value = 0;
    for (int i = 3; i >= 0; --i)
        value = (value << 8) | quint32(byteAt(frame, offset + i));
    return value;
}

QByteArray u32Bytes(quint32 value)
{
    QByteArray bytes(4, '\0');
    putU32(bytes, 0, value);
    return bytes;
}

void putU32(QByteArray &frame, int offset, quint32 value)
{
    for (int i = 0; i < 4; ++i)
        frame[offset + i] = char((value >> (8 * i)) & 0xFF);
}

QByteArray abort(ObjectAddress address, quint32 code)
{
    QByteArray frame = frameWith(0x80, address);
    putU32(frame, 4, code);
    return frame;
}

// CiA 301 7.2.4.3.3: ccs=1, n = 4 - size (bits 3..2), e=1, s=1.
QByteArray initiateDownloadExpedited(ObjectAddress address, const QByteArray &data)
{
    const int size = int(qMin<qsizetype>(data.size(), kExpeditedMax));
    QByteArray frame = frameWith(quint8(0x23 | ((kExpeditedMax - size) << 2)), address);
    for (int i = 0; i < size; ++i)
        frame[4 + i] = data.at(i);
    return frame;
}

// ccs=1, e=0, s=1: size in the data bytes.
QByteArray initiateDownloadSegmented(ObjectAddress address, quint32 size)
{
    QByteArray frame = frameWith(0x21, address);
    putU32(frame, 4, size);
    return frame;
}

// CiA 301 7.2.4.3.4: ccs=0, t (bit 4), n = 7 - size (bits 3..1), c (bit 0).
QByteArray downloadSegment(bool toggle, const QByteArray &chunk, bool last)
{
    const int size = int(qMin<qsizetype>(chunk.size(), kSegmentMax));
    QByteArray frame =
        frameWith(quint8((toggle ? 0x10 : 0) | ((kSegmentMax - size) << 1) | (last ? 0x01 : 0)));
    for (int i = 0; i < size; ++i)
        frame[1 + i] = chunk.at(i);
    return frame;
}

QByteArray initiateUpload(ObjectAddress address)
{
    return frameWith(0x40, address);
}

QByteArray uploadSegmentRequest(bool toggle)
{
    return frameWith(quint8(0x60 | (toggle ? 0x10 : 0)));
}

// CiA 301 7.2.4.3.6: scs=2, n (bits 3..2), e (bit 1), s (bit 0).
InitiateUploadResponse parseInitiateUpload(const QByteArray &frame)
{
    InitiateUploadResponse r;
    const quint8 cmd = quint8(byteAt(frame, 0));
    r.expedited = cmd & 0x02;
    r.sizeIndicated = cmd & 0x01;
    if (r.expedited) {
        const int size = r.sizeIndicated ? kExpeditedMax - ((cmd >> 2) & 0x03) : kExpeditedMax;
        r.data = frame.mid(4, size);
        r.size = quint32(r.data.size());
    } else {
        r.size = r.sizeIndicated ? u32(frame, 4) : 0;
    }
    return r;
}

// CiA 301 7.2.4.3.7: scs=0, t (bit 4), n = 7 - size (bits 3..1), c (bit 0).
Segment parseUploadSegment(const QByteArray &frame)
{
    Segment s;
    const quint8 cmd = quint8(byteAt(frame, 0));
    s.toggle = cmd & 0x10;
    s.last = cmd & 0x01;
    s.data = frame.mid(1, kSegmentMax - ((cmd >> 1) & 0x07));
    return s;
}

// CiA 301 7.2.4.3.9: ccs=6, cc (bit 2), s (bit 1), cs=0.
QByteArray initiateBlockDownload(ObjectAddress address, quint32 size, bool crc)
{
    QByteArray frame = frameWith(quint8(0xC2 | (crc ? 0x04 : 0)), address);
    putU32(frame, 4, size);
    return frame;
}

// CiA 301 7.2.4.3.10: c (bit 7), seqno (bits 6..0), 7 data bytes.
QByteArray blockSegment(int sequence, const QByteArray &chunk, bool last)
{
    QByteArray frame = frameWith(quint8((last ? 0x80 : 0) | (sequence & 0x7F)));
    const int size = int(qMin<qsizetype>(chunk.size(), kSegmentMax));
    for (int i = 0; i < size; ++i)
        frame[1 + i] = chunk.at(i);
    return frame;
}

// CiA 301 7.2.4.3.12: ccs=6, n (bits 4..2), cs=1, CRC in bytes 1..2.
QByteArray endBlockDownload(int unusedInLast, quint16 crc)
{
    QByteArray frame = frameWith(quint8(0xC1 | ((unusedInLast & 0x07) << 2)));
    frame[1] = char(crc & 0xFF);
    frame[2] = char(crc >> 8);
    return frame;
}

// CiA 301 7.2.4.3.13: ccs=5, cc (bit 2), cs=0; blksize in byte 4, pst in byte 5.
QByteArray initiateBlockUpload(ObjectAddress address, int blockSize, bool crc)
{
    QByteArray frame = frameWith(quint8(0xA0 | (crc ? 0x04 : 0)), address);
    frame[4] = char(blockSize & 0x7F);
    frame[5] = 0; // protocol switch threshold: never fall back to segmented
    return frame;
}

QByteArray startBlockUpload()
{
    return frameWith(0xA3);
}

QByteArray blockUploadAck(int ackSequence, int nextBlockSize)
{
    QByteArray frame = frameWith(0xA2);
    frame[1] = char(ackSequence & 0x7F);
    frame[2] = char(nextBlockSize & 0x7F);
    return frame;
}

QByteArray endBlockUploadResponse()
{
    return frameWith(0xA1);
}

quint16 crc16(const QByteArray &data, quint16 crc)
{
    for (const char c : data) {
        crc ^= quint16(quint8(c)) << 8;
        for (int bit = 0; bit < 8; ++bit)
            crc = (crc & 0x8000) ? quint16((crc << 1) ^ 0x1021) : quint16(crc << 1);
    }
    return crc;
}

QString hex(const QByteArray &frame)
{
    return QString::fromLatin1(frame.toHex(' ')).toUpper();
}

} // namespace db::canopen::sdocodec
