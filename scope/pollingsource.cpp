#include "pollingsource.h"

#include "core/datatype.h"

#include <QCoreApplication>
#include <cmath>
#include <limits>

namespace db::scope {

namespace {

// Reply values are the codec's canonical types; strings and byte arrays are not samples.
std::optional<double> sampleValue(const QVariant &v)
{
    const int type = v.typeId();
    if (!v.isValid() || type == QMetaType::QString || type == QMetaType::QByteArray)
        return std::nullopt;
    bool ok = false;
    const double d = v.toDouble(&ok);
    return ok ? std::optional<double>(d) : std::nullopt;
}

} // namespace

PollingSource::PollingSource(DeviceConnection *connection, QObject *parent)
    : TraceSource(parent)
    , m_connection(connection)
{
    m_wakeup.setSingleShot(true);
    m_wakeup.setTimerType(Qt::PreciseTimer);
    connect(&m_wakeup, &QTimer::timeout, this, &PollingSource::pump);
    if (connection) {
        connect(connection, &DeviceConnection::stateChanged, this,
                &PollingSource::onConnectionState);
        // A connection deleted while sampling ends the source like a lost link.
        connect(connection, &QObject::destroyed, this, [this] {
            if (m_running)
                fail(Error(Error::Kind::Disconnected, tr("the connection was closed")));
        });
    }
}

PollingSource::~PollingSource()
{
    delete m_inFlight.data();
}

Result<int> PollingSource::addChannel(ObjectAddress address, int rateMs)
{
    if (!m_connection)
        return Error(Error::Kind::InvalidArgument, tr("no connection to poll"));
    return addChannel(ChannelInfo::forObject(address, m_connection->dictionary(),
                                             m_connection->uri().toString(), rateMs,
                                             &m_connection->addressFormat()));
}

Result<int> PollingSource::addChannel(const ChannelInfo &info)
{
    if (m_running)
        return Error(Error::Kind::InvalidArgument, tr("cannot add a channel while sampling"));
    if (info.sourceRateMs < 0)
        return Error(Error::Kind::InvalidArgument,
                     tr("%1: the sample period must be >= 0 ms").arg(info.id));
    if (m_connection) {
        if (const ObjectDef *def = m_connection->dictionary().find(info.address)) {
            if (!def->readable())
                return Error(Error::Kind::AccessDenied,
                             tr("%1 (%2) is write-only").arg(info.id, def->name));
            if (!datatype::isNumeric(def->type))
                return Error(
                    Error::Kind::InvalidArgument,
                    tr("%1 (%2) is not a number and cannot be recorded").arg(info.id, def->name));
        }
    }
    m_entries.append({ info, 0 });
    Q_EMIT channelsChanged();
    return int(m_entries.size()) - 1;
}

void PollingSource::removeChannel(int channel)
{
    if (m_running || channel < 0 || channel >= m_entries.size())
        return;
    m_entries.removeAt(channel);
    Q_EMIT channelsChanged();
}

void PollingSource::setRateMs(int channel, int rateMs)
{
    if (m_running || channel < 0 || channel >= m_entries.size() || rateMs < 0)
        return;
    m_entries[channel].info.sourceRateMs = rateMs;
    Q_EMIT channelsChanged();
}

QList<ChannelInfo> PollingSource::channels() const
{
    QList<ChannelInfo> list;
    for (const Entry &e : m_entries)
        list.append(e.info);
    return list;
}

void PollingSource::start(const QElapsedTimer &timeBase)
{
    if (m_running)
        return;
    m_timeBase = timeBase;
    m_delivered = 0;
    m_lost = 0;
    m_failed = 0;
    m_lastReadError = Error();
    m_unanswered = {};
    m_lastServed = -1;
    m_running = true;
    Q_EMIT runningChanged(true);
    if (!m_connection || !m_connection->isConnected()) {
        fail(Error(Error::Kind::Disconnected,
                   tr("cannot sample %1: not connected")
                       .arg(m_connection ? m_connection->uri().toString() : QString())));
        return;
    }
    const double now = nowS();
    for (Entry &e : m_entries)
        e.nextDue = now;
    pump();
}

void PollingSource::stop()
{
    if (!m_running)
        return;
    m_running = false;
    m_wakeup.stop();
    const double now = nowS();
    m_unanswered =
        m_inFlight ? Unanswered { m_inFlightChannel, now - m_inFlightSinceS } : Unanswered {};
    for (int i = 0; i < m_entries.size(); ++i) {
        Entry &e = m_entries[i];
        const double period = e.info.sourceRateMs * 1e-3;
        if (period <= 0 || e.nextDue > now)
            continue;
        if (const auto missed = qint64(std::floor((now - e.nextDue) / period)); missed > 0) {
            m_lost += missed;
            e.nextDue += double(missed) * period;
            Q_EMIT samplesLost(i, missed);
        }
    }
    if (m_inFlight) {
        // We own the reply; the engine copes with a reply deleted early and drops its answer.
        m_inFlight->disconnect(this);
        m_inFlight->deleteLater();
    }
    m_inFlight = nullptr;
    m_inFlightChannel = -1;
    Q_EMIT runningChanged(false);
}

double PollingSource::nowS() const
{
    return double(m_timeBase.nsecsElapsed()) * 1e-9;
}

void PollingSource::pump()
{
    if (!m_running || m_inFlight || m_entries.isEmpty())
        return;
    if (!m_connection) {
        fail(Error(Error::Kind::Disconnected, tr("the connection was closed")));
        return;
    }
    const double now = nowS();
    // Earliest due channel; among equal due times, the first after the last one served.
    int pick = -1;
    const int n = int(m_entries.size());
    for (int k = 1; k <= n; ++k) {
        const int i = (m_lastServed + k) % n;
        if (pick < 0 || m_entries[i].nextDue < m_entries[pick].nextDue)
            pick = i;
    }
    Entry &e = m_entries[pick];
    if (e.nextDue > now) {
        m_wakeup.start(std::max(0, int(std::ceil((e.nextDue - now) * 1000.0))));
        return;
    }
    const double period = e.info.sourceRateMs * 1e-3;
    if (period > 0) {
        // Periods that passed completely without a read are lost samples (a gap).
        const auto missed = qint64(std::floor((now - e.nextDue) / period));
        if (missed > 0) {
            m_lost += missed;
            e.nextDue += double(missed) * period;
            Q_EMIT samplesLost(pick, missed);
        }
        e.nextDue += period;
    } else {
        e.nextDue = now;
    }
    m_lastServed = pick;
    m_inFlightChannel = pick;
    m_inFlightSinceS = now;
    m_inFlight = m_connection->read(e.info.address);
    connect(m_inFlight.data(), &Reply::finished, this, &PollingSource::onReply);
}

void PollingSource::onReply()
{
    auto *reply = qobject_cast<Reply *>(sender());
    if (!reply || reply != m_inFlight)
        return;
    const int channel = m_inFlightChannel;
    m_inFlight = nullptr;
    m_inFlightChannel = -1;
    reply->deleteLater();
    if (!m_running)
        return;
    const double t = nowS();
    if (reply->ok()) {
        if (const auto value = sampleValue(reply->value())) {
            ++m_delivered;
            Q_EMIT samplesReady(channel, TraceSamples { { t, *value } });
            pump();
            return;
        }
    } else if (!m_connection || !m_connection->isConnected()) {
        fail(reply->error());
        return;
    }
    // A failed read (device error, timeout, garbage, non-number): one lost sample, a gap.
    ++m_failed;
    const QString reading = tr("reading %1").arg(m_entries[channel].info.id);
    m_lastReadError = reply->ok()
        ? Error(Error::Kind::Malformed, tr("%1: the answer is not a number").arg(reading))
        : reply->error().prefixed(reading);
    ++m_lost;
    Q_EMIT samplesLost(channel, 1);
    pump();
}

void PollingSource::onConnectionState(DeviceConnection::State state)
{
    if (m_running && state != DeviceConnection::State::Connected) {
        Error error = m_connection ? m_connection->lastError() : Error();
        if (!error.isError())
            error = Error(Error::Kind::Disconnected, tr("the connection was closed"));
        fail(error);
    }
}

void PollingSource::fail(const Error &error)
{
    stop();
    Q_EMIT errorOccurred(error.prefixed(tr("sampling stopped")));
}

} // namespace db::scope
