#include "cannetwork.h"

#include "emcyconsumer.h"
#include "heartbeatproducer.h"
#include "lssmaster.h"
#include "nmtmaster.h"
#include "nodeguarding.h"
#include "nodemonitor.h"
#include "sdoclient.h"
#include "syncproducer.h"
#include "transport/canbus.h"

#include <QEventLoop>
#include <QTimer>

#include <QCoreApplication>
#include <algorithm>
#include <utility>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::canopen)
};
} // namespace

namespace db::canopen {

CanNetwork::CanNetwork(CanBus *bus, int bitrate, QObject *parent)
    : QObject(parent)
    , m_bus(bus)
    , m_bitrate(bitrate)
{
    m_bus->setParent(this);
    m_sdo = new SdoClient(m_bus, this);
    m_nmt = new NmtMaster(m_bus, this);
    m_monitor = new NodeMonitor(m_bus, this);
    m_emcy = new EmcyConsumer(m_bus, this);
    m_sync = new SyncProducer(m_bus, this);
    m_lss = new LssMaster(m_bus, this);
    m_heartbeat = new HeartbeatProducer(m_bus, this);
    m_guarding = new NodeGuarding(m_bus, this);
    connect(m_bus, &CanBus::opened, this, &CanNetwork::opened);
    connect(m_bus, &CanBus::closed, this, [this](const Error &error) {
        const bool requested = std::exchange(m_closing, false);
        if (requested && m_users > 0 && !error.isError()) {
            // Acquired again while closing: open once more for the new users.
            m_bus->open();
            return;
        }
        // A bus that closed by itself (link lost) has no users left to release it.
        m_users = 0;
        Q_EMIT closed(error);
    });
    connect(m_bus, &CanBus::warning, this, &CanNetwork::warning);
    connect(m_bus, &CanBus::frameReceived, this, &CanNetwork::dispatch);
}

CanNetwork::~CanNetwork()
{
    // The SDO client first: its replies fail while the bus still exists.
    delete m_sdo;
    m_sdo = nullptr;
}

QString CanNetwork::name() const
{
    return m_bus->name();
}

bool CanNetwork::isOpen() const
{
    return m_bus->isOpen();
}

void CanNetwork::acquire()
{
    ++m_users;
    if (m_bus->state() == CanBus::State::Closed)
        m_bus->open();
}

void CanNetwork::release()
{
    if (m_users == 0)
        return;
    if (--m_users == 0 && m_bus->state() != CanBus::State::Closed) {
        m_closing = true;
        m_bus->close();
    }
}

Result<void> CanNetwork::acquireAndWait(int timeoutMs)
{
    ++m_users;
    if (m_bus->isOpen())
        return {};
    if (m_bus->state() == CanBus::State::Closed)
        return m_bus->openAndWait(timeoutMs);
    // Opening or closing for another user: wait for the outcome.
    Error failure;
    QEventLoop loop;
    connect(m_bus, &CanBus::opened, &loop, &QEventLoop::quit);
    connect(m_bus, &CanBus::closed, &loop, [&](const Error &error) {
        failure = error;
        loop.quit();
    });
    QTimer::singleShot(timeoutMs, &loop, &QEventLoop::quit);
    loop.exec();
    if (m_bus->isOpen())
        return {};
    return failure.isError()
        ? failure
        : Error(Error::Kind::Timeout,
                Tr::tr("%1 did not open within %2 ms").arg(name()).arg(timeoutMs));
}

bool CanNetwork::send(const QCanBusFrame &frame)
{
    return m_bus->send(frame);
}

void CanNetwork::subscribe(quint32 cobId, QObject *context, FrameHandler handler)
{
    m_subscriptions[cobId].push_back({ context, std::move(handler) });
}

void CanNetwork::setDictionary(NodeId node, const ObjectDictionary &dictionary)
{
    m_emcy->setDictionary(node, dictionary);
    m_dictionaries.insert(node, dictionary);
    Q_EMIT dictionaryChanged(node);
}

const ObjectDictionary *CanNetwork::dictionary(NodeId node) const
{
    const auto it = m_dictionaries.constFind(node);
    return it == m_dictionaries.cend() ? nullptr : &it.value();
}

QList<NodeId> CanNetwork::describedNodes() const
{
    return m_dictionaries.keys();
}

void CanNetwork::dispatch(const QCanBusFrame &frame)
{
    const auto it = m_subscriptions.find(frame.frameId());
    if (it == m_subscriptions.end())
        return;
    auto &list = it->second;
    list.erase(std::remove_if(list.begin(), list.end(),
                              [](const Subscription &s) { return s.context.isNull(); }),
               list.end());
    // A copy: a handler may subscribe or unsubscribe.
    const std::vector<Subscription> handlers = list;
    for (const Subscription &s : handlers) {
        if (s.context)
            s.handler(frame);
    }
    if (list.empty())
        m_subscriptions.erase(frame.frameId());
}

} // namespace db::canopen
