#include "heartbeatproducer.h"

#include "transport/canbus.h"

#include <QCanBusFrame>

namespace db::canopen {

HeartbeatProducer::HeartbeatProducer(CanBus *bus, QObject *parent)
    : QObject(parent)
    , m_bus(bus)
{
    m_timer.setTimerType(Qt::PreciseTimer);
    connect(&m_timer, &QTimer::timeout, this, &HeartbeatProducer::beat);
}

HeartbeatProducer::~HeartbeatProducer() = default;

void HeartbeatProducer::acquire(int periodMs)
{
    const int period = qMax(1, periodMs);
    ++m_users;
    if (!m_timer.isActive() || period < m_timer.interval()) {
        m_timer.start(period);
        beat(); // consumers start watching with the first heartbeat
    }
}

void HeartbeatProducer::release()
{
    if (m_users == 0)
        return;
    if (--m_users == 0)
        m_timer.stop();
}

void HeartbeatProducer::beat()
{
    if (m_bus->isOpen())
        m_bus->send(
            QCanBusFrame(cob::heartbeat(m_node), QByteArray(1, char(NmtState::Operational))));
}

} // namespace db::canopen
