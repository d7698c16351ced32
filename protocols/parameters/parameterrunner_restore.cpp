// ParameterRestore: running the plan (write, read back, store) and the report text.

#include "core/printable.h"
#include "parameterrunner_p.h"

#include <QTimer>

namespace db {

namespace {
constexpr int kMaxConsecutiveTimeouts = 2; // then the device is taken as gone

QString rowLabel(const RestoreRow &row, const AddressFormat &format)
{
    const QString address = format.format(row.address);
    return row.name.isEmpty() ? address : QStringLiteral("%1 %2").arg(address, row.name);
}
} // namespace

void ParameterRestore::start()
{
    if (isRunning())
        return;
    plan();
    m_state = State::Writing;
    m_stepIndex = 0;
    m_cancelRequested = false;
    m_timeoutsInRow = 0;
    // finished() must not fire inside start(); the first request leaves from the event loop.
    QTimer::singleShot(0, this, [this] {
        if (m_state != State::Writing)
            return;
        // An empty run must not look like a successful one, and must never store.
        if (m_report.rows.isEmpty()) {
            stopWithError(Error(Error::Kind::InvalidArgument,
                                m_set.isEmpty()
                                    ? tr("nothing to restore: the parameter set holds no object")
                                    : tr("nothing to restore: no selected object is in the set")));
            return;
        }
        if (!m_connection || !m_connection->isConnected()) {
            stopWithError(Error(Error::Kind::Disconnected, tr("not connected")));
            return;
        }
        // The same text is another object in another format: never restore across them.
        if (m_set.addressFormat->key() != m_connection->addressFormat().key()) {
            stopWithError(Error(Error::Kind::InvalidArgument,
                                tr("the set's addresses are %1 addresses (like %2), the "
                                   "device's are %3 addresses (like %4): it is not a set for "
                                   "this device")
                                    .arg(m_set.addressFormat->key(), m_set.addressFormat->example(),
                                         m_connection->addressFormat().key(),
                                         m_connection->addressFormat().example())));
            return;
        }
        Q_EMIT progress(0, int(m_steps->size()));
        runNext();
    });
}

void ParameterRestore::cancel()
{
    if (isRunning())
        m_cancelRequested = true;
}

void ParameterRestore::track(Reply *reply, void (ParameterRestore::*handler)(Reply *))
{
    m_inFlight = reply;
    connect(reply, &Reply::finished, this, [this, reply, handler] {
        m_inFlight.clear();
        reply->deleteLater();
        (this->*handler)(reply);
    });
}

QString ParameterRestore::blockReason(const Step &step) const
{
    if (!step.pdo)
        return {};
    if (const auto it = m_groupBlocked.find(step.pdo); it != m_groupBlocked.end())
        return it.value();
    if (step.part == Step::Part::Mapping)
        return m_mappingBlocked.value(step.pdo);
    return {};
}

void ParameterRestore::runNext()
{
    if (m_cancelRequested) {
        stopWithError(Error(Error::Kind::Cancelled, tr("restore cancelled")));
        return;
    }
    // A lost link ends the run here, so the next row is reported as not attempted.
    if (!m_connection || !m_connection->isConnected()) {
        stopWithError(Error(Error::Kind::Disconnected,
                            m_connection && m_connection->lastError().isError()
                                ? m_connection->lastError().message()
                                : tr("the connection was closed")));
        return;
    }
    // Steps of a PDO group whose earlier step failed are not attempted.
    while (m_stepIndex < int(m_steps->size())) {
        const Step &step = m_steps->at(size_t(m_stepIndex));
        const QString blocked = blockReason(step);
        if (blocked.isEmpty())
            break;
        if (step.kind == Step::Kind::Row)
            m_report.rows[step.row].reason = blocked;
        ++m_stepIndex;
    }
    if (m_stepIndex >= int(m_steps->size())) {
        store();
        return;
    }
    const Step &step = m_steps->at(size_t(m_stepIndex));
    m_state = State::Writing;
    DeviceConnection *c = m_connection;
    switch (step.kind) {
    case Step::Kind::Row:
        track(c->write(step.address, m_report.rows.at(step.row).value),
              &ParameterRestore::onWriteDone);
        break;
    case Step::Kind::ReadCurrent:
        track(c->read(step.address), &ParameterRestore::onWriteDone);
        break;
    case Step::Kind::Disable: {
        const quint64 cob = m_current.value(step.address).toULongLong();
        track(c->write(step.address, QVariant::fromValue<qulonglong>(cob | restore::kCobIdInvalid)),
              &ParameterRestore::onWriteDone);
        break;
    }
    case Step::Kind::ClearMapping:
        track(c->write(step.address, QVariant::fromValue<qulonglong>(0)),
              &ParameterRestore::onWriteDone);
        break;
    case Step::Kind::Previous:
        track(c->write(step.address, m_current.value(step.address)),
              &ParameterRestore::onWriteDone);
        break;
    }
}

void ParameterRestore::advance()
{
    ++m_stepIndex;
    Q_EMIT progress(m_stepIndex, int(m_steps->size()));
    runNext();
}

void ParameterRestore::onWriteDone(Reply *reply)
{
    const Step step = m_steps->at(size_t(m_stepIndex));
    const Error error = reply->error();
    const QString pdo = QString::number(step.pdo, 16).toUpper();
    if (error.isError()) {
        if (step.kind == Step::Kind::Row) {
            RestoreRow &row = m_report.rows[step.row];
            row.outcome = RestoreOutcome::Failed;
            row.reason = error.message();
        }
        m_timeoutsInRow = error.kind() == Error::Kind::Timeout ? m_timeoutsInRow + 1 : 0;
        if (restore::isFatal(error) || m_timeoutsInRow >= kMaxConsecutiveTimeouts) {
            stopWithError(
                error.prefixed(tr("writing %1").arg(m_report.addressFormat->format(step.address))));
            return;
        }
    } else {
        m_timeoutsInRow = 0;
    }
    const bool ok = !error.isError();
    switch (step.kind) {
    case Step::Kind::Row:
        if (!ok)
            break;
        if (step.part == Step::Part::Enable)
            m_disabled.remove(step.pdo);
        if (m_verify && !m_cancelRequested) {
            const ObjectDef *def = m_connection->dictionary().find(step.address);
            if (def && def->readable()) {
                m_state = State::Verifying;
                track(m_connection->read(step.address), &ParameterRestore::onReadBackDone);
                return;
            }
            m_report.rows[step.row].reason = tr("write-only: not read back");
        } else if (m_cancelRequested) {
            m_report.rows[step.row].reason = tr("cancelled before the read-back");
        }
        m_report.rows[step.row].outcome = RestoreOutcome::Written;
        break;
    case Step::Kind::ReadCurrent:
        if (ok)
            m_current.insert(step.address, reply->value());
        else if (step.part == Step::Part::Disable)
            m_groupBlocked.insert(
                step.pdo,
                tr("PDO %1h not changed: reading its COB-ID failed: %2").arg(pdo, error.message()));
        else
            m_mappingBlocked.insert(
                step.pdo,
                tr("mapping not changed: reading %1 failed: %2")
                    .arg(m_report.addressFormat->format(step.address), error.message()));
        break;
    case Step::Kind::Disable:
        if (ok)
            m_disabled.insert(step.pdo);
        else
            m_groupBlocked.insert(
                step.pdo, tr("PDO %1h could not be disabled: %2").arg(pdo, error.message()));
        break;
    case Step::Kind::ClearMapping:
        if (!ok)
            m_mappingBlocked.insert(
                step.pdo,
                tr("mapping %1 could not be cleared: %2")
                    .arg(m_report.addressFormat->format(step.address), error.message()));
        break;
    case Step::Kind::Previous:
        if (ok && step.part == Step::Part::Enable)
            m_disabled.remove(step.pdo);
        else if (!ok)
            m_report.notes.append(
                tr("writing back the previous value of %1 failed: %2")
                    .arg(m_report.addressFormat->format(step.address), error.message()));
        break;
    }
    advance();
}

void ParameterRestore::onReadBackDone(Reply *reply)
{
    const Step step = m_steps->at(size_t(m_stepIndex));
    RestoreRow &row = m_report.rows[step.row];
    const Error error = reply->error();
    if (error.isError()) {
        row.outcome = RestoreOutcome::Mismatch;
        row.reason = tr("written, but the read-back failed: %1").arg(error.message());
        if (restore::isFatal(error)) {
            stopWithError(error.prefixed(
                tr("reading back %1").arg(m_report.addressFormat->format(step.address))));
            return;
        }
    } else {
        // Compared after normalisation, so a device answering 16 matches a set holding 0x10.
        const auto got = codec::normalize(row.type, reply->value());
        const auto want = codec::normalize(row.type, row.value);
        row.readBack = got ? got.value() : reply->value();
        if (got && want && got.value() == want.value()) {
            row.outcome = RestoreOutcome::Verified;
        } else {
            row.outcome = RestoreOutcome::Mismatch;
            // As the editor shows them: physical values with decimals and unit.
            const ObjectDef *def = m_connection->dictionary().find(step.address);
            const auto text = [&](const QVariant &raw) {
                return def ? def->displayText(raw) : codec::toText(row.type, raw);
            };
            row.reason = tr("read back %1, expected %2").arg(text(row.readBack), text(row.value));
        }
    }
    advance();
}

void ParameterRestore::store()
{
    if (!m_store) {
        finish();
        return;
    }
    const int bad = int(m_report.rows.size()) - m_report.count(RestoreOutcome::Verified)
        - m_report.count(RestoreOutcome::Written);
    if (bad > 0) {
        m_report.storeReason = tr("not stored: %n row(s) did not succeed", nullptr, bad);
        finish();
        return;
    }
    m_state = State::Storing;
    track(m_connection->storeNonVolatile(), &ParameterRestore::onStoreDone);
}

void ParameterRestore::onStoreDone(Reply *reply)
{
    m_report.stored = reply->ok();
    if (!reply->ok())
        m_report.storeReason =
            tr("storing (1010h sub 1 = \"save\") failed: %1").arg(reply->error().message());
    finish();
}

void ParameterRestore::stopWithError(const Error &error)
{
    m_report.error = error;
    if (m_store && !m_report.stored)
        m_report.storeReason = tr("not stored: the restore stopped");
    finish();
}

void ParameterRestore::finish()
{
    for (RestoreRow &row : m_report.rows) {
        if (row.outcome == RestoreOutcome::Skipped && row.reason.isEmpty())
            row.reason = tr("not attempted: %1").arg(m_report.error.message());
    }
    for (const quint16 pdo : std::as_const(m_disabled))
        m_report.notes.append(tr("PDO %1h left disabled (COB-ID bit 31 set)")
                                  .arg(QString::number(pdo, 16).toUpper()));
    m_disabled.clear();
    m_state = State::Finished;
    Q_EMIT finished();
}

// ---- RestoreReport ----

int RestoreReport::count(RestoreOutcome outcome) const
{
    return int(std::count_if(rows.cbegin(), rows.cend(),
                             [outcome](const RestoreRow &r) { return r.outcome == outcome; }));
}

bool RestoreReport::succeeded() const
{
    return !error.isError() && !rows.isEmpty()
        && count(RestoreOutcome::Verified) + count(RestoreOutcome::Written) == rows.size()
        && (!storeRequested || stored);
}

QString RestoreReport::summary() const
{
    QStringList lines;
    lines << QObject::tr("restore: %1 verified, %2 written, %3 failed, %4 mismatch, %5 skipped")
                 .arg(count(RestoreOutcome::Verified))
                 .arg(count(RestoreOutcome::Written))
                 .arg(count(RestoreOutcome::Failed))
                 .arg(count(RestoreOutcome::Mismatch))
                 .arg(count(RestoreOutcome::Skipped));
    if (error.isError())
        lines << QObject::tr("stopped: %1").arg(error.toString());
    for (const RestoreOutcome o :
         { RestoreOutcome::Verified, RestoreOutcome::Written, RestoreOutcome::Failed,
           RestoreOutcome::Mismatch, RestoreOutcome::Skipped }) {
        for (const RestoreRow &row : rows) {
            if (row.outcome != o)
                continue;
            QString line =
                QStringLiteral("  %1  %2")
                    .arg(restoreOutcomeName(o).leftJustified(8), rowLabel(row, *addressFormat));
            if (!row.reason.isEmpty())
                line += QStringLiteral(": ") + row.reason;
            lines << line;
        }
    }
    if (storeRequested)
        lines << (stored ? QObject::tr("stored to non-volatile memory (1010h sub 1 = \"save\")")
                         : storeReason);
    for (const QString &note : notes)
        lines << QObject::tr("note: %1").arg(note);
    // Names, values and reasons come from the set's file and the device: each line stays one
    // line, without control characters.
    for (QString &line : lines)
        line = printable(line);
    return lines.join(QLatin1Char('\n'));
}

} // namespace db
