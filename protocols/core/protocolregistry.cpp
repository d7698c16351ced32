#include "protocolregistry.h"

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
                     QStringLiteral("unknown protocol '%1' in %2 (known: %3)")
                         .arg(uri->scheme(), text.trimmed(), known.join(QStringLiteral(", "))));
    }
    ConnectionUri result = uri.value();
    if (result.port() < 0 && info->defaultPort >= 0)
        result.setPort(info->defaultPort);
    if (result.port() > 65535)
        return Error(Error::Kind::InvalidArgument,
                     QStringLiteral("port %1 in %2 is out of range").arg(result.port()).arg(text));
    if (info->check) {
        if (auto checked = info->check(result); !checked)
            return checked.error();
    }
    return result;
}

Result<std::shared_ptr<DeviceConnection>> ProtocolRegistry::create(const QString &text) const
{
    auto uri = parseUri(text);
    if (!uri)
        return uri.error();
    const ProtocolInfo *info = find(uri->scheme());
    std::shared_ptr<DeviceConnection> connection = info->create(uri.value());
    if (!connection)
        return Error(Error::Kind::InvalidArgument,
                     QStringLiteral("cannot make a %1 connection for %2").arg(info->key, text));
    return connection;
}

} // namespace db
