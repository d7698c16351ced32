#include "cannetworkpool.h"

#include "canbusfactory.h"
#include <QCoreApplication>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::canopen)
};
} // namespace

namespace db::canopen {

QString CanNetworkPool::busKey(const ConnectionUri &uri)
{
    const QString transport = CanBusFactory::transportOf(uri);
    QString key = transport + QStringLiteral("://") + uri.host();
    if (transport == u"slcan")
        key += QStringLiteral(":%1").arg(uri.portOr(CanBusFactory::kDefaultSlcanPort));
    return key;
}

Result<std::shared_ptr<CanNetwork>> CanNetworkPool::networkFor(const ConnectionUri &uri)
{
    const auto bitrate = CanBusFactory::bitrateOf(uri);
    if (!bitrate)
        return bitrate.error();
    const QString key = busKey(uri);
    if (auto existing = m_networks[key].lock()) {
        if (*bitrate != 0 && existing->bitrate() != 0 && *bitrate != existing->bitrate())
            return Error(Error::Kind::InvalidArgument,
                         Tr::tr("%1 is already in use at %2 bit/s, not %3 bit/s")
                             .arg(existing->name())
                             .arg(existing->bitrate())
                             .arg(*bitrate));
        return existing;
    }
    auto bus = CanBusFactory::makeBus(uri);
    if (!bus)
        return bus.error();
    auto network = std::make_shared<CanNetwork>(bus.value(), *bitrate);
    m_networks[key] = network;
    return network;
}

int CanNetworkPool::size() const
{
    int alive = 0;
    for (auto it = m_networks.begin(); it != m_networks.end();) {
        if (it->second.expired()) {
            it = m_networks.erase(it);
        } else {
            ++alive;
            ++it;
        }
    }
    return alive;
}

} // namespace db::canopen
