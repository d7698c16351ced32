#include "sdoserver.h"

#include "canopen/sdoabort.h"
#include "canopen/sdocodec.h"

#include <QLoggingCategory>
#include <QtEndian>

namespace db::canopen {

Q_LOGGING_CATEGORY(lcSdoServer, "drivebench.canopen.sdoserver")

namespace {

// -1, 0, 1 for a < b, a == b, a > b in the type's own arithmetic.
int compareRaw(DataType type, const QVariant &a, const QVariant &b)
{
    if (datatype::isSignedInteger(type))
        return a.toLongLong() < b.toLongLong() ? -1 : a.toLongLong() > b.toLongLong();
    if (datatype::isUnsignedInteger(type))
        return a.toULongLong() < b.toULongLong() ? -1 : a.toULongLong() > b.toULongLong();
    return a.toDouble() < b.toDouble() ? -1 : a.toDouble() > b.toDouble();
}

} // namespace

SdoServer::SdoServer(ObjectAccess *access, NodeId node, QObject *parent)
    : QObject(parent)
    , m_access(access)
    , m_node(node)
{
    m_timer.setSingleShot(true);
    m_timer.setInterval(kDefaultTimeoutMs);
    connect(&m_timer, &QTimer::timeout, this, [this] {
        qCDebug(lcSdoServer) << "node" << m_node << "SDO transfer timed out in" << m_state;
        abortTransfer(abort::Timeout);
    });
}

void SdoServer::handleRequest(const QCanBusFrame &frame)
{
    QByteArray d = frame.payload();
    if (d.isEmpty())
        return;
    if (d.size() < 8)
        d.append(QByteArray(8 - d.size(), '\0')); // CiA 301 frames have DLC 8; tolerate less
    const auto cmd = quint8(d.at(0));
    const int ccs = cmd >> 5;
    if (cmd == sdo::AbortByte || (ccs == sdo::CcsAbort && m_state != State::BlockDownload)) {
        if (m_state != State::Idle)
            Q_EMIT transferFinished(m_address, m_download, sdocodec::u32(d, 4));
        enter(State::Idle);
        return;
    }
    if (m_state == State::BlockDownload) {
        blockDownloadSegment(d); // inside a sub-block every frame is a segment (7.2.4.3.12)
    } else if (ccs == sdo::CcsInitiateDownload) {
        initiateDownload(d);
    } else if (ccs == sdo::CcsInitiateUpload) {
        initiateUpload(d);
    } else if (ccs == sdo::CcsDownloadSegment && m_state == State::DownloadSegmented) {
        downloadSegment(d);
    } else if (ccs == sdo::CcsUploadSegment && m_state == State::UploadSegmented) {
        uploadSegment(d);
    } else if (ccs == sdo::CcsBlockDownload && (cmd & 1) == 0) {
        blockDownloadInitiate(d);
    } else if (ccs == sdo::CcsBlockDownload && m_state == State::BlockDownloadEnd) {
        blockDownloadEnd(d);
    } else if (ccs == sdo::CcsBlockUpload && (cmd & 3) == 0) {
        blockUploadInitiate(d);
    } else if (ccs == sdo::CcsBlockUpload) {
        blockUploadRequest(d);
    } else {
        abortTransfer(abort::InvalidCommand);
        return;
    }
    if (m_state != State::Idle)
        m_timer.start(); // per-transfer timeout: silence since the last request
}

void SdoServer::reset()
{
    enter(State::Idle);
}

// ---- expedited and segmented (CiA 301 7.2.4.3.3 - 7.2.4.3.8) ----

void SdoServer::initiateDownload(const QByteArray &d)
{
    enter(State::Idle);
    const auto cmd = quint8(d.at(0));
    m_address = sdocodec::address(d);
    m_download = true;
    if (const quint32 code = lookup(m_address, true))
        return abortTransfer(code);
    const bool expedited = cmd & 0x02;
    const bool sized = cmd & 0x01;
    if (expedited) {
        QByteArray bytes = d.mid(4, sized ? 4 - ((cmd >> 2) & 3) : 4);
        const int fixed = datatype::byteSize(m_access->dictionary().find(m_address)->type);
        if (!sized && fixed > 0 && fixed < 4)
            bytes.truncate(fixed); // size not indicated: the object's size decides
        if (const quint32 code = commitWrite(bytes))
            return abortTransfer(code);
        send(0x60);
        return finish(true);
    }
    m_size = sized ? qint64(sdocodec::u32(d, 4)) : -1;
    if (const quint32 code = sized ? lengthCheck(m_size, true) : 0)
        return abortTransfer(code);
    m_toggle = false;
    send(0x60);
    enter(State::DownloadSegmented);
}

void SdoServer::downloadSegment(const QByteArray &d)
{
    const auto cmd = quint8(d.at(0));
    const bool toggle = cmd & 0x10;
    if (toggle != m_toggle)
        return abortTransfer(abort::ToggleNotAlternated);
    const bool last = cmd & 0x01;
    m_data += d.mid(1, kSegmentBytes - ((cmd >> 1) & 7));
    if (const quint32 code = lengthCheck(m_data.size(), false))
        return abortTransfer(code);
    if (last) {
        if (m_size >= 0 && m_data.size() != m_size)
            return abortTransfer(abort::LengthMismatch);
        if (const quint32 code = commitWrite(m_data))
            return abortTransfer(code);
    }
    QByteArray payload(8, '\0');
    payload[0] = char(0x20 | (toggle ? 0x10 : 0));
    sendRaw(payload);
    m_toggle = !m_toggle;
    if (last)
        finish(true);
}

void SdoServer::initiateUpload(const QByteArray &d)
{
    enter(State::Idle);
    m_address = sdocodec::address(d);
    m_download = false;
    if (const quint32 code = lookup(m_address, false))
        return abortTransfer(code);
    if (const quint32 code = readBytes(m_data))
        return abortTransfer(code);
    respondUpload();
}

void SdoServer::respondUpload()
{
    const qsizetype size = m_data.size();
    if (size > 0 && size <= 4) {
        send(quint8(0x43 | ((4 - size) << 2)), m_data);
        return finish(false);
    }
    send(0x41, sdocodec::u32Bytes(quint32(size)));
    m_offset = 0;
    m_toggle = false;
    enter(State::UploadSegmented);
}

void SdoServer::uploadSegment(const QByteArray &d)
{
    const bool toggle = quint8(d.at(0)) & 0x10;
    if (toggle != m_toggle)
        return abortTransfer(abort::ToggleNotAlternated);
    const QByteArray chunk = m_data.mid(m_offset, kSegmentBytes);
    m_offset += chunk.size();
    const bool last = m_offset >= m_data.size();
    QByteArray payload(8, '\0');
    payload[0] = char((toggle ? 0x10 : 0) | ((kSegmentBytes - chunk.size()) << 1) | (last ? 1 : 0));
    payload.replace(1, chunk.size(), chunk);
    sendRaw(payload);
    m_toggle = !m_toggle;
    if (last)
        finish(false);
}

// ---- object access ----

quint32 SdoServer::lookup(ObjectAddress address, bool forWrite) const
{
    const ObjectDef *def = m_access->dictionary().find(address);
    if (!def)
        return m_access->dictionary().subObjects(address.index).isEmpty() ? abort::NoSuchObject
                                                                          : abort::NoSuchSubIndex;
    if (forWrite && !def->writable())
        return abort::ReadOnly;
    if (!forWrite && !def->readable())
        return abort::WriteOnly;
    return 0;
}

quint32 SdoServer::lengthCheck(qsizetype size, bool final) const
{
    const int fixed = datatype::byteSize(m_access->dictionary().find(m_address)->type);
    if (size > kMaxTransferBytes)
        return abort::OutOfMemory;
    if (fixed > 0 && size > fixed)
        return abort::LengthTooHigh;
    if (fixed > 0 && final && size < fixed)
        return abort::LengthTooLow;
    return 0;
}

quint32 SdoServer::commitWrite(const QByteArray &bytes)
{
    const ObjectDef *def = m_access->dictionary().find(m_address);
    if (const quint32 code = lengthCheck(bytes.size(), true))
        return code;
    const auto raw = codec::decode(def->type, bytes);
    if (!raw)
        return mapError(raw.error(), true, {});
    const auto valid = def->validate(raw.value());
    if (!valid)
        return mapError(valid.error(), true, raw.value());
    const auto written = m_access->write(m_address, valid.value());
    return written ? 0 : mapError(written.error(), true, valid.value());
}

quint32 SdoServer::readBytes(QByteArray &bytes)
{
    const auto raw = m_access->read(m_address);
    if (!raw)
        return mapError(raw.error(), false, {});
    const auto encoded = codec::encode(m_access->dictionary().find(m_address)->type, raw.value());
    if (!encoded)
        return abort::General;
    bytes = encoded.value();
    return 0;
}

quint32 SdoServer::mapError(const Error &error, bool forWrite, const QVariant &raw) const
{
    if (error.deviceCode() != 0)
        return error.deviceCode();
    const ObjectDef *def = m_access->dictionary().find(m_address);
    switch (error.kind()) {
    case Error::Kind::AccessDenied:
        return forWrite ? abort::ReadOnly : abort::WriteOnly;
    case Error::Kind::OutOfRange:
        if (raw.isValid() && def->maximum.isValid() && compareRaw(def->type, raw, def->maximum) > 0)
            return abort::ValueTooHigh;
        if (raw.isValid() && def->minimum.isValid() && compareRaw(def->type, raw, def->minimum) < 0)
            return abort::ValueTooLow;
        return abort::InvalidValue;
    case Error::Kind::InvalidArgument:
        return forWrite ? abort::InvalidValue : abort::General;
    case Error::Kind::Malformed:
        return abort::LengthMismatch;
    case Error::Kind::NotSupported:
        return abort::UnsupportedAccess;
    case Error::Kind::Busy:
        return abort::CannotStoreState;
    default:
        return abort::General;
    }
}

// ---- frames and state ----

void SdoServer::send(quint8 command, const QByteArray &data)
{
    QByteArray payload(8, '\0');
    payload[0] = char(command);
    qToLittleEndian(m_address.index, payload.data() + 1);
    payload[3] = char(m_address.sub);
    payload.replace(4, qMin<qsizetype>(data.size(), 4), data.left(4));
    sendRaw(payload);
}

void SdoServer::sendRaw(const QByteArray &payload)
{
    Q_EMIT response(QCanBusFrame(cob::sdoResponse(m_node), payload));
}

void SdoServer::abortTransfer(quint32 code)
{
    qCDebug(lcSdoServer).noquote() << QStringLiteral("node %1 aborts %2: %3")
                                          .arg(m_node)
                                          .arg(m_address.toString(), abortText(code));
    send(sdo::AbortByte, sdocodec::u32Bytes(code));
    Q_EMIT transferFinished(m_address, m_download, code);
    enter(State::Idle);
}

void SdoServer::finish(bool download)
{
    Q_EMIT transferFinished(m_address, download, 0);
    enter(State::Idle);
}

void SdoServer::enter(State state)
{
    m_state = state;
    if (state == State::Idle) {
        m_timer.stop();
        m_data.clear();
        m_size = -1;
    }
}

} // namespace db::canopen
