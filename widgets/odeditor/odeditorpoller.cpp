#include "odeditorpoller.h"

#include "odeditormodel.h"

#include "core/connectionhealth.h"

namespace db::widgets {

OdEditorPoller::OdEditorPoller(OdEditorModel *model, QObject *parent)
    : QObject(parent)
    , m_model(model)
{
    m_timer.setSingleShot(false);
    connect(&m_timer, &QTimer::timeout, this, &OdEditorPoller::tick);
}

OdEditorPoller::~OdEditorPoller()
{
    holdStatusSource(false);
}

void OdEditorPoller::setConnection(DeviceConnection *connection)
{
    if (connection == m_connection)
        return;
    clear();
    m_connection = connection;
    bindStatusSource();
}

void OdEditorPoller::setPeriodMs(int ms)
{
    m_periodMs = qMax(0, ms);
    if (m_periodMs == 0) {
        holdStatusSource(false);
        m_timer.stop();
        return;
    }
    if (m_holding && m_source)
        m_source->acquire(this, m_periodMs);
    m_timer.start(m_periodMs);
}

void OdEditorPoller::bindStatusSource()
{
    StatusSource *source = m_connection ? m_connection->statusSource() : nullptr;
    if (source == m_source)
        return;
    holdStatusSource(false);
    disconnect(m_sourceUpdated);
    m_source = source;
    if (source)
        m_sourceUpdated =
            connect(source, &StatusSource::updated, this, &OdEditorPoller::onStatusUpdated);
}

void OdEditorPoller::holdStatusSource(bool on)
{
    if (on == m_holding)
        return;
    m_holding = on;
    if (!m_source)
        return;
    if (on)
        m_source->acquire(this, m_periodMs);
    else
        m_source->release(this);
}

void OdEditorPoller::onStatusUpdated()
{
    // Only while refreshing: with the refresh off the editor shows what it read last.
    if (!m_source || m_periodMs == 0 || !m_connection || !m_connection->isConnected())
        return;
    for (ObjectAddress a : m_source->cycleObjects()) {
        if (!m_model->definition(a) || !m_source->readInLastCycle(a))
            continue;
        if (m_source->isFresh(a))
            m_model->setValue(a, m_source->value(a));
        else if (const auto error = m_source->errors().find(a); error != m_source->errors().end())
            m_model->setReadFailed(a, error.value());
    }
}

bool OdEditorPoller::wanted(ObjectAddress address) const
{
    const ObjectDef *def = m_model->definition(address);
    // Objects being written are left alone until the write has finished.
    return def && def->readable() && m_model->state(address) != OdEditorModel::CellState::Writing
        && !m_queued.contains(address);
}

void OdEditorPoller::readNow(const QList<ObjectAddress> &addresses, bool urgent)
{
    for (ObjectAddress a : addresses) {
        if (!wanted(a))
            continue;
        m_queued.insert(a);
        (urgent ? m_urgent : m_background).append(a);
    }
    pump();
}

void OdEditorPoller::readAll()
{
    readNow(m_model->addresses(), false);
    m_backgroundTotal = m_backgroundDone + int(m_background.size() + m_backgroundInFlight.size());
    if (m_backgroundTotal == m_backgroundDone)
        m_backgroundTotal = m_backgroundDone = 0;
    Q_EMIT readAllProgress(m_backgroundDone, m_backgroundTotal);
}

void OdEditorPoller::cancelReadAll()
{
    for (ObjectAddress a : std::as_const(m_background))
        m_queued.remove(a);
    m_background.clear();
    m_backgroundInFlight.clear();
    m_backgroundDone = m_backgroundTotal = 0;
    Q_EMIT readAllProgress(0, 0);
}

void OdEditorPoller::backgroundFinished(ObjectAddress address)
{
    if (!m_backgroundInFlight.remove(address) || m_backgroundTotal == 0)
        return;
    ++m_backgroundDone;
    if (m_backgroundDone >= m_backgroundTotal)
        m_backgroundDone = m_backgroundTotal = 0;
    Q_EMIT readAllProgress(m_backgroundDone, m_backgroundTotal);
}

void OdEditorPoller::clear()
{
    holdStatusSource(false);
    ++m_generation; // replies in flight are dropped when they arrive
    m_inFlight = 0;
    m_urgent.clear();
    m_background.clear();
    m_queued.clear();
    const bool wasReading = m_backgroundTotal > 0;
    m_backgroundInFlight.clear();
    m_backgroundDone = m_backgroundTotal = 0;
    if (wasReading)
        Q_EMIT readAllProgress(0, 0);
}

void OdEditorPoller::tick()
{
    // The previous round is still running: skip this one rather than pile up requests.
    if (!m_urgent.isEmpty() || !m_connection || !m_connection->isConnected() || !m_visibleRows)
        return;
    // A device that does not answer is not asked every period; the next round after it has
    // answered again (ConnectionHealth probes it meanwhile).
    if (ConnectionHealth::isSilent(m_connection))
        return;
    bindStatusSource();
    QList<ObjectAddress> visible = m_visibleRows();
    if (m_source) {
        const QList<ObjectAddress> shared = m_source->cycleObjects();
        const qsizetype before = visible.size();
        visible.removeIf([&shared](ObjectAddress a) { return shared.contains(a); });
        holdStatusSource(visible.size() != before);
    }
    readNow(visible, true);
}

void OdEditorPoller::pump()
{
    if (!m_connection || !m_connection->isConnected())
        return;
    while (m_inFlight < kMaxInFlight && (!m_urgent.isEmpty() || !m_background.isEmpty())) {
        const bool background = m_urgent.isEmpty();
        const ObjectAddress a = background ? m_background.takeFirst() : m_urgent.takeFirst();
        if (background)
            m_backgroundInFlight.insert(a);
        m_queued.remove(a);
        Reply *reply = m_connection->read(a);
        reply->setParent(this);
        ++m_inFlight;
        ++m_sent;
        m_maxInFlight = qMax(m_maxInFlight, m_inFlight);
        const quint64 generation = m_generation;
        connect(reply, &Reply::finished, this,
                [this, reply, generation] { onReply(reply, generation); });
    }
}

void OdEditorPoller::onReply(Reply *reply, quint64 generation)
{
    reply->deleteLater();
    if (generation != m_generation)
        return;
    --m_inFlight;
    backgroundFinished(reply->address());
    if (reply->ok())
        m_model->setValue(reply->address(), reply->value());
    else if (reply->error().kind() != Error::Kind::Cancelled)
        m_model->setReadFailed(reply->address(), reply->error().toString());
    pump();
    if (m_inFlight == 0 && m_urgent.isEmpty() && m_background.isEmpty())
        Q_EMIT idle();
}

} // namespace db::widgets
