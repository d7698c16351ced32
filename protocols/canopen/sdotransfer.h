#pragma once

// One SDO transfer as a pure state machine (ARCHITECTURE.md habit 5): frames in, frames out, no
// timers and no bus. SdoClient owns the timers, the queue and the replies; the state machines
// decide what each server frame means. All frames are the 8-byte SDO payloads of sdocodec.h.

#include "core/error.h"
#include "core/objectaddress.h"

#include <QByteArrayList>

namespace db::canopen {

// What the engine does after start() or after a server frame.
struct SdoStep
{
    enum class Outcome {
        Continue, // send `frames`, restart the response timer, wait for the next server frame
        Done, // send `frames` (maybe none), finish the reply with `data`
        Failed, // send `frames` (usually an abort), fail the reply with `error`
        Ignore, // the frame is not for this transfer (late, foreign, wrong echo): drop it
    };
    Outcome outcome = Outcome::Continue;
    QByteArrayList frames;
    QByteArray data; // uploaded bytes when Done
    Error error;

    static SdoStep send(QByteArrayList frames)
    {
        SdoStep s;
        s.frames = std::move(frames);
        return s;
    }
    static SdoStep done(QByteArray data = {}, QByteArrayList frames = {})
    {
        SdoStep s;
        s.outcome = Outcome::Done;
        s.frames = std::move(frames);
        s.data = std::move(data);
        return s;
    }
    static SdoStep ignore()
    {
        SdoStep s;
        s.outcome = Outcome::Ignore;
        return s;
    }
};

class SdoTransfer
{
public:
    explicit SdoTransfer(ObjectAddress address)
        : m_address(address)
    { }
    virtual ~SdoTransfer() = default;
    SdoTransfer(const SdoTransfer &) = delete;
    SdoTransfer &operator=(const SdoTransfer &) = delete;

    ObjectAddress address() const { return m_address; }
    // "segmented upload of 1008:0", for logs and error messages.
    virtual QString describe() const = 0;
    virtual SdoStep start() = 0;
    virtual SdoStep onFrame(const QByteArray &frame) = 0;
    // Bytes moved so far (progress of long transfers).
    virtual qsizetype transferred() const = 0;

protected:
    // Shared checks: a server abort for this object fails the transfer; an abort for another
    // object is a late answer to an earlier request and is ignored.
    SdoStep serverAbort(const QByteArray &frame) const;
    // The echo check of CiA 301 7.2.4.3 (python-canopen does the same): an initiate response
    // must name the object that was asked for.
    bool echoMatches(const QByteArray &frame) const;
    // Ends the transfer with an abort frame sent to the server and an error for the requester.
    SdoStep abortWith(quint32 code, Error::Kind kind, const QString &message) const;
    // A frame with the wrong command specifier: abort 05040001.
    SdoStep unexpected(const QByteArray &frame) const;

private:
    ObjectAddress m_address;
};

// Expedited (<= 4 bytes) or segmented download (CiA 301 7.2.4.3.3 - 7.2.4.3.5).
//   AwaitInitiate --60--> [expedited: Done] | AwaitSegmentAck --2t--> ... --last acked--> Done
class SdoDownload : public SdoTransfer
{
public:
    SdoDownload(ObjectAddress address, QByteArray data, bool forceSegmented);
    QString describe() const override;
    SdoStep start() override;
    SdoStep onFrame(const QByteArray &frame) override;
    qsizetype transferred() const override { return m_offset; }

private:
    enum class State { AwaitInitiate, AwaitSegmentAck };
    QByteArray nextSegment();

    QByteArray m_data;
    bool m_expedited;
    State m_state = State::AwaitInitiate;
    qsizetype m_offset = 0;
    bool m_toggle = false;
    bool m_lastSent = false;
};

// Upload, expedited or segmented as the server chooses (CiA 301 7.2.4.3.6 - 7.2.4.3.8).
//   AwaitInitiate --4x expedited--> Done
//                 --41 size--> AwaitSegment --0t.. (toggle checked)--> ... --c=1--> Done
class SdoUpload : public SdoTransfer
{
public:
    explicit SdoUpload(ObjectAddress address);
    QString describe() const override;
    SdoStep start() override;
    SdoStep onFrame(const QByteArray &frame) override;
    qsizetype transferred() const override { return m_data.size(); }

    // A server that announces more than this is refused (abort 05040005, out of memory).
    static constexpr qsizetype kMaxSize = 16 * 1024 * 1024;

private:
    enum class State { AwaitInitiate, AwaitSegment };

    State m_state = State::AwaitInitiate;
    QByteArray m_data;
    bool m_toggle = false;
    bool m_sizeIndicated = false;
    quint32 m_size = 0;
};

} // namespace db::canopen
