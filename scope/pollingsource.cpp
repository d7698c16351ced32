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
    connect(&m_wakeup, &WakeupTimer::timeout, this, &PollingSource::pump);
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
    for (const Entry &e : std::as_const(m_entries))
        delete e.inFlight.data();
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
                             tr("%1 (%2) is write-only").arg(info.id, def->displayName()));
            if (!datatype::isNumeric(def->type))
                return Error(Error::Kind::InvalidArgument,
                             tr("%1 (%2) is not a number and cannot be recorded")
                                 .arg(info.id, def->displayName()));
        }
    }
    m_entries.append({ info, nullptr, 0 });
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
    m_reads = 0;
    m_delivered = 0;
    m_lost = 0;
    m_failed = 0;
    m_lastReadError = Error();
    m_unanswered = {};
    m_schedule = PollSchedule();
    for (const Entry &e : std::as_const(m_entries))
        m_schedule.addChannel(qint64(e.info.sourceRateMs) * 1000000);
    m_schedule.start(nowNs());
    m_running = true;
    Q_EMIT runningChanged(true);
    if (!m_connection || !m_connection->isConnected()) {
        fail(Error(Error::Kind::Disconnected,
                   tr("cannot sample %1: not connected")
                       .arg(m_connection ? m_connection->uri().toString() : QString())));
        return;
    }
    m_group = GroupReader::of(m_connection);
    m_groupHeld.clear();
    if (m_group && m_readTogether && m_entries.size() >= 2) {
        QList<ObjectAddress> objects;
        for (const Entry &e : std::as_const(m_entries))
            objects.append(e.info.address);
        m_groupHeld = m_group->join(this, objects);
    }
    pump();
}

void PollingSource::stop()
{
    if (!m_running)
        return;
    m_running = false;
    m_wakeup.stop();
    if (m_group)
        m_group->leave(this);
    m_group = nullptr;
    m_groupHeld.clear();
    const qint64 now = nowNs();
    m_unanswered = {};
    const QList<qint64> lost = m_schedule.lostUntil(now);
    for (int i = 0; i < m_entries.size(); ++i) {
        countLost(i, lost.at(i));
        Entry &e = m_entries[i];
        if (!e.inFlight)
            continue;
        const double waitedS = double(now - e.sinceNs) * 1e-9;
        if (m_unanswered.channel < 0 || waitedS > m_unanswered.waitedS)
            m_unanswered = { i, waitedS };
        // We own the reply; the engine copes with a reply deleted early and drops its answer.
        e.inFlight->disconnect(this);
        e.inFlight->deleteLater();
        e.inFlight = nullptr;
    }
    Q_EMIT runningChanged(false);
}

qint64 PollingSource::nowNs() const
{
    return m_timeBase.nsecsElapsed();
}

void PollingSource::countLost(int channel, qint64 count)
{
    if (count <= 0)
        return;
    m_lost += count;
    Q_EMIT samplesLost(channel, count);
}

void PollingSource::pump()
{
    if (!m_running || m_entries.isEmpty() || m_holdPump)
        return;
    if (!m_connection) {
        fail(Error(Error::Kind::Disconnected, tr("the connection was closed")));
        return;
    }
    const qint64 now = nowNs();
    // Channels the group holds and that are due now are read in one exchange.
    const QList<ObjectAddress> held = m_group ? m_group->heldFor(this) : QList<ObjectAddress>();
    QList<int> together;
    for (const PollSchedule::Read &read : m_schedule.due(now)) {
        countLost(read.channel, read.lostBefore);
        Entry &e = m_entries[read.channel];
        e.sinceNs = now;
        if (held.contains(e.info.address) && held == m_groupHeld)
            together.append(read.channel);
        else
            readAlone(read.channel);
    }
    if (!together.isEmpty()) {
        Reply *reply = together.size() > 1 ? m_group->read(this) : nullptr;
        if (!reply) {
            for (int channel : std::as_const(together))
                readAlone(channel);
        } else {
            ++m_reads;
            QList<int> places;
            for (int channel : std::as_const(together)) {
                m_entries[channel].inFlight = reply;
                places.append(int(held.indexOf(m_entries[channel].info.address)));
            }
            // Every channel of the read takes its sample before the next reads start, so that
            // channels read together stay together.
            connect(reply, &Reply::finished, this, [this, reply, together, places] {
                m_holdPump = true;
                for (qsizetype i = 0; i < together.size(); ++i)
                    onReply(together.at(i), reply, places.at(i));
                m_holdPump = false;
                pump();
            });
        }
    }
    if (const auto next = m_schedule.nextDueNs())
        m_wakeup.wakeAt(m_timeBase, *next);
    else
        m_wakeup.stop();
}

void PollingSource::readAlone(int channel)
{
    Entry &e = m_entries[channel];
    ++m_reads;
    e.inFlight = m_connection->read(e.info.address);
    Reply *reply = e.inFlight.data();
    connect(reply, &Reply::finished, this, [this, channel, reply] { onReply(channel, reply); });
}

void PollingSource::onReply(int channel, Reply *reply, int slot)
{
    reply->deleteLater();
    if (!m_running || channel >= m_entries.size() || m_entries[channel].inFlight != reply)
        return;
    m_entries[channel].inFlight = nullptr;
    m_schedule.finished(channel);
    const double t = double(nowNs()) * 1e-9;
    if (reply->ok()) {
        const QVariant raw = slot < 0 ? reply->value() : reply->value().toList().value(slot);
        if (const auto value = sampleValue(raw)) {
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
    countLost(channel, 1);
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
