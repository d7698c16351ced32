#pragma once

// Pure builders and readers for the 8-byte SDO frames of CiA 301 7.2.4.3 (no state, no I/O).
// Every builder returns exactly 8 bytes (all examples in the specs use DLC 8); readers accept
// shorter frames where noted and never read past the end.

#include "core/objectaddress.h"

#include <QByteArray>

namespace db::canopen::sdocodec {

constexpr int kFrameSize = 8;
constexpr int kExpeditedMax = 4; // data bytes in an expedited transfer
constexpr int kSegmentMax = 7; // data bytes in one (block) segment

// Command specifier (bits 7..5 of byte 0).
inline quint8 specifier(const QByteArray &frame)
{
    return frame.isEmpty() ? 0xFF : quint8(frame.at(0)) >> 5;
}
inline bool isAbort(const QByteArray &frame)
{
    return !frame.isEmpty() && quint8(frame.at(0)) == 0x80;
}
// Bytes 1..3 (multiplexer); a default address when the frame is shorter.
ObjectAddress address(const QByteArray &frame);
quint32 u32(const QByteArray &frame, int offset); // little-endian, 0 beyond the end
void putU32(QByteArray &frame, int offset, quint32 value);
QByteArray u32Bytes(quint32 value); // 4 bytes, little-endian

// --- Abort (7.2.4.3.17) ------------------------------------------------------------------------
QByteArray abort(ObjectAddress address, quint32 code);
inline quint32 abortCode(const QByteArray &frame)
{
    return u32(frame, 4);
}

// --- Expedited and segmented download (7.2.4.3.3 - 7.2.4.3.5) --------------------------------
// 1..4 bytes with the size indicated: 2F/2B/27/23 + data.
QByteArray initiateDownloadExpedited(ObjectAddress address, const QByteArray &data);
// Segmented: 21 + size in bytes 4..7.
QByteArray initiateDownloadSegmented(ObjectAddress address, quint32 size);
// Segment: 000 t nnn c + up to 7 bytes.
QByteArray downloadSegment(bool toggle, const QByteArray &chunk, bool last);

// --- Upload (7.2.4.3.6 - 7.2.4.3.8) -----------------------------------------------------------
QByteArray initiateUpload(ObjectAddress address);
QByteArray uploadSegmentRequest(bool toggle);

// Server's initiate upload response (scs 2): expedited data or the announced size.
struct InitiateUploadResponse
{
    bool expedited = false;
    bool sizeIndicated = false;
    quint32 size = 0; // announced size (segmented) or data size (expedited)
    QByteArray data; // expedited data: n bytes when indicated, all 4 otherwise
};
InitiateUploadResponse parseInitiateUpload(const QByteArray &frame);

// Server's upload segment (scs 0): toggle, last flag, data (7 - n bytes).
struct Segment
{
    bool toggle = false;
    bool last = false;
    QByteArray data;
};
Segment parseUploadSegment(const QByteArray &frame);
inline bool downloadSegmentToggle(const QByteArray &frame) // scs 1 response: bit 4
{
    return !frame.isEmpty() && (quint8(frame.at(0)) & 0x10);
}

// --- Block download (7.2.4.3.9 - 7.2.4.3.12) --------------------------------------------------
// C6: client CRC support, size indicated.
QByteArray initiateBlockDownload(ObjectAddress address, quint32 size, bool crc = true);
// Block segment: c + seqno(1..127) + 7 bytes (padded with zeros).
QByteArray blockSegment(int sequence, const QByteArray &chunk, bool last);
// End: 110 nnn 01 + CRC; n = bytes of the last segment that carry no data.
QByteArray endBlockDownload(int unusedInLast, quint16 crc);
// Server's replies read as: initiate (A0|sc<<2: crc, blksize in byte 4), ack (A2: ackseq in
// byte 1, next blksize in byte 2), end (A1).
inline bool serverCrc(const QByteArray &frame)
{
    return !frame.isEmpty() && (quint8(frame.at(0)) & 0x04);
}
inline quint8 serverSubcommand(const QByteArray &frame) // ss bits 1..0
{
    return frame.isEmpty() ? 0xFF : quint8(frame.at(0)) & 0x03;
}
inline int byteAt(const QByteArray &frame, int offset)
{
    return offset < frame.size() ? quint8(frame.at(offset)) : 0;
}

// --- Block upload (7.2.4.3.13 - 7.2.4.3.16) ---------------------------------------------------
// A4: client CRC support, blksize, protocol switch threshold 0 (never switch).
QByteArray initiateBlockUpload(ObjectAddress address, int blockSize, bool crc = true);
QByteArray startBlockUpload(); // A3
QByteArray blockUploadAck(int ackSequence, int nextBlockSize); // A2
QByteArray endBlockUploadResponse(); // A1
// Block segment as received: byte 0 = c<<7 | seqno, 7 data bytes.
inline int segmentSequence(const QByteArray &frame)
{
    return frame.isEmpty() ? -1 : quint8(frame.at(0)) & 0x7F;
}
inline bool segmentLast(const QByteArray &frame)
{
    return !frame.isEmpty() && (quint8(frame.at(0)) & 0x80);
}
// Server's end (C1 | n<<2): bytes without data in the last segment.
inline int endUnused(const QByteArray &frame)
{
    return frame.isEmpty() ? 0 : (quint8(frame.at(0)) >> 2) & 0x07;
}
inline quint16 endCrc(const QByteArray &frame)
{
    return quint16(byteAt(frame, 1) | (byteAt(frame, 2) << 8));
}

// CRC-16 of CiA 301 7.2.4.3.16: polynomial x^16 + x^12 + x^5 + 1 (0x1021), initial value 0,
// no reflection, no final XOR ("123456789" -> 0x31C3). `crc` chains calls over pieces.
quint16 crc16(const QByteArray &data, quint16 crc = 0);

// "40 41 60 00 00 00 00 00" for logs and test messages.
QString hex(const QByteArray &frame);

} // namespace db::canopen::sdocodec
