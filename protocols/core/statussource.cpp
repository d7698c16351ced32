#include "statussource.h"

#include "connectionhealth.h"
#include "deviceconnection.h"
#include "reply.h"

#include <QCoreApplication>

#include <limits>
#include <memory>

namespace db {

StatusSource::StatusSource(DeviceConnection *connection, QObject *parent)
    : QObject(parent)
    , m_connection(connection)
{
    m_timer.setSingleShot(true);
    connect(&m_timer, &QTimer::timeout, this, &StatusSource::start);
    if (connection)
        connect(connection, &DeviceConnection::stateChanged, this, &StatusSource::onStateChanged);
}

StatusSource::~StatusSource() = default;

DeviceConnection *StatusSource::connection() const
{
    return m_connection;
}

void StatusSource::acquire()
{
    if (++m_users == 1)
        schedule(0);
}

void StatusSource::release()
{
    if (m_users == 0)
        return;
    --m_users;
    if (!wanted())
        m_timer.stop(); // a cycle in flight finishes; schedule() then does nothing
}

void StatusSource::acquire(const QObject *holder, int intervalMs, const QList<ObjectAddress> &extra)
{
    if (!holder)
        return;
    const bool first = !wanted();
    Demand &demand = m_holders[holder];
    demand.intervalMs = qMax(10, intervalMs);
    demand.extra = extra;
    if (!demand.destroyed)
        demand.destroyed =
            connect(holder, &QObject::destroyed, this, [this, holder] { release(holder); });
    if (first)
        schedule(0);
    else if (m_timer.isActive() && m_timer.remainingTime() > effectiveIntervalMs())
        m_timer.start(effectiveIntervalMs());
}

void StatusSource::release(const QObject *holder)
{
    const auto it = m_holders.find(holder);
    if (it == m_holders.end())
        return;
    disconnect(it->destroyed);
    m_holders.erase(it);
    if (!wanted())
        m_timer.stop();
}

int StatusSource::effectiveIntervalMs() const
{
    int ms = m_users > 0 || m_holders.isEmpty() ? m_intervalMs : std::numeric_limits<int>::max();
    for (const Demand &demand : m_holders)
        ms = qMin(ms, demand.intervalMs);
    return ms;
}

void StatusSource::setIntervalMs(int ms)
{
    m_intervalMs = qMax(10, ms);
    if (m_timer.isActive())
        m_timer.start(effectiveIntervalMs());
}

quint64 StatusSource::refresh()
{
    if (!m_connection || !m_connection->isConnected())
        return m_serial + 1;
    m_refreshAll = true;
    return refresh(nullptr);
}

quint64 StatusSource::refresh(const QObject *requester)
{
    if (!m_connection || !m_connection->isConnected())
        return m_serial + 1;
    if (const auto it = m_holders.find(requester); it != m_holders.end())
        it->refresh = true;
    m_refresh = true;
    m_refreshStatusWord = true;
    if (m_busy)
        return m_serial + 2; // the running cycle, then the fresh one
    m_timer.start(0);
    return m_serial + 1;
}

QList<ObjectAddress> StatusSource::statusWordObjects() const
{
    const QList<ObjectAddress> polled = polledObjects();
    if (polled.contains(m_statusWordAddress))
        return { m_statusWordAddress };
    return {};
}

void StatusSource::addKnown(QList<ObjectAddress> &to, const QList<ObjectAddress> &objects) const
{
    if (!m_connection)
        return;
    const ObjectDictionary &dictionary = m_connection->dictionary();
    for (ObjectAddress address : objects) {
        if (!to.contains(address) && dictionary.contains(address))
            to.append(address);
    }
}

QList<ObjectAddress> StatusSource::cycleObjects() const
{
    QList<ObjectAddress> objects = m_users > 0 ? polledObjects() : statusWordObjects();
    for (const Demand &demand : m_holders)
        addKnown(objects, demand.extra);
    return objects;
}

bool StatusSource::isDue(const QElapsedTimer &served, int intervalMs)
{
    // Timers may fire a little early: a consumer whose interval has nearly passed is served
    // now rather than one cycle later.
    const int slackMs = qMax(2, intervalMs / 8);
    return !served.isValid() || served.elapsed() + slackMs >= intervalMs;
}

void StatusSource::planCycle()
{
    m_due = statusWordObjects();
    // Asked for by name: read even where the description does not list it.
    if (m_refreshStatusWord && m_due.isEmpty() && m_statusWordAddress != ObjectAddress())
        m_due.append(m_statusWordAddress);
    m_refreshStatusWord = false;
    if (m_refreshAll || (m_users > 0 && isDue(m_usersServed, m_intervalMs))) {
        for (ObjectAddress address : polledObjects()) {
            if (!m_due.contains(address))
                m_due.append(address);
        }
        if (m_users > 0)
            m_usersServed.start();
    }
    for (Demand &demand : m_holders) {
        if (!m_refreshAll && !demand.refresh && !isDue(demand.served, demand.intervalMs))
            continue;
        addKnown(m_due, demand.extra);
        demand.served.start();
        demand.refresh = false;
    }
    m_refreshAll = false;
}

void StatusSource::onStateChanged()
{
    ++m_generation; // replies still in flight belong to the old link
    m_busy = false;
    m_refresh = false;
    m_refreshAll = false;
    m_refreshStatusWord = false;
    m_pending = 0;
    m_timer.stop();
    m_fresh.clear();
    m_lastCycle.clear();
    m_usersServed.invalidate();
    for (Demand &demand : m_holders) {
        demand.served.invalidate();
        demand.refresh = false;
    }
    if (m_connection && m_connection->isConnected()) {
        m_errors.clear();
        m_readErrors.clear();
        m_cycles = 0;
        connectionMade();
        schedule(0);
        return;
    }
    Q_EMIT updated();
}

void StatusSource::schedule(int delayMs)
{
    if (m_busy || !wanted() || !m_connection || !m_connection->isConnected())
        return;
    m_timer.start(delayMs);
}

void StatusSource::start()
{
    if (m_busy || !wanted() || !m_connection || !m_connection->isConnected())
        return;
    m_busy = true;
    m_refresh = false; // this cycle's reads start now: it is the fresh one
    m_readThisCycle.clear();
    planCycle();
    poll();
}

void StatusSource::readEach(const QList<ObjectAddress> &addresses)
{
    if (addresses.isEmpty()) {
        finishCycle();
        return;
    }
    m_pending = int(addresses.size());
    const quint64 generation = m_generation;
    auto replies = std::make_shared<QList<QPointer<Reply>>>();
    for (ObjectAddress address : addresses) {
        Reply *reply = m_connection->read(address);
        reply->setParent(this); // deleted with the source if it never finishes in time
        replies->append(reply);
        connect(reply, &Reply::finished, this, [this, reply, generation, replies] {
            reply->deleteLater();
            if (generation != m_generation)
                return;
            if (reply->ok()) {
                store(reply->address(), reply->value());
            } else {
                storeError(reply->address(), reply->error());
                if (ConnectionHealth::isNoAnswer(reply->error()))
                    withdraw(*replies, reply->error());
            }
            if (--m_pending == 0)
                finishCycle();
        });
    }
}

// The device did not answer one read of the cycle (or the link failed): the reads queued behind
// it would each wait out their own time limit, so the cycle ends now and says so at once. Its
// other objects keep their old values, stale, with the same cause. Deleting an unsent request
// withdraws it; one already answered still comes (its result is in the queue).
void StatusSource::withdraw(const QList<QPointer<Reply>> &replies, const Error &cause)
{
    for (const QPointer<Reply> &other : replies) {
        if (!other || other->isFinished())
            continue;
        storeError(other->address(), cause);
        delete other.data();
        --m_pending;
    }
}

void StatusSource::store(ObjectAddress address, const QVariant &raw)
{
    m_values.insert(address, raw);
    m_fresh.insert(address);
    m_errors.remove(address);
    m_readErrors.remove(address);
    m_readThisCycle.insert(address);
}

void StatusSource::storeError(ObjectAddress address, const Error &error)
{
    m_fresh.remove(address);
    m_errors.insert(address, error.toString());
    m_readErrors.insert(address, error);
    m_readThisCycle.insert(address);
}

void StatusSource::finishCycle()
{
    if (!m_busy)
        return;
    m_busy = false;
    if (!m_connection || !m_connection->isConnected())
        m_fresh.clear(); // the link went away during the cycle
    m_lastCycle = m_readThisCycle;
    ++m_cycles;
    ++m_serial;
    Q_EMIT updated();
    // A device that stopped answering is asked less often until it answers again.
    schedule(m_refresh ? 0 : ConnectionHealth::pollIntervalMs(m_connection, effectiveIntervalMs()));
}

std::optional<quint32> StatusSource::statusWord() const
{
    const QVariant raw = m_values.value(m_statusWordAddress);
    if (!raw.isValid())
        return std::nullopt;
    return quint32(raw.toULongLong());
}

StatusValue StatusSource::statusWordValue() const
{
    StatusValue v = makeValue(QStringLiteral("statusword"), statusWordLabel(), m_statusWordAddress);
    if (const auto word = statusWord())
        v.text = QStringLiteral("0x%1").arg(*word, 4, 16, QLatin1Char('0'));
    return v;
}

StatusSource::State StatusSource::state() const
{
    const auto word = statusWord();
    return word ? decodeState(*word) : State::Unknown;
}

StatusSource::State StatusSource::decodeState(quint32 sw)
{
    // Bit 5 (quick stop) only matters where the pattern says so: mask 0x4F first.
    switch (sw & 0x4F) {
    case 0x00:
        return State::NotReadyToSwitchOn;
    case 0x40:
        return State::SwitchOnDisabled;
    case 0x0F:
        return State::FaultReactionActive;
    case 0x08:
        return State::Fault;
    default:
        break;
    }
    switch (sw & 0x6F) {
    case 0x21:
        return State::ReadyToSwitchOn;
    case 0x23:
        return State::SwitchedOn;
    case 0x27:
        return State::OperationEnabled;
    case 0x07:
        return State::QuickStopActive;
    default:
        return State::Unknown;
    }
}

QString StatusSource::stateText(State state)
{
    switch (state) {
    case State::NotReadyToSwitchOn:
        return tr("Not ready to switch on");
    case State::SwitchOnDisabled:
        return tr("Switch on disabled");
    case State::ReadyToSwitchOn:
        return tr("Ready to switch on");
    case State::SwitchedOn:
        return tr("Switched on");
    case State::OperationEnabled:
        return tr("Operation enabled");
    case State::QuickStopActive:
        return tr("Quick stop active");
    case State::FaultReactionActive:
        return tr("Fault reaction active");
    case State::Fault:
        return tr("Fault");
    case State::Unknown:
        break;
    }
    return tr("Unknown state");
}

StatusValue StatusSource::makeValue(const QString &key, const QString &label,
                                    ObjectAddress address) const
{
    StatusValue v;
    v.key = key;
    v.label = label;
    v.address = address;
    v.raw = m_values.value(address);
    v.fresh = m_fresh.contains(address);
    v.error = m_errors.value(address);
    if (!v.raw.isValid()) {
        v.text = QStringLiteral("—");
    } else {
        const ObjectDef *def = m_connection ? m_connection->dictionary().find(address) : nullptr;
        v.text = def ? def->localDisplayText(v.raw) : v.raw.toString();
    }
    return v;
}

} // namespace db
