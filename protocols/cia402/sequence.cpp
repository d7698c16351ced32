#include "sequence.h"

#include "cia402statussource.h"
#include "statusword.h"

#include <QCoreApplication>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::cia402)
};
} // namespace

namespace db::cia402 {

Sequence::Sequence(DeviceConnection *connection, QString name, QObject *parent)
    : QObject(parent)
    , m_connection(connection)
    , m_name(std::move(name))
{
    m_pollTimer.setSingleShot(true);
    m_deadline.setSingleShot(true);
    connect(&m_pollTimer, &QTimer::timeout, this, &Sequence::poll);
    connect(&m_deadline, &QTimer::timeout, this, &Sequence::onDeadline);
    m_overdue.setSingleShot(true);
    connect(&m_overdue, &QTimer::timeout, this, [this] { failNoAnswer(); });
}

void Sequence::onDeadline()
{
    const Step &step = m_steps[m_index];
    // The step's own status read is still out (queued behind other requests, or behind one
    // lost to a silence): judge the step by that read, not by the clock alone. The read has
    // its own timeout; the grace only bounds a queue that never drains.
    if (m_waitSerial != 0 && m_connection->isConnected()) {
        m_deadlinePassed = true;
        m_overdue.start(qMax(step.timeoutMs, 2 * m_connection->requestTimeoutMs()));
        return;
    }
    if (!m_answeredInStep) {
        failNoAnswer();
        return;
    }
    failNotReached();
}

void Sequence::failNoAnswer()
{
    // A drive that never reported its state in this step did not refuse: say that, not a
    // statusword never read.
    const Step &step = m_steps[m_index];
    fail(Error(Error::Kind::Timeout,
               Tr::tr("%1: no answer within %2 ms: the drive did not report its state "
                      "(waiting for %3)")
                   .arg(m_name)
                   .arg(m_stepTimer.elapsed())
                   .arg(step.what)));
}

void Sequence::failNotReached()
{
    const Step &step = m_steps[m_index];
    fail(Error(Error::Kind::Timeout,
               Tr::tr("%1: %2 did not happen within %3 ms (statusword 0x%4)")
                   .arg(m_name, step.what)
                   .arg(step.timeoutMs)
                   .arg(m_statusword, 4, 16, QLatin1Char('0'))));
}

Sequence::~Sequence()
{
    if (m_reply)
        m_reply->fail(Error(Error::Kind::Cancelled, m_name + QStringLiteral(": abandoned")));
}

Sequence *Sequence::write(ObjectAddress address, const QVariant &raw)
{
    m_steps.append({ Step::Kind::Write, address, raw, {}, {}, 0, {} });
    return this;
}

Sequence *Sequence::waitFor(QString what, Check check, int timeoutMs)
{
    m_steps.append(
        { Step::Kind::Wait, kStatusword, {}, std::move(what), std::move(check), timeoutMs, {} });
    return this;
}

Sequence *Sequence::call(std::function<void(Sequence *)> action)
{
    m_steps.append({ Step::Kind::Call, {}, {}, {}, {}, 0, std::move(action) });
    return this;
}

Reply *Sequence::start()
{
    Q_ASSERT(!m_reply);
    auto *reply = new Reply(kControlword);
    m_reply = reply;
    m_index = 0;
    // A caller that drops its reply abandons the procedure.
    connect(reply, &QObject::destroyed, this, [this] {
        m_pollTimer.stop();
        m_deadline.stop();
        m_overdue.stop();
        deleteLater();
    });
    QMetaObject::invokeMethod(this, &Sequence::runStep, Qt::QueuedConnection);
    return reply;
}

void Sequence::cancel(const Error &error)
{
    fail(error);
}

void Sequence::runStep()
{
    if (!isRunning())
        return;
    if (m_index >= m_steps.size()) {
        finishOk();
        return;
    }
    const Step &step = m_steps[m_index];
    switch (step.kind) {
    case Step::Kind::Call:
        step.action(this);
        next();
        return;
    case Step::Kind::Write: {
        Reply *r = m_connection->write(step.address, step.value);
        r->setParent(this); // dies with the sequence when it is abandoned
        m_request = r;
        connect(r, &Reply::finished, this, [this, r] {
            r->deleteLater();
            if (!isRunning() || r != m_request)
                return;
            if (!r->ok()) {
                fail(r->error().prefixed(m_name));
                return;
            }
            next();
        });
        return;
    }
    case Step::Kind::Wait:
        m_answeredInStep = false;
        m_deadlinePassed = false;
        m_stepTimer.start();
        m_deadline.start(step.timeoutMs);
        poll();
        return;
    }
}

void Sequence::poll()
{
    if (!isRunning())
        return;
    if (!m_source) {
        m_source = Cia402StatusSource::sourceOf(m_connection);
        connect(m_source, &StatusSource::updated, this, &Sequence::onStatusUpdated);
    }
    m_waitSerial = m_source->refresh(this);
    if (!m_connection->isConnected())
        onStatusUpdated(); // no cycle will come
}

void Sequence::onStatusUpdated()
{
    if (!isRunning() || m_waitSerial == 0)
        return;
    if (!m_connection->isConnected()) {
        m_waitSerial = 0;
        const Error lost = m_connection->lastError();
        fail((lost.isError()
                  ? lost
                  : Error(Error::Kind::Disconnected,
                          Tr::tr("connection to %1 closed").arg(m_connection->uri().toString())))
                 .prefixed(m_name));
        return;
    }
    if (m_source->serial() < m_waitSerial)
        return; // a cycle that may have read before the ask
    m_waitSerial = 0;
    if (!m_source->isFresh(kStatusword)) {
        Error error = m_source->readError(kStatusword);
        if (!error.isError())
            error = Error(Error::Kind::Malformed, Tr::tr("the statusword was not read"));
        fail(error.prefixed(m_name));
        return;
    }
    onStatus(quint16(m_source->value(kStatusword).toULongLong()));
}

void Sequence::onStatus(quint16 statusword)
{
    m_statusword = statusword;
    m_answeredInStep = true;
    QString why;
    switch (m_steps[m_index].check(m_statusword, why)) {
    case WaitVerdict::Reached:
        m_deadline.stop();
        m_overdue.stop();
        next();
        return;
    case WaitVerdict::Failed:
        fail(Error(Error::Kind::DeviceError,
                   Tr::tr("%1: %2 (statusword 0x%3)")
                       .arg(m_name, why)
                       .arg(m_statusword, 4, 16, QLatin1Char('0'))));
        return;
    case WaitVerdict::Pending:
        if (m_deadlinePassed) {
            failNotReached(); // the read that came after the deadline still says no
            return;
        }
        m_pollTimer.start(kPollIntervalMs);
        return;
    }
}

void Sequence::next()
{
    ++m_index;
    runStep();
}

void Sequence::fail(const Error &error)
{
    m_pollTimer.stop();
    m_deadline.stop();
    m_overdue.stop();
    if (m_reply && m_reply->fail(error))
        deleteLater();
}

void Sequence::finishOk()
{
    m_pollTimer.stop();
    m_deadline.stop();
    m_overdue.stop();
    if (m_reply && m_reply->finish(m_statusword))
        deleteLater();
}

namespace {
Sequence::Check bitsCheck(quint16 mask, bool set, bool failOnFault)
{
    return [=](quint16 word, QString &why) {
        if (failOnFault && (word & sw::Fault)) {
            why = Tr::tr("the drive went to fault");
            return WaitVerdict::Failed;
        }
        const bool match = set ? (word & mask) == mask : (word & mask) == 0;
        return match ? WaitVerdict::Reached : WaitVerdict::Pending;
    };
}
} // namespace

Sequence::Check bitsSet(quint16 mask, bool failOnFault)
{
    return bitsCheck(mask, true, failOnFault);
}

Sequence::Check bitsClear(quint16 mask, bool failOnFault)
{
    return bitsCheck(mask, false, failOnFault);
}

} // namespace db::cia402
