#include "sdotransfer.h"

#include "canopenids.h"
#include "sdoabort.h"
#include "sdocodec.h"
#include <QCoreApplication>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::canopen)
};
} // namespace

namespace db::canopen {

using namespace sdocodec;

SdoStep SdoTransfer::serverAbort(const QByteArray &frame) const
{
    const ObjectAddress from = sdocodec::address(frame);
    // Some servers leave the multiplexer empty in aborts during segment phases.
    if (from != m_address && from != ObjectAddress())
        return SdoStep::ignore();
    const quint32 code = abortCode(frame);
    SdoStep step;
    step.outcome = SdoStep::Outcome::Failed;
    step.error = Error(Error::Kind::DeviceError, abortText(code), code);
    return step;
}

bool SdoTransfer::echoMatches(const QByteArray &frame) const
{
    return frame.size() >= 4 && sdocodec::address(frame) == m_address;
}

SdoStep SdoTransfer::abortWith(quint32 code, Error::Kind kind, const QString &message) const
{
    SdoStep step;
    step.outcome = SdoStep::Outcome::Failed;
    step.frames = { sdocodec::abort(m_address, code) };
    step.error = Error(kind,
                       Tr::tr("%1 in %2 (sent SDO abort 0x%3)")
                           .arg(message, describe())
                           .arg(code, 8, 16, QLatin1Char('0')),
                       code);
    return step;
}

SdoStep SdoTransfer::unexpected(const QByteArray &frame) const
{
    return abortWith(abort::InvalidCommand, Error::Kind::Malformed,
                     QStringLiteral("unexpected server frame %1").arg(hex(frame)));
}

// --- SdoDownload -------------------------------------------------------------------------------

SdoDownload::SdoDownload(ObjectAddress address, QByteArray data, bool forceSegmented)
    : SdoTransfer(address)
    , m_data(std::move(data))
    , m_expedited(!forceSegmented && !m_data.isEmpty() && m_data.size() <= kExpeditedMax)
{ }

QString SdoDownload::describe() const
{
    return QStringLiteral("%1 download of %2 (%3 bytes)")
        .arg(m_expedited ? QStringLiteral("expedited") : QStringLiteral("segmented"),
             address().toString())
        .arg(m_data.size());
}

SdoStep SdoDownload::start()
{
    m_state = State::AwaitInitiate;
    if (m_expedited)
        return SdoStep::send({ initiateDownloadExpedited(address(), m_data) });
    return SdoStep::send({ initiateDownloadSegmented(address(), quint32(m_data.size())) });
}

QByteArray SdoDownload::nextSegment()
{
    const QByteArray chunk = m_data.mid(m_offset, kSegmentMax);
    m_offset += chunk.size();
    m_lastSent = m_offset >= m_data.size();
    const QByteArray frame = downloadSegment(m_toggle, chunk, m_lastSent);
    return frame;
}

SdoStep SdoDownload::onFrame(const QByteArray &frame)
{
    if (isAbort(frame))
        return serverAbort(frame);
    switch (m_state) {
    case State::AwaitInitiate:
        if (!echoMatches(frame))
            return SdoStep::ignore();
        if (specifier(frame) != sdo::ScsInitiateDownload)
            return unexpected(frame);
        if (m_expedited) {
            m_offset = m_data.size();
            return SdoStep::done();
        }
        m_state = State::AwaitSegmentAck;
        return SdoStep::send({ nextSegment() });
    case State::AwaitSegmentAck:
        if (specifier(frame) != sdo::ScsDownloadSegment)
            return unexpected(frame);
        if (downloadSegmentToggle(frame) != m_toggle)
            return abortWith(abort::ToggleNotAlternated, Error::Kind::Malformed,
                             QStringLiteral("toggle bit not alternated"));
        if (m_lastSent)
            return SdoStep::done();
        m_toggle = !m_toggle;
        return SdoStep::send({ nextSegment() });
    }
    return unexpected(frame);
}

// --- SdoUpload ---------------------------------------------------------------------------------

SdoUpload::SdoUpload(ObjectAddress address)
    : SdoTransfer(address)
{ }

QString SdoUpload::describe() const
{
    return QStringLiteral("%1 of %2")
        .arg(m_state == State::AwaitSegment ? QStringLiteral("segmented upload")
                                            : QStringLiteral("upload"),
             address().toString());
}

SdoStep SdoUpload::start()
{
    m_state = State::AwaitInitiate;
    m_data.clear();
    m_toggle = false;
    return SdoStep::send({ initiateUpload(address()) });
}

SdoStep SdoUpload::onFrame(const QByteArray &frame)
{
    if (isAbort(frame))
        return serverAbort(frame);
    switch (m_state) {
    case State::AwaitInitiate: {
        if (!echoMatches(frame))
            return SdoStep::ignore();
        if (specifier(frame) != sdo::ScsInitiateUpload)
            return unexpected(frame);
        const InitiateUploadResponse r = parseInitiateUpload(frame);
        if (r.expedited)
            return SdoStep::done(r.data);
        if (r.sizeIndicated && r.size > kMaxSize)
            return abortWith(abort::OutOfMemory, Error::Kind::Malformed,
                             QStringLiteral("announced size %1 bytes is too large").arg(r.size));
        m_sizeIndicated = r.sizeIndicated;
        m_size = r.size;
        m_state = State::AwaitSegment;
        if (m_sizeIndicated)
            m_data.reserve(m_size);
        return SdoStep::send({ uploadSegmentRequest(m_toggle) });
    }
    case State::AwaitSegment: {
        if (specifier(frame) != sdo::ScsUploadSegment)
            return unexpected(frame);
        const Segment s = parseUploadSegment(frame);
        if (s.toggle != m_toggle)
            return abortWith(abort::ToggleNotAlternated, Error::Kind::Malformed,
                             QStringLiteral("toggle bit not alternated"));
        m_data += s.data;
        if (m_data.size() > kMaxSize || (m_sizeIndicated && m_data.size() > qsizetype(m_size)))
            return abortWith(abort::LengthTooHigh, Error::Kind::Malformed,
                             QStringLiteral("server sent %1 bytes, announced %2")
                                 .arg(m_data.size())
                                 .arg(m_size));
        if (s.last) {
            if (m_sizeIndicated && m_data.size() != qsizetype(m_size))
                return abortWith(abort::LengthTooLow, Error::Kind::Malformed,
                                 QStringLiteral("server sent %1 bytes, announced %2")
                                     .arg(m_data.size())
                                     .arg(m_size));
            return SdoStep::done(m_data);
        }
        m_toggle = !m_toggle;
        return SdoStep::send({ uploadSegmentRequest(m_toggle) });
    }
    }
    return unexpected(frame);
}

} // namespace db::canopen
