#pragma once

#include "canopen/cannetworkpool.h"
#include "core/connectionuri.h"
#include "transport/canbus.h"

#include <QEventLoop>
#include <QTimer>

#include <memory>

namespace db::cli {

// The CANopen network of a URI's bus, for the commands that work on the bus (no ?node= needed).
// Closing waits for the bus to close, so that queued frames leave before the process ends.
class NetworkSession
{
public:
    ~NetworkSession()
    {
        if (!m_network)
            return;
        CanBus *bus = m_network->bus();
        if (bus->state() == CanBus::State::Closed)
            return;
        QEventLoop loop;
        QObject::connect(bus, &CanBus::closed, &loop, &QEventLoop::quit);
        QTimer::singleShot(1000, &loop, &QEventLoop::quit);
        m_network->release();
        if (bus->state() != CanBus::State::Closed)
            loop.exec();
    }

    Result<void> open(const QString &text, int timeoutMs)
    {
        const auto uri = ConnectionUri::parse(text);
        if (!uri)
            return uri.error();
        auto network = m_pool.networkFor(*uri);
        if (!network)
            return network.error();
        m_network = network.value();
        QObject::connect(m_network->bus(), &CanBus::frameSent, m_network.get(),
                         [this] { ++m_sent; });
        return m_network->acquireAndWait(timeoutMs);
    }
    canopen::CanNetwork *network() const { return m_network.get(); }
    CanBus *bus() const { return m_network->bus(); }

    // Waits until `frames` frames in all have gone out since open (frameSent), at most ms.
    void flush(int frames, int ms)
    {
        if (m_sent >= frames)
            return;
        QEventLoop loop;
        QObject::connect(m_network->bus(), &CanBus::frameSent, &loop, [&] {
            if (m_sent >= frames)
                loop.quit();
        });
        QTimer::singleShot(ms, &loop, &QEventLoop::quit);
        loop.exec();
    }

private:
    canopen::CanNetworkPool m_pool;
    std::shared_ptr<canopen::CanNetwork> m_network;
    int m_sent = 0;
};

} // namespace db::cli
