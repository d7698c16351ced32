#pragma once

// SYNC producer (CiA 301 7.2.5): a frame on 080h every period, empty or with a counter that runs
// 1..overflow (CiA 301 1019h: overflow 2..240; 0 = no counter).

#include <QObject>
#include <QTimer>

namespace db {
class CanBus;
}

namespace db::canopen {

class SyncProducer : public QObject
{
    Q_OBJECT
public:
    static constexpr int kMinCounterOverflow = 2;
    static constexpr int kMaxCounterOverflow = 240;

    // The bus is not owned and must outlive the producer.
    explicit SyncProducer(CanBus *bus, QObject *parent = nullptr);

    // Starts (or restarts) sending every periodMs (>= 1). counterOverflow 0 = no counter byte,
    // otherwise clamped to 2..240. The first SYNC goes out after one period.
    void start(int periodMs, int counterOverflow = 0);
    void stop();
    bool isRunning() const { return m_timer.isActive(); }
    int periodMs() const { return m_timer.interval(); }
    // One SYNC now (with the next counter value when counting); false if the bus is not open.
    bool sendOnce();

Q_SIGNALS:
    void syncSent(int counter); // 0 without counter

private:
    CanBus *m_bus;
    QTimer m_timer;
    int m_overflow = 0;
    int m_counter = 0;
};

} // namespace db::canopen
