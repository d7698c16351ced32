#pragma once

// One request engine for request/response protocols over a ByteStream (RefGo's ASCII lines,
// VABus/TCP's binary telegrams). It knows no protocol: a protocol gives it encoded requests, a
// framer and a matcher per request.
//
// Contracts:
// - One request in flight; the others wait in a FIFO queue. The next request goes out from the
//   receive handler that completed the previous one (no timer hop), so the round-trip rate is
//   bound by the link.
// - The protocol's framer turns received bytes into complete answers (or framing errors); the
//   engine never parses bytes itself. A framing error (e.g. "answer too long", the framer's
//   bounded buffer) fails the request in flight with that error, naming the peer.
// - Each answer is shown to the matcher of the request in flight: Mine (its value, or
//   Malformed/DeviceError when it is the request's answer but unusable), NotMine, or Retry
//   (the device asks for the request again).
// - Timeout: one ResponseTimer, restarted for every transmission (without registering a
//   dispatcher timer per request). On timeout the request is sent
//   again while it has had fewer than maxTransmissions() transmissions (default 1: no resend),
//   else it fails with Timeout. A Retry verdict resends the same way, or fails with the
//   verdict's reason once the transmissions are used up.
// - Late answers: requests that timed out (or were sent more than once) are remembered, at most
//   kMaxAbandoned; an answer their matcher claims is dropped and logged, never given to the
//   request in flight. Devices answer in order, so once the request in flight gets its own
//   answer the remembered ones are forgotten. An answer that is neither late nor the request
//   in flight's is dropped and logged, or, with setForeignAnswerFails(true), fails the request
//   in flight as Malformed (for protocols where any answer after a request is that request's).
//   With lateGraceMs() > 0 nothing is sent for that long after a timeout, so a late answer
//   arrives while the link is quiet; answers still missing when it ends are taken as lost and
//   their requests forgotten, so that an identical request sent next gets its own answer.
// - Every Reply finishes exactly once: value, Timeout, Malformed, DeviceError, Disconnected
//   (link closed: the stream's close error), or Cancelled (engine deleted). Requests made while
//   the stream is not open fail at once with Disconnected. Replies deleted by their requester
//   before they are sent are skipped. A request may instead carry a handler (Completion), which
//   gets the same results with no Reply object; it is skipped the same way once its context is
//   gone.
// - Keep-alive (off by default): a request the protocol supplies, sent when nothing has been
//   transmitted for keepAliveIdleMs() while the stream is open and no request is queued or in
//   flight. So it never overtakes a user request, and delays one by at most its own round trip
//   (it is sent once, never resent). It stops when the stream closes and restarts when it opens.
//   Its traffic goes to the debug log only; a failed keep-alive is shown like a failed request.
//
// Protocol requirements (a traits struct):
//   using Answer = ...;                 // one framed answer
//   using Framer = ...;                 // std::vector<Result<Answer>> feed(const QByteArray &);
//                                       // void reset(); qsizetype bufferedBytes() const;
//   using Matcher = ...;                // Verdict operator()(const Answer &) const; movable.
//                                       // Also asked about answers that may be late ones for
//                                       // requests that timed out, so it has no side effects.
//   static QString summary(const Answer &);  // its content, for the log console: "-3658"
//   static QString identify(const Answer &); // what it says it answers, for drops: "TP"

#include "bytestream.h"
#include "core/completion.h"
#include "core/reply.h"
#include "core/result.h"
#include "responsetimer.h"

#include <QList>
#include <QLoggingCategory>
#include <QPointer>
#include <QTimer>

#include <optional>
#include <utility>

namespace db {

// A matcher's judgement of one framed answer against one request.
struct Verdict
{
    enum class Kind { Mine, NotMine, Retry };

    // The request's answer: its value, or the Malformed/DeviceError it amounts to.
    static Verdict mine(Result<QVariant> result) { return { Kind::Mine, std::move(result) }; }
    // Not this request's (late, foreign); reason says why, e.g. "echo is 'TS'".
    static Verdict notMine(const QString &reason)
    {
        return { Kind::NotMine, Error(Error::Kind::Malformed, reason) };
    }
    // This request's, and the device asks for it again; reason is the error once retries run out.
    static Verdict retry(Error reason) { return { Kind::Retry, std::move(reason) }; }

    Kind kind = Kind::NotMine;
    Result<QVariant> result = QVariant();
};

// The protocol-neutral part: timers, options, logging, stream signals.
class RequestEngineBase : public QObject
{
    Q_OBJECT
public:
    static constexpr int kDefaultTimeoutMs = 1000;
    static constexpr int kDefaultMaxTransmissions = 1;
    static constexpr int kMaxAbandoned = 32; // remembered requests whose answer may still come

    using Category = const QLoggingCategory &(*)();

    ByteStream *stream() const { return m_stream; }

    // Both apply to requests sent from now on.
    int timeoutMs() const { return m_timeoutMs; }
    void setTimeoutMs(int ms) { m_timeoutMs = qMax(1, ms); }
    // Transmissions per request, the first included (at least 1).
    int maxTransmissions() const { return m_maxTransmissions; }
    void setMaxTransmissions(int count) { m_maxTransmissions = qMax(1, count); }
    // Quiet time after a timeout before the next request is sent (0: none).
    int lateGraceMs() const { return m_quiet.interval(); }
    void setLateGraceMs(int ms) { m_quiet.setInterval(qMax(0, ms)); }
    bool foreignAnswerFails() const { return m_foreignAnswerFails; }
    void setForeignAnswerFails(bool fails) { m_foreignAnswerFails = fails; }
    // With true, a partial answer the framer holds when a transmission times out is dropped
    // before the request is sent again, so the retransmission's answer is framed from its first
    // byte (for binary protocols whose framer cannot resynchronise on its own). Default false.
    bool dropsPartialAnswerOnTimeout() const { return m_dropPartialOnTimeout; }
    void setDropsPartialAnswerOnTimeout(bool drops) { m_dropPartialOnTimeout = drops; }

    // 0 when keep-alive is off.
    int keepAliveIdleMs() const { return m_keepAliveIdleMs; }
    // True while the idle timer that sends the next keep-alive runs.
    bool isKeepAliveScheduled() const { return m_keepAlive.isActive(); }

Q_SIGNALS:
    // One human-readable line per request, answer, drop or error, for the log console.
    void logLine(const QString &line);

protected:
    // The stream is not owned and must outlive the engine; the categories are the protocol's
    // (raw traffic at debug level in the second).
    RequestEngineBase(ByteStream *stream, Category category, Category rawCategory, QObject *parent);
    void connectNotify(const QMetaMethod &signal) override;
    void disconnectNotify(const QMetaMethod &signal) override;

    virtual void onReceived(const QByteArray &bytes) = 0;
    virtual void onTimeout() = 0;
    virtual void onQuietOver() = 0;
    virtual void onKeepAliveDue() = 0;
    virtual void onClosed(const Error &error) = 0;

    // Writes one transmission; false when the stream is not open.
    bool writeRaw(const QByteArray &bytes);
    // After a transmission: starts its timeout and the keep-alive idle time, logs it.
    void transmitted(const QString &label, int transmission, bool keepAlive);
    void stopTimeout() { m_timer.stop(); }
    // True when someone listens to logLine(): the lines are only formatted for a listener.
    bool wantsLogLines() const;
    bool isQuiet() const { return m_quiet.isActive(); }
    void startQuiet();
    void enableKeepAlive(int idleMs);
    void restartKeepAlive();

    // Finishes a request's reply or calls its handler (a keep-alive has neither), logging
    // failures: one info line per episode of timeouts (the first, and the answer that ends it),
    // the rest at debug level. Inside a submit() call, a handler is called from the loop.
    void finish(Completion &done, bool keepAlive, const Result<QVariant> &result);

    // True while submit() runs (its failures must not call a handler from inside the call).
    bool m_submitting = false;
    void logReceivedRaw(const QByteArray &bytes) const;
    void logAnswer(const QString &summary, bool keepAlive);
    void logRetry(const QString &label, const QString &why, int transmission);
    void logLate(const QString &label, const QString &identity, const QString &summary);
    void logUnsolicited(const QString &identity, const QString &summary);
    void logForeign(const QString &label, const QString &reason, const QString &summary);
    void logForgotten(const QStringList &labels) const;
    Error framingError(const Error &error);

    Error notConnected(const QString &label) const;
    Error timedOut(const QString &label, int transmissions) const;
    Error foreign(const QString &label, const QString &reason) const;
    Error closedError(const Error &error) const;

private:
    ByteStream *m_stream;
    Category m_category;
    Category m_rawCategory;
    ResponseTimer m_timer; // time limit of the transmission in flight
    QTimer m_quiet; // after a timeout: late answers are dropped, nothing is sent
    QTimer m_keepAlive; // idle time before the next keep-alive
    int m_timeoutMs = kDefaultTimeoutMs;
    int m_maxTransmissions = kDefaultMaxTransmissions;
    int m_keepAliveIdleMs = 0;
    bool m_foreignAnswerFails = false;
    bool m_dropPartialOnTimeout = false;
    // Timeouts since the device last answered: only the first of a silent episode is logged
    // at info level, so that a device that stops answering does not flood the user's log.
    int m_timeoutsInRow = 0;
    // Whether logLine() has a listener: 1 yes, 0 no, -1 to be looked up again (after a
    // disconnect). Asked twice per request, so it is not looked up every time.
    mutable qint8 m_wantsLogLines = -1;
};

template<typename Protocol>
class RequestEngine final : public RequestEngineBase
{
public:
    using Answer = typename Protocol::Answer;
    using Framer = typename Protocol::Framer;
    using Matcher = typename Protocol::Matcher;

    RequestEngine(ByteStream *stream, Category category, Category rawCategory,
                  QObject *parent = nullptr)
        : RequestEngineBase(stream, category, rawCategory, parent)
    { }
    ~RequestEngine() override
    {
        failAll(Error(Error::Kind::Cancelled, QStringLiteral("request engine deleted")));
    }

    // Queues one request: bytes as sent, label for messages ("TP"), the matcher for its answers.
    // Returns a new Reply owned by the caller.
    Reply *submit(QByteArray bytes, QString label, Matcher matcher, ObjectAddress address = {})
    {
        if (!stream()->isOpen())
            return Reply::failed(address, notConnected(label));
        auto *reply = new Reply(address);
        submit(std::move(bytes), std::move(label), std::move(matcher), Completion(reply));
        return reply;
    }
    // The same with the result delivered to `done` (see Completion).
    void submit(QByteArray bytes, QString label, Matcher matcher, Completion done)
    {
        if (!stream()->isOpen()) {
            done.completeLater(notConnected(label));
            return;
        }
        m_queue.append(
            Pending { std::move(bytes), std::move(label), std::move(matcher), std::move(done) });
        const bool outer = !std::exchange(m_submitting, true);
        sendNext();
        if (outer)
            m_submitting = false;
    }

    // Sends this request whenever nothing has been transmitted for idleMs (<= 0: off).
    void setKeepAlive(int idleMs, QByteArray bytes, QString label, Matcher matcher)
    {
        m_keepAlivePrototype.reset();
        if (idleMs > 0) {
            m_keepAlivePrototype =
                Pending { std::move(bytes), std::move(label), std::move(matcher), {}, true };
        }
        enableKeepAlive(idleMs);
    }

    // Requests queued or in flight, a keep-alive included.
    int pendingCount() const { return int(m_queue.size()) + (m_inFlight ? 1 : 0); }
    // Bytes of a partial answer held by the framer (bounded by the framer).
    qsizetype bufferedBytes() const { return m_framer.bufferedBytes(); }

    // Fails every queued and in-flight request with error (e.g. Cancelled by the owner).
    void failAll(const Error &error)
    {
        stopTimeout();
        QList<Pending> all = std::exchange(m_queue, {});
        if (m_inFlight)
            all.prepend(takeInFlight());
        for (Pending &request : all)
            request.done.completeLater(error); // one cause for all: the caller reports it
    }

private:
    struct Pending
    {
        QByteArray bytes;
        QString label;
        Matcher match;
        Completion done; // none for a keep-alive
        bool keepAlive = false;
        int sent = 0; // transmissions so far
        int answered = 0; // answers received (Retry verdicts included)
    };
    // A request whose answers (count of them) may still arrive.
    struct Abandoned
    {
        QString label;
        Matcher match;
        int count = 1;
    };

    Pending takeInFlight()
    {
        stopTimeout();
        Pending request = std::move(*m_inFlight);
        m_inFlight.reset();
        return request;
    }

    void sendNext()
    {
        while (!m_inFlight && !m_queue.isEmpty() && !isQuiet()) {
            Pending request = m_queue.takeFirst();
            if (!request.keepAlive && !request.done.wanted())
                continue; // the requester gave up before it was sent
            if (!writeRaw(request.bytes)) {
                finish(request.done, request.keepAlive, notConnected(request.label));
                continue;
            }
            request.sent = 1;
            m_inFlight = std::move(request);
            transmitted(m_inFlight->label, 1, m_inFlight->keepAlive);
        }
    }

    void resend()
    {
        if (!writeRaw(m_inFlight->bytes)) {
            complete(notConnected(m_inFlight->label));
            return;
        }
        ++m_inFlight->sent;
        transmitted(m_inFlight->label, m_inFlight->sent, m_inFlight->keepAlive);
    }

    // A keep-alive is sent once: resending it could only delay the user requests behind it.
    bool mayResend() const
    {
        return !m_inFlight->keepAlive && m_inFlight->sent < maxTransmissions();
    }

    // Transmissions of the request that got no answer yet are remembered, so their late
    // answers are dropped.
    void complete(const Result<QVariant> &result)
    {
        Pending request = takeInFlight();
        if (const int outstanding = request.sent - request.answered; outstanding > 0)
            abandon(request, outstanding);
        finish(request.done, request.keepAlive, result);
        sendNext();
    }

    void abandon(Pending &request, int count)
    {
        m_abandoned.append(Abandoned { request.label, std::move(request.match), count });
        if (m_abandoned.size() > kMaxAbandoned)
            m_abandoned.removeFirst();
    }

    void onReceived(const QByteArray &bytes) override
    {
        logReceivedRaw(bytes);
        for (const Result<Answer> &answer : m_framer.feed(bytes)) {
            if (answer.ok()) {
                onAnswer(answer.value());
                continue;
            }
            const Error error = framingError(answer.error());
            if (m_inFlight) {
                ++m_inFlight->answered; // the garbled answer was the one in flight's
                complete(error);
            }
        }
    }

    void onAnswer(const Answer &answer)
    {
        // Devices answer in order: a late answer to a timed-out request arrives before the
        // answer to whatever was sent after it.
        qsizetype late = -1;
        for (qsizetype i = 0; i < m_abandoned.size() && late < 0; ++i) {
            if (m_abandoned.at(i).match(answer).kind != Verdict::Kind::NotMine)
                late = i;
        }
        std::optional<Verdict> verdict;
        if (m_inFlight)
            verdict = m_inFlight->match(answer);
        const bool mine = verdict && verdict->kind != Verdict::Kind::NotMine;
        if (late == 0 || (late > 0 && !mine)) {
            logLate(m_abandoned.at(late).label, Protocol::identify(answer),
                    Protocol::summary(answer));
            m_abandoned.remove(0, late);
            if (--m_abandoned.first().count == 0)
                m_abandoned.removeFirst();
            return;
        }
        if (!m_inFlight) {
            logUnsolicited(Protocol::identify(answer), Protocol::summary(answer));
            return;
        }
        if (!mine) {
            const QString reason = verdict->result.error().message();
            if (foreignAnswerFails()) {
                ++m_inFlight->answered;
                complete(foreign(m_inFlight->label, reason));
            } else {
                logForeign(m_inFlight->label, reason, Protocol::summary(answer));
            }
            return;
        }
        forgetAbandoned();
        ++m_inFlight->answered;
        if (m_inFlight->keepAlive || wantsLogLines())
            logAnswer(Protocol::summary(answer), m_inFlight->keepAlive);
        if (verdict->kind == Verdict::Kind::Retry && mayResend()) {
            logRetry(m_inFlight->label, verdict->result.error().message(), m_inFlight->sent + 1);
            resend();
            return;
        }
        complete(verdict->result);
    }

    void onTimeout() override
    {
        if (!m_inFlight)
            return;
        if (dropsPartialAnswerOnTimeout())
            m_framer.reset();
        if (mayResend()) {
            logRetry(m_inFlight->label, timedOut(m_inFlight->label, 1).message(),
                     m_inFlight->sent + 1);
            resend();
            return;
        }
        const Error error = timedOut(m_inFlight->label, m_inFlight->sent);
        startQuiet();
        complete(error);
    }

    void onQuietOver() override
    {
        forgetAbandoned();
        sendNext();
    }

    void forgetAbandoned()
    {
        if (m_abandoned.isEmpty())
            return;
        QStringList labels;
        for (const Abandoned &a : std::as_const(m_abandoned))
            labels.append(a.label);
        logForgotten(labels);
        m_abandoned.clear();
    }

    void onKeepAliveDue() override
    {
        if (!m_keepAlivePrototype || !stream()->isOpen())
            return;
        if (m_inFlight || !m_queue.isEmpty() || isQuiet()) {
            restartKeepAlive(); // busy: that traffic keeps the link alive
            return;
        }
        m_queue.append(*m_keepAlivePrototype);
        sendNext();
    }

    void onClosed(const Error &error) override
    {
        m_framer.reset();
        m_abandoned.clear();
        failAll(closedError(error));
    }

    Framer m_framer;
    QList<Pending> m_queue;
    std::optional<Pending> m_inFlight;
    QList<Abandoned> m_abandoned; // oldest first
    std::optional<Pending> m_keepAlivePrototype;
};

} // namespace db
