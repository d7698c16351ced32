#include "acusteps.h"

#include "acuaxis.h"

#include <QCoreApplication>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::bonfiglioli)
};
constexpr quint16 kStatusWord = 411;
constexpr quint16 kFaultBit = 0x0008;
constexpr int kOnce = -1; // a wait step that reads once
} // namespace

namespace db::bonfiglioli {

AcuSteps::AcuSteps(AcuAxis *axis, const QString &name)
    : QObject(axis)
    , m_axis(axis)
    , m_name(name)
{
    m_deadline.setSingleShot(true);
    m_retry.setSingleShot(true);
    m_retry.setInterval(kStatusReadMs);
    connect(&m_retry, &QTimer::timeout, this, &AcuSteps::readStatus);
    connect(&m_deadline, &QTimer::timeout, this, &AcuSteps::onDeadline);
    m_overdue.setSingleShot(true);
    connect(&m_overdue, &QTimer::timeout, this, [this] {
        fail(Error(Error::Kind::Timeout,
                   Tr::tr("no answer within %1 ms: the inverter did not report its state")
                       .arg(m_stepTimer.elapsed())));
    });
}

void AcuSteps::onDeadline()
{
    // The step's own read of 411 is still out (queued behind other requests, or behind one lost
    // to a silence): judge the step by that read, not by the clock alone. The read has its own
    // timeout; the grace only bounds a queue that never drains.
    if (m_waitSerial != 0 && m_axis->connection()->isConnected()) {
        m_deadlinePassed = true;
        m_overdue.start(
            qMax(m_steps.at(m_index).timeoutMs, 2 * m_axis->connection()->requestTimeoutMs()));
        return;
    }
    fail(Error(Error::Kind::Timeout, m_steps.at(m_index).failText));
}

void AcuSteps::write(quint16 parameter, qint64 value)
{
    Step s;
    s.kind = Step::Kind::Write;
    s.parameter = parameter;
    s.value = value;
    m_steps.append(s);
}

void AcuSteps::waitStatus(std::function<bool(quint16)> pred, int timeoutMs, const QString &failText,
                          bool faultOk)
{
    Step s;
    s.kind = Step::Kind::Wait;
    s.pred = std::move(pred);
    s.timeoutMs = timeoutMs;
    s.failText = failText;
    s.faultOk = faultOk;
    m_steps.append(s);
}

void AcuSteps::checkStatus(std::function<bool(quint16)> pred, const QString &failText)
{
    waitStatus(std::move(pred), kOnce, failText, true);
}

void AcuSteps::checkValue(quint16 parameter, std::function<bool(qint64)> pred,
                          const QString &failText)
{
    Step s;
    s.kind = Step::Kind::Check;
    s.parameter = parameter;
    s.valuePred = std::move(pred);
    s.failText = failText;
    m_steps.append(s);
}

void AcuSteps::call(std::function<Result<void>()> fn)
{
    Step s;
    s.kind = Step::Kind::Call;
    s.fn = std::move(fn);
    m_steps.append(s);
}

Reply *AcuSteps::start()
{
    auto *reply = new Reply(ObjectAddress(410, 0));
    m_reply = reply;
    QTimer::singleShot(0, this, &AcuSteps::next);
    return reply;
}

void AcuSteps::cancel(const Error &error)
{
    fail(error);
}

void AcuSteps::fail(const Error &error)
{
    if (m_done)
        return;
    m_done = true;
    m_deadline.stop();
    m_overdue.stop();
    m_retry.stop();
    if (m_reply)
        m_reply->fail(error.prefixed(m_name));
    deleteLater();
}

void AcuSteps::next()
{
    if (m_done)
        return;
    m_deadline.stop();
    m_overdue.stop();
    m_deadlinePassed = false;
    if (++m_index >= m_steps.size()) {
        m_done = true;
        if (m_reply)
            m_reply->finish(m_result ? m_result() : QVariant());
        deleteLater();
        return;
    }
    const Step &s = m_steps.at(m_index);
    switch (s.kind) {
    case Step::Kind::Write: {
        Reply *r = m_axis->connection()->write(ObjectAddress(s.parameter, kRamDataSet),
                                               QVariant::fromValue(s.value));
        r->setParent(this); // dies with the steps when they are abandoned
        const quint16 parameter = s.parameter;
        const qint64 value = s.value;
        connect(r, &Reply::finished, this, [this, r, parameter, value] {
            r->deleteLater();
            if (m_done)
                return;
            if (!r->ok()) {
                fail(r->error().prefixed(Tr::tr("writing %1").arg(parameter)));
                return;
            }
            if (parameter == 410)
                m_axis->m_controlWord = quint16(value);
            else if (parameter == 1454)
                m_axis->m_mode = AcuAxis::Mode(qint16(qint8(value)));
            next();
        });
        return;
    }
    case Step::Kind::Wait:
        m_stepTimer.start();
        if (s.timeoutMs != kOnce)
            m_deadline.start(s.timeoutMs);
        readStatus();
        return;
    case Step::Kind::Check:
        readValue();
        return;
    case Step::Kind::Call:
        if (auto ok = s.fn(); !ok) {
            fail(ok.error());
            return;
        }
        next();
        return;
    }
}

void AcuSteps::readStatus()
{
    if (m_done)
        return;
    if (!m_source) {
        m_source = m_axis->statusSource();
        if (!m_source) {
            fail(Error(Error::Kind::NotSupported, Tr::tr("the connection has no status source")));
            return;
        }
        connect(m_source, &StatusSource::updated, this, &AcuSteps::onStatusUpdated);
    }
    m_waitSerial = m_source->refresh(this);
    if (!m_axis->connection()->isConnected())
        onStatusUpdated(); // no cycle will come
}

void AcuSteps::onStatusUpdated()
{
    if (m_done || m_waitSerial == 0)
        return;
    if (!m_axis->connection()->isConnected()) {
        m_waitSerial = 0;
        fail(motion::ConnectionAxis::lossCause(*m_axis->connection()));
        return;
    }
    if (m_source->serial() < m_waitSerial)
        return; // a cycle that may have read before the ask
    m_waitSerial = 0;
    const ObjectAddress address(kStatusWord, 0);
    if (!m_source->isFresh(address)) {
        const Error error = m_source->readError(address);
        fail(error.isError() ? error : Error(Error::Kind::Malformed, Tr::tr("411 was not read")));
        return;
    }
    onStatus(quint16(m_source->value(address).toUInt()));
}

void AcuSteps::onStatus(quint16 word)
{
    m_lastStatus = word;
    const Step &s = m_steps.at(m_index);
    if (s.pred(word)) {
        next();
        return;
    }
    if (s.timeoutMs == kOnce) {
        fail(Error(Error::Kind::DeviceError, s.failText));
        return;
    }
    if ((word & kFaultBit) && !s.faultOk) {
        fail(Error(Error::Kind::DeviceError,
                   Tr::tr("the inverter went to fault (status word 0x%1)")
                       .arg(word, 4, 16, QLatin1Char('0'))));
        return;
    }
    if (m_deadlinePassed) {
        fail(Error(Error::Kind::Timeout, s.failText)); // read after the deadline, still not there
        return;
    }
    m_retry.start();
}

void AcuSteps::readValue()
{
    const Step &s = m_steps.at(m_index);
    Reply *r = m_axis->connection()->read(ObjectAddress(s.parameter, 0));
    connect(r, &Reply::finished, this, [this, r] {
        r->deleteLater();
        if (m_done)
            return;
        if (!r->ok()) {
            fail(r->error());
            return;
        }
        const Step &s = m_steps.at(m_index);
        if (!s.valuePred(r->value().toLongLong())) {
            fail(Error(Error::Kind::Busy, s.failText));
            return;
        }
        next();
    });
}

} // namespace db::bonfiglioli
