// SDO part of FrameDecoder (CiA 301 7.2.4.3): initiate, segments, block transfer and abort, read
// from either side. The multiplexer of the last initiate per node names the segments that
// follow, and a flag follows block transfers, whose segments have no command specifier.
#include "framedecoder.h"
#include "sdoabort.h"
#include "sdocodec.h"

#include <QCoreApplication>

namespace db::canopen {

namespace {

struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::canopen::FrameDecoder)
};

QString segmentText(const QByteArray &bytes)
{
    bool printable = !bytes.isEmpty();
    for (char c : bytes)
        printable = printable && c >= 0x20 && c < 0x7F;
    return printable ? QStringLiteral("\"%1\"").arg(QString::fromLatin1(bytes)) : hexBytes(bytes);
}

QString toggleText(const QByteArray &data)
{
    return QStringLiteral("t=%1").arg((sdocodec::byteAt(data, 0) >> 4) & 1);
}

} // namespace

void FrameDecoder::decodeSdo(DecodedFrame &out, const QByteArray &data, bool request)
{
    out.service = request ? Service::SdoRequest : Service::SdoResponse;
    const QString head = Tr::tr("%1 node %2: ").arg(serviceName(out.service)).arg(out.node);
    if (data.isEmpty()) {
        out.text = head + Tr::tr("empty frame");
        return;
    }
    // Block segments carry c | seqno in byte 0 instead of a command specifier.
    const auto it = m_transfers.find(out.node);
    const bool segmentsFromClient = it != m_transfers.end() && it->block && !it->upload;
    if (it != m_transfers.end() && it->blockData && request == segmentsFromClient
        && !sdocodec::isAbort(data)) {
        out.hasAddress = true;
        out.address = it->address;
        const bool last = sdocodec::segmentLast(data);
        if (last) {
            it->blockData = false;
            it->lastSegment = true;
        }
        out.text = head
            + Tr::tr("block segment %1%2 %3: %4")
                  .arg(sdocodec::segmentSequence(data))
                  .arg(last ? Tr::tr(" last") : QString())
                  .arg(objectText(out.node, it->address), hexBytes(data.mid(1)));
        return;
    }
    if (sdocodec::isAbort(data)) {
        out.hasAddress = true;
        out.address = sdocodec::address(data);
        const quint32 code = sdocodec::abortCode(data);
        out.text = head
            + Tr::tr("abort %1: 0x%2 %3")
                  .arg(objectText(out.node, out.address))
                  .arg(code, 8, 16, QLatin1Char('0'))
                  .arg(abortText(code));
        m_transfers.remove(out.node);
        return;
    }
    out.text = head;
    if (request)
        decodeSdoRequest(out, data);
    else
        decodeSdoResponse(out, data);
}

void FrameDecoder::decodeSdoRequest(DecodedFrame &out, const QByteArray &data)
{
    const quint8 b0 = quint8(data.at(0));
    const ObjectAddress address = sdocodec::address(data);
    Transfer &t = m_transfers[out.node];
    const auto initiate = [&](bool upload, bool block) {
        t = Transfer { address, upload, block, false, false };
        out.hasAddress = true;
        out.address = address;
    };
    const auto known = [&] {
        out.hasAddress = true;
        out.address = t.address;
        return objectText(out.node, t.address);
    };
    switch (sdocodec::specifier(data)) {
    case sdo::CcsInitiateDownload: {
        initiate(false, false);
        const bool expedited = b0 & 0x02;
        const bool sized = b0 & 0x01;
        if (expedited) {
            const int n = sized ? 4 - ((b0 >> 2) & 0x03) : 4;
            out.text += Tr::tr("download %1 ← %2")
                            .arg(objectText(out.node, address),
                                 valueText(out.node, address, data.mid(4, n)));
        } else {
            out.text +=
                Tr::tr("download %1, %2 bytes")
                    .arg(objectText(out.node, address))
                    .arg(sized ? QString::number(sdocodec::u32(data, 4)) : Tr::tr("unknown"));
        }
        break;
    }
    case sdo::CcsDownloadSegment: {
        const int n = 7 - ((b0 >> 1) & 0x07);
        out.text += Tr::tr("download segment %1 %2%3: %4")
                        .arg(known(), toggleText(data), (b0 & 0x01) ? Tr::tr(" last") : QString(),
                             segmentText(data.mid(1, n)));
        break;
    }
    case sdo::CcsInitiateUpload:
        initiate(true, false);
        out.text += Tr::tr("upload %1").arg(objectText(out.node, address));
        break;
    case sdo::CcsUploadSegment:
        out.text += Tr::tr("upload segment request %1 %2").arg(known(), toggleText(data));
        break;
    case sdo::CcsBlockUpload:
        switch (b0 & 0x03) {
        case 0:
            initiate(true, true);
            out.text += Tr::tr("block upload %1, blksize %2")
                            .arg(objectText(out.node, address))
                            .arg(sdocodec::byteAt(data, 4));
            break;
        case 3:
            t.blockData = true;
            out.text += Tr::tr("block upload start %1").arg(known());
            break;
        case 2:
            t.blockData = t.block && !t.lastSegment;
            out.text += Tr::tr("block upload ack %1: seq %2, blksize %3")
                            .arg(known())
                            .arg(sdocodec::byteAt(data, 1))
                            .arg(sdocodec::byteAt(data, 2));
            break;
        default:
            out.text += Tr::tr("block upload end %1 ok").arg(known());
            m_transfers.remove(out.node);
            break;
        }
        break;
    case sdo::CcsBlockDownload:
        if ((b0 & 0x01) == 0) {
            initiate(false, true);
            out.text += Tr::tr("block download %1, %2 bytes")
                            .arg(objectText(out.node, address))
                            .arg(sdocodec::u32(data, 4));
        } else {
            out.text += Tr::tr("block download end %1, %2 unused, crc 0x%3")
                            .arg(known())
                            .arg(sdocodec::endUnused(data))
                            .arg(sdocodec::endCrc(data), 4, 16, QLatin1Char('0'));
        }
        break;
    default:
        out.text += Tr::tr("unknown command 0x%1").arg(b0, 2, 16, QLatin1Char('0'));
        break;
    }
}

void FrameDecoder::decodeSdoResponse(DecodedFrame &out, const QByteArray &data)
{
    const quint8 b0 = quint8(data.at(0));
    const ObjectAddress address = sdocodec::address(data);
    Transfer &t = m_transfers[out.node];
    const auto echoed = [&] {
        out.hasAddress = true;
        out.address = address;
        t.address = address;
        return objectText(out.node, address);
    };
    const auto known = [&] {
        out.hasAddress = true;
        out.address = t.address;
        return objectText(out.node, t.address);
    };
    switch (sdocodec::specifier(data)) {
    case sdo::ScsInitiateDownload:
        out.text += Tr::tr("download %1 ok").arg(echoed());
        break;
    case sdo::ScsDownloadSegment:
        out.text += Tr::tr("download segment %1 %2 ok").arg(known(), toggleText(data));
        break;
    case sdo::ScsInitiateUpload: {
        const auto r = sdocodec::parseInitiateUpload(data);
        if (r.expedited)
            out.text +=
                Tr::tr("upload %1 → %2").arg(echoed(), valueText(out.node, address, r.data));
        else
            out.text +=
                Tr::tr("upload %1, %2 bytes")
                    .arg(echoed(), r.sizeIndicated ? QString::number(r.size) : Tr::tr("unknown"));
        break;
    }
    case sdo::ScsUploadSegment: {
        const auto s = sdocodec::parseUploadSegment(data);
        out.text += Tr::tr("upload segment %1 %2%3: %4")
                        .arg(known(), toggleText(data), s.last ? Tr::tr(" last") : QString(),
                             segmentText(s.data));
        break;
    }
    case sdo::ScsBlockDownload:
        switch (sdocodec::serverSubcommand(data)) {
        case 0:
            t.block = true;
            t.upload = false;
            t.blockData = true;
            out.text += Tr::tr("block download %1 ok, blksize %2")
                            .arg(echoed())
                            .arg(sdocodec::byteAt(data, 4));
            break;
        case 2:
            t.blockData = t.block && !t.upload && !t.lastSegment;
            out.text += Tr::tr("block download ack %1: seq %2, blksize %3")
                            .arg(known())
                            .arg(sdocodec::byteAt(data, 1))
                            .arg(sdocodec::byteAt(data, 2));
            break;
        default:
            out.text += Tr::tr("block download end %1 ok").arg(known());
            m_transfers.remove(out.node);
            break;
        }
        break;
    case sdo::ScsBlockUpload:
        if (sdocodec::serverSubcommand(data) == 0) {
            t.block = true;
            t.upload = true;
            out.text +=
                Tr::tr("block upload %1, %2 bytes").arg(echoed()).arg(sdocodec::u32(data, 4));
        } else {
            t.blockData = false;
            out.text += Tr::tr("block upload end %1, %2 unused, crc 0x%3")
                            .arg(known())
                            .arg(sdocodec::endUnused(data))
                            .arg(sdocodec::endCrc(data), 4, 16, QLatin1Char('0'));
        }
        break;
    default:
        out.text += Tr::tr("unknown command 0x%1").arg(b0, 2, 16, QLatin1Char('0'));
        break;
    }
}

} // namespace db::canopen
