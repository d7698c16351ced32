#include "syncproducer.h"

#include "canopenids.h"
#include "transport/canbus.h"

#include <QCanBusFrame>

namespace db::canopen {

SyncProducer::SyncProducer(CanBus *bus, QObject *parent)
    : QObject(parent)
    , m_bus(bus)
{
    m_timer.setTimerType(Qt::PreciseTimer);
    connect(&m_timer, &QTimer::timeout, this, &SyncProducer::sendOnce);
    connect(bus, &CanBus::closed, this, &SyncProducer::stop);
}

void SyncProducer::start(int periodMs, int counterOverflow)
{
    m_overflow = counterOverflow <= 0
        ? 0
        : qBound(kMinCounterOverflow, counterOverflow, kMaxCounterOverflow);
    m_counter = 0;
    m_timer.start(qMax(1, periodMs));
}

void SyncProducer::stop()
{
    m_timer.stop();
}

bool SyncProducer::sendOnce()
{
    QByteArray payload;
    int counter = 0;
    if (m_overflow > 0) {
        // CiA 301 7.2.5.3.1: the counter starts at 1 and wraps to 1 after the overflow value.
        m_counter = m_counter >= m_overflow ? 1 : m_counter + 1;
        counter = m_counter;
        payload.append(char(counter));
    }
    if (!m_bus->send(QCanBusFrame(cob::Sync, payload)))
        return false;
    Q_EMIT syncSent(counter);
    return true;
}

} // namespace db::canopen
