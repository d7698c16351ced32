#include "protocolregistry.h"
#include <QCoreApplication>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::core)
};
} // namespace

namespace db {

void ProtocolRegistry::add(const ProtocolInfo &info)
{
    m_protocols.removeIf([&](const ProtocolInfo &p) { return p.scheme == info.scheme; });
    m_protocols.append(info);
}

const ProtocolInfo *ProtocolRegistry::find(const QString &scheme) const
{
    for (const ProtocolInfo &p : m_protocols) {
        if (p.scheme.compare(scheme, Qt::CaseInsensitive) == 0)
            return &p;
    }
    return nullptr;
}

Result<ConnectionUri> ProtocolRegistry::parseUri(const QString &text) const
{
    auto uri = ConnectionUri::parse(text);
    if (!uri)
        return uri;
    const ProtocolInfo *info = find(uri->scheme());
    if (!info) {
        QStringList known;
        for (const ProtocolInfo &p : m_protocols)
            known.append(p.scheme);
        return Error(Error::Kind::InvalidArgument,
                     Tr::tr("unknown protocol '%1' in %2 (known: %3)")
                         .arg(uri->scheme(), text.trimmed(), known.join(QStringLiteral(", "))));
    }
    ConnectionUri result = uri.value();
    if (result.port() < 0 && info->defaultPort >= 0)
        result.setPort(info->defaultPort);
    if (result.port() > 65535)
        return Error(Error::Kind::InvalidArgument,
                     Tr::tr("port %1 in %2 is out of range").arg(result.port()).arg(text));
    if (info->check) {
        if (auto checked = info->check(result); !checked)
            return checked.error();
    }
    return result;
}

Result<ConnectionPlan> ProtocolRegistry::prepare(const QString &text, int connectTimeoutMs,
                                                 int requestTimeoutMs) const
{
    auto uri = parseUri(text);
    if (!uri)
        return uri.error();
    ConnectionPlan plan;
    plan.uri = uri.value();
    plan.connectTimeoutMs = connectTimeoutMs;
    plan.requestTimeoutMs = requestTimeoutMs;
    const ProtocolInfo *info = find(plan.uri.scheme());
    if (info->prepare) {
        if (auto prepared = info->prepare(plan); !prepared)
            return prepared.error();
    }
    return plan;
}

Result<std::shared_ptr<DeviceConnection>> ProtocolRegistry::create(const ConnectionPlan &plan) const
{
    const ProtocolInfo *info = find(plan.uri.scheme());
    if (!info || !info->create)
        return Error(
            Error::Kind::InvalidArgument,
            Tr::tr("unknown protocol '%1' in %2").arg(plan.uri.scheme(), plan.uri.toString()));
    auto made = info->create(plan);
    if (!made)
        return made.error();
    std::shared_ptr<DeviceConnection> connection = std::move(made).value();
    connection->setConnectTimeoutMs(plan.connectTimeoutMs);
    connection->setRequestTimeoutMs(plan.requestTimeoutMs);
    return connection;
}

Result<std::shared_ptr<DeviceConnection>> ProtocolRegistry::create(const QString &text) const
{
    auto plan = prepare(text);
    if (!plan)
        return plan.error();
    return create(plan.value());
}

} // namespace db
